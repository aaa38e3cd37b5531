"""SurfaceMaps: bijective maps between genus-0 surfaces via adaptive common triangulations.

The VTK classes of the module are available directly from this package::

    import surfacemaps
    reader = surfacemaps.vtkSurfaceMeshReader(file_name="spot.obj")

Helpers:

``read_mesh(path, landmarks=None)``
    Read a mesh (and optional landmark file) into a vtkPolyData; raises
    ``surfacemaps.InputError`` with the reader's message on failure.
``validate(*meshes)``
    Validate one or more vtkPolyData as SurfaceMaps inputs; returns a list of
    dictionaries (one per mesh) with the statistics and the defects.
"""

import vtkmodules.vtkCommonCore  # noqa: F401  (VTK's base classes must be loaded first)
import vtkmodules.vtkCommonDataModel  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .SurfaceMapsFilters import *  # noqa: F401,F403
from .SurfaceMapsFilters import vtkSurfaceMeshReader, vtkSurfaceMeshValidator

__version__ = "0.1.0"


class InputError(ValueError):
    """A mesh or landmark file cannot be used; the message says why and where."""


def _silence_errors(algorithm):
    # Errors are turned into exceptions; keep VTK's output window quiet.
    from vtkmodules.vtkCommonCore import vtkCommand
    algorithm.AddObserver(vtkCommand.ErrorEvent, lambda *args: None)


def read_mesh(path, landmarks=None):
    """Read a mesh file (OBJ, OFF, PLY, STL, VTP, VTK) and optionally a landmark file."""
    reader = vtkSurfaceMeshReader()
    _silence_errors(reader)
    reader.SetFileName(str(path))
    if landmarks is not None:
        reader.SetLandmarkFileName(str(landmarks))
    reader.Update()
    message = reader.GetLastErrorMessage()
    if message:
        raise InputError(message)
    return reader.GetOutput()


def validate(*meshes, check_landmark_correspondence=True):
    """Validate meshes (vtkPolyData); one dict per mesh with statistics and 'defects'."""
    validator = vtkSurfaceMeshValidator()
    validator.SetCheckLandmarkCorrespondence(check_landmark_correspondence)
    for mesh in meshes:
        validator.AddInputDataObject(mesh)
    validator.Update()
    table = validator.GetOutput()
    rows = []
    for r in range(table.GetNumberOfRows()):
        row = {}
        for c in range(table.GetNumberOfColumns()):
            column = table.GetColumn(c)
            row[column.GetName()] = column.GetValue(r)
        row["defects"] = [d for d in row.pop("Defects").split("\n") if d]
        row["Valid"] = bool(row["Valid"])
        rows.append(row)
    return rows
