"""Regression baselines: the quality of every bundled case may not get worse.

Each case's summary metrics are stored in Testing/Baselines/*.json. A test
fails when a certificate fails, or when a metric gets worse than its baseline
by more than the stated tolerance. Improvements pass; to record them (or
after an intended change), regenerate the baselines on purpose:

    SURFACEMAPS_REGENERATE_BASELINES=1 ctest --test-dir build -R baselines

and commit the changed JSON files with the reason in the message.
"""

import json
import os

import pytest

import surfacemaps
from vtkmodules.vtkCommonDataModel import vtkPolyData

from cli import data

BASELINES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Baselines")
REGENERATE = os.environ.get("SURFACEMAPS_REGENERATE_BASELINES") == "1"
# Allowed relative worsening of the distortion (optimisation order and
# rounding may differ a little between machines; a real regression is larger).
TOLERANCE = 0.02

EMBEDDING_CASES = ["ellipsoid.obj", "ellipsoid_coarse.stl", "blob.off", "blob.vtp", "limbs.ply",
                   "limbs_coarse.vtk", "spot.obj"]


def embedding_metrics(name):
    mesh = surfacemaps.read_mesh(data(name))
    embedded = surfacemaps.embed_on_sphere(mesh)
    on_sphere = vtkPolyData()
    on_sphere.DeepCopy(embedded)
    on_sphere.GetPoints().SetData(embedded.GetPointData().GetArray("SpherePosition"))
    m = surfacemaps.evaluate_map(embedded, on_sphere)
    return {
        "bijective": m["Bijective"] == 1.0,
        "symmetric_dirichlet": m["SymmetricDirichlet"],
        "max_distortion": m["MaxDistortion"],
        "area_below_1.5": m["AreaBelow1.5"],
    }


def test_sphere_embedding_baselines():
    path = os.path.join(BASELINES, "sphere_embedding.json")
    measured = {name: embedding_metrics(name) for name in EMBEDDING_CASES}
    if REGENERATE:
        with open(path + ".tmp", "w") as f:
            json.dump(measured, f, indent=2, sort_keys=True)
            f.write("\n")
        os.replace(path + ".tmp", path)
        pytest.skip(f"baselines regenerated in {path}")
    with open(path) as f:
        baseline = json.load(f)
    assert set(baseline) == set(EMBEDDING_CASES), "regenerate the baselines: the cases changed"
    for name, m in measured.items():
        b = baseline[name]
        assert m["bijective"], f"{name}: embedding not certified"
        assert m["symmetric_dirichlet"] <= b["symmetric_dirichlet"] * (1 + TOLERANCE), \
            f"{name}: distortion {m['symmetric_dirichlet']:.4f} worse than baseline {b['symmetric_dirichlet']:.4f}"
        assert m["area_below_1.5"] >= b["area_below_1.5"] - TOLERANCE, \
            f"{name}: area below 1.5 {m['area_below_1.5']:.4f} under baseline {b['area_below_1.5']:.4f}"
