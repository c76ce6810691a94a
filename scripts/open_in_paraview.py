# Open output files with ParaView's own readers (run with pvpython) and
# print, for the first and the last time step, the number of points and
# cells and the range of every point field. Exits with 1 if a file does not
# open, has no points, or holds a value that is not finite.
# Usage: pvpython scripts/open_in_paraview.py FILE.pvd|FILE.xdmf ...
import math
import sys

from paraview.simple import OpenDataFile

failed = False
for name in sys.argv[1:]:
    reader = OpenDataFile(name)
    if reader is None:
        print(f"{name}: ParaView has no reader for it")
        failed = True
        continue
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    for time in (times[0], times[-1]):
        reader.UpdatePipeline(time)
        info = reader.GetDataInformation()
        fields = []
        for i in range(len(reader.PointData)):
            array = reader.PointData.GetArray(i)
            ranges = [array.GetRange(c)
                      for c in range(array.GetNumberOfComponents())]
            if not all(math.isfinite(v) for r in ranges for v in r):
                failed = True
            low = min(r[0] for r in ranges)
            high = max(r[1] for r in ranges)
            fields.append(f"{array.GetName()}[{array.GetNumberOfComponents()}]"
                          f" {low:.6g}..{high:.6g}")
        if info.GetNumberOfPoints() == 0:
            failed = True
        print(f"{name} ({reader.GetXMLName()}): t = {time:g} "
              f"(step {times.index(time) + 1} of {len(times)}), "
              f"{info.GetNumberOfPoints()} points, "
              f"{info.GetNumberOfCells()} cells")
        print("    " + "; ".join(fields))
sys.exit(1 if failed else 0)
