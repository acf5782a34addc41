#!/usr/bin/env bash
# The viewer's measurements of docs/viewer.md, run by hand (not a test):
# frame time at 1280x720, 1x and 4x MSAA, headless, for the bunny scene
# (path T on the world's threads) and a CAD pair (the 2CylinderEngine's
# crankcase and cylinder block, 515 strings); then the haptic thread's
# period with the viewer rendering beside it (lavapipe on every core, then
# on one) against `proxima run` on the same scene and threads without it.
# Usage: bench/viewer_bench.sh [BUILD_DIR]   (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/deps.sh
build=${1:-build/release}
viewer=$build/samples/viewer/proxima-viewer
assets=$(assets_dir)
mkdir -p build/viewer-bench
for part in body_1 body_2; do
  [ -f build/viewer-bench/engine-$part.obj ] ||
    python3 bench/gltf_to_obj.py "$assets/gltf/2CylinderEngine.glb" build/viewer-bench/engine-$part.obj \
      --mesh $part --scale 0.001
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"
for msaa in 1 4; do
  echo "== bunny, path T on the threads, ${msaa}x"
  "$viewer" --headless --frames 300 --size 1280x720 --msaa $msaa | grep frames
  echo "== CAD pair (crankcase, cylinder block 20 mm out), ${msaa}x"
  "$viewer" build/viewer-bench/engine-body_1.obj build/viewer-bench/engine-body_2.obj \
    --pose-b 0.02 0 0 1 0 0 0 --headless --frames 300 --size 1280x720 --msaa $msaa | grep frames
done
echo "== haptic thread, viewer rendering beside it (1280x720 4x, path T, 12 s)"
"$viewer" --headless --frames 100000 --seconds 4 --size 1280x720 --msaa 4 &
pid=$!
sleep 12
kill -INT $pid
wait $pid || true
echo "== haptic thread, viewer rendering beside it with lavapipe on one thread (LP_NUM_THREADS=1)"
LP_NUM_THREADS=1 "$viewer" --headless --frames 100000 --seconds 4 --size 1280x720 --msaa 4 &
pid=$!
sleep 12
kill -INT $pid
wait $pid || true
echo "== haptic thread without the viewer (proxima run, path T, 12 s)"
"$build/samples/cli/proxima" run --seconds 8 --hold 4 | grep -A4 "^thread"
