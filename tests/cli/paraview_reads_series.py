"""Opens a run's series.pvd with ParaView's own reader and prints what ParaView sees:
its times, the point arrays of the last frame, its number of points and its field data."""
import sys

from paraview.simple import PVDReader

reader = PVDReader(FileName=sys.argv[1])
reader.UpdatePipelineInformation()
print('times', list(reader.TimestepValues))
reader.UpdatePipeline(reader.TimestepValues[-1])
print('arrays', sorted(reader.PointData.keys()))
print('points', reader.GetDataInformation().GetNumberOfPoints())
print('field data', sorted(reader.FieldData.keys(), key=str.lower))
