#!/usr/bin/env bash
# The Windows build, from Linux (docs/install.md, "Windows"): proxima.dll
# cross-compiled with MinGW-w64 (cmake/toolchains/mingw-w64-x86_64.cmake),
# the C API, threads, streamed-device, glTF and accuracy suites run under
# Wine, then the Windows zip made with CPack and samples/hello built against
# it and run. Called by scripts/test.sh; runs alone too (installs what it
# needs). Everything goes to build/windows/.
#
# Wine's timing is not Windows': the tests run here check what the loops do
# and report, not how well they keep time.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/deps.sh
# libopenxr-dev: the OpenXR headers, for the OpenXR device in proxima.dll.
need_packages "${CORE_PACKAGES[@]}" "${WINDOWS_PACKAGES[@]}" libopenxr-dev

jobs=$(nproc)
root=$(pwd)
out=$root/build/windows
deps=$out/deps
toolchain=$root/cmake/toolchains/mingw-w64-x86_64.cmake
assets=$(assets_dir)
wine=/usr/lib/wine/wine64
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
step() { echo "-- $* [at $((SECONDS / 60)) min $((SECONDS % 60)) s of the Windows stage]"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

# The header-only libraries the build needs come from Debian's own packages
# (libglm-dev, libtinygltf-dev, nlohmann-json3-dev, libopenxr-dev's headers):
# a root of links to just them, so that the cross build never sees the rest
# of /usr/include.
step "dependencies: header-only libraries linked in, GoogleTest cross-built from Debian's sources"
mkdir -p "$deps/include" "$deps/share/cmake"
ln -sfn /usr/include/glm "$deps/include/glm"
ln -sfn /usr/share/cmake/glm "$deps/share/cmake/glm"
ln -sfn /usr/include/tiny_gltf.h "$deps/include/tiny_gltf.h"
ln -sfn /usr/include/nlohmann "$deps/include/nlohmann"
ln -sfn /usr/include/openxr "$deps/include/openxr"
if [ ! -f "$deps/lib/cmake/GTest/GTestConfig.cmake" ]; then
  cmake -S /usr/src/googletest -B "$out/gtest" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$toolchain" \
    -DCMAKE_BUILD_TYPE=Release -DBUILD_GMOCK=OFF -DCMAKE_INSTALL_PREFIX="$deps" "${launcher[@]}" >/dev/null
  cmake --build "$out/gtest" -j "$jobs" >/dev/null
  cmake --install "$out/gtest" >/dev/null
fi

step "proxima.dll, the test suites and hello (MinGW-w64, -Werror)"
cmake -S . -B "$out/build" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_FIND_ROOT_PATH="$deps" \
  -DCMAKE_BUILD_TYPE=Release -DPROX_WARNINGS_AS_ERRORS=ON -DPROX_SHARED_ASSETS_DIR="$assets" \
  -DPROX_BUILD_CSHARP=OFF -DCMAKE_CROSSCOMPILING_EMULATOR="$wine" "${launcher[@]}" >/dev/null
suites=(proxima_capi_tests proxima_capi_threads_tests proxima_capi_stream_tests proxima_gltf_tests
  proxima_contact_tests proxima_threads_tests)
cmake --build "$out/build" -j "$jobs" --target proxima_capi proxima_msvc_import_lib "${suites[@]}" \
  proxima_header_c11 proxima_header_parts_c11 hello

# The DLL exports exactly the C API: the PROX_API functions of every public
# header but proxima_hid.h (no HID on Windows).
dll=$out/build/bin/proxima.dll
headers=$(ls sdk/include/proxima/*.h | grep -v '/proxima_hid\.h$')
# shellcheck disable=SC2086
grep -hoE '^PROX_API [^(]+\(' $headers |
  sed -E 's/.*[ *]([A-Za-z0-9_]+)\($/\1/' | sort >"$out/api.txt"
x86_64-w64-mingw32-objdump -p "$dll" | sed -n '/\[Ordinal\/Name Pointer\] Table/,/^$/p' |
  awk '/^[ \t]*\[ *[0-9]+\]/ {print $NF}' | sort >"$out/exports.txt"
diff "$out/api.txt" "$out/exports.txt" >"$out/exports.diff" ||
  fail "proxima.dll's exports are not the C API's functions (< header only, > DLL only): $(cat "$out/exports.diff")"
imports=$(x86_64-w64-mingw32-objdump -p "$dll" | awk '/DLL Name:/ {print $3}' | tr '\n' ' ')
echo "   proxima.dll exports the $(wc -l <"$out/api.txt") C API functions and imports only: $imports"
case "$imports" in
  *libstdc++* | *libgcc* | *libwinpthread*) fail "proxima.dll needs MinGW's runtime DLLs: $imports" ;;
esac

# A throwaway Wine prefix, quiet and headless: no Mono or Gecko installer.
export WINEPREFIX=$out/wineprefix WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
unset DISPLAY
step "the test suites under Wine"
[ -f "$WINEPREFIX/system.reg" ] || "$wine" wineboot -i >/dev/null 2>&1
tests=("${suites[@]}" capi.header_c11 capi.header_parts_c11)
names=$(printf '%s|' "${tests[@]}")
# What the hand feels tick by tick (Fidelity.*) depends on how well the loops
# keep time, which is Wine's here, not Windows': those tests run on Linux
# (under load, and under ThreadSanitizer) and are left out under Wine, where
# a late wake-up on a busy machine made a contact go stale once in a dozen
# runs. Every other test of the suites runs.
export GTEST_FILTER='-Fidelity.*'
ctest --test-dir "$out/build" --output-on-failure -j "$jobs" -R "^(${names%|})$" --timeout 900 |
  tee "$out/ctest.log"
grep -q "100% tests passed, 0 tests failed out of ${#tests[@]}\$" "$out/ctest.log" ||
  fail "not every one of the ${#tests[@]} Windows tests ran and passed"
# The haptic loop's own word on its timing under Wine (sleep_timer_capi_test),
# for the log only: the suites above are the check. Wine's server exits a
# few seconds after its last client, and a client starting at that moment
# once lost its connection here ("wine client error: recvmsg: Connection
# reset by peer") after every suite had passed.
"$wine" "$out/build/bin/proxima_capi_threads_tests.exe" --gtest_filter='SleepTimer.*' | grep -E "haptic loop|priority" |
  sed 's/^/   /' || echo "   (no word from the haptic loop under Wine this time)"

step "the Windows zip (CPack), and hello built against it and run under Wine"
rm -f "$out"/build/proxima-*-win64.zip
(cd "$out/build" && cpack -G ZIP >/dev/null)
zip=$(ls "$out"/build/proxima-*-win64.zip)
rm -rf "$out/zip" "$out/hello"
mkdir -p "$out/zip"
python3 -c 'import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])' "$zip" "$out/zip"
prefix=$(ls -d "$out"/zip/proxima-*-win64)
for f in bin/proxima.dll lib/libproxima.dll.a lib/proxima.lib include/proxima/proxima.h include/proxima/threads.h \
  include/proxima/base.h include/proxima/types.h \
  lib/cmake/proxima/proximaConfig.cmake; do
  [ -f "$prefix/$f" ] || fail "the zip has no $f"
done
[ ! -e "$prefix/include/proxima/proxima_hid.h" ] || fail "the zip has proxima_hid.h, but the DLL has no HID devices"
cmake -S tests/install/find_package -B "$out/hello" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$toolchain" \
  -DCMAKE_FIND_ROOT_PATH="$prefix" -DHELLO_SOURCE="$root/samples/hello/hello.c" -DPROXIMA_COMPONENTS=gltf \
  >"$out/hello.log" 2>&1 || fail "find_package(proxima) in the zip: $(cat "$out/hello.log")"
cmake --build "$out/hello" >>"$out/hello.log" 2>&1 || fail "hello against the zip: $(cat "$out/hello.log")"
# As a Windows user would: the zip's bin/ on the PATH.
WINEPATH=$("$wine" winepath -w "$prefix/bin" 2>/dev/null) "$wine" "$out/hello/hello.exe" "$assets/bunny.obj" \
  >"$out/hello.out" || fail "hello under Wine: $(cat "$out/hello.out")"
grep -q "contacts within" "$out/hello.out" || fail "hello printed no contacts: $(cat "$out/hello.out")"
echo "   $(basename "$zip"): hello found $(grep 'contacts within' "$out/hello.out")"
step "Windows done"
