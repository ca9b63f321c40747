"""Render a hyperelastic result to PNG with ParaView's pvbatch.

    pvbatch scripts/render.py output/default.pvd [--field von_Mises_stress]
            [--step last|N|all] [--output picture.png] [--size 1024x768]

The body is drawn deformed (warped by the displacement, scale 1), coloured by
a field of the VTU files: a cell field (von_Mises_stress, J,
energy_density, cauchy_xx, ..., mpi_rank) or a point field (displacement,
velocity, contact_force, pressure; vectors by their magnitude), with a
colour bar. --step picks the PVD entry: `last` (default), its index N (0 is
the undeformed state), or `all` for a frame sequence <output>_NNNN.png, one
per entry, with the colour range of the last entry (for animations).
3D bodies are seen from an oblique angle, 2D ones from +z.

scripts/render.sh wraps this with a virtual display where needed (pvbatch
of Debian's paraview package renders through X).
"""

import argparse
import os
import sys

from paraview import simple as pv


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pvd", help="the run's <base>.pvd")
    parser.add_argument("--field", default="von_Mises_stress")
    parser.add_argument("--step", default="last")
    parser.add_argument("--output", default=None,
                        help="PNG file (default: <base>.png beside the PVD)")
    parser.add_argument("--size", default="1024x768")
    return parser.parse_args(argv)


def fail(message):
    sys.stderr.write("render.py: " + message + "\n")
    sys.exit(1)


def main(argv):
    args = parse_arguments(argv)
    if not os.path.isfile(args.pvd):
        fail("no such file: '%s'" % args.pvd)
    try:
        width, height = (int(v) for v in args.size.split("x"))
    except ValueError:
        fail("--size must be WIDTHxHEIGHT, got '%s'" % args.size)
    output = args.output or os.path.splitext(args.pvd)[0] + ".png"

    reader = pv.PVDReader(FileName=args.pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) or [0.0]
    if args.step == "last":
        frames = [len(times) - 1]
    elif args.step == "all":
        frames = list(range(len(times)))
    else:
        try:
            frames = [int(args.step)]
        except ValueError:
            fail("--step must be last, all or an index, got '%s'" % args.step)
        if not 0 <= frames[0] < len(times):
            fail("--step %d: the series has %d entries" % (frames[0], len(times)))

    cell_fields = reader.CellData.keys()
    point_fields = reader.PointData.keys()
    if args.field in cell_fields:
        association = "CELLS"
    elif args.field in point_fields:
        association = "POINTS"
    else:
        fail("no field '%s' in %s (cell fields: %s; point fields: %s)"
             % (args.field, args.pvd, ", ".join(cell_fields),
                ", ".join(point_fields)))

    warped = pv.WarpByVector(Input=reader)
    warped.Vectors = ["POINTS", "displacement"]
    warped.ScaleFactor = 1.0

    view = pv.CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    display = pv.Show(warped, view)
    array = reader.CellData[args.field] if association == "CELLS" \
        else reader.PointData[args.field]
    if array.GetNumberOfComponents() > 1:
        pv.ColorBy(display, (association, args.field, "Magnitude"))
    else:
        pv.ColorBy(display, (association, args.field))
    display.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(pv.GetColorTransferFunction(args.field), view)
    bar.Title = args.field
    bar.ComponentTitle = ""
    bar.TitleColor = [0.0, 0.0, 0.0]
    bar.LabelColor = [0.0, 0.0, 0.0]

    # The colour range and the camera of the last frame, for every frame.
    view.ViewTime = times[frames[-1]]
    warped.UpdatePipeline(times[frames[-1]])
    display.RescaleTransferFunctionToDataRange(False, True)
    bounds = warped.GetDataInformation().GetBounds()
    view.ResetCamera()
    if bounds[5] - bounds[4] > 0.0:  # 3D: an oblique view
        camera = view.GetActiveCamera()
        camera.Elevation(25.0)
        camera.Azimuth(35.0)
        view.ResetCamera()
        camera.Dolly(1.3)

    base = os.path.splitext(output)[0]
    if os.path.dirname(output):
        os.makedirs(os.path.dirname(output), exist_ok=True)
    for frame in frames:
        view.ViewTime = times[frame]
        target = output if args.step != "all" else "%s_%04d.png" % (base, frame)
        if os.path.exists(target):
            os.remove(target)
        pv.SaveScreenshot(target, view, ImageResolution=[width, height])
        if not os.path.isfile(target) or os.path.getsize(target) == 0:
            fail("could not write '%s'" % target)
        print("render.py: %s (t = %g, coloured by %s)"
              % (target, times[frame], args.field))


if __name__ == "__main__":
    main(sys.argv[1:])
