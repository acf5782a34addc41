#!/usr/bin/env bash
# Builds everything and runs every test: the core alone (optional parts off),
# an AddressSanitizer + UndefinedBehaviorSanitizer build of the whole suite, a
# ThreadSanitizer build of the threaded tests, the benchmarks once (so they
# never rot), the release suite, the Windows build under Wine, and the
# Python bindings last.
# Works on a fresh Debian 12 machine; installs the packages it needs.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/deps.sh
need_packages "${CORE_PACKAGES[@]}" libbenchmark-dev python3 python3-venv
# The viewer's tests (label "viewer") run in the ASan and release suites, on lavapipe.
need_packages "${VIEWER_PACKAGES[@]}"
# The C# bindings: the release ctest runs their NUnit suite (label csharp).
need_packages "${CSHARP_PACKAGES[@]}"
# The OpenXR device's tests (tests/openxr): Debian's loader and validation layer.
need_packages "${OPENXR_PACKAGES[@]}"

# HID devices (PROX_WITH_HIDAPI) and their emulation for the tests (tests/hid).
need_packages "${HID_PACKAGES[@]}"

# The install tests (in the release suite): consume.sh installs the .deb
# packages for real only on CI's throwaway machines (docs/install.md).
need_packages "${INSTALL_PACKAGES[@]}"
[ -n "${CI:-}" ] && export PROX_DEB_SYSTEM_INSTALL=${PROX_DEB_SYSTEM_INSTALL:-1}

# The Windows build (scripts/windows.sh): MinGW-w64, Wine, GoogleTest's sources.
need_packages "${WINDOWS_PACKAGES[@]}"

# ccache: within one run the library is compiled with the release build's
# flags three times (the release build, install.subdirectory's vendored
# build, the Python wheel); the later two are then cache hits. Every build
# below goes through it (the consumers and pip inherit the variables). The
# cache is build/ccache unless CCACHE_DIR says otherwise.
need_packages "${TEST_PACKAGES[@]}"
export CCACHE_DIR=${CCACHE_DIR:-$(pwd)/build/ccache}
export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
ccache --zero-stats >/dev/null

jobs=$(nproc)
# Each stage says when it starts, so a slow CI run shows where its time went
# (the whole run must stay under 30 minutes).
# With the CPU time of everything run so far (bash's times, children's user +
# system), which a busy machine stretches far less than the wall-clock time.
stage() {
  mkdir -p build
  times >build/times.txt
  local cpu
  cpu=$(awk 'END { split($1, u, "m"); split($2, s, "m"); printf "%d", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' \
    build/times.txt)
  echo "== $* [at $((SECONDS / 60)) min $((SECONDS % 60)) s, CPU so far $((cpu / 60)) min $((cpu % 60)) s]"
}
configure() {  # configure DIR [cmake args...]
  local dir=$1
  shift
  cmake -S . -B "$dir" -G Ninja -DPROX_WARNINGS_AS_ERRORS=ON -DPROX_SHARED_ASSETS_DIR="$(assets_dir)" \
    -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache "$@" >/dev/null
}

stage "core only (nothing optional: no tests, samples, benchmarks or glTF)"
configure build/core -DCMAKE_BUILD_TYPE=Release -DPROX_BUILD_TESTS=OFF -DPROX_BUILD_SAMPLES=OFF -DPROX_BUILD_BENCHMARKS=OFF \
  -DPROX_WITH_GLTF=OFF -DPROX_BUILD_CSHARP=OFF \
  -DPROX_WITH_HIDAPI=OFF \
  -DPROX_WITH_OPENXR=OFF
cmake --build build/core -j "$jobs"

stage "address + undefined-behaviour sanitizers"
# Unity builds of the test programs (PROX_UNITY_TESTS, docs/build.md): about
# half the compile time under the sanitizers; the release build below
# compiles each test file on its own.
# The sanitizer builds (here, ThreadSanitizer's and the fuzzers') keep -O2
# but carry line tables only (-g1): their reports still name each frame's
# function, file and line, and the compile takes about a quarter less time
# (gltf.cpp under ASan: 68 s of CPU with -g, 49 s with -g1).
sanitizer_flags=(-DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG")
configure build/asan -DCMAKE_BUILD_TYPE=RelWithDebInfo "${sanitizer_flags[@]}" -DPROX_SANITIZE=address,undefined \
  -DPROX_UNITY_TESTS=ON
cmake --build build/asan -j "$jobs"
ctest --test-dir build/asan --output-on-failure -j "$jobs"

stage "thread sanitizer (the tests labelled 'threads': handoffs, runtime threads, C API threads and devices)"
configure build/tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo "${sanitizer_flags[@]}" -DPROX_SANITIZE=thread \
  -DPROX_BUILD_SAMPLES=OFF \
  -DPROX_UNITY_TESTS=ON
cmake --build build/tsan -j "$jobs" --target proxima_runtime_tests proxima_threads_tests proxima_capi_threads_tests \
  proxima_capi_stream_tests proxima_capi_timing_tests \
  proxima_hid_capi_tests proxima_hid_pid_device_tests proxima_openxr_tests proxima_coupling_threads_tests proxima_parallel_tests
# Two at a time, as the other suites: these tests close their loops on what
# they measure (counts, gaps), never on a quiet machine.
ctest --test-dir build/tsan --output-on-failure -L threads -j "$jobs"

stage "fuzzers (libFuzzer, ASan + UBSan): each target 12 s on corpora from the shared assets, one per core at a time (docs/robustness.md)"
need_packages "${FUZZ_PACKAGES[@]}"
# clang warns where GCC does not (INFINITY, a float, promoted in the kernel):
# the fuzz build does not add -Werror; the GCC builds keep it.
CC=clang CXX=clang++ cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${sanitizer_flags[@]}" \
  -DPROX_BUILD_FUZZERS=ON \
  -DPROX_BUILD_TESTS=OFF -DPROX_BUILD_SAMPLES=OFF -DPROX_SHARED_ASSETS_DIR="$(assets_dir)" \
  -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
cmake --build build/fuzz -j "$jobs" --target proxima_fuzz_obj proxima_fuzz_poses proxima_fuzz_gltf \
  proxima_fuzz_gltf_capi proxima_fuzz_create_mesh proxima_fuzz_capi proxima_fuzz_hid_descriptor proxima_fuzz_kernel
tests/fuzz/run.sh build/fuzz "$(assets_dir)" "${PROX_FUZZ_SECONDS:-12}"

stage "release"
# FCL, the scene benchmark's peer (never a dependency of the SDK): the smoke
# run below measures against it, and the test Bench.PeersApart checks that no
# benchmark executable loads two builds of one library (docs/benchmarks.md).
need_packages libfcl-dev
configure build/release -DCMAKE_BUILD_TYPE=Release -DPROX_BUILD_BENCHMARKS=ON
cmake --build build/release -j "$jobs"
echo "-- micro-benchmark smoke run"
build/release/bench/proxima_kernel_bench --benchmark_min_time=0.01 >/dev/null
echo "-- scene benchmark smoke run, every scene at 5 poses (docs/benchmarks.md)"
# The scaling scene's decimated bunnies come from fast-simplification (PyPI)
# in build/bench-venv; without it those two levels are skipped, said here.
if bench_venv --no-plots >/dev/null &&
  build/bench-venv/bin/python bench/decimate.py "$(assets_dir)/bunny.obj" build/bench-meshes >/dev/null; then
  :
else
  echo "   fast-simplification could not be installed: scaling-2k and scaling-7k are skipped"
fi
build/release/bench/proxima_bench --scene all --poses 5 --builds 1 --meshes build/bench-meshes --out build/bench-smoke >/dev/null
build/release/bench/proxima_timing_bench --seconds 0.1 --out build/bench-smoke >/dev/null
build/release/bench/proxima_patches_bench --runs 1 >/dev/null
build/release/bench/proxima_fidelity_bench --scene bunny --speeds 50 >/dev/null
build/release/bench/proxima_deform_bench --frames 2 --churn-seconds 0.5 >/dev/null
ctest --test-dir build/release --output-on-failure -j "$jobs"

stage "Windows: proxima.dll cross-built with MinGW-w64, its suites and the zip's hello under Wine (scripts/windows.sh)"
scripts/windows.sh

stage "Python bindings (bindings/python): pip install into a fresh venv, then pytest"
# Pinned PyPI versions: bindings/python/ci-constraints.txt. The contacts are
# compared with the release build's proxima tool (PROXIMA_CLI). With the
# release build's compilers and warning flags (scikit-build-core would take
# Python's g++ for c++), so that ccache has the library already.
rm -rf build/py-venv
python3 -m venv build/py-venv
release_cache=build/release/CMakeCache.txt
PIP_CONSTRAINT="$(pwd)/bindings/python/ci-constraints.txt" CMAKE_BUILD_PARALLEL_LEVEL="$jobs" \
  build/py-venv/bin/pip install --quiet ./bindings/python -r bindings/python/tests/requirements.txt \
  --config-settings=build-dir="$(pwd)/build/py-wheel" --config-settings=cmake.define.PROX_WARNINGS_AS_ERRORS=ON \
  --config-settings=cmake.define.CMAKE_C_COMPILER="$(sed -n 's/^CMAKE_C_COMPILER:[A-Z]*=//p' "$release_cache")" \
  --config-settings=cmake.define.CMAKE_CXX_COMPILER="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$release_cache")"
echo "-- Python benchmarks smoke run (docs/python.md)"
build/py-venv/bin/python bindings/python/bench/step_overhead.py "$(assets_dir)/bunny.obj" --iterations 20 >/dev/null
build/py-venv/bin/python bindings/python/bench/gil.py "$(assets_dir)/bunny.obj" --seconds 0.2 >/dev/null
# test_hid.py runs a child Python under the release build's HID emulator
# (PROXIMA_HID_EMULATE): an emulated DualSense on umockdev, real hidapi.
# test_openxr.py drives the real OpenXR loader on the release build's mock
# runtime (PROXIMA_XR_RUNTIME_JSON, its manifest).
PROXIMA_CLI="$(pwd)/build/release/samples/cli/proxima" PROXIMA_ASSETS="$(assets_dir)" \
  PROXIMA_HID_EMULATE="$(pwd)/build/release/tests/hid/proxima_hid_emulate" \
  PROXIMA_XR_RUNTIME_JSON="$(pwd)/build/release/tests/openxr/mock_runtime.json" \
  build/py-venv/bin/pytest -q bindings/python/tests
echo "-- ccache: $(ccache --print-stats | awk -F'\t' '$1 == "direct_cache_hit" || $1 == "preprocessed_cache_hit" { h += $2 }
  $1 == "cache_miss" { m = $2 } END { printf "%d hits, %d misses", h, m }')"
stage "every stage passed"
