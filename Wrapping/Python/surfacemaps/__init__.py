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
``map_surfaces(meshes, landmarks=None, target_error=1e-3, pairs="star", keep_landmarks=True, **settings)``
    Certified bijective map between meshes (vtkSurfaceMapFilter); returns one
    output per mesh (the common triangulation lifted onto each), or with
    ``mapped=True`` also the first mesh mapped onto each; raises InputError or
    MapError.

Submodules: ``surfacemaps.plots`` (distortion curves), ``surfacemaps.render``
(offscreen pictures).
"""

import vtkmodules.vtkCommonCore  # noqa: F401  (VTK's base classes must be loaded first)
import vtkmodules.vtkCommonDataModel  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .SurfaceMapsFilters import *  # noqa: F401,F403
from .SurfaceMapsFilters import (vtkSphereEmbeddingFilter, vtkSurfaceMapEvaluation, vtkSurfaceMapFilter,
                                 vtkSurfaceMeshReader, vtkSurfaceMeshValidator)

__version__ = "0.1.0"


class InputError(ValueError):
    """A mesh or landmark file cannot be used; the message says why and where."""


class MapError(RuntimeError):
    """No certified bijective map was found (or the computation failed otherwise)."""


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


_PAIR_MODES = {"star": vtkSurfaceMapFilter.PAIRS_STAR, "sequence": vtkSurfaceMapFilter.PAIRS_SEQUENCE,
               "cycle": vtkSurfaceMapFilter.PAIRS_CYCLE, "all": vtkSurfaceMapFilter.PAIRS_ALL}


def _with_landmarks(mesh, landmarks):
    """`mesh` (vtkPolyData or path) with landmarks from a file or a sequence of vertex ids (id = position)."""
    import os
    from vtkmodules.vtkCommonCore import vtkIntArray
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    if isinstance(mesh, (str, os.PathLike)):
        if landmarks is None or isinstance(landmarks, (str, os.PathLike)):
            return read_mesh(mesh, landmarks=landmarks)
        mesh = read_mesh(mesh)
    elif not isinstance(mesh, vtkPolyData):
        raise TypeError(f"meshes are vtkPolyData or file names, not {type(mesh).__name__}")
    if landmarks is None:
        return mesh
    if isinstance(landmarks, (str, os.PathLike)):
        raise TypeError("a landmark file needs its mesh as a file name; give vertex ids for a vtkPolyData")
    ids = vtkIntArray()
    ids.SetName("Landmarks")
    ids.SetNumberOfValues(mesh.GetNumberOfPoints())
    ids.Fill(-1)
    for landmark_id, vertex in enumerate(landmarks):
        if not 0 <= int(vertex) < mesh.GetNumberOfPoints():
            raise InputError(f"landmark {landmark_id} is vertex {vertex}, but the mesh has "
                             f"{mesh.GetNumberOfPoints()} vertices")
        ids.SetValue(int(vertex), landmark_id)
    copy = vtkPolyData()
    copy.ShallowCopy(mesh)  # the caller's mesh keeps its own arrays
    copy.GetPointData().AddArray(ids)
    return copy


def map_surfaces(meshes, landmarks=None, target_error=1e-3, pairs="star", keep_landmarks=True, mapped=False,
                 **settings):
    """Certified bijective map between closed genus-0 meshes through one common triangulation.

    Runs vtkSurfaceMapFilter on `meshes` (vtkPolyData or file names; one mesh
    gives a bijective remeshing).

    - `landmarks`: None, or one entry per mesh: a landmark file (when the mesh
      is a file name) or a sequence of vertex indices, the k-th entry being
      landmark id k; the same id on two meshes marks corresponding points.
      Meshes may also carry a "Landmarks" point array already.
    - `target_error`: approximation error of the fine phase in unit-area units
      (each mesh centred and scaled to unit area); smaller gives a finer T.
    - `pairs`: "star" (0-i), "sequence", "cycle" or "all": the pairs whose
      distortion is minimised with three or more meshes.
    - `keep_landmarks`: lock landmarks exactly after the landmark phase (True)
      or release them.
    - `settings`: any other vtkSurfaceMapFilter setting by name, e.g.
      ``CoarseIterations=10``, ``FineIterations=20``, ``MapWeight=2.0``.

    Returns the list of outputs, one per mesh: the common triangulation lifted
    onto mesh i, same triangles for all, with the point arrays
    "SpherePosition", "SourceCellId", "SourceBarycentric", "Landmarks" and the
    mesh's own point arrays, cell data "Distortion" and field data (energies,
    per-phase iterations and times, "Bijective"). With ``mapped=True`` returns
    ``(common, mapped)`` where ``mapped[j]`` is the first mesh mapped onto mesh
    j by the exact map (its connectivity), computed from the same map.

    Raises InputError when a mesh or its landmarks cannot be used, MapError
    when no certified map is found, TypeError for an unknown setting.
    """
    meshes = list(meshes)
    if not meshes:
        raise InputError("no meshes to map")
    if landmarks is not None:
        landmarks = list(landmarks)
        if len(landmarks) != len(meshes):
            raise InputError(f"{len(meshes)} meshes but {len(landmarks)} landmark entries")
    if pairs not in _PAIR_MODES:
        raise ValueError(f"pairs is one of {sorted(_PAIR_MODES)}, not {pairs!r}")
    f = vtkSurfaceMapFilter()
    errors = _collect_errors(f)
    f.SetTargetError(target_error)
    f.SetPairMode(_PAIR_MODES[pairs])
    f.SetKeepLandmarks(bool(keep_landmarks))
    for name, value in settings.items():
        setter = getattr(f, "Set" + name, None)
        if setter is None:
            raise TypeError(f"vtkSurfaceMapFilter has no setting {name!r}")
        setter(value)
    for k, mesh in enumerate(meshes):
        f.AddInputData(_with_landmarks(mesh, None if landmarks is None else landmarks[k]))

    def outputs():
        f.Update()
        if errors or f.GetOutput(0).GetNumberOfPoints() == 0:
            message = "; ".join(errors) or "the map was aborted"
            raise (InputError if f.GetErrorCode() == vtkSurfaceMapFilter.InvalidInputError else MapError)(message)
        result = []
        for i in range(len(meshes)):
            copy = f.GetOutput(i).NewInstance()
            copy.ShallowCopy(f.GetOutput(i))
            result.append(copy)
        return result

    common = outputs()
    if not mapped:
        return common
    f.SetOutputModeToMappedFirstInput()
    return common, outputs()
