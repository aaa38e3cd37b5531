"""Carrying point data through a map (vtkSurfaceMapTransfer): from a saved map directory or a map in
memory, with the source's own arrays or new ones (source_data)."""

import os

from vtkmodules.vtkCommonDataModel import vtkPolyData

from .SurfaceMapsFilters import vtkSurfaceMapFilter, vtkSurfaceMapTransfer
from .errors import InputError, MapError, _collect_errors, _error_observer, _update
from .files import _verify_map_files
from .mesh import _set_array_transfer_modes, _shallow_copy, point_arrays, read_mesh


def transfer(mapping, source, target, arrays=None, categorical=None, continuous=None, source_data=None,
             as_numpy=False):
    """Carry the point data of input `source` of a map onto the vertices of input `target`.

    `mapping` is the map, saved or in memory:

    - a directory written by ``surfacemap map`` (its embedding_<i>.vtp and
      common_<i>.vtp of both inputs are read and checked against its
      report.json: from another map, swapped or changed files are refused, as
      ``surfacemap transfer`` does, and so is an embedding that does not agree
      with its common file, e.g. rotated, even when report.json vouches for it);
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

    Raises InputError for missing or unvouched map files, a MapResult whose
    inputs were changed in place after it was computed, input indices the
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


def _map_ports(mapping, source, target):
    """The four inputs of vtkSurfaceMapTransfer (target and source with their embeddings, T lifted
    onto target and source) of a map directory or an in-memory map, and the source's name for
    messages."""
    algorithm = getattr(mapping, "filter", mapping)
    changed = mapping.changed_inputs() if hasattr(mapping, "changed_inputs") else []
    if changed:
        raise InputError(f"input{'s' if len(changed) > 1 else ''} {', '.join(map(str, changed))} of the map changed "
                         "after map_surfaces returned this result: the filter would compute another map than the "
                         "result holds; call map_surfaces again (or transfer through result.filter to accept that)")
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
