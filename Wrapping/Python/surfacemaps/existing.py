"""The map that map_surfaces(..., add_to=...) adds meshes to: one in memory (what map_surfaces
returned) or a map directory (``surfacemap map``'s, every file checked against its report.json),
as the inputs of vtkSurfaceMapFilter's port 1 and the embeddings its first inputs carry."""

import json
import os

from vtkmodules.vtkCommonCore import vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkFieldData

from .SurfaceMapsFilters import vtkSurfaceMapFilter, vtkSurfaceMapsSettings
from .errors import InputError, MapError, _collect_errors, _update
from .files import _verify_map_files
from .mesh import _shallow_copy, read_mesh

_S = vtkSurfaceMapsSettings


class ExistingMap:
    """`common[j]`: T lifted onto input j (with "SpherePosition" g_j and "Landmarks");
    `embeddings[j]`: input j with the embedding the map used ("SpherePosition");
    `apply_settings(f)` sets the map's settings on a vtkSurfaceMapFilter."""

    def __init__(self, common, embeddings, settings):
        self.common, self.embeddings, self._settings = common, embeddings, settings

    def apply_settings(self, f):
        for k, value in self._settings.items():
            f.SetSetting(k, value)


def existing_map(add_to):
    """An ExistingMap from a MapResult (map_surfaces' outputs) or a map directory; raises InputError."""
    if isinstance(add_to, (str, os.PathLike)):
        return _from_directory(os.fspath(add_to))
    f = getattr(add_to, "filter", None)
    if not isinstance(f, vtkSurfaceMapFilter):
        raise TypeError("add_to is what map_surfaces returned (a MapResult) or a map directory, "
                        f"not {type(add_to).__name__}")
    if add_to.changed_inputs():
        raise InputError(f"the inputs {add_to.changed_inputs()} of the map to add to were changed after "
                         "it was computed")
    mode = f.GetOutputMode()
    try:
        f.SetOutputModeToCommonTriangulation()
        common = _outputs(f)
        f.SetOutputModeToInputEmbeddings()
        embeddings = [_only_file_name(mesh) for mesh in _outputs(f)]
    finally:
        f.SetOutputMode(mode)
    settings = {k: f.GetSetting(k) for k in range(_S.GetNumberOfSettings(_S.MAP_SETTINGS))}
    return ExistingMap(common, embeddings, settings)


def _outputs(f):
    errors = _collect_errors(f)
    _update(f, errors)
    if errors or f.GetOutput(0).GetNumberOfPoints() == 0:
        raise MapError("the map to add to has no outputs: " + ("; ".join(errors) or "empty"))
    return [_shallow_copy(f.GetOutput(i)) for i in range(f.GetNumberOfOutputPorts())]


def _only_file_name(mesh):
    """The mesh with its own field data only ("FileName"): the figures of the existing map do not
    belong to the new one."""
    fields = vtkFieldData()
    name = mesh.GetFieldData().GetAbstractArray("FileName")
    if isinstance(name, vtkStringArray):
        fields.AddArray(name)
    mesh.SetFieldData(fields)
    return mesh


def _setting_text(value):
    if isinstance(value, bool):
        return "1" if value else "0"
    return value if isinstance(value, str) else repr(value)


def _from_directory(map_dir):
    report_path = os.path.join(map_dir, "report.json")
    if not os.path.isdir(map_dir):
        raise InputError(f"{map_dir} is no directory (the map to add to)")
    try:
        with open(report_path) as f:
            report = json.load(f)
    except (OSError, ValueError):
        report = {}
    m = len(report.get("inputs") or [])
    _verify_map_files(map_dir, [f"{stem}_{j}.vtp" for j in range(m) for stem in ("common", "embedding")])
    if m == 0:
        raise InputError(f"{report_path} lists no inputs")
    settings = {}
    given = report.get("settings") or {}
    for k in range(_S.GetNumberOfSettings(_S.MAP_SETTINGS)):
        key = _S.GetJsonKey(_S.MAP_SETTINGS, k)
        if key in given:
            value = _S.Parse(_S.MAP_SETTINGS, k, _setting_text(given[key]))
            if value != value:  # NaN: no value of that setting
                raise InputError(f"{report_path}: settings.{key} is {given[key]!r}, no value of that setting")
            settings[k] = value
    common = [read_mesh(os.path.join(map_dir, f"common_{j}.vtp")) for j in range(m)]
    embeddings = [_only_file_name(read_mesh(os.path.join(map_dir, f"embedding_{j}.vtp"))) for j in range(m)]
    return ExistingMap(common, embeddings, settings)
