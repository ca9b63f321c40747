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
3D bodies are seen from an oblique angle, 2D ones from +z. The colour bar
goes below the body (horizontal) or right of it (vertical), whichever lets
the body be drawn larger, and the camera frames the body in the rest of the
picture, clear of the bar (for --step all: the body of every frame).
--hide bar|body leaves the colour bar or the body out, with the same framing
(tests check with it that the two do not overlap).

scripts/render.sh wraps this with a virtual display where needed (pvbatch
of Debian's paraview package renders through X).
"""

import argparse
import math
import os
import sys

import numpy
from paraview import simple as pv
from vtkmodules.util import numpy_support
from vtkmodules.vtkRenderingCore import vtkCamera


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pvd", help="the run's <base>.pvd")
    parser.add_argument("--field", default="von_Mises_stress")
    parser.add_argument("--step", default="last")
    parser.add_argument("--output", default=None,
                        help="PNG file (default: <base>.png beside the PVD)")
    parser.add_argument("--size", default="1024x768")
    parser.add_argument("--hide", choices=["bar", "body"], default=None,
                        help="leave the colour bar or the body out (same "
                        "framing; for tests)")
    return parser.parse_args(argv)


def fail(message):
    sys.stderr.write("render.py: " + message + "\n")
    sys.exit(1)


def point_blocks(data):
    """The points of a data set, or of each leaf of a composite one, as
    N x 3 arrays (views of the data, not copies)."""
    if data.IsA("vtkCompositeDataSet"):
        iterator = data.NewIterator()
        iterator.InitTraversal()
        while not iterator.IsDoneWithTraversal():
            yield from point_blocks(iterator.GetCurrentDataObject())
            iterator.GoToNextItem()
    elif hasattr(data, "GetPoints") and data.GetPoints() is not None \
            and data.GetNumberOfPoints() > 0:
        yield numpy_support.vtk_to_numpy(data.GetPoints().GetData())


def aim_camera(bounds, oblique):
    """A camera (vtkCamera) looking at the centre of the bounds, from +z (2D)
    or from an oblique angle (3D), from where their bounding sphere fits the
    view (as ResetCamera)."""
    low, high = numpy.array(bounds[0::2]), numpy.array(bounds[1::2])
    centre = 0.5 * (low + high)
    camera = vtkCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + [0.0, 0.0, 1.0]))
    camera.SetViewUp(0.0, 1.0, 0.0)
    if oblique:
        camera.Elevation(25.0)
        camera.Azimuth(35.0)
        camera.OrthogonalizeViewUp()
    radius = max(0.5 * numpy.linalg.norm(high - low), 1e-12)
    distance = radius / math.sin(0.5 * math.radians(camera.GetViewAngle()))
    direction = numpy.array(camera.GetDirectionOfProjection())
    camera.SetPosition(*(centre - distance * direction))
    return camera


def body_extent(source, times, camera, aspect):
    """The box [xmin, xmax, ymin, ymax] of the images of the source's points
    at all the times in normalized device coordinates (-1 to 1 across the
    picture) for the camera, the points' bounds, and whether a point lies
    behind the camera (then the box is of no use). Reads one time at a
    time."""
    matrix = camera.GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0)
    m = numpy.array([[matrix.GetElement(i, j) for j in range(4)]
                     for i in range(4)])
    near = 1e-6 * camera.GetDistance()
    extent = [numpy.inf, -numpy.inf, numpy.inf, -numpy.inf]
    bounds = [numpy.inf, -numpy.inf] * 3
    behind = False
    for time in times:
        source.UpdatePipeline(time)
        data = source.GetClientSideObject().GetOutputDataObject(0)
        for points in point_blocks(data):
            image = points @ m[:, :3].T + m[:, 3]
            if image[:, 3].min() <= near:
                behind = True
                image = image[image[:, 3] > near]
            x, y = image[:, 0] / image[:, 3], image[:, 1] / image[:, 3]
            if len(x):
                extent = [min(extent[0], x.min()), max(extent[1], x.max()),
                          min(extent[2], y.min()), max(extent[3], y.max())]
            for axis in range(3):
                bounds[2 * axis] = min(bounds[2 * axis],
                                       points[:, axis].min())
                bounds[2 * axis + 1] = max(bounds[2 * axis + 1],
                                           points[:, axis].max())
    return extent, bounds, behind


def bar_rectangle(view, bar_proxy):
    """The colour bar's box (bar, labels and title) in pixels from the lower
    left corner of the picture, [xmin, xmax, ymin, ymax], after a render."""
    actor = bar_proxy.GetClientSideObject().GetRepresentation() \
        .GetScalarBarActor()
    x, y = actor.GetPositionCoordinate().GetComputedDisplayValue(
        view.GetRenderer())
    rect = actor.GetBoundingRect()  # relative to the actor's position
    return [x + rect.GetX(), x + rect.GetX() + rect.GetWidth(),
            y + rect.GetY(), y + rect.GetY() + rect.GetHeight()]


def place_bar(bar, orientation):
    bar.Orientation = orientation
    bar.WindowLocation = "Lower Center" if orientation == "Horizontal" \
        else "Lower Right Corner"
    bar.ScalarBarLength = 0.5 if orientation == "Horizontal" else 0.6


def frame_body(view, bar, camera, extent, width, height):
    """Places the colour bar below or right of the body, whichever leaves
    the body larger, and gives the view the camera, zoomed and shifted (view
    angle and window centre) so that the body's image, extent in normalized
    device coordinates for the camera, fills the rest of the picture, a
    margin from its edges and from the bar."""
    margin = max(4.0, 0.03 * min(width, height))
    ex = [0.5 * (1.0 + extent[0]) * width, 0.5 * (1.0 + extent[1]) * width,
          0.5 * (1.0 + extent[2]) * height, 0.5 * (1.0 + extent[3]) * height]
    body_w = max(ex[1] - ex[0], 1e-9)
    body_h = max(ex[3] - ex[2], 1e-9)
    best = None
    for orientation in ("Horizontal", "Vertical"):
        place_bar(bar, orientation)
        pv.Render(view)
        box = bar_rectangle(view, bar)
        if orientation == "Horizontal":  # the body above the bar
            free = [margin, width - margin, box[3] + margin, height - margin]
        else:  # the body left of the bar
            free = [margin, box[0] - margin, margin, height - margin]
        scale = min((free[1] - free[0]) / body_w, (free[3] - free[2]) / body_h)
        if best is None or scale > best[0]:
            best = (scale, orientation, free)
    scale, orientation, free = best
    place_bar(bar, orientation)
    # Through the view's properties: the view sets its camera from them.
    view.CameraPosition = camera.GetPosition()
    view.CameraFocalPoint = camera.GetFocalPoint()
    view.CameraViewUp = camera.GetViewUp()
    view.CameraParallelProjection = 0
    if scale <= 0.0:  # a picture too small for a bar and a body
        view.CameraViewAngle = camera.GetViewAngle()
        return
    # The image of a point p goes to scale * p - window centre (normalized
    # device coordinates): the view angle's tangent shrinks by scale, and
    # the window centre moves the body's centre to the free box's.
    view.CameraViewAngle = math.degrees(2.0 * math.atan(
        math.tan(0.5 * math.radians(camera.GetViewAngle())) / scale))
    body_centre = [0.5 * (extent[0] + extent[1]),
                   0.5 * (extent[2] + extent[3])]
    free_centre = [(free[0] + free[1]) / width - 1.0,
                   (free[2] + free[3]) / height - 1.0]
    view.GetActiveCamera().SetWindowCenter(
        scale * body_centre[0] - free_centre[0],
        scale * body_centre[1] - free_centre[1])


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

    # The colour range of the last frame and one camera for every frame:
    # aimed at the last frame's body, from an oblique angle in 3D, then
    # zoomed and shifted so that every frame's body is clear of the colour
    # bar (aimed at all frames' bodies if one was behind the camera).
    view.ViewTime = times[frames[-1]]
    warped.UpdatePipeline(times[frames[-1]])
    display.RescaleTransferFunctionToDataRange(False, True)
    bounds = warped.GetDataInformation().GetBounds()
    oblique = bounds[5] - bounds[4] > 0.0
    camera = aim_camera(bounds, oblique)
    framed = [times[frame] for frame in frames]
    extent, bounds, behind = body_extent(warped, framed, camera,
                                         width / float(height))
    if behind:
        camera = aim_camera(bounds, oblique)
        extent, bounds, behind = body_extent(warped, framed, camera,
                                             width / float(height))
    if not numpy.isfinite(extent).all():
        fail("no points in %s" % args.pvd)
    frame_body(view, bar, camera, extent, width, height)
    if args.hide == "bar":
        bar.Visibility = 0
    elif args.hide == "body":
        display.Visibility = 0  # the property: simple.Hide drops the bar too

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
