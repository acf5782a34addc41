# Sourced by the other scripts: installs missing Debian packages. Runs
# apt-get only when something is missing, so repeated runs are quick.
need_packages() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "Installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# scripts/test.sh's compiler cache: one run compiles the library with the
# release flags three times (docs/build.md).
TEST_PACKAGES=(ccache)

# The compiler, CMake and the libraries the core and its tests need.
CORE_PACKAGES=(g++ cmake ninja-build libglm-dev libgtest-dev
  libtinygltf-dev nlohmann-json3-dev)  # glTF loading (PROX_WITH_GLTF)

# The Vulkan viewer (samples/viewer, docs/viewer.md) and its tests: the
# loader and headers, lavapipe (the CPU driver), the shader compiler, GLFW,
# libpng, the validation layers, ImGui for the HUD's text, and Xvfb with
# xwd, xdotool and umockdev (an emulated gamepad) for the windowed test.
VIEWER_PACKAGES=(libvulkan-dev mesa-vulkan-drivers glslang-tools libglfw3-dev libpng-dev
  vulkan-validationlayers libimgui-dev libstb-dev xvfb xauth x11-apps xdotool umockdev)

# The C# bindings (bindings/csharp, docs/csharp.md): Mono's C# compiler and
# runtime, and NUnit 2.6 for their suite.
CSHARP_PACKAGES=(mono-mcs mono-devel mono-runtime nunit-console libnunit-cil-dev)

# The OpenXR device (PROX_WITH_OPENXR, docs/openxr.md): the headers to build
# it; the loader, the core validation layer and readelf (binutils) for its
# tests and the sample.
OPENXR_PACKAGES=(libopenxr-dev libopenxr-loader1 openxr-layer-corevalidation binutils)

# Installing and packaging the SDK (the tests labelled install, docs/install.md).
INSTALL_PACKAGES=(pkg-config dpkg-dev file)

# HID devices (PROX_WITH_HIDAPI, sdk/src/devices, docs/devices.md#hid-devices):
# hidapi's hidraw backend; its tests emulate hidraw nodes with umockdev's C
# API and run under umockdev-wrapper.
HID_PACKAGES=(libhidapi-dev pkg-config libumockdev-dev umockdev)

# The Windows build (scripts/windows.sh, docs/install.md, "Windows"): MinGW-w64's
# compilers with POSIX threads (std::thread) and its binutils (objdump,
# dlltool), Wine to run the cross-built tests and hello, and GoogleTest's
# sources (googletest), cross-built for the tests.
WINDOWS_PACKAGES=(g++-mingw-w64-x86-64-posix binutils-mingw-w64-x86-64 wine64 googletest)

# The fuzz targets (tests/fuzz): clang with libFuzzer and the sanitizer runtimes.
FUZZ_PACKAGES=(clang libclang-rt-14-dev libfuzzer-14-dev)

# The scene benchmark's peers and plots (scripts/bench.sh): FCL to measure
# against (never a dependency of the SDK) and a venv for matplotlib.
BENCH_PACKAGES=(libbenchmark-dev libfcl-dev python3 python3-venv)

# PyPI packages of the benchmark, pinned (docs/dependencies.md).
SIMPLIFIER_VERSION=0.2.0  # fast-simplification: the decimated bunnies (bench/decimate.py)
COAL_VERSION=3.0.3        # coal: the peer behind PROX_BENCH_WITH_COAL (scripts/bench.sh)

# The shared assets, as an absolute path: PROXIMA_ASSETS if set, else
# ../shared/assets beside the repository, else beside the repository this one
# was cloned from (a clone made elsewhere, as CI makes), else the first.
assets_dir() {
  local candidates=("${PROXIMA_ASSETS:-}" "../shared/assets")
  local origin
  origin=$(git remote get-url origin 2>/dev/null || true)
  [ -n "$origin" ] && [ -d "$origin" ] && candidates+=("$origin/../shared/assets")
  for dir in "${candidates[@]}"; do
    if [ -n "$dir" ] && [ -f "$dir/bunny.obj" ]; then
      (cd "$dir" && pwd)
      return
    fi
  done
  echo "$(pwd)/../shared/assets"
}

# build/bench-venv with the simplifier (and matplotlib unless "--no-plots"):
# returns non-zero if pip cannot install them.
bench_venv() {
  [ -x build/bench-venv/bin/python ] || python3 -m venv build/bench-venv || return 1
  build/bench-venv/bin/python -c "import fast_simplification" 2>/dev/null ||
    build/bench-venv/bin/pip install --quiet "fast-simplification==$SIMPLIFIER_VERSION" || return 1
  [ "${1:-}" = "--no-plots" ] && return 0
  build/bench-venv/bin/python -c "import matplotlib" 2>/dev/null ||
    build/bench-venv/bin/pip install --quiet matplotlib
}
