#!/usr/bin/env bash
# scripts/render.sh (render.py under pvbatch) on the default scene:
#  - it makes its picture every time: RENDER_RUNS (default 20) runs in a
#    row, each a PNG of the requested size whose body covers a good part of
#    the picture in several colours (tests/png_pixels.py's criteria);
#  - the colour bar is clear of the body: with the same framing, the
#    picture without the body (--hide body) and the one without the bar
#    (--hide bar) have non-white boxes that do not overlap, and together
#    they make the full picture;
#  - --step all writes one PNG per PVD entry.
# Exits 77 (ctest: skipped) without pvbatch.
# Usage: render_default.sh PROGRAM SOURCE_DIR WORK_DIR
set -euo pipefail
program=$1 root=$2 work=$3
runs=${RENDER_RUNS:-20}
if ! command -v pvbatch >/dev/null 2>&1; then
  echo "SKIPPED: pvbatch not found (apt-get install paraview xvfb)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work/runs"
cd "$work"
"$root/scripts/mpirun.sh" -np 1 "$program" "$root/parameters/default.prm" >run.log

render() {  # render LOG ARGS...: render.sh on the default scene into LOG
  local log=$1
  shift
  bash "$root/scripts/render.sh" output/default.pvd "$@" >"$log" 2>&1
}
render_or_fail() {  # the same, failing the test when render.sh fails
  render "$@" && return 0
  echo "FAIL: render.sh ${*:2}:"
  tail -n 5 "$1"
  exit 1
}

failed=0
start=$(date +%s%N)
for ((i = 1; i <= runs; ++i)); do
  png=runs/default_$i.png
  if ! render runs/render_$i.log --size 640x480 --output "$png" \
    || [ ! -s "$png" ]; then
    echo "FAIL: run $i of $runs made no picture:"
    tail -n 5 runs/render_$i.log
    failed=$((failed + 1))
  fi
done
ms=$((($(date +%s%N) - start) / 1000000 / runs))
retried=$(grep -l 'pvbatch died' runs/render_*.log | wc -l || true)
echo "render.sh: $((runs - failed)) of $runs runs in a row made a picture" \
  "($ms ms per run; $retried needed a second try)"
[ "$failed" -eq 0 ] || exit 1
pvpython "$root/tests/png_pixels.py" runs/default_1.png 640 480

render_or_fail bar.log --size 640x480 --hide body --output bar_only.png
render_or_fail body.log --size 640x480 --hide bar --output body_only.png
cat >check_pictures.py <<'EOF'
"""check_pictures.py FULL BAR_ONLY BODY_ONLY WIDTH HEIGHT [MORE_FULL...]:
every full picture of the given size with at least 5 % body pixels (not
white) in at least 20 colours; the non-white boxes of BAR_ONLY and
BODY_ONLY apart, and the two together the non-white pixels of FULL."""
import sys

import numpy
from vtkmodules.util import numpy_support
from vtkmodules.vtkIOImage import vtkPNGReader


def read(name):
    reader = vtkPNGReader()
    reader.SetFileName(name)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[:, :, :3]


def box(mask):  # [xmin, xmax, ymin, ymax] of the True pixels
    ys, xs = numpy.nonzero(mask)
    return [xs.min(), xs.max(), ys.min(), ys.max()]


full, bar_only, body_only = sys.argv[1:4]
width, height = int(sys.argv[4]), int(sys.argv[5])
ok = True
for name in dict.fromkeys([full] + sys.argv[6:]):
    pixels = read(name)
    body = (pixels != 255).any(axis=2)
    colours = len(numpy.unique(pixels[body], axis=0))
    good = pixels.shape[:2] == (height, width) and body.mean() >= 0.05 \
        and colours >= 20
    ok = ok and good
    if not good or name == full:
        print("%s: %d x %d pixels, %.1f %% body, %d colours: %s"
              % (name, pixels.shape[1], pixels.shape[0], 100 * body.mean(),
                 colours, "PASS" if good else "FAIL"))
masks = [(read(name) != 255).any(axis=2) for name in (full, bar_only,
                                                       body_only)]
if not masks[1].any() or not masks[2].any():
    print("FAIL: no colour bar or no body")
    sys.exit(1)
bar, body = box(masks[1]), box(masks[2])
apart = bar[0] > body[1] or body[0] > bar[1] or bar[2] > body[3] \
    or body[2] > bar[3]
same = (masks[0] == (masks[1] | masks[2])).mean()
print("colour bar: x %d-%d, y %d-%d; body: x %d-%d, y %d-%d: %s"
      % tuple(bar + body + ["apart" if apart else "OVERLAP"]))
print("full picture = bar + body at %.2f %% of its pixels" % (100 * same))
ok = ok and apart and same > 0.999
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
EOF
pvpython check_pictures.py runs/default_1.png bar_only.png body_only.png \
  640 480 runs/default_*.png

render_or_fail frames.log --size 320x240 --step all --field displacement \
  --output frames/frame.png
entries=$(grep -c '<DataSet' output/default.pvd)
frames=$(ls frames/frame_*.png | wc -l)
echo "PVD entries: $entries, frames: $frames"
if [ "$entries" -ne "$frames" ] || [ "$frames" -lt 2 ]; then
  echo "FAIL: --step all wrote $frames frames for $entries PVD entries"
  exit 1
fi
echo "PASS: one frame per PVD entry"
