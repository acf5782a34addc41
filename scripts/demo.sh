#!/usr/bin/env bash
# Proxima's main job on its built-in default. For now (the engine lands next)
# that is the numerical stress report of the exact triangle kernel: seeded
# triangle pairs in every hard family, checked against a quad-precision
# reference. Works on a fresh Debian 12 machine; installs what it needs.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/deps.sh
need_packages "${CORE_PACKAGES[@]}"

cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release --target proxima_stress_report -j "$(nproc)"
build/release/tests/proxima_stress_report "$@"
