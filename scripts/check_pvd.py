# Opens a PVD series with ParaView's own reader (as ParaView does) and
# prints its time steps and, at the last one, the point arrays and the range
# of the velocity's z component, if there is one.
#
#   apt-get install -y --no-install-recommends paraview python3-paraview
#   pvbatch scripts/check_pvd.py output/swinging_cantilever.pvd
import sys

from paraview.simple import PVDReader, UpdatePipeline, servermanager

if len(sys.argv) != 2:
    sys.exit("usage: pvbatch scripts/check_pvd.py SERIES.pvd")
reader = PVDReader(FileName=sys.argv[1])
times = list(reader.TimestepValues)
if not times:
    sys.exit("%s: no time steps" % sys.argv[1])
print("time steps: %d, from %g to %g" % (len(times), times[0], times[-1]))
UpdatePipeline(time=times[-1], proxy=reader)
data = servermanager.Fetch(reader)
block = data.GetBlock(0) if hasattr(data, "GetNumberOfBlocks") else data
points = block.GetPointData()
names = [points.GetArrayName(i) for i in range(points.GetNumberOfArrays())]
print("last step: %d points, %d cells; point arrays: %s"
      % (block.GetNumberOfPoints(), block.GetNumberOfCells(), ", ".join(names)))
velocity = points.GetArray("velocity")
if velocity is not None:
    print("velocity z range at t = %g: %g .. %g" % ((times[-1],) + velocity.GetRange(2)))
