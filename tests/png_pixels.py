"""Checks a rendered PNG (run with pvpython): its size, the share of pixels
that are not the white background (the body, at least 5 %) and the number of
distinct colours among them (a colour map, at least 20).
Usage: pvpython png_pixels.py FILE WIDTH HEIGHT"""
import sys

from vtkmodules.vtkIOImage import vtkPNGReader

name, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
reader = vtkPNGReader()
reader.SetFileName(name)
reader.Update()
image = reader.GetOutput()
dims = image.GetDimensions()
scalars = image.GetPointData().GetScalars()
body, colours = 0, set()
for i in range(scalars.GetNumberOfTuples()):
    pixel = tuple(int(c) for c in scalars.GetTuple(i)[:3])
    if pixel != (255, 255, 255):
        body += 1
        colours.add(pixel)
share = body / float(dims[0] * dims[1])
print("%s: %d x %d pixels, %.1f %% body, %d colours"
      % (name, dims[0], dims[1], 100 * share, len(colours)))
ok = dims[0] == width and dims[1] == height and share >= 0.05 \
    and len(colours) >= 20
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
