"""Running a map: map_surfaces (vtkSurfaceMapFilter) and what it returns, the settings table and
presets it takes, a single sphere embedding, and the metrics of a map (vtkSurfaceMapEvaluation).
The settings and their documentation come from the engine's list (vtkSurfaceMapsSettings)."""

import math
import os
import textwrap

from vtkmodules.vtkCommonDataModel import vtkPolyData

from .SurfaceMapsFilters import (vtkSphereEmbeddingFilter, vtkSurfaceMapEvaluation, vtkSurfaceMapFilter,
                                 vtkSurfaceMapsSettings)
from .errors import InputError, MapError, _collect_errors, _update
from .existing import existing_map
from .mesh import _set_array_transfer_modes, _with_landmarks


_SUMMARY = ("SymmetricDirichlet", "AreaBelow1.5", "AreaBelow2", "MaxDistortion", "DegenerateTriangles",
            "MinAngleSource", "MeanMinAngleSource", "MinAngleTarget", "MeanMinAngleTarget", "HausdorffSource",
            "HausdorffTarget", "TwoSidedDistanceSource", "TwoSidedDistanceTarget", "Bijective",
            "NonPositiveTriangles")


def embed_on_sphere(mesh, **settings):
    """Certified bijective embedding of `mesh` (vtkPolyData) on the unit sphere.

    Settings are vtkSphereEmbeddingFilter's, by name: ``OutputPointsOnSphere=True``
    and those listed below (``settings_table("sphere_embedding")``). Returns
    the output vtkPolyData (point array "SpherePosition"); raises InputError
    with the filter's message when the input is invalid or no embedding is
    certified.
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


_S = vtkSurfaceMapsSettings
_TABLES = {"map": _S.MAP_SETTINGS, "sphere_embedding": _S.SPHERE_EMBEDDING_SETTINGS}


def _flag_setting(flag):
    """The index of the map setting whose command-line flag is `flag`."""
    return _S.FindFlag(_S.MAP_SETTINGS, "--" + flag)


_PAIRS = _flag_setting("pairs")
_PAIR_MODES = {name: k for k, name in enumerate(_S.GetChoices(_S.MAP_SETTINGS, _PAIRS).split("|"))}


def settings_table(of="map"):
    """The settings of the surface map (``of="map"``, vtkSurfaceMapFilter) or
    of the sphere embedding (``of="sphere_embedding"``,
    vtkSphereEmbeddingFilter), one dict per setting, from the engine's one list
    (vtkSurfaceMapsSettings): name (the filter's Set<name>/Get<name>), flag
    (``surfacemap map --<flag>``, ``surfacemap embed --<flag>``), type ("real",
    "count", "switch", "choice"), minimum, maximum, default, choices (for
    "choice"), doc, topic, and description (the doc with the default and the
    range, as every help text shows it)."""
    t = _TABLES[of]
    types = {_S.REAL: "real", _S.COUNT: "count", _S.SWITCH: "switch", _S.CHOICE: "choice"}
    rows = []
    for i in range(_S.GetNumberOfSettings(t)):
        choices = _S.GetChoices(t, i)
        rows.append({"name": _S.GetName(t, i), "flag": _S.GetFlag(t, i), "type": types[_S.GetType(t, i)],
                     "minimum": _S.GetMinimum(t, i), "maximum": _S.GetMaximum(t, i),
                     "default": _S.GetDefault(t, i), "choices": choices.split("|") if choices else None,
                     "doc": _S.GetDocumentation(t, i), "topic": _S.GetTopic(t, i),
                     "description": _S.GetDescription(t, i)})
    return rows


def _settings_doc(of):
    """The settings of `of` for a docstring: each setting's name and description, by topic."""
    text, topic = "", None
    for row in settings_table(of):
        if row["topic"] != topic:
            topic = row["topic"]
            text += f"\n    {topic}:\n"
        text += textwrap.fill(f"``{row['name']}``: {row['description']}", width=100,
                              initial_indent="    - ", subsequent_indent="      ",
                              break_on_hyphens=False, break_long_words=False) + "\n"
    return text


def presets():
    """The names of the surface map's presets with their documentation (what
    each is for and the settings it sets), from vtkSurfaceMapFilter."""
    f = vtkSurfaceMapFilter
    return {f.GetPresetName(p): f.GetPresetDocumentation(p) for p in range(f.GetNumberOfPresets())}


def map_surfaces(meshes, landmarks=None, target_error=None, pairs=None, keep_landmarks=None, mapped=False,
                 categorical=None, continuous=None, preset=None, add_to=None, **settings):
    """Certified bijective map between closed genus-0 meshes through one common triangulation.

    Runs vtkSurfaceMapFilter on `meshes` (vtkPolyData or file names; one mesh
    gives a bijective remeshing).

    - `landmarks`: None, or one entry per mesh: a landmark file (when the mesh
      is a file name) or a sequence of vertex indices, the k-th entry being
      landmark id k; the same id on two meshes marks corresponding points.
      Meshes may also carry a "Landmarks" point array already.
    - `target_error`: approximation error of the fine phase in unit-area units
      (each mesh centred and scaled to unit area); smaller gives a finer T.
    - `pairs`: "star" (0-i), "sequence", "cycle", "all" or "mean" (each mesh
      against the meshes' mean shape): whose distortion is minimised with
      three or more meshes; with "all" and "mean" the map does not depend on
      the order of the meshes.
    - `keep_landmarks`: lock landmarks exactly after the landmark phase (True)
      or release them.
    - `categorical`, `continuous`: names of point arrays carried onto the
      outputs as labels (the nearest corner's value) or interpolated, instead
      of by type (integer arrays categorical, floating-point ones continuous).
    - `preset`: None, "pair" or "population" (``presets()`` documents them):
      sets a group of settings for a kind of study first; every other
      argument overrides it. "population" is for many specimens in one map
      (statistics over the common triangulation).
    - `add_to`: None, or a map to add `meshes` to without mapping its inputs
      again (``surfacemap map --add-to``): what map_surfaces returned, or a
      map directory (its files checked against its report.json). Its inputs'
      embeddings and maps are kept and T is refined by edge splits only where
      a new mesh needs it; its settings apply unless given here (refinement
      rounds and error bound must be 0, as in the "population" preset). The
      result holds every input, the map's first.
    - `settings`: any other setting of vtkSurfaceMapFilter by name: the
      settings listed below (``settings_table()``), ``SizingMode`` and
      ``NumberOfThreads``.
    A setting left at None keeps the filter's default (the list's).

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
    existing = None if add_to is None else existing_map(add_to)
    f = vtkSurfaceMapFilter()
    errors = _collect_errors(f)
    if existing is not None:
        existing.apply_settings(f)  # the arguments below override them
    if preset is not None:
        names = [f.GetPresetName(p) for p in range(f.GetNumberOfPresets())]
        if preset not in names:
            raise ValueError(f"preset is one of {names}, not {preset!r}")
        f.ApplyPreset(names.index(preset))
    if pairs is not None:
        f.SetSetting(_PAIRS, _PAIR_MODES[pairs])
    if keep_landmarks is not None:
        f.SetSetting(_flag_setting("keep-landmarks"), bool(keep_landmarks))
    _set_array_transfer_modes(f, categorical, continuous)
    table = {row["name"]: row for row in settings_table()}
    known = set(table) | {"SizingMode", "NumberOfThreads"}
    if target_error is not None:
        target = _S.GetName(_S.MAP_SETTINGS, _flag_setting("target-error"))
        settings = dict(settings, **{target: target_error})
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
    if existing is not None:
        for k, mesh in enumerate(existing.embeddings):
            f.AddInputData(mesh)
            f.AddInputData(1, existing.common[k])
    for k, mesh in enumerate(meshes):
        f.AddInputData(_with_landmarks(mesh, None if landmarks is None else landmarks[k]))

    def outputs():
        _update(f, errors)
        if errors or f.GetOutput(0).GetNumberOfPoints() == 0:
            message = "; ".join(errors) or "the map was aborted"
            raise (InputError if f.GetErrorCode() == vtkSurfaceMapFilter.InvalidInputError else MapError)(message)
        result = []
        for i in range(f.GetNumberOfOutputPorts()):
            copy = f.GetOutput(i).NewInstance()
            copy.ShallowCopy(f.GetOutput(i))
            result.append(copy)
        return result

    common = MapResult(outputs(), f)
    if not mapped:
        return common
    f.SetOutputModeToMappedFirstInput()
    return common, MapResult(outputs(), f)


class MapResult(list):
    """What map_surfaces returns: a list of vtkPolyData, one output per mesh, that also holds the map.

    ``filter`` is the updated vtkSurfaceMapFilter, so that ``transfer(result,
    source, target, ...)`` carries data between the meshes in memory; it keeps
    the map (a few times the size of the outputs) alive while the list lives.
    An input changed in place afterwards (its points or arrays modified) would
    make the filter compute another map than this result holds: transfer then
    raises InputError instead (``changed_inputs()`` names them).
    """

    def __init__(self, outputs, algorithm):
        super().__init__(outputs)
        self.filter = algorithm
        self._input_times = self._input_mtimes()

    def _input_mtimes(self):
        f = self.filter
        return [f.GetInputDataObject(0, k).GetMTime() for k in range(f.GetNumberOfInputConnections(0))]

    def changed_inputs(self):
        """The indices of the inputs modified since this result was computed (empty if none)."""
        now = self._input_mtimes()
        if len(now) != len(self._input_times):
            return list(range(max(len(now), len(self._input_times))))
        return [k for k, (then, t) in enumerate(zip(self._input_times, now)) if t != then]


map_surfaces.__doc__ += "\n    Settings of the map (the engine's list):\n" + _settings_doc("map")
embed_on_sphere.__doc__ += ("\n    Settings of the sphere embedding (the engine's list):\n"
                            + _settings_doc("sphere_embedding"))
