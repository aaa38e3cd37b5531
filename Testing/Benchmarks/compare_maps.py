"""Compares two map directories (what `surfacemap map` writes) bit for bit:
the points, the triangles and every point array of common_*.vtp,
mapped_*.vtp and embedding_*.vtp. A refactoring that must not change a map
is checked with it on the corpus (corpus_report.py --work DIR for each
build, then this on each pair's map directories).

    /usr/bin/python3 Testing/Benchmarks/compare_maps.py DIR_A DIR_B [DIR_A2 DIR_B2 ...]

Prints one line per pair of directories; exit code 0 when all are the same,
1 when any differs or a file is missing.
"""

import glob
import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import numpy as np

PATTERNS = ("common_*.vtp", "mapped_*.vtp", "embedding_*.vtp")


def read(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def arrays(mesh):
    """name -> numpy array: the points, the triangles and each point array."""
    found = {"points": vtk_to_numpy(mesh.GetPoints().GetData()),
             "triangles": vtk_to_numpy(mesh.GetPolys().GetConnectivityArray())}
    data = mesh.GetPointData()
    for k in range(data.GetNumberOfArrays()):
        array = data.GetArray(k)
        if array is not None:
            found["point data " + array.GetName()] = vtk_to_numpy(array)
    return found


def differences(first, second):
    """What differs between two map directories, as lines; empty when none."""
    names = sorted({os.path.basename(p) for pattern in PATTERNS
                    for d in (first, second) for p in glob.glob(os.path.join(d, pattern))})
    if not names:
        return ["no map files in " + first + " or " + second]
    lines = []
    for name in names:
        a, b = os.path.join(first, name), os.path.join(second, name)
        if not (os.path.exists(a) and os.path.exists(b)):
            lines.append(name + ": only in one directory")
            continue
        x, y = arrays(read(a)), arrays(read(b))
        for key in sorted(set(x) | set(y)):
            if key not in x or key not in y:
                lines.append(f"{name}: {key} only in one")
            elif x[key].shape != y[key].shape:
                lines.append(f"{name}: {key} shape {x[key].shape} vs {y[key].shape}")
            elif not np.array_equal(x[key], y[key]):
                diff = np.max(np.abs(x[key].astype(float) - y[key].astype(float)))
                lines.append(f"{name}: {key} differs (largest difference {diff:.3g})")
    return lines


def main(argv):
    if len(argv) < 2 or len(argv) % 2:
        print(__doc__, file=sys.stderr)
        return 2
    same = True
    for first, second in zip(argv[0::2], argv[1::2]):
        lines = differences(first, second)
        print(f"{first} vs {second}: " + ("the same bit for bit" if not lines else "DIFFERENT"))
        for line in lines:
            print("  " + line)
        same = same and not lines
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
