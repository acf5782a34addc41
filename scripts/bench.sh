#!/usr/bin/env bash
# The full scene benchmark (docs/benchmarks.md): builds Release with the
# benchmarks and FCL on, runs every scene of proxima_bench at full size (a few
# minutes; the machine should be otherwise idle), and makes the plots and
# tables in docs/benchmarks/. Per-step CSV and summary JSON go to
# build/bench-results/. Extra arguments go to proxima_bench (e.g. --poses 200,
# --reference-every 10, --scene path-r).
# Works on a fresh Debian 12 machine; installs what it needs (matplotlib and
# fast-simplification from PyPI into build/bench-venv, Coal's wheel into
# build/coal-venv). About 4 minutes on the 2-core development machine once
# those are installed, the build included; allow 10 on a fresh one.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/deps.sh
need_packages "${CORE_PACKAGES[@]}" "${BENCH_PACKAGES[@]}"

jobs=$(( $(nproc) < 2 ? $(nproc) : 2 ))

# Python for the plots and the decimated bunnies (build/bench-venv), and
# Coal's wheel (its C++ library and CMake config) in a venv of its own
# (build/coal-venv). Versions as in docs/dependencies.md.
bench_venv
if [ ! -x build/coal-venv/bin/python ]; then
  python3 -m venv build/coal-venv
fi
build/coal-venv/bin/python -c "import coal" 2>/dev/null ||
  build/coal-venv/bin/pip install --quiet "coal==$COAL_VERSION"
coal_prefix=$(ls -d build/coal-venv/lib/python3*/site-packages/cmeel.prefix)

# Coal's prefix goes to its peer's own build only (PROX_COAL_PREFIX, see
# bench/CMakeLists.txt): on CMAKE_PREFIX_PATH it would hand FCL the wheel's
# octomap. An earlier configure may have left that in the cache.
stale=()
grep -qs "^octomap_DIR.*cmeel" build/release/CMakeCache.txt &&
  stale=(-UCMAKE_PREFIX_PATH -Doctomap_DIR=octomap_DIR-NOTFOUND)
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DPROX_WARNINGS_AS_ERRORS=ON \
  -DPROX_SHARED_ASSETS_DIR="$(assets_dir)" \
  -DPROX_BUILD_BENCHMARKS=ON -DPROX_BENCH_WITH_FCL=ON -DPROX_BENCH_WITH_COAL=ON \
  -DPROX_COAL_PREFIX="$PWD/$coal_prefix" "${stale[@]}" >/dev/null
cmake --build build/release --target proxima_bench proxima_timing_bench -j "$jobs"
# The bench and Coal's peer each load one build of every library.
bench/check_peers.sh build/release/bench/proxima_bench build/release/bench/proxima_coal_peer

build/bench-venv/bin/python bench/decimate.py "$(assets_dir)/bunny.obj" build/bench-meshes

mkdir -p build/bench-results
{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- sdk bench 2>/dev/null || echo ' with uncommitted changes in sdk/ or bench/')"
  lscpu | grep -E "^(Model name|CPU\(s\)|Thread|Core|Socket|CPU max MHz|Hypervisor vendor|L2 cache|L3 cache):" || true
} | tee build/bench-results/machine.txt
echo "== proxima_bench --scene all --meshes build/bench-meshes --out build/bench-results $*"
build/release/bench/proxima_bench --scene all --meshes build/bench-meshes --out build/bench-results "$@" |
  tee build/bench-results.txt
build/bench-venv/bin/python bench/plot.py build/bench-results docs/benchmarks
# The haptic loop's timing, each way of waiting with and without real-time
# priority, search idle and busy (docs/benchmarks-runtime.md, "Keeping the beat").
echo "== proxima_timing_bench --out build/bench-results"
build/release/bench/proxima_timing_bench --out build/bench-results | tee build/bench-timing.txt
build/bench-venv/bin/python bench/plot_timing.py build/bench-results docs/benchmarks
