"""Maps two bundled meshes with the SurfaceMaps plugin in pvbatch or pvpython.

    ParaView/pvsurfacemaps pvbatch ParaView/Examples/map_pair.py [DATA_DIR [OUTPUT_DIR]]

Reads the ellipsoid and the blob with their landmarks, maps them on a short
schedule, writes the map's multiblock (block i: the common triangulation
lifted onto input i) and extracts the blob's block by its selector. Blocks
are named after their inputs' files; a selector is /Root/ and that name
with every character but letters, digits and '_' dropped ('_' in front if
it then starts with a digit): /Root/bloboff for blob.off. Exits with status
1 when the map is not certified. CI's ParaView.pvbatch runs it.
"""

import os
import sys

from paraview import servermanager
from paraview.simple import ExtractBlock, SaveData, SurfaceMap, SurfaceMeshReader

data = sys.argv[1] if len(sys.argv) > 1 else "Data"
output = sys.argv[2] if len(sys.argv) > 2 else "."
os.makedirs(output, exist_ok=True)

ellipsoid = SurfaceMeshReader(FileName=os.path.join(data, "ellipsoid.obj"),
                              LandmarkFileName=os.path.join(data, "ellipsoid.pinned"))
blob = SurfaceMeshReader(FileName=os.path.join(data, "blob.off"),
                         LandmarkFileName=os.path.join(data, "blob.vts"))
surface_map = SurfaceMap(Input=[ellipsoid, blob], CoarseIterations=10, FineIterations=10,
                         RefinementRounds=0)
SaveData(os.path.join(output, "map.vtm"), proxy=surface_map)

on_blob = ExtractBlock(Input=surface_map, Selectors=["/Root/bloboff"])
blocks = servermanager.Fetch(on_blob)
lifted = blocks.GetBlock(0) if blocks.GetNumberOfBlocks() == 1 else None
if lifted is None or lifted.GetFieldData().GetArray("Bijective").GetValue(0) != 1:
    print("the map is not certified, or /Root/bloboff selected no block", file=sys.stderr)
    sys.exit(1)
print(f"block /Root/bloboff: T has {lifted.GetNumberOfPoints()} vertices on the blob, "
      f"certified bijective")
