"""Files: every file written atomically (a temporary name, then a rename), meshes and ParaView
collections written that way, and a map directory's files checked against its report.json."""

import hashlib
import json
import os
import re
from xml.sax.saxutils import quoteattr

from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from .errors import InputError, _error_observer
from .mesh import read_mesh


def replace_atomically(path, write):
    """Call write(temporary_path) for a temporary file next to `path`, then rename it to `path`."""
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

    replace_atomically(path, write)


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

    replace_atomically(pvd, write_collection)
    return pvd


def write_collection(meshes, times, directory, name, subdirectory=None, stem=None):
    """Write vtkPolyData `meshes`, one per time of `times`, and a ParaView collection listing them.

    Writes ``directory/[subdirectory/]stem_XXXX.vtp`` (stem defaults to `name`;
    XXXX the index, at least four digits) and ``directory/name.pvd``, each
    atomically, as write_time_series does for a temporal source. Returns the
    paths written: the .vtp files, then the .pvd.
    """
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


_MAP_FILE = re.compile(r"(common|mapped|embedding)_[0-9]+\.vtp")


def _verify_map_files(map_dir, names):
    """Raises InputError naming the first of the files `names` of a map directory that its
    report.json does not vouch for: missing, from another map, another file of this map
    (swapped, renamed) or changed (size or MD5 differ), as `surfacemap transfer` does."""
    report_path = os.path.join(map_dir, "report.json")
    try:
        with open(report_path) as f:
            report = json.load(f)
    except FileNotFoundError:
        if any(_MAP_FILE.fullmatch(name) for name in os.listdir(map_dir)):
            raise InputError(f"{map_dir} holds an interrupted run (common_/mapped_/embedding_ files, "
                             "no report.json): give --overwrite or remove it") from None
        raise InputError(f"{report_path} is missing: the directory holds no map (written by "
                         "'surfacemap map')") from None
    except ValueError:
        raise InputError(f"{report_path} is not valid JSON") from None
    if not isinstance(report.get("map_id"), str) or not isinstance(report.get("files"), list):
        raise InputError(f"{report_path} has no map id and file checksums (\"map_id\", \"files\"): "
                         "written by an older surfacemap; run 'surfacemap map' again")
    records = {r.get("name"): r for r in report["files"] if isinstance(r, dict)}
    # Each common_<j> with its embedding_<j>: an edited report.json can vouch for any bytes, the
    # geometry between the two it cannot.
    commons = [int(m.group(1)) for m in map(_COMMON_FILE.fullmatch, names) if m]
    names = list(names) + [f"embedding_{j}.vtp" for j in commons if f"embedding_{j}.vtp" not in names]
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
    _check_map_geometry(map_dir, commons)


# As Applications/MapConsistency.h: the largest distance on the unit sphere between T's vertex on
# sphere j (common_<j>'s SpherePosition) and input j's embedding at the vertex's source point.
_MAP_SPHERE_TOLERANCE = 1e-6
_COMMON_FILE = re.compile(r"common_([0-9]+)\.vtp")


def _point_text(p):
    return "(" + ", ".join(f"{x:.4g}" for x in p) + ")"


def _triangles(mesh):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    polys = mesh.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    if len(offsets) > 1 and not (offsets[1:] - offsets[:-1] == 3).all():
        return None
    return vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3)


def _point_array(mesh, path, name, components):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    array = mesh.GetPointData().GetArray(name)
    if (array is None or array.GetNumberOfComponents() != components
            or array.GetNumberOfTuples() != mesh.GetNumberOfPoints()):
        raise InputError(f"{path} has no {name} point array of {components} value"
                         f"{'' if components == 1 else 's'} per point: not a file 'surfacemap map' wrote")
    return vtk_to_numpy(array).reshape(-1, components).astype(float)


def _check_map_geometry(map_dir, inputs):
    """Raises InputError unless the files common_<j>.vtp of `inputs` hold one triangulation and
    each agrees with its embedding_<j>.vtp: the embedding at T's vertex's source point
    (SourceCellId, SourceBarycentric), normalised, is the vertex's SpherePosition, as the map
    located it (the same check as `surfacemap evaluate`, `transfer` and `statistics`)."""
    import numpy
    first = None
    for j in inputs:
        common_path = os.path.join(map_dir, f"common_{j}.vtp")
        embedding_path = os.path.join(map_dir, f"embedding_{j}.vtp")
        common, embedding = read_mesh(common_path), read_mesh(embedding_path)
        triangles = _triangles(common)
        if first is None:
            first = (common_path, common.GetNumberOfPoints(), triangles)
        elif common.GetNumberOfPoints() != first[1]:
            raise InputError(f"{common_path} and {first[0]} do not hold the same common triangulation "
                             f"({common.GetNumberOfPoints()} vs {first[1]} points)")
        elif triangles is None or first[2] is None or not numpy.array_equal(triangles, first[2]):
            raise InputError(f"{common_path} and {first[0]} do not hold the same common triangulation "
                             "(their triangles differ)")
        g = _point_array(common, common_path, "SpherePosition", 3)
        cells = _point_array(common, common_path, "SourceCellId", 1)[:, 0]
        barycentric = _point_array(common, common_path, "SourceBarycentric", 3)
        f = _point_array(embedding, embedding_path, "SpherePosition", 3)
        corners = _triangles(embedding)
        if corners is None or (len(corners) and not (0 <= corners.min() and corners.max() < len(f))):
            raise InputError(f"{embedding_path} holds cells that are no triangles of its points: not a file "
                             "'surfacemap map' wrote")
        outside = numpy.flatnonzero(~((cells >= 0) & (cells < len(corners))))
        if len(outside):
            v = outside[0]
            raise InputError(f"{common_path} places T's vertex {v} on triangle {cells[v]:g}, which "
                             f"{embedding_path} does not have ({len(corners)} cells): the files are not one map")
        q = numpy.einsum("vk,vkc->vc", barycentric, f[corners[cells.astype(int)]])
        q /= numpy.maximum(numpy.linalg.norm(q, axis=1), 1e-300)[:, None]
        distance = numpy.linalg.norm(q - g, axis=1)
        wrong = numpy.flatnonzero(~(distance <= _MAP_SPHERE_TOLERANCE))
        if len(wrong):
            v = wrong[0]
            raise InputError(f"{embedding_path} and {common_path} are not one map: at {len(wrong)} of T's "
                             f"{len(g)} vertices the embedding of input {j} does not send the vertex's source "
                             f"point to its sphere position (vertex {v}: {_point_text(g[v])} in the common "
                             f"file, {_point_text(q[v])} by the embedding, {distance[v]:.3g} apart): a file "
                             "was edited, rotated or swapped after the map was written")
