#!/usr/bin/env bash
# Builds samples/hello/hello.c the ways a customer takes Proxima, from outside
# the source tree, and runs it on the bunny (hello exits non-zero unless it
# finds contacts):
#   consume.sh tree         BUILD SOURCE ASSETS WORK   cmake --install into WORK/prefix; find_package and pkg-config
#   consume.sh deb          BUILD SOURCE ASSETS WORK   cpack -G DEB; the packages' contents and control data; hello against them
#   consume.sh subdirectory BUILD SOURCE ASSETS WORK   add_subdirectory() of the source tree
#   consume.sh fetchcontent BUILD SOURCE ASSETS WORK   FetchContent of the source tree (configure only)
# The deb mode unpacks the packages with dpkg -x into WORK; with
# PROX_DEB_SYSTEM_INSTALL=1 (CI's throwaway machines) it installs them with
# apt-get instead, builds against /usr, and removes them again. The vendored
# builds take PROX_WARNINGS_AS_ERRORS, CC, CXX and CMAKE_<LANG>_COMPILER_LAUNCHER
# from the environment (tests/install/CMakeLists.txt passes the parent build's).
set -euo pipefail
mode=$1
version=${PROX_VERSION:?PROX_VERSION (the project version, major.minor.patch) must be set}
build=$(cd "$2" && pwd) source=$(cd "$3" && pwd) assets=$(cd "$4" && pwd) work=$(realpath -m "$5")
hello_source="$source/samples/hello/hello.c"
mesh="$assets/bunny.obj"
generator=(-G "${CMAKE_GENERATOR:-Ninja}")
command -v ninja >/dev/null || generator=()
cc=${CC:-cc}

fail() { echo "FAIL: $*" >&2; exit 1; }
for tool in pkg-config readelf ldd; do
  command -v $tool >/dev/null || fail "$tool is needed (Debian: pkg-config, binutils, libc-bin)"
done
[ "$mode" != deb ] || command -v dpkg-deb >/dev/null || fail "dpkg-deb is needed to check the .deb packages"
rm -rf "$work"
mkdir -p "$work"

# hello linked against the libproxima.so in LIBDIR, run on the bunny.
run_hello() {  # run_hello EXE LIBDIR WHAT
  local exe=$1 libdir=$2 what=$3
  local resolved
  resolved=$(ldd "$exe" | awk '/libproxima\.so/ {print $3}')
  [ "$(readlink -f "$resolved")" = "$(readlink -f "$libdir/libproxima.so.0")" ] ||
    fail "$what: hello loads '$resolved', not the libproxima.so.0 in $libdir"
  "$exe" "$mesh" >"$work/hello.out" || fail "$what: hello failed: $(cat "$work/hello.out")"
  grep -q "contacts within" "$work/hello.out" || fail "$what: hello printed no contacts"
  echo "ok: $what: $(grep 'contacts within' "$work/hello.out")"
}

# The CMake consumer: configure with PREFIX_PATH (may be empty) and extra
# arguments into DIR; returns cmake's status, output in DIR.log.
configure_consumer() {  # configure_consumer DIR PREFIX_PATH [cmake args...]
  local dir=$1 prefix_path=$2
  shift 2
  cmake -S "$source/tests/install/find_package" -B "$dir" "${generator[@]}" -DCMAKE_C_COMPILER="$cc" \
    -DHELLO_SOURCE="$hello_source" ${prefix_path:+-DCMAKE_PREFIX_PATH="$prefix_path"} "$@" >"$dir.log" 2>&1
}

# find_package and pkg-config against an installed prefix ROOT whose
# libraries are in LIBDIR.
consume_prefix() {  # consume_prefix PREFIX_PATH LIBDIR PKG_CONFIG_PATH WHAT
  local prefix_path=$1 libdir=$2 pc_path=$3 what=$4
  configure_consumer "$work/cmake" "$prefix_path" -DPROXIMA_COMPONENTS=gltf ||
    fail "$what: find_package(proxima CONFIG REQUIRED COMPONENTS gltf): $(cat "$work/cmake.log")"
  cmake --build "$work/cmake" >"$work/cmake-build.log" 2>&1 || fail "$what: build: $(cat "$work/cmake-build.log")"
  run_hello "$work/cmake/hello" "$libdir" "$what, find_package"

  # What the package must refuse: another major version, unknown components.
  if configure_consumer "$work/cmake-v1" "$prefix_path" -DPROXIMA_VERSION_WANTED=1.0; then
    fail "$what: find_package(proxima 1.0) accepted version 0.x"
  fi
  configure_consumer "$work/cmake-v0" "$prefix_path" -DPROXIMA_VERSION_WANTED=0.1 ||
    fail "$what: find_package(proxima 0.1) refused: $(cat "$work/cmake-v0.log")"
  if configure_consumer "$work/cmake-bad" "$prefix_path" -DPROXIMA_COMPONENTS=nonesuch; then
    fail "$what: find_package(proxima COMPONENTS nonesuch) succeeded"
  fi
  grep -q "'nonesuch' is not a proxima component" "$work/cmake-bad.log" ||
    fail "$what: the unknown component is not named: $(cat "$work/cmake-bad.log")"
  echo "ok: $what: find_package refuses version 1.0 and component 'nonesuch', accepts 0.1"

  local flags
  flags=$(PKG_CONFIG_PATH="$pc_path" pkg-config --cflags --libs proxima) || fail "$what: pkg-config proxima"
  local pc_libdir
  pc_libdir=$(PKG_CONFIG_PATH="$pc_path" pkg-config --variable=libdir proxima)
  # shellcheck disable=SC2086
  "$cc" -std=c11 -Wall -Wextra -Werror "$hello_source" -o "$work/hello-pc" $flags -Wl,-rpath,"$pc_libdir" ||
    fail "$what: cc \$(pkg-config --cflags --libs proxima) hello.c"
  run_hello "$work/hello-pc" "$libdir" "$what, pkg-config ($flags)"
}

case $mode in
  tree)
    cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" || fail "cmake --install"
    # lib, or lib/<multiarch> for a /usr prefix (GNUInstallDirs).
    library=$(find "$work/prefix" -name libproxima.so.$version | head -1)
    [ -n "$library" ] || fail "cmake --install did not install libproxima.so.$version"
    lib=${library#"$work/prefix/"}
    lib=${lib%/libproxima.so.$version}
    for f in $lib/libproxima.so.0 $lib/libproxima.so include/proxima/proxima.h include/proxima/version.h \
      include/proxima/base.h include/proxima/types.h \
      $lib/cmake/proxima/proximaConfig.cmake $lib/cmake/proxima/proximaConfigVersion.cmake \
      $lib/cmake/proxima/proximaTargets.cmake $lib/pkgconfig/proxima.pc; do
      [ -e "$work/prefix/$f" ] || fail "cmake --install did not install $f"
    done
    [ "$(readlink "$work/prefix/$lib/libproxima.so")" = libproxima.so.0 ] ||
      fail "libproxima.so does not link to libproxima.so.0"
    soname=$(readelf -d "$library" | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')
    [ "$soname" = libproxima.so.0 ] || fail "SONAME is '$soname', not libproxima.so.0"
    echo "ok: install tree: $lib/libproxima.so.$version (SONAME $soname), headers, CMake package, pkg-config file"
    consume_prefix "$work/prefix" "$work/prefix/$lib" "$work/prefix/$lib/pkgconfig" "install tree"
    # The openxr component, in a build with the OpenXR device (its header is
    # installed then): find_package finds OpenXR's headers for it.
    if [ -e "$work/prefix/include/proxima/proxima_openxr.h" ]; then
      configure_consumer "$work/cmake-openxr" "$work/prefix" "-DPROXIMA_COMPONENTS=gltf;openxr" ||
        fail "install tree: find_package(proxima COMPONENTS openxr): $(cat "$work/cmake-openxr.log")"
      echo "ok: install tree: find_package(proxima COMPONENTS openxr), with OpenXR's headers"
    fi
    ;;
  deb)
    (cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" >"$work/cpack.log" 2>&1) ||
      fail "cpack -G DEB: $(cat "$work/cpack.log")"
    runtime=$(ls "$work"/proxima_*-libproxima0.deb) || fail "no proxima_*-libproxima0.deb"
    dev=$(ls "$work"/proxima_*-libproxima-dev.deb) || fail "no proxima_*-libproxima-dev.deb"
    [ "$(dpkg-deb -f "$runtime" Package)" = libproxima0 ] || fail "$runtime is not package libproxima0"
    [ "$(dpkg-deb -f "$dev" Package)" = libproxima-dev ] || fail "$dev is not package libproxima-dev"
    dpkg-deb -f "$runtime" Depends | grep -q "libstdc++6" || fail "libproxima0 does not depend on libstdc++6"
    dpkg-deb -f "$dev" Depends | grep -q "libproxima0 (= $version)" || fail "libproxima-dev does not depend on libproxima0 (= $version)"
    if dpkg-deb -c "$dev" | grep -q "proxima_openxr.h"; then
      dpkg-deb -f "$dev" Depends | grep -q "libopenxr-dev" || fail "libproxima-dev has proxima_openxr.h but does not depend on libopenxr-dev"
    fi
    # The runtime package holds the library and its SONAME link only.
    runtime_files=$(dpkg-deb -c "$runtime" | awk '{print $6}' | grep -v '/$' | sort | tr '\n' ' ')
    version_re=$(printf '%s' "$version" | sed 's/\./\\./g')
    lib=$(dpkg-deb -c "$runtime" | awk '{print $6}' | sed -n "s|^\./usr/\(.*\)/libproxima\.so\.$version_re\$|\1|p")
    [ -n "$lib" ] && [ "$runtime_files" = "./usr/$lib/libproxima.so.0 ./usr/$lib/libproxima.so.$version " ] ||
      fail "libproxima0 holds: $runtime_files"
    for f in ./usr/$lib/libproxima.so ./usr/include/proxima/proxima.h ./usr/$lib/cmake/proxima/proximaConfig.cmake \
      ./usr/$lib/pkgconfig/proxima.pc; do
      dpkg-deb -c "$dev" | awk '{print $6}' | grep -qx "$f" || fail "libproxima-dev lacks $f"
    done
    echo "ok: $(basename "$runtime") and $(basename "$dev"): names, dependencies, contents"
    if [ "${PROX_DEB_SYSTEM_INSTALL:-0}" = 1 ]; then
      sudo=""
      [ "$(id -u)" -ne 0 ] && sudo="sudo"
      trap '$sudo apt-get purge -y -qq libproxima0 libproxima-dev >/dev/null 2>&1 || true' EXIT
      DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$runtime" "$dev" >"$work/apt.log" 2>&1 ||
        fail "apt-get install $runtime $dev: $(cat "$work/apt.log")"
      consume_prefix "" "/usr/$lib" "" "installed .deb"
    else
      dpkg -x "$runtime" "$work/root"
      dpkg -x "$dev" "$work/root"
      consume_prefix "$work/root/usr" "$work/root/usr/$lib" "$work/root/usr/$lib/pkgconfig" ".deb (dpkg -x)"
    fi
    ;;
  subdirectory | fetchcontent)
    cmake -S "$source/tests/install/subdirectory" -B "$work/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
      -DPROXIMA_VIA="$mode" -DPROXIMA_SOURCE_DIR="$source" -DHELLO_SOURCE="$hello_source" \
      -DPROX_SHARED_ASSETS_DIR="$assets" -DPROX_WARNINGS_AS_ERRORS="${PROX_WARNINGS_AS_ERRORS:-OFF}" \
      >"$work/configure.log" 2>&1 || fail "$mode: configure: $(cat "$work/configure.log")"
    echo "ok: $mode: configured with Proxima's tests, samples, benchmarks and install rules off"
    if [ "$mode" = subdirectory ]; then
      cmake --build "$work/build" -j 2 >"$work/build.log" 2>&1 || fail "$mode: build: $(tail -30 "$work/build.log")"
      run_hello "$work/build/hello" "$work/build/proxima/sdk" "$mode"
    fi
    ;;
  *)
    fail "unknown mode '$mode' (tree, deb, subdirectory, fetchcontent)"
    ;;
esac
