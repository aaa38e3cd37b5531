"""The README's picture of landmarks as guides: a checkerboard of A's
positions drawn on A, and carried onto B by two maps of the same pair (the
same wrong landmark set, released; and used as guides). Where a map is
right, the squares on B look like those on A; where the wrong landmarks led
it astray, they stretch across the wrong finger.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \\
        Testing/Benchmarks/landmark_pictures.py RELEASED_MAPDIR GUIDED_MAPDIR -o PICTURE.png

The map directories are `surfacemap map` outputs of one pair (e.g. from
landmark_robustness.py's work directory: WORK/hands/swap-far/map without
and with --guides).
"""

import argparse
import os
import sys

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from surfacemaps import render


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetOutput().GetNumberOfPoints() == 0:
        raise SystemExit(f"{path}: no surface read")
    return reader.GetOutput()


def with_positions_of(mesh, source):
    """`mesh` with the point array "APosition": the points of `source` (T on A)."""
    array = numpy_to_vtk(vtk_to_numpy(source.GetPoints().GetData()).copy(), deep=True)
    array.SetName("APosition")
    mesh.GetPointData().AddArray(array)
    return mesh


def panel(mesh, caption):
    return render.Panel(render.checkered(mesh, "APosition", squares=14), render.configure_checkerboard, caption)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("released")
    parser.add_argument("guided")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args(argv)
    a = read_vtp(os.path.join(args.guided, "common_0.vtp"))
    panels = [panel(with_positions_of(a, a), "A: a checkerboard of its positions")]
    for directory, caption in ((args.released, "on B: wrong landmarks, released"),
                               (args.guided, "on B: landmarks as guides")):
        common_0 = read_vtp(os.path.join(directory, "common_0.vtp"))
        panels.append(panel(with_positions_of(read_vtp(os.path.join(directory, "common_1.vtp")), common_0), caption))
    render.render_panels(panels, args.output, panel_size=(420, 340))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
