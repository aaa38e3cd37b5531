"""Every specimen of a population on its own: its name, how well the common triangulation fits it
(the fit table, fit.csv) and where T's vertices lie on it (correspondences.npz), in the form
``surfacemap map`` writes them for its inputs, so that a user can check each specimen's fit and
take the correspondences to numpy or R.

    import numpy as np
    with np.load("OUT/correspondences.npz") as c:
        points, triangles, names = c["points"], c["triangles"], c["names"]  # N x V x 3, F x 3, N
"""

import csv
import io
import os

import numpy as np

from .files import replace_atomically, write_mesh
from .mapping import evaluate_map
from .synthetic import polydata

#: The fit table's columns: distances in percent of the specimen's bounding-box diagonal, the
#: symmetric Dirichlet energies (SD, 1 for an isometry) and distortions of the maps from the
#: first specimen of its map (empty for that specimen itself).
FIT_COLUMNS = ("input", "name", "file", "hausdorff", "two_sided_distance", "approximating_sd", "exact_sd",
               "exact_max_distortion", "exact_area_below_1.5", "landmark_error")


def unique_names(names):
    """`names` with "_<i>" appended to each one that occurs more than once (i: its place)."""
    return [f"{s}_{i}" if names.count(s) > 1 else s for i, s in enumerate(names)]


def specimen_names(files, groups=None):
    """A name per file: its stem; where two stems coincide, "<group>_<stem>" when `groups` (one
    name per file, e.g. its stage) tells them apart, then "_<i>" appended as unique_names does."""
    stems = [os.path.splitext(os.path.basename(os.fspath(f)))[0] for f in files]
    if groups is not None and len(set(stems)) < len(stems):
        stems = [f"{g}_{s}" for g, s in zip(groups, stems)]
    return unique_names(stems)


def map_fit(meshes, common, mapped):
    """Per mesh i the figures of the map from mesh 0 to mesh i: "approximating_sd" (common[0] ->
    common[i]), "exact_sd", "exact_max_distortion" and "exact_area_below_1.5" (mesh 0 -> mapped[i],
    map_surfaces(..., mapped=True)); None for mesh 0, every map's source."""
    rows = [dict.fromkeys(("approximating_sd", "exact_sd", "exact_max_distortion", "exact_area_below_1.5"))]
    for i in range(1, len(meshes)):
        approximating = evaluate_map(common[0], common[i])
        exact = evaluate_map(meshes[0], mapped[i])
        rows.append({"approximating_sd": approximating["SymmetricDirichlet"],
                     "exact_sd": exact["SymmetricDirichlet"], "exact_max_distortion": exact["MaxDistortion"],
                     "exact_area_below_1.5": exact["AreaBelow1.5"]})
    return rows


def surface_fit(mesh, approximation):
    """How well `approximation` (a vtkPolyData: T on the specimen) fits the specimen `mesh`:
    "hausdorff" (the specimen's vertices to it) and "two_sided_distance" in percent of the
    specimen's bounding-box diagonal, and "landmark_error": the largest distance between a
    landmark's vertex on it and on the specimen (both "Landmarks" point arrays), same unit, None
    when either has no landmarks."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    figures = evaluate_map(approximation, approximation, None, mesh)
    fit = {"hausdorff": figures["HausdorffTarget"], "two_sided_distance": figures["TwoSidedDistanceTarget"],
           "landmark_error": None}
    ids = [mesh.GetPointData().GetArray("Landmarks"), approximation.GetPointData().GetArray("Landmarks")]
    if ids[0] is None or ids[1] is None:
        return fit
    on_mesh, on_t = (dict((int(k), v) for v, k in enumerate(vtk_to_numpy(a)) if k >= 0) for a in ids)
    common_ids = sorted(set(on_mesh) & set(on_t))
    if common_ids:
        a = vtk_to_numpy(mesh.GetPoints().GetData())[[on_mesh[k] for k in common_ids]]
        b = vtk_to_numpy(approximation.GetPoints().GetData())[[on_t[k] for k in common_ids]]
        fit["landmark_error"] = float(100.0 * np.linalg.norm(a - b, axis=1).max() / mesh.GetLength())
    return fit


def fit_csv(rows):
    """The fit table (rows: dicts with FIT_COLUMNS) as CSV text; empty fields for None."""
    text = io.StringIO()
    w = csv.writer(text, lineterminator="\n")
    w.writerow(FIT_COLUMNS)
    for row in rows:
        w.writerow(["" if row.get(c) is None else repr(float(row[c])) if isinstance(row[c], float) else row[c]
                    for c in FIT_COLUMNS])
    return text.getvalue()


def write_correspondences(path, names, points, triangles):
    """correspondences.npz at `path` (atomically): "points" (N x V x 3 float64: T's vertex v on
    specimen i), "triangles" (F x 3 int64), "names" (N strings); numpy.load reads it without
    allow_pickle."""
    points = np.asarray(points, dtype=np.float64)
    if points.ndim != 3 or points.shape[0] != len(names) or points.shape[2] != 3:
        raise ValueError(f"points of shape {points.shape} for {len(names)} names (N x V x 3)")

    def write(temporary):
        with open(temporary, "wb") as f:  # a file object: savez would append .npz to a name
            np.savez(f, points=points, triangles=np.asarray(triangles, dtype=np.int64),
                     names=np.asarray(names, dtype=str))
    replace_atomically(os.fspath(path), write)


def write_specimens(out, files, names, meshes, map_fits, lifted, common):
    """A population's specimens on its common triangulation, into the directory `out`:
    specimens/<name>.vtp (with T's landmarks), correspondences.npz and fit.csv; returns the fit
    table's rows. `files`, `names`: the specimens' files and names (specimen_names); `meshes`: the specimens as
    dicts of numpy arrays "points", "triangles", "landmarks" (None without); `map_fits`: map_fit's
    rows of the maps they were mapped with; `lifted`: T's vertices on each specimen (N x V x 3);
    `common`: T's "triangles" and "landmarks" (None without)."""
    rows = []
    for i, (name, points, mesh, fit) in enumerate(zip(names, lifted, meshes, map_fits)):
        on_t = polydata(points, common["triangles"], landmarks=common["landmarks"])
        write_mesh(on_t, os.path.join(out, "specimens", name + ".vtp"))
        specimen = polydata(mesh["points"], mesh["triangles"], landmarks=mesh["landmarks"])
        rows.append(dict(input=i, name=name, file=os.fspath(files[i]), **surface_fit(specimen, on_t), **fit))
    write_correspondences(os.path.join(out, "correspondences.npz"), names, lifted, common["triangles"])

    def write(temporary):
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(fit_csv(rows))
    replace_atomically(os.path.join(out, "fit.csv"), write)
    return rows
