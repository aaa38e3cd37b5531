"""Meshes: reading them (with landmark and sizing files), validating them as inputs, landmarks given
as vertex ids, their point arrays as numpy arrays, and how point arrays are carried (categorical or
continuous) by the algorithms that carry them."""

import math
import numbers
import os

from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkCommonDataModel import vtkPolyData

from .SurfaceMapsFilters import vtkSurfaceMeshReader, vtkSurfaceMeshValidator
from .errors import InputError, _collect_errors, _update


def read_mesh(path, landmarks=None, sizing=None):
    """Read a mesh file (OBJ, OFF, PLY, STL, VTP, VTK), optionally with a landmark file and a sizing file.

    Landmarks: vertex indices (.pinned, .txt, SHREC .vts) or points (.vts without index, .csv x,y,z[,id],
    3D Slicer .fcsv and .mrk.json), each point snapped to the closest vertex; the mesh's field data then
    holds LandmarkSnapId, LandmarkSnapVertex and LandmarkSnapDistance, and a point farther than 1 % of
    the bounding-box diagonal from its vertex raises a UserWarning. Sizing: one target edge length per
    vertex per line, read into the point array "Sizing" (used by map_surfaces instead of curvature).
    """
    reader = vtkSurfaceMeshReader()
    errors = _collect_errors(reader)
    reader.SetFileName(str(path))
    if landmarks is not None:
        reader.SetLandmarkFileName(str(landmarks))
    if sizing is not None:
        reader.SetSizingFileName(str(sizing))
    # The reader's warnings (e.g. a landmark point far from its vertex) become SurfaceMapsWarnings.
    _update(reader, errors)
    message = reader.GetLastErrorMessage() or "; ".join(errors)
    if message:
        raise InputError(message)
    return reader.GetOutput()


def validate(*meshes, check_landmark_correspondence=True):
    """Validate meshes (vtkPolyData); one dict per mesh with statistics and 'defects'."""
    validator = vtkSurfaceMeshValidator()
    validator.SetCheckLandmarkCorrespondence(check_landmark_correspondence)
    for mesh in meshes:
        validator.AddInputDataObject(mesh)
    _update(validator)
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


def _with_landmarks(mesh, landmarks):
    """`mesh` (vtkPolyData or path) with landmarks from a file or a sequence of vertex ids (id = position)."""
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
    seen = {}
    for landmark_id, vertex in enumerate(landmarks):
        # Vertex ids are integers: 3.7 is an error, not vertex 3 (3.0 is vertex 3).
        if (isinstance(vertex, bool) or not isinstance(vertex, numbers.Real) or not math.isfinite(vertex)
                or vertex != int(vertex)):
            raise InputError(f"landmark {landmark_id} is {vertex!r}, not an integer vertex id")
        vertex = int(vertex)
        if not 0 <= vertex < mesh.GetNumberOfPoints():
            raise InputError(f"landmark {landmark_id} is vertex {vertex}, but the mesh has "
                             f"{mesh.GetNumberOfPoints()} vertices")
        if vertex in seen:
            raise InputError(f"landmarks {seen[vertex]} and {landmark_id} are the same vertex {vertex}")
        seen[vertex] = landmark_id
        ids.SetValue(vertex, landmark_id)
    copy = vtkPolyData()
    copy.ShallowCopy(mesh)  # the caller's mesh keeps its own arrays
    copy.GetPointData().AddArray(ids)
    return copy


def point_arrays(mesh):
    """The point arrays of a vtkPolyData as a dict {name: numpy array}, copies (one row per point)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    data = mesh.GetPointData()
    result = {}
    for a in range(data.GetNumberOfArrays()):
        array = data.GetArray(a)  # None for string arrays: not numeric data
        if array is not None and array.GetName():
            result[array.GetName()] = vtk_to_numpy(array).copy()
    return result


def _shallow_copy(mesh):
    copy = mesh.NewInstance()
    copy.ShallowCopy(mesh)
    return copy


def _set_array_transfer_modes(algorithm, categorical, continuous):
    """Per-array transfer modes on a vtkSurfaceArrayTransferAlgorithm from two lists of array names."""
    chosen = {}
    for names, mode in ((categorical, algorithm.ARRAY_TRANSFER_CATEGORICAL),
                        (continuous, algorithm.ARRAY_TRANSFER_CONTINUOUS)):
        if names is None:
            continue
        if isinstance(names, (str, bytes)):
            raise TypeError(f"categorical and continuous are lists of array names, not the string {names!r}")
        for name in names:
            if not isinstance(name, str) or not name:
                raise TypeError(f"array names are non-empty strings, not {name!r}")
            if chosen.get(name, mode) != mode:
                raise ValueError(f"array {name!r} is given both categorical and continuous")
            chosen[name] = mode
    for name, mode in chosen.items():
        algorithm.SetArrayTransferMode(name, mode)
