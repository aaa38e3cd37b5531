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
``embed_on_sphere(mesh, **settings)``
    Certified bijective sphere embedding (vtkSphereEmbeddingFilter); returns
    the mesh with the point array "SpherePosition"; raises InputError.
``evaluate_map(source, target, source_original=None, target_original=None)``
    The metrics of vtkSurfaceMapEvaluation as a dictionary.

Submodules: ``surfacemaps.plots`` (distortion curves), ``surfacemaps.render``
(offscreen pictures).
"""

import vtkmodules.vtkCommonCore  # noqa: F401  (VTK's base classes must be loaded first)
import vtkmodules.vtkCommonDataModel  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .SurfaceMapsFilters import *  # noqa: F401,F403
from .SurfaceMapsFilters import (vtkSphereEmbeddingFilter, vtkSurfaceMapEvaluation, vtkSurfaceMeshReader,
                                 vtkSurfaceMeshValidator)

__version__ = "0.1.0"


class InputError(ValueError):
    """A mesh or landmark file cannot be used; the message says why and where."""


def _collect_errors(algorithm):
    """Turn the algorithm's ErrorEvents into a list of messages (instead of VTK's output window)."""
    from vtkmodules.vtkCommonCore import vtkCommand
    messages = []

    def on_error(obj, event, text=None):
        messages.append(text.split("): ", 1)[-1].strip() if text else "unknown error")

    on_error.CallDataType = "string0"
    algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)
    return messages


_SUMMARY = ("SymmetricDirichlet", "AreaBelow1.5", "AreaBelow2", "MaxDistortion", "DegenerateTriangles",
            "MinAngleSource", "MeanMinAngleSource", "MinAngleTarget", "MeanMinAngleTarget", "HausdorffSource",
            "HausdorffTarget", "TwoSidedDistanceSource", "TwoSidedDistanceTarget", "Bijective",
            "NonPositiveTriangles")


def read_mesh(path, landmarks=None):
    """Read a mesh file (OBJ, OFF, PLY, STL, VTP, VTK) and optionally a landmark file."""
    reader = vtkSurfaceMeshReader()
    _collect_errors(reader)
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


def embed_on_sphere(mesh, **settings):
    """Certified bijective embedding of `mesh` (vtkPolyData) on the unit sphere.

    Settings are vtkSphereEmbeddingFilter's, by name: e.g. ``BarrierWeight=0.1``,
    ``FinalIterations=50``, ``OutputPointsOnSphere=True``. Returns the output
    vtkPolyData (point array "SpherePosition"); raises InputError with the
    filter's message when the input is invalid or no embedding is certified.
    """
    f = vtkSphereEmbeddingFilter()
    errors = _collect_errors(f)
    for name, value in settings.items():
        setter = getattr(f, "Set" + name, None)
        if setter is None:
            raise TypeError(f"vtkSphereEmbeddingFilter has no setting {name!r}")
        setter(value)
    f.SetInputData(mesh)
    f.Update()
    if errors or f.GetOutput().GetNumberOfPoints() == 0:
        raise InputError("; ".join(errors) or "the embedding was aborted")
    return f.GetOutput()


def evaluate_map(source, target, source_original=None, target_original=None):
    """Metrics of the map between two meshes of equal connectivity, as a dict (DESIGN.md section 6)."""
    e = vtkSurfaceMapEvaluation()
    errors = _collect_errors(e)
    for port, mesh in enumerate((source, target, source_original, target_original)):
        if mesh is not None:
            e.SetInputData(port, mesh)
    e.Update()
    if errors:
        raise InputError("; ".join(errors))
    fields = e.GetOutput().GetFieldData()
    return {name: fields.GetArray(name).GetValue(0) for name in _SUMMARY if fields.GetArray(name) is not None}
