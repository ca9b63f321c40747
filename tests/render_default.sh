#!/usr/bin/env bash
# scripts/render.sh (render.py under pvbatch) on the default scene: the last
# step as a PNG of the requested size whose body covers a good part of the
# picture in several colours (tests/png_pixels.py), and --step all as one
# PNG per PVD entry. Exits 77 (ctest: skipped) without pvbatch.
# Usage: render_default.sh PROGRAM SOURCE_DIR WORK_DIR
set -euo pipefail
program=$1 root=$2 work=$3
if ! command -v pvbatch >/dev/null 2>&1; then
  echo "SKIPPED: pvbatch not found (apt-get install paraview xvfb)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
cd "$work"
"$root/scripts/mpirun.sh" -np 1 "$program" "$root/parameters/default.prm" >run.log
bash "$root/scripts/render.sh" output/default.pvd --size 640x480 \
  --output default.png
pvpython "$root/tests/png_pixels.py" default.png 640 480
bash "$root/scripts/render.sh" output/default.pvd --size 320x240 \
  --step all --field displacement --output frames/frame.png
entries=$(grep -c '<DataSet' output/default.pvd)
frames=$(ls frames/frame_*.png | wc -l)
echo "PVD entries: $entries, frames: $frames"
if [ "$entries" -ne "$frames" ] || [ "$frames" -lt 2 ]; then
  echo "FAIL: --step all wrote $frames frames for $entries PVD entries"
  exit 1
fi
echo "PASS: one frame per PVD entry"
