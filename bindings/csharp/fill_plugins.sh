#!/usr/bin/env bash
# Copies the native library from a CMake build into the Unity package's
# Runtime/Plugins/x86_64/, where Unity loads it from (the binaries are never
# committed). Run it before adding the package to a Unity project.
#
#   bindings/csharp/fill_plugins.sh [BUILD_DIR]    (default: build/release)
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
