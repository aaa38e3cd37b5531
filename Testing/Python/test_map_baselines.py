"""Regression baselines of the surface map: its quality on bundled cases may not get worse.

Each case runs `surfacemap map` on Data/ meshes with a short schedule (seconds;
the default schedule is for the benchmarks), then `surfacemap evaluate DIR`, and
compares the figures of DESIGN.md section 6 with Testing/Baselines/surface_map.json.
A test fails when the certificate fails or a figure gets worse than its baseline
by more than its tolerance; improvements pass. To record them (or after an
intended change), regenerate on purpose and commit the JSON with the reason:

    SURFACEMAPS_REGENERATE_BASELINES=1 ctest --test-dir build -R baselines

Tolerances. On our machine the figures are identical with 1 and 2 threads; the
tolerances absorb other compilers, CPUs and library versions, whose rounding can
tip a remeshing decision of the short schedule:
- symmetric Dirichlet (SD), both maps: 2 % relative, as for the sphere
  embeddings (a broken distortion term or line search costs far more);
- area below distortion 1.5: 0.02 absolute;
- H and the two-sided distance, per input: 10 % relative: each is the largest
  of many distances, so one different edge split moves it more than the
  averages, while a broken approximation term or point location multiplies it;
- mean minimum angle of T on each input (mesh quality): 2 % relative;
- the certificate (T's embeddings, exact predicates, degree 1): must hold.
"""

import json
import os

import pytest

from cli import data, run

BASELINE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Baselines", "surface_map.json")
REGENERATE = os.environ.get("SURFACEMAPS_REGENERATE_BASELINES") == "1"

SD_TOLERANCE = 0.02  # relative
AREA_TOLERANCE = 0.02  # absolute (area fraction)
DISTANCE_TOLERANCE = 0.10  # relative (H, two-sided distance)
ANGLE_TOLERANCE = 0.02  # relative (mean minimum angle)
SLACK = 1e-9  # absolute, for figures that are 0 (the exact map's source side)

# name: (meshes, landmark files or None, schedule). ellipsoid.pinned and blob.vts
# both list the +x, -x, +y and +z extremes of their mesh, so ids 0..3 correspond.
CASES = {
    "ellipsoid_blob": (["ellipsoid.obj", "blob.off"], ["ellipsoid.pinned", "blob.vts"],
                       ["--landmark-iterations", "20", "--coarse-iterations", "10", "--fine-iterations", "10"]),
    # N = 1: a bijective remeshing; both maps are the identity, so it is about H and mesh quality.
    "spot_remeshing": (["spot.obj"], None, ["--coarse-iterations", "5", "--fine-iterations", "5"]),
}


def measure(name, directory):
    meshes, landmarks, schedule = CASES[name]
    args = ["map", *map(data, meshes)]
    if landmarks:
        args += ["--landmarks", *map(data, landmarks)]
    r = run(*args, *schedule, "--output-dir", directory)
    assert r.returncode == 0, f"{name}: map failed ({r.returncode}): {r.stderr}"
    r = run("evaluate", directory)
    assert r.returncode in (0, 3), f"{name}: evaluate failed ({r.returncode}): {r.stderr}"
    with open(os.path.join(directory, "summary.json")) as f:
        (m,) = json.load(f)["maps"]

    def figures(metrics):
        return {
            "symmetric_dirichlet": metrics["SymmetricDirichlet"],
            "area_below_1.5": metrics["AreaBelow1.5"],
            "max_distortion": metrics["MaxDistortion"],  # recorded, not checked: one triangle
            "hausdorff": [metrics["HausdorffSource"], metrics["HausdorffTarget"]],
            "two_sided_distance": [metrics["TwoSidedDistanceSource"], metrics["TwoSidedDistanceTarget"]],
            "mean_min_angle": [metrics["MeanMinAngleSource"], metrics["MeanMinAngleTarget"]],
        }

    with open(os.path.join(directory, "report.json")) as f:
        vertices = json.load(f)["common_triangulation"]["vertices"]
    return {
        "schedule": schedule,
        "bijective": m["certificate"]["bijective"],
        "common_vertices": vertices,  # recorded, not checked
        "approximating_map": figures(m["approximating_map"]),
        "exact_map": figures(m["exact_map"]),
    }


def regenerate(name, measured):
    baselines = {}
    if os.path.exists(BASELINE):
        with open(BASELINE) as f:
            baselines = json.load(f)
    baselines = {case: figures for case, figures in baselines.items() if case in CASES}
    baselines[name] = measured
    with open(BASELINE + ".tmp", "w") as f:
        json.dump(baselines, f, indent=2, sort_keys=True)
        f.write("\n")
    os.replace(BASELINE + ".tmp", BASELINE)


def worse_than(baseline, tolerance):
    """Largest value that still passes for a figure where smaller is better."""
    return baseline * (1 + tolerance) + SLACK


@pytest.mark.parametrize("name", sorted(CASES))
def test_surface_map_baseline(name, tmp_path):
    measured = measure(name, tmp_path / name)
    if REGENERATE:
        regenerate(name, measured)
        pytest.skip(f"baseline of {name} regenerated in {BASELINE}")
    with open(BASELINE) as f:
        baseline = json.load(f).get(name)
    assert baseline is not None, f"{name} has no baseline: regenerate the baselines"
    assert baseline["schedule"] == measured["schedule"], f"{name}: the schedule changed: regenerate the baselines"

    assert measured["bijective"], f"{name}: the map is not certified bijective"
    failures = []
    for kind in ("approximating_map", "exact_map"):
        m, b = measured[kind], baseline[kind]
        if m["symmetric_dirichlet"] > worse_than(b["symmetric_dirichlet"], SD_TOLERANCE):
            failures.append(f"{kind} SD {m['symmetric_dirichlet']:.4f} > baseline {b['symmetric_dirichlet']:.4f}")
        if m["area_below_1.5"] < b["area_below_1.5"] - AREA_TOLERANCE:
            failures.append(f"{kind} a1.5 {m['area_below_1.5']:.4f} < baseline {b['area_below_1.5']:.4f}")
        for figure in ("hausdorff", "two_sided_distance"):
            for side, (value, limit) in enumerate(zip(m[figure], b[figure])):
                if value > worse_than(limit, DISTANCE_TOLERANCE):
                    failures.append(f"{kind} {figure} ({['source', 'target'][side]}) {value:.4f}% > "
                                    f"baseline {limit:.4f}%")
        for side, (value, limit) in enumerate(zip(m["mean_min_angle"], b["mean_min_angle"])):
            if value < limit * (1 - ANGLE_TOLERANCE):
                failures.append(f"{kind} mean min angle ({['source', 'target'][side]}) {value:.2f} < "
                                f"baseline {limit:.2f}")
    assert not failures, f"{name} got worse than its baseline:\n  " + "\n  ".join(failures)
