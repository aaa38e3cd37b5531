"""SurfaceMaps: bijective maps between genus-0 surfaces via adaptive common triangulations.

The VTK classes of the module are available directly from this package::

    import surfacemaps
    reader = surfacemaps.vtkSurfaceMeshReader(file_name="spot.obj")

Helpers:

``read_mesh(path, landmarks=None, sizing=None)``
    Read a mesh (and optional landmark and sizing files) into a vtkPolyData;
    landmarks given as points are snapped to the closest vertex (distances in
    the field data, a warning above 1 % of the bounding-box diagonal); raises
    ``surfacemaps.InputError`` with the reader's message on failure.
``validate(*meshes)``
    Validate one or more vtkPolyData as SurfaceMaps inputs; returns a list of
    dictionaries (one per mesh) with the statistics and the defects.
``embed_on_sphere(mesh, **settings)``
    Certified bijective sphere embedding (vtkSphereEmbeddingFilter); returns
    the mesh with the point array "SpherePosition"; raises InputError.
``evaluate_map(source, target, source_original=None, target_original=None)``
    The metrics of vtkSurfaceMapEvaluation as a dictionary.
``map_surfaces(meshes, landmarks=None, target_error=None, pairs=None, keep_landmarks=None, **settings)``
    Certified bijective map between meshes (vtkSurfaceMapFilter); returns one
    output per mesh (the common triangulation lifted onto each), or with
    ``mapped=True`` also the first mesh mapped onto each, as a MapResult (a
    list that also holds the map, for transfer); raises InputError or
    MapError.
``transfer(mapping, source, target, arrays=None, source_data=None, as_numpy=False)``
    Point data (and texture coordinates) of input `source` of a map carried
    onto input `target`'s vertices (vtkSurfaceMapTransfer): a saved map
    (``surfacemap map``'s directory) or one in memory (what map_surfaces
    returns, or a vtkSurfaceMapFilter); `source_data` carries new arrays (a
    dict of numpy arrays, one row per source vertex, or a vtkPolyData of the
    source's connectivity) instead of those the source had; raises InputError.
``point_arrays(mesh)``
    The point arrays of a vtkPolyData as a dict of numpy arrays.
``average_surfaces(meshes, weights=None, align="rigid")``
    Weighted mean shape of meshes with identical connectivity (e.g. the
    outputs of map_surfaces) after generalized Procrustes alignment; it does
    not depend on the order of the meshes (vtkSurfaceAverage).
``shape_statistics(meshes, modes=3, align="rigid")``
    Mean shape, principal modes of variation, variances, explained-variance
    fractions, scores and per-vertex spread of meshes with identical
    connectivity (vtkSurfaceShapeStatistics), as a ShapeStatistics.

Point arrays carried onto other points (map_surfaces, transfer,
average_surfaces) are continuous (interpolated; by default the floating-point
arrays) or categorical (labels: never a value the source does not have; by
default the integer arrays): through a map the value of the nearest corner of
the source triangle, in an average input 0's values. Each of these helpers
takes ``categorical=[names]`` and ``continuous=[names]`` to choose per array
(vtkSurfaceArrayTransferAlgorithm.SetArrayTransferMode).
``write_time_series(source, times, directory, name="surface")``
    The output of a temporal source (e.g. vtkSurfaceSequenceInterpolator) at
    each time as .vtp files plus a ParaView .pvd collection.
``write_collection(meshes, times, directory, name)``
    Given meshes, one per time, as .vtp files plus a ParaView .pvd collection.

Submodules: ``surfacemaps.plots`` (distortion curves), ``surfacemaps.render``
(offscreen pictures), ``surfacemaps.population`` (``python3 -m
surfacemaps.population STAGES_DIR --output-dir OUT``: stage maps and means,
spread, one map across the stages, shape statistics over all specimens, the
interpolated series; under MPI when run with mpirun).
"""

import math
import os

import vtkmodules.vtkCommonCore  # noqa: F401  (VTK's base classes must be loaded first)
import vtkmodules.vtkCommonDataModel  # noqa: F401
from vtkmodules.vtkCommonDataModel import vtkPolyData
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .SurfaceMapsFilters import *  # noqa: F401,F403
from .SurfaceMapsFilters import (vtkSphereEmbeddingFilter, vtkSurfaceMapEvaluation, vtkSurfaceMapFilter,
                                 vtkSurfaceMapTransfer, vtkSurfaceMeshReader, vtkSurfaceMeshValidator)
from .SurfaceMapsFilters import vtkSurfaceAverage, vtkSurfaceSequenceInterpolator, vtkSurfaceShapeStatistics

__version__ = "0.1.0"


class InputError(ValueError):
    """A mesh or landmark file cannot be used; the message says why and where."""


class MapError(RuntimeError):
    """No certified bijective map was found (or the computation failed otherwise)."""


class SurfaceMapsWarning(UserWarning):
    """Valid but suspect input, e.g. landmarks that are the mirror image of the first mesh's."""


def _error_observer(algorithm):
    """Turn the algorithm's ErrorEvents into a list of messages (instead of VTK's output window).

    Returns the list and the observer's tag (for RemoveObserver)."""
    from vtkmodules.vtkCommonCore import vtkCommand
    messages = []

    def on_error(obj, event, text=None):
        messages.append(text.split("): ", 1)[-1].strip() if text else "unknown error")

    on_error.CallDataType = "string0"
    return messages, algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)


def _collect_errors(algorithm):
    """The algorithm's error messages from now on, as a list that fills as they come."""
    return _error_observer(algorithm)[0]


def _macro_text(text, default):
    """The message of a vtkErrorMacro/vtkWarningMacro text, without file, line and object."""
    return text.split("): ", 1)[-1].strip() if text else default


def _update(algorithm, errors=None):
    """algorithm.Update() with the error itself as the only message.

    When RequestData fails, VTK's executive adds its own error ("Algorithm ...
    returned failure for request: ..." and the whole request) through the
    output window; here it is observed for this update only and dropped when
    the algorithm reported why (its ErrorEvents fill `errors`), else appended
    to `errors` so that the caller raises it. The algorithm's warnings become
    Python warnings (SurfaceMapsWarning)."""
    import warnings
    from vtkmodules.vtkCommonCore import vtkCommand
    executive = algorithm.GetExecutive()
    pipeline_errors = []

    def on_pipeline_error(obj, event, text=None):
        pipeline_errors.append(_macro_text(text, "pipeline error"))

    def on_warning(obj, event, text=None):
        warnings.warn(_macro_text(text, "unknown warning"), SurfaceMapsWarning, stacklevel=4)

    on_pipeline_error.CallDataType = "string0"
    on_warning.CallDataType = "string0"
    tags = [(executive, executive.AddObserver(vtkCommand.ErrorEvent, on_pipeline_error)),
            (algorithm, algorithm.AddObserver(vtkCommand.WarningEvent, on_warning))]
    try:
        algorithm.Update()
    finally:
        for obj, tag in tags:
            obj.RemoveObserver(tag)
    if errors is not None and not errors:
        errors.extend(pipeline_errors)


_SUMMARY = ("SymmetricDirichlet", "AreaBelow1.5", "AreaBelow2", "MaxDistortion", "DegenerateTriangles",
            "MinAngleSource", "MeanMinAngleSource", "MinAngleTarget", "MeanMinAngleTarget", "HausdorffSource",
            "HausdorffTarget", "TwoSidedDistanceSource", "TwoSidedDistanceTarget", "Bijective",
            "NonPositiveTriangles")


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
    _update(f, errors)
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
    _update(e, errors)
    if errors:
        raise InputError("; ".join(errors))
    fields = e.GetOutput().GetFieldData()
    return {name: fields.GetArray(name).GetValue(0) for name in _SUMMARY if fields.GetArray(name) is not None}


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
    import math
    import numbers
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


def settings_table():
    """The surface map's settings, one dict per setting, from the engine's one
    table (vtkSurfaceMapFilter.GetSettingName(i) and friends): name (the
    filter's Set<name>/Get<name>), flag (``surfacemap map --<flag>``), type
    ("real", "count", "switch", "choice"), minimum, maximum, default,
    choices (for "choice"), doc."""
    f = vtkSurfaceMapFilter
    types = {f.SETTING_REAL: "real", f.SETTING_COUNT: "count", f.SETTING_SWITCH: "switch",
             f.SETTING_CHOICE: "choice"}
    rows = []
    for i in range(f.GetNumberOfSettings()):
        choices = f.GetSettingChoices(i)
        rows.append({"name": f.GetSettingName(i), "flag": f.GetSettingFlag(i),
                     "type": types[f.GetSettingType(i)], "minimum": f.GetSettingMinimum(i),
                     "maximum": f.GetSettingMaximum(i), "default": f.GetSettingDefault(i),
                     "choices": choices.split("|") if choices else None,
                     "doc": f.GetSettingDocumentation(i)})
    return rows


def presets():
    """The names of the surface map's presets with their documentation (what
    each is for and the settings it sets), from vtkSurfaceMapFilter."""
    f = vtkSurfaceMapFilter
    return {f.GetPresetName(p): f.GetPresetDocumentation(p) for p in range(f.GetNumberOfPresets())}


def map_surfaces(meshes, landmarks=None, target_error=None, pairs=None, keep_landmarks=None, mapped=False,
                 categorical=None, continuous=None, preset=None, **settings):
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
    - `categorical`, `continuous`: names of point arrays carried onto the
      outputs as labels (the nearest corner's value) or interpolated, instead
      of by type (integer arrays categorical, floating-point ones continuous).
    - `preset`: None, "pair" or "population" (``presets()`` documents them):
      sets a group of settings for a kind of study first; every other
      argument overrides it. "population" is for many specimens in one map
      (statistics over the common triangulation).
    - `settings`: any other setting of vtkSurfaceMapFilter's settings table by
      name, e.g. ``CoarseIterations=10``, ``FineIterations=20``,
      ``MapWeight=2.0`` (``settings_table()`` lists them).
    A setting left at None keeps the filter's default (the settings table's).

    Returns the list of outputs, one per mesh: the common triangulation lifted
    onto mesh i, same triangles for all, with the point arrays
    "SpherePosition", "SourceCellId", "SourceBarycentric", "Landmarks" and the
    mesh's own point arrays (continuous or categorical, see above), cell data
    "Distortion" and field data (energies,
    per-phase iterations and times, "Bijective"). With ``mapped=True`` returns
    ``(common, mapped)`` where ``mapped[j]`` is the first mesh mapped onto mesh
    j by the exact map (its connectivity), computed from the same map. Each
    list is a MapResult, which also holds the map (``.filter``): pass it to
    transfer() to carry data between the meshes without files.

    Raises InputError when a mesh or its landmarks cannot be used, MapError
    when no certified map is found, TypeError for an unknown setting or for
    `meshes` that is one file name or mesh instead of a list, ValueError for a
    setting outside its range (or not finite), as the command line does.
    """
    if isinstance(meshes, (str, bytes, os.PathLike, vtkPolyData)):
        raise TypeError(f"meshes is a list of meshes or file names, e.g. [{meshes!r}], not one")
    meshes = list(meshes)
    if not meshes:
        raise InputError("no meshes to map")
    if landmarks is not None:
        landmarks = list(landmarks)
        if len(landmarks) != len(meshes):
            raise InputError(f"{len(meshes)} meshes but {len(landmarks)} landmark entries")
    if pairs is not None and pairs not in _PAIR_MODES:
        raise ValueError(f"pairs is one of {sorted(_PAIR_MODES)}, not {pairs!r}")
    f = vtkSurfaceMapFilter()
    errors = _collect_errors(f)
    if preset is not None:
        names = [f.GetPresetName(p) for p in range(f.GetNumberOfPresets())]
        if preset not in names:
            raise ValueError(f"preset is one of {names}, not {preset!r}")
        f.ApplyPreset(names.index(preset))
    if pairs is not None:
        f.SetPairMode(_PAIR_MODES[pairs])
    if keep_landmarks is not None:
        f.SetKeepLandmarks(bool(keep_landmarks))
    _set_array_transfer_modes(f, categorical, continuous)
    table = {row["name"]: row for row in settings_table()}
    known = set(table) | {"SizingMode", "NumberOfThreads"}
    if target_error is not None:
        settings = dict(settings, TargetError=target_error)
    for name, value in settings.items():
        if name not in known:
            raise TypeError(f"vtkSurfaceMapFilter has no setting {name!r}")
        row = table.get(name)
        if row and row["type"] in ("real", "count"):
            number = float(value)
            if not math.isfinite(number) or not row["minimum"] <= number <= row["maximum"]:
                raise ValueError(f"{name} must be a finite number in [{row['minimum']:g}, "
                                 f"{row['maximum']:g}], not {value!r}")
        getattr(f, "Set" + name)(value)
    for k, mesh in enumerate(meshes):
        f.AddInputData(_with_landmarks(mesh, None if landmarks is None else landmarks[k]))

    def outputs():
        _update(f, errors)
        if errors or f.GetOutput(0).GetNumberOfPoints() == 0:
            message = "; ".join(errors) or "the map was aborted"
            raise (InputError if f.GetErrorCode() == vtkSurfaceMapFilter.InvalidInputError else MapError)(message)
        result = []
        for i in range(len(meshes)):
            copy = f.GetOutput(i).NewInstance()
            copy.ShallowCopy(f.GetOutput(i))
            result.append(copy)
        return result

    common = MapResult(outputs(), f)
    if not mapped:
        return common
    f.SetOutputModeToMappedFirstInput()
    return common, MapResult(outputs(), f)


def transfer(mapping, source, target, arrays=None, categorical=None, continuous=None, source_data=None,
             as_numpy=False):
    """Carry the point data of input `source` of a map onto the vertices of input `target`.

    `mapping` is the map, saved or in memory:

    - a directory written by ``surfacemap map`` (its embedding_<i>.vtp and
      common_<i>.vtp of both inputs are read and checked against its
      report.json: from another map, swapped or changed files are refused, as
      ``surfacemap transfer`` does);
    - what map_surfaces returned (a MapResult: its ``.filter``), or any
      vtkSurfaceMapFilter with its inputs connected. The filter is brought up
      to date (no computation when it already is) and its outputs are read in
      the modes INPUT_EMBEDDINGS and COMMON_TRIANGULATION in turn: the map is
      reused, not recomputed, and the filter is left in the OutputMode it had,
      with its outputs updated in that mode again (downstream filters see it
      modified and re-run).

    `source` and `target` are input indices. Runs vtkSurfaceMapTransfer:
    every vertex of the target is sent onto the source by the map, where the
    source's point arrays are read: continuous arrays interpolated,
    categorical ones (labels) taken from the nearest corner of the source
    triangle, so the target never gets a label the source does not have. By
    default integer arrays are categorical and floating-point ones
    continuous; `categorical` and `continuous` (lists of array names) choose
    per array.

    `source_data` carries new data instead of the point arrays input `source`
    had when the map was computed (as ``surfacemap transfer --source-data``):

    - a dict {name: numpy array}, one row per vertex of input `source` (shape
      (n,) or (n, k)), of an integer or floating-point dtype; the types are
      kept, so integer arrays stay integer and are categorical by default.
      These become the source's point arrays; its cell data (per-corner
      texture coordinates "CornerTCoords") stays.
    - a vtkPolyData with input `source`'s connectivity (same vertex count, the
      same triangles in the same order; a triangle may start at another
      corner), e.g. a copy of the input with new arrays: its point and cell
      data replace the source's.

    Returns the target mesh (vtkPolyData) with the source's arrays (all but
    "SpherePosition", "Landmarks", "SourceCellId", "SourceBarycentric", or the
    names in `arrays`), "SourceCellId", "SourceBarycentric" (where on the
    source) and "TCoords" (the source's per-corner or point texture
    coordinates evaluated there); with ``as_numpy=True`` instead a dict
    {name: numpy array} of those point arrays (one row per target vertex).

    Raises InputError for missing or unvouched map files, input indices the
    map does not have, unknown array names, inputs that do not fit together,
    `source_data` with the wrong number of rows (naming the array, its length
    and the vertex count), a non-numeric dtype or another connectivity
    (naming the first mismatch); MapError when an in-memory map cannot be
    computed; TypeError for a `mapping` that is neither; ValueError for an
    array given both ways.
    """
    for name, index in (("source", source), ("target", target)):
        if isinstance(index, bool) or not isinstance(index, int) or index < 0:
            raise TypeError(f"{name} is an input index (0, 1, ...), not {index!r}")
    ports, source_name = _map_ports(mapping, source, target)
    if source_data is not None:
        ports[1] = _with_source_data(ports[1], source_data, source, source_name)
        _check_array_names(ports[1], arrays, categorical, continuous)
    t = vtkSurfaceMapTransfer()
    _set_array_transfer_modes(t, categorical, continuous)
    errors = _collect_errors(t)
    for port, mesh in enumerate(ports):
        t.SetInputDataObject(port, mesh)
    for name in arrays or ():
        t.AddArrayName(str(name))
    _update(t, errors)
    if errors or t.GetOutput().GetNumberOfPoints() == 0:
        message = "; ".join(errors) or "the transfer was aborted"
        raise (InputError if t.GetErrorCode() == vtkSurfaceMapTransfer.InvalidInputError else MapError)(message)
    result = _shallow_copy(t.GetOutput())
    return point_arrays(result) if as_numpy else result


class MapResult(list):
    """What map_surfaces returns: a list of vtkPolyData, one output per mesh, that also holds the map.

    ``filter`` is the updated vtkSurfaceMapFilter, so that ``transfer(result,
    source, target, ...)`` carries data between the meshes in memory; it keeps
    the map (a few times the size of the outputs) alive while the list lives.
    """

    def __init__(self, outputs, algorithm):
        super().__init__(outputs)
        self.filter = algorithm


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


def _map_ports(mapping, source, target):
    """The four inputs of vtkSurfaceMapTransfer (target and source with their embeddings, T lifted
    onto target and source) of a map directory or an in-memory map, and the source's name for
    messages."""
    algorithm = getattr(mapping, "filter", mapping)
    if isinstance(algorithm, vtkSurfaceMapFilter):
        return _filter_ports(algorithm, source, target), f"input {source}"
    if isinstance(mapping, (str, os.PathLike)):
        return _directory_ports(os.fspath(mapping), source, target), f"input {source} (embedding_{source}.vtp)"
    raise TypeError("the map is a directory written by 'surfacemap map', a vtkSurfaceMapFilter or what "
                    f"map_surfaces returns, not {type(mapping).__name__}")


def _directory_ports(map_dir, source, target):
    """The transfer's inputs read from a map directory, every file vouched for by its report.json."""
    files = [os.path.join(map_dir, f"{kind}_{index}.vtp")
             for kind, index in (("embedding", target), ("embedding", source), ("common", target), ("common", source))]
    missing = sorted({os.path.basename(f) for f in files if not os.path.isfile(f)})
    if missing:
        raise InputError(f"{map_dir} has no {', '.join(missing)} (written by 'surfacemap map')")
    _verify_map_files(map_dir, [os.path.basename(f) for f in files])
    return [read_mesh(path) for path in files]


def _filter_ports(f, source, target):
    """The transfer's inputs from a vtkSurfaceMapFilter's outputs in the modes INPUT_EMBEDDINGS and
    COMMON_TRIANGULATION. Switching only the mode reuses the map; the mode the filter had is
    restored (and updated, so its outputs match it again) when the outputs are copied."""
    inputs = f.GetNumberOfInputConnections(0)
    for name, index in (("source", source), ("target", target)):
        if index >= inputs:
            raise InputError(f"{name} is input {index}, but the map has {inputs} input"
                             f"{'' if inputs == 1 else 's'}")
    mode = f.GetOutputMode()
    # The filter's own mode last: nothing to restore when it is one of the two.
    kinds = sorted((f.INPUT_EMBEDDINGS, f.COMMON_TRIANGULATION), key=lambda kind: kind == mode)
    copies = {}
    try:
        for kind in kinds:
            f.SetOutputMode(kind)
            _update_map(f)
            copies[kind] = [_shallow_copy(f.GetOutput(i)) for i in (target, source)]
    finally:
        f.SetOutputMode(mode)  # also when the map fails: the user's setting stays
    if mode not in kinds:
        _update_map(f)
    return copies[f.INPUT_EMBEDDINGS] + copies[f.COMMON_TRIANGULATION]


def _update_map(f):
    """Updates a vtkSurfaceMapFilter; raises InputError or MapError with its messages on failure."""
    messages, tag = _error_observer(f)
    try:
        _update(f, messages)
    finally:
        f.RemoveObserver(tag)
    if messages or f.GetOutput(0).GetNumberOfPoints() == 0:
        message = "; ".join(messages) or "the map was aborted"
        raise (InputError if f.GetErrorCode() == vtkSurfaceMapFilter.InvalidInputError else MapError)(message)


def _with_source_data(mesh, source_data, source, source_name):
    """`mesh` (the source with "SpherePosition") carrying `source_data` (a dict of numpy arrays
    or a vtkPolyData of the same connectivity) instead of its own point arrays."""
    from collections.abc import Mapping
    result = _shallow_copy(mesh)
    sphere = mesh.GetPointData().GetArray("SpherePosition")
    if isinstance(source_data, vtkPolyData):
        _check_same_connectivity(source_data, mesh, source, source_name)
        result.GetPointData().ShallowCopy(source_data.GetPointData())
        result.GetPointData().RemoveArray("SpherePosition")
        result.GetCellData().ShallowCopy(source_data.GetCellData())
    elif isinstance(source_data, Mapping):
        arrays = [_vtk_point_array(name, values, mesh.GetNumberOfPoints(), source_name)
                  for name, values in source_data.items()]
        result.GetPointData().Initialize()
        for array in arrays:
            result.GetPointData().AddArray(array)
    else:
        raise TypeError("source_data is a dict {name: numpy array} or a vtkPolyData, "
                        f"not {type(source_data).__name__}")
    result.GetPointData().AddArray(sphere)
    return result


def _vtk_point_array(name, values, vertices, source_name):
    """One source_data entry as a VTK array of the same type (integers stay integer); raises
    InputError naming it when it is not numeric or not one row per vertex."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk
    if not isinstance(name, str) or not name:
        raise TypeError(f"source_data names are non-empty strings, not {name!r}")
    if name == "SpherePosition":
        raise InputError("source_data cannot replace 'SpherePosition': it is the map's embedding of the source")
    array = np.asarray(values)
    if array.dtype.kind not in "iuf":
        raise InputError(f"source_data array {name!r} has dtype {array.dtype}: not numeric "
                         "(give integers for labels, floating point for continuous data)")
    if array.ndim not in (1, 2) or array.ndim == 2 and array.shape[1] == 0:
        raise InputError(f"source_data array {name!r} has shape {array.shape}: (n,) or (n, k) expected, "
                         "one row per vertex")
    if len(array) != vertices:
        raise InputError(f"source_data array {name!r} has {len(array)} rows, {source_name} has {vertices} "
                         "vertices: one row per vertex")
    if array.dtype == np.float16:
        array = array.astype(np.float32)  # VTK has no half-precision arrays
    result = numpy_to_vtk(np.ascontiguousarray(array), deep=True)
    result.SetName(name)
    return result


def _check_same_connectivity(given, mesh, source, source_name):
    """Raises InputError naming the first difference between the vertex counts or triangles of
    `given` (source_data) and `mesh` (input `source`), in the words of
    ``surfacemap transfer --source-data`` (vtkSurfaceMapTransfer.DescribeConnectivityDifference)."""
    difference = vtkSurfaceMapTransfer.DescribeConnectivityDifference(given, mesh, source_name)
    if difference:
        raise InputError(f"source_data {difference}: not the connectivity of input {source}")


def _check_array_names(mesh, arrays, categorical, continuous):
    """Raises InputError for array names (arrays=, categorical=, continuous=) the source_data lacks."""
    data = mesh.GetPointData()
    for names in (arrays, categorical, continuous):
        for name in [] if names is None or isinstance(names, (str, bytes)) else names:
            if isinstance(name, str) and data.GetAbstractArray(name) is None:
                raise InputError(f"source_data has no point array {name!r}")


def map_file_stamp(path, name):
    """The stamp `name` ("MapId" or "MapFile") that `surfacemap map` put into the field data of
    one of its files (the text's bytes in an unsigned char array); "" when absent or unreadable."""
    try:
        array = read_mesh(path).GetFieldData().GetAbstractArray(name)
    except InputError:
        return ""
    if array is None:
        return ""
    return bytes(int(array.GetValue(k)) for k in range(array.GetNumberOfValues())).decode("utf-8", "replace")


def _verify_map_files(map_dir, names):
    """Raises InputError naming the first of the files `names` of a map directory that its
    report.json does not vouch for: missing, from another map, another file of this map
    (swapped, renamed) or changed (size or MD5 differ), as `surfacemap transfer` does."""
    import hashlib
    import json
    import os
    report_path = os.path.join(map_dir, "report.json")
    try:
        with open(report_path) as f:
            report = json.load(f)
    except FileNotFoundError:
        raise InputError(f"{report_path} is missing: the directory holds no complete map "
                         "(was 'surfacemap map' interrupted?)") from None
    except ValueError:
        raise InputError(f"{report_path} is not valid JSON") from None
    if not isinstance(report.get("map_id"), str) or not isinstance(report.get("files"), list):
        raise InputError(f"{report_path} has no map id and file checksums (\"map_id\", \"files\"): "
                         "written by an older surfacemap; run 'surfacemap map' again")
    records = {r.get("name"): r for r in report["files"] if isinstance(r, dict)}
    for name in names:
        path = os.path.join(map_dir, name)
        record = records.get(name)
        if record is None:
            raise InputError(f"{path} is not a file of the map {report_path} describes")
        with open(path, "rb") as f:
            content = f.read()
        if record.get("bytes") == len(content) and record.get("md5") == hashlib.md5(content).hexdigest():
            continue
        stamp = {key: map_file_stamp(path, key) for key in ("MapId", "MapFile")}
        if stamp["MapId"] != report["map_id"]:
            raise InputError(f"{path} belongs to another map (map id {stamp['MapId'] or 'none'}, "
                             f"{report_path} has {report['map_id']}): a stale or copied file")
        if stamp["MapFile"] != name:
            raise InputError(f"{path} is {stamp['MapFile']} of this map, not {name}: swapped or renamed")
        raise InputError(f"{path} was changed after the map was written (its size or checksum differs "
                         f"from {report_path})")


_ALIGN_MODES = {"none": vtkSurfaceAverage.ALIGN_NONE, "rigid": vtkSurfaceAverage.ALIGN_RIGID,
                "similarity": vtkSurfaceAverage.ALIGN_SIMILARITY}


def average_surfaces(meshes, weights=None, align="rigid", categorical=None, continuous=None):
    """Weighted mean shape of meshes with identical connectivity (vtkSurfaceAverage).

    - `meshes`: vtkPolyData or file names, all with the same points count and
      cells, e.g. the outputs of map_surfaces (one common triangulation lifted
      onto each surface).
    - `weights`: None (all 1) or one weight >= 0 per mesh; normalised to sum 1.
    - `align`: "none", "rigid" (rotation and translation of each mesh onto the
      mean, area-weighted least squares, iterated with the mean: generalized
      Procrustes) or "similarity" (also a uniform scale).
    - `categorical`, `continuous`: names of point arrays taken from the first
      mesh (labels) or averaged, instead of by type (integer arrays
      categorical, floating-point ones continuous).

    The mean does not depend on the order of the meshes (with their weights):
    it lies where the meshes lie (placed by the rigid motion that fits it best
    to them as given), with the mean size of theirs under "similarity".
    Categorical arrays are the first mesh's.

    Returns a vtkPolyData with the first mesh's cells, the averaged points
    and point arrays, and field data "AlignmentRMS" (per mesh, the
    area-weighted RMS distance of the aligned mesh to the mean),
    "AlignmentTransform" (per mesh, the 3x4 matrix into the mean's frame),
    "AverageWeight" (and "AlignmentScale"). Raises InputError when the
    connectivity differs or a weight is invalid.
    """
    meshes = list(meshes)
    if not meshes:
        raise InputError("no meshes to average")
    if align not in _ALIGN_MODES:
        raise ValueError(f"align is one of {sorted(_ALIGN_MODES)}, not {align!r}")
    if weights is not None:
        weights = [float(w) for w in weights]
        if len(weights) != len(meshes):
            raise InputError(f"{len(meshes)} meshes but {len(weights)} weights")
    a = vtkSurfaceAverage()
    _set_array_transfer_modes(a, categorical, continuous)
    errors = _collect_errors(a)
    a.SetAlignMode(_ALIGN_MODES[align])
    for k, mesh in enumerate(meshes):
        a.AddInputData(_with_landmarks(mesh, None))
        if weights is not None:
            a.SetInputWeight(k, weights[k])
    _update(a, errors)
    if errors or a.GetOutput().GetNumberOfPoints() == 0:
        raise InputError("; ".join(errors) or "the average was aborted")
    result = a.GetOutput().NewInstance()
    result.ShallowCopy(a.GetOutput())
    return result


class ShapeStatistics:
    """The result of shape_statistics (numpy arrays; k modes, N meshes, V vertices).

    - ``mean``: vtkPolyData of the mean shape with the point arrays
      "StandardDeviation" and "Mode_1" ... "Mode_k";
    - ``variances`` (k), ``explained_fractions`` (k), ``total_variance``;
    - ``scores`` (N x k): mesh i ~ mean + sum_m scores[i, m] * modes[m];
    - ``modes`` (k x V x 3): unit area-weighted norm;
    - ``standard_deviation`` (V), ``alignment_rms`` (N).
    ``shape(mode, coefficient)`` is the mean moved `coefficient` standard
    deviations along `mode` (1-based), a vtkPolyData.
    """

    def __init__(self, algorithm):
        from vtkmodules.util.numpy_support import vtk_to_numpy
        import numpy as np

        self._algorithm = algorithm
        self.mean = algorithm.GetOutput().NewInstance()
        self.mean.ShallowCopy(algorithm.GetOutput())
        fields, points = self.mean.GetFieldData(), self.mean.GetPointData()
        self.variances = vtk_to_numpy(fields.GetArray("Variance")).copy()
        k = len(self.variances)
        self.explained_fractions = vtk_to_numpy(fields.GetArray("ExplainedVarianceFraction")).copy()
        self.total_variance = fields.GetArray("TotalVariance").GetValue(0)
        self.scores = vtk_to_numpy(fields.GetArray("Scores")).reshape(-1, k).copy()
        self.modes = np.array([vtk_to_numpy(points.GetArray(f"Mode_{m + 1}")) for m in range(k)])
        self.standard_deviation = vtk_to_numpy(points.GetArray("StandardDeviation")).copy()
        self.alignment_rms = vtk_to_numpy(fields.GetArray("AlignmentRMS")).copy()

    def shape(self, mode, coefficient):
        """The mean + coefficient * sqrt(variance) * mode (mode 1-based) as vtkPolyData."""
        a = self._algorithm
        if not 1 <= mode <= len(self.variances):
            raise ValueError(f"mode is 1 to {len(self.variances)}, not {mode}")
        a.SetMode(mode)
        a.SetCoefficient(coefficient)
        _update(a)
        result = a.GetOutput().NewInstance()
        result.ShallowCopy(a.GetOutput())
        return result


def shape_statistics(meshes, modes=3, align="rigid"):
    """Mean shape and principal modes of variation of meshes with identical connectivity.

    - `meshes`: two or more vtkPolyData or file names with the same points
      count and cells, e.g. the outputs of map_surfaces.
    - `modes`: modes computed (at most N - 1 come out).
    - `align`: "none", "rigid" (size stays part of the variation) or
      "similarity" (shape alone): generalized Procrustes alignment first, as
      average_surfaces does it (the same order-free mean).

    Variances, scores and mode norms use the area-weighted inner product
    (vertex areas, normalised to sum 1), with 1/N: sqrt(variance) is an RMS
    displacement over the surface in length units. Returns a ShapeStatistics;
    raises InputError (connectivity, fewer than 2 meshes).
    """
    meshes = list(meshes)
    if align not in _ALIGN_MODES:
        raise ValueError(f"align is one of {sorted(_ALIGN_MODES)}, not {align!r}")
    if len(meshes) < 2:
        raise InputError(f"shape statistics need at least 2 meshes, not {len(meshes)}")
    a = vtkSurfaceShapeStatistics()
    errors = _collect_errors(a)
    a.SetAlignMode(_ALIGN_MODES[align])
    a.SetNumberOfModes(int(modes))
    for mesh in meshes:
        a.AddInputData(_with_landmarks(mesh, None))
    _update(a, errors)
    if errors or a.GetOutput().GetNumberOfPoints() == 0:
        raise InputError("; ".join(errors) or "the statistics were aborted")
    return ShapeStatistics(a)


def _replace_atomically(path, write):
    """Call write(temporary_path) for a temporary file next to `path`, then rename it to `path`."""
    import os
    # Next to `path` (same file system, so the rename is atomic), created with the usual permissions.
    temporary = os.path.join(os.path.dirname(path), f".{os.path.basename(path)}.{os.getpid()}.tmp")
    try:
        write(temporary)
        # Data on the disk before the rename (a full disk may only show here).
        with open(temporary, "rb") as written:
            os.fsync(written.fileno())
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def write_mesh(mesh, path):
    """Write vtkPolyData to a VTK XML .vtp file atomically (temporary name, then rename).

    The directory is created if needed; readers never see a partial file.
    Raises ValueError for another suffix, OSError when the file cannot be written.
    """
    import os
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    path = os.fspath(path)
    if not path.lower().endswith(".vtp"):
        raise ValueError(f"{path}: write_mesh writes VTK XML PolyData (.vtp)")
    directory = os.path.dirname(path)
    if directory:
        os.makedirs(directory, exist_ok=True)

    def write(temporary):
        writer = vtkXMLPolyDataWriter()
        writer.SetInputData(mesh)
        writer.SetFileName(temporary)
        # Write() returns 1 even when the data did not fit on the disk; the
        # error code says so.
        if writer.Write() != 1 or writer.GetErrorCode() != 0:
            raise OSError(f"cannot write {path} (VTK error code {writer.GetErrorCode()})")

    _replace_atomically(path, write)


def write_time_series(source, times, directory, name="surface"):
    """Write a temporal source's output at each time as VTK XML files plus a ParaView collection.

    `source` is a vtkSurfaceSequenceInterpolator or any algorithm whose output
    port 0 produces vtkPolyData for vtkAlgorithm.UpdateTimeStep(t). Writes
    ``directory/name_XXXX.vtp`` (XXXX the time's index, at least four digits)
    for each of `times` and ``directory/name.pvd`` listing them with their
    times (open it in ParaView for an animation). Every file is written to a
    temporary name and renamed, so readers never see a partial file; the
    directory is created if needed.

    Returns the paths written: the .vtp files in the order of `times`, then the
    .pvd. Raises InputError when the source reports an error or produces an
    empty surface, OSError when a file cannot be written.
    """
    import os

    times = [float(t) for t in times]
    directory = os.fspath(directory)
    os.makedirs(directory, exist_ok=True)
    digits = max(4, len(str(max(len(times) - 1, 0))))
    messages, tag = _error_observer(source)
    paths = []
    try:
        for k, t in enumerate(times):
            source.UpdateTimeStep(t)
            output = source.GetOutputDataObject(0)
            if messages or output is None or output.GetNumberOfPoints() == 0:
                raise InputError("; ".join(messages) or f"no surface at time {t!r}")
            path = os.path.join(directory, f"{name}_{k:0{digits}d}.vtp")
            write_mesh(output, path)
            paths.append(path)
    finally:
        source.RemoveObserver(tag)

    return paths + [_write_pvd(os.path.join(directory, f"{name}.pvd"), times, paths)]


def _write_pvd(pvd, times, paths):
    """A ParaView collection `pvd` listing `paths` (relative to its directory) at `times`; returns `pvd`."""
    import os
    from xml.sax.saxutils import quoteattr

    base = os.path.dirname(pvd)
    lines = ['<?xml version="1.0"?>',
             '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
             "  <Collection>"]
    for t, path in zip(times, paths):
        lines.append(f'    <DataSet timestep="{t!r}" group="" part="0" '
                     f'file={quoteattr(os.path.relpath(path, base))}/>')
    lines += ["  </Collection>", "</VTKFile>", ""]

    def write_collection(temporary):
        with open(temporary, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))

    _replace_atomically(pvd, write_collection)
    return pvd


def write_collection(meshes, times, directory, name, subdirectory=None, stem=None):
    """Write vtkPolyData `meshes`, one per time of `times`, and a ParaView collection listing them.

    Writes ``directory/[subdirectory/]stem_XXXX.vtp`` (stem defaults to `name`;
    XXXX the index, at least four digits) and ``directory/name.pvd``, each
    atomically, as write_time_series does for a temporal source. Returns the
    paths written: the .vtp files, then the .pvd.
    """
    import os

    times = [float(t) for t in times]
    if len(times) != len(meshes):
        raise ValueError(f"{len(meshes)} meshes but {len(times)} times")
    directory = os.fspath(directory)
    folder = os.path.join(directory, subdirectory) if subdirectory else directory
    digits = max(4, len(str(max(len(times) - 1, 0))))
    paths = []
    for k, mesh in enumerate(meshes):
        paths.append(os.path.join(folder, f"{stem or name}_{k:0{digits}d}.vtp"))
        write_mesh(mesh, paths[-1])
    return paths + [_write_pvd(os.path.join(directory, f"{name}.pvd"), times, paths)]
