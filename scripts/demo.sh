#!/usr/bin/env bash
# Proxima's main job on its built-in default: the paper's bunny-against-bunny
# scene (section 6.1). The held bunny approaches the fixed one along +x from
# 50 mm to 0.5 mm (path T of docs/cli.md), one deterministic step per pose,
# with the precise method and the original Johnson-Cohen baseline side by
# side: LMD counts, forces, force jumps and timings, and a CSV per step.
# Then the same approach in real time on Proxima's threads (`proxima run`),
# the scripted device holding the bunny.
# Extra arguments go to `proxima path` (e.g. --steps 200 --force soft).
# Last, the Vulkan viewer shows the scene: in a window when there is a
# display, else headless (the CPU driver, no GPU needed) as frames in
# build/demo/.
# Works on a fresh Debian 12 machine; installs what it needs.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/deps.sh
need_packages "${CORE_PACKAGES[@]}"
need_packages "${VIEWER_PACKAGES[@]}"  # the viewer, last

cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DPROX_SHARED_ASSETS_DIR="$(assets_dir)" >/dev/null
cmake --build build/release --target proxima -j "$(nproc)"
build/release/samples/cli/proxima path --csv build/proxima-path.csv "$@"
echo
build/release/samples/cli/proxima run --json build/proxima-run.json

# The viewer (docs/viewer.md), on lavapipe when there is no GPU.
cmake --build build/release --target proxima-viewer -j "$(nproc)"
echo
if [ -n "${DISPLAY:-}" ]; then
  echo "proxima-viewer: a window on $DISPLAY (Esc closes it)"
  build/release/samples/viewer/proxima-viewer
else
  echo "proxima-viewer: no display, so 60 headless frames of the scene go to build/demo/"
  build/release/samples/viewer/proxima-viewer --headless --frames 60 --seconds 0.5 --out build/demo
fi
