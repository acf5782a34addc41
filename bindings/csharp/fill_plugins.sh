#!/usr/bin/env bash
# Copies the native libraries from CMake builds into the Unity package's
# Runtime/Plugins/x86_64/, where Unity loads them from (the binaries are never
# committed): libproxima.so from a Linux build, proxima.dll from a Windows
# one (scripts/windows.sh makes it in build/windows/build). Each .meta there
# enables its library for its own platform. Run it before adding the package
# to a Unity project.
#
#   bindings/csharp/fill_plugins.sh [BUILD_DIR [WINDOWS_BUILD_DIR]]
#     (defaults: build/release, and build/windows/build when it has proxima.dll)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../../build/release}"
lib="$build/sdk/libproxima.so"
if [ ! -e "$lib" ]; then
  echo "no $lib: build the library first (cmake --build $build --target proxima_capi)" >&2
  exit 1
fi
dest="$here/com.proxima.sdk/Runtime/Plugins/x86_64"
cp -L "$lib" "$dest/libproxima.so"
echo "copied $(readlink -f "$lib") to $dest/libproxima.so"

windows="${2:-$here/../../build/windows/build}"
dll="$windows/bin/proxima.dll"
if [ -e "$dll" ]; then
  cp "$dll" "$dest/proxima.dll"
  echo "copied $(readlink -f "$dll") to $dest/proxima.dll"
elif [ -n "${2:-}" ]; then
  echo "no $dll: build it first (scripts/windows.sh)" >&2
  exit 1
else
  echo "no Windows build ($dll): the package has no proxima.dll (scripts/windows.sh makes one)"
fi
