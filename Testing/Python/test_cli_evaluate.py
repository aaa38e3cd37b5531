"""`surfacemap evaluate`: summary, files, connectivity mismatch; map output directories."""

import csv
import json
import shutil

import pytest

from cli import SHORT, data, locate_on_sphere, read_vtp, refresh_report, run


def test_evaluate_writes_summary_and_tables(tmp_path):
    r = run("evaluate", data("ellipsoid.obj"), data("blob.off"), "--originals", data("ellipsoid.obj"),
            data("blob.off"), "--output-dir", str(tmp_path))
    assert r.returncode == 0, r.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["triangles"] == 1280
    assert summary["SymmetricDirichlet"] > 1.0
    assert 0.0 < summary["AreaBelow1.5"] <= 1.0
    assert summary["HausdorffSource"] == 0.0 and summary["HausdorffTarget"] == 0.0
    rows = list(csv.DictReader(open(tmp_path / "triangles.csv")))
    assert len(rows) == 1280 and float(rows[0]["s1"]) >= float(rows[0]["s2"])
    curve = list(csv.DictReader(open(tmp_path / "distortion_curve.csv")))
    assert len(curve) == 201 and float(curve[-1]["area_fraction_below"]) <= 1.0
    assert f"SymmetricDirichlet     {summary['SymmetricDirichlet']:.10g}"[:30] in r.stdout


def test_evaluate_creates_a_new_output_dir(tmp_path):
    out = tmp_path / "new" / "nested"  # neither exists
    r = run("evaluate", data("ellipsoid.obj"), data("blob.off"), "--output-dir", out)
    assert r.returncode == 0, r.stderr
    assert sorted(p.name for p in out.iterdir()) == [
        "distortion_curve.csv", "evaluated.vtp", "summary.json", "triangles.csv"]
    assert json.loads((out / "summary.json").read_text())["triangles"] == 1280


def test_output_dir_is_checked_before_computing(tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    r = run("evaluate", data("ellipsoid.obj"), data("blob.off"), "--output-dir", blocker / "out")
    assert r.returncode == 2
    assert "cannot create the output directory" in r.stderr
    assert "SymmetricDirichlet" not in r.stdout  # nothing was computed
    # A failed evaluation leaves no directory behind that it created.
    r = run("evaluate", data("ellipsoid.obj"), data("limbs.ply"), "--output-dir", tmp_path / "made")
    assert r.returncode == 2 and "do not have the same connectivity" in r.stderr
    assert not (tmp_path / "made").exists()


def test_mismatched_connectivity_is_bad_input():
    r = run("evaluate", data("ellipsoid.obj"), data("limbs.ply"))
    assert r.returncode == 2
    assert "do not have the same connectivity (642 vs 2562 points)" in r.stderr


def test_usage():
    assert run("evaluate", data("ellipsoid.obj")).returncode == 2
    r = run("evaluate", "--help")
    assert r.returncode == 0 and "--originals" in r.stdout


# The directory form: every map of a `surfacemap map` output directory.
@pytest.fixture(scope="module")
def map_dir(tmp_path_factory):
    """A map of ellipsoid <-> blob with a short schedule (about a second)."""
    out = tmp_path_factory.mktemp("map")
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *SHORT, "--output-dir", out)
    assert r.returncode == 0, r.stderr
    return out


def test_evaluate_map_directory(map_dir, tmp_path):
    out = tmp_path / "evaluation"  # created
    r = run("evaluate", map_dir, "--output-dir", out)
    assert r.returncode == 0, r.stderr
    assert "certificate 0 -> 1: bijective" in r.stdout
    report = json.loads((map_dir / "report.json").read_text())
    summary = json.loads((out / "summary.json").read_text())
    assert summary["inputs"] == [i["file"] for i in report["inputs"]]
    t = report["common_triangulation"]
    assert summary["common_triangulation"] == {"vertices": t["vertices"], "triangles": t["triangles"]}
    assert len(summary["maps"]) == 1
    m = summary["maps"][0]
    assert (m["source"], m["target"]) == (0, 1)
    assert m["certificate"] == {"bijective": True, "non_positive_triangles": 0}
    approximating, exact = m["approximating_map"], m["exact_map"]
    assert approximating["triangles"] == t["triangles"] and exact["triangles"] == 1280
    # The same figures `surfacemap map` reported for its own outputs.
    for mine, theirs in ((approximating, report["approximating_map"][0]), (exact, report["exact_map"][0])):
        for name, value in theirs.items():
            if name not in ("source", "target"):
                assert mine[name] == pytest.approx(value, rel=1e-8), name
    assert exact["HausdorffSource"] == pytest.approx(0.0, abs=1e-9)  # input 0 itself
    assert exact["TwoSidedDistanceSource"] == pytest.approx(0.0, abs=1e-9)
    for metrics in (approximating, exact):
        assert metrics["SymmetricDirichlet"] > 1.0
        assert 0.0 < metrics["AreaBelow1.5"] <= metrics["AreaBelow2"] <= 1.0
        assert 0.0 < metrics["MinAngleTarget"] <= metrics["MeanMinAngleTarget"] <= 60.0
        assert metrics["TwoSidedDistanceTarget"] >= metrics["HausdorffTarget"] > 0.0
    assert approximating["TwoSidedDistanceSource"] >= approximating["HausdorffSource"] > 0.0

    for kind, figures, rows in (("approximating", approximating, t["triangles"]), ("exact", exact, 1280)):
        triangles = list(csv.DictReader(open(out / f"{kind}_1_triangles.csv")))
        assert len(triangles) == rows
        assert max(float(row["distortion"]) for row in triangles) == pytest.approx(figures["MaxDistortion"])
        curve = list(csv.DictReader(open(out / f"{kind}_1_distortion_curve.csv")))
        assert len(curve) == 201
        assert float(curve[50]["distortion"]) == pytest.approx(1.5)
        assert float(curve[50]["area_fraction_below"]) == pytest.approx(figures["AreaBelow1.5"], abs=1e-9)
        mesh = read_vtp(out / f"{kind}_1.vtp")
        assert mesh.GetNumberOfPolys() == rows
        assert mesh.GetCellData().GetArray("MaxStretch").GetRange()[1] == pytest.approx(figures["MaxDistortion"])
        positions = mesh.GetPointData().GetArray("SourcePosition")
        assert positions is not None and positions.GetNumberOfComponents() == 3
        assert max(positions.GetRange(k)[1] - positions.GetRange(k)[0] for k in range(3)) == pytest.approx(2.0)
    # The approximating map's figures belong to common_1's surface (on input 1).
    common_1 = read_vtp(map_dir / "common_1.vtp")
    view = read_vtp(out / "approximating_1.vtp")
    assert view.GetPoint(7) == common_1.GetPoint(7)


def test_evaluate_map_directory_writes_into_it_by_default(map_dir, tmp_path):
    copy = tmp_path / "copy"
    shutil.copytree(map_dir, copy)
    r = run("evaluate", copy)
    assert r.returncode == 0, r.stderr
    assert (copy / "summary.json").exists() and (copy / "exact_1_distortion_curve.csv").exists()


def test_single_input_map_directory(tmp_path):
    out = tmp_path / "remeshing"
    r = run("map", data("ellipsoid_coarse.stl"), "--coarse-iterations", "2", "--fine-iterations", "0",
            "--output-dir", out)
    assert r.returncode == 0, r.stderr
    r = run("evaluate", out)
    assert r.returncode == 0, r.stderr
    (m,) = json.loads((out / "summary.json").read_text())["maps"]
    assert (m["source"], m["target"]) == (0, 0)
    assert m["approximating_map"]["SymmetricDirichlet"] == pytest.approx(1.0)  # T onto itself
    assert m["exact_map"]["MaxDistortion"] == pytest.approx(1.0)  # input 0 onto itself
    assert m["approximating_map"]["HausdorffSource"] > 0.0  # T only approximates the input


def test_inputs_override_the_report(map_dir, tmp_path):
    copy = tmp_path / "copy"
    shutil.copytree(map_dir, copy)
    r = run("evaluate", copy, "--inputs", data("ellipsoid.obj"))
    assert r.returncode == 2 and "--inputs needs one file per input of the map (2 in" in r.stderr
    r = run("evaluate", copy, "--inputs", data("ellipsoid.obj"), data("blob.off"))
    assert r.returncode == 0, r.stderr
    # Wrong inputs: blob is not what common_0 approximates, so H grows.
    r = run("evaluate", copy, "--inputs", data("blob.off"), data("blob.off"), "--output-dir", tmp_path / "wrong")
    assert r.returncode == 0, r.stderr
    right = json.loads((copy / "summary.json").read_text())["maps"][0]["approximating_map"]
    wrong = json.loads((tmp_path / "wrong" / "summary.json").read_text())["maps"][0]["approximating_map"]
    assert wrong["HausdorffSource"] > 2 * right["HausdorffSource"]


def test_missing_files_are_named(map_dir, tmp_path):
    r = run("evaluate", tmp_path)
    assert r.returncode == 2
    assert f"{tmp_path} has no common_0.vtp" in r.stderr

    copy = tmp_path / "no_mapped"
    shutil.copytree(map_dir, copy)
    (copy / "mapped_1.vtp").unlink()
    r = run("evaluate", copy)
    assert r.returncode == 2 and f"{copy / 'mapped_1.vtp'} is missing ({copy}/report.json lists it)" in r.stderr

    copy = tmp_path / "moved_input"
    shutil.copytree(map_dir, copy)
    report = json.loads((copy / "report.json").read_text())
    report["inputs"][1]["file"] = str(tmp_path / "gone.off")
    (copy / "report.json").write_text(json.dumps(report))
    r = run("evaluate", copy)
    assert r.returncode == 2 and f"cannot open '{tmp_path / 'gone.off'}'" in r.stderr
    assert not (copy / "summary.json").exists()

    (copy / "report.json").write_text("{ not json")
    r = run("evaluate", copy)
    assert r.returncode == 2 and "report.json is not valid JSON" in r.stderr

    r = run("evaluate", tmp_path / "nowhere")
    assert r.returncode == 2 and "cannot open" in r.stderr and "nowhere" in r.stderr


def test_a_failed_certificate_is_exit_3(map_dir, tmp_path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    copy = tmp_path / "broken"
    shutil.copytree(map_dir, copy)
    common_1 = read_vtp(copy / "common_1.vtp")
    sphere = common_1.GetPointData().GetArray("SpherePosition")
    x, y, z = sphere.GetTuple3(0)
    sphere.SetTuple3(0, -x, -y, -z)  # one vertex to the antipode: its triangles turn over
    # ... and its source point with it, so that common_1 still agrees with embedding_1.
    cell, barycentric = locate_on_sphere(read_vtp(copy / "embedding_1.vtp"), (-x, -y, -z))
    common_1.GetPointData().GetArray("SourceCellId").SetTuple1(0, cell)
    common_1.GetPointData().GetArray("SourceBarycentric").SetTuple3(0, *barycentric)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(common_1)
    writer.SetFileName(str(copy / "common_1.vtp"))
    assert writer.Write() == 1
    refresh_report(copy, "common_1.vtp")  # a consistent map directory, only not bijective
    r = run("evaluate", copy)
    assert r.returncode == 3
    assert "certificate 0 -> 1: FAILED" in r.stdout and "not certified bijective" in r.stderr
    certificate = json.loads((copy / "summary.json").read_text())["maps"][0]["certificate"]
    assert certificate["bijective"] is False and certificate["non_positive_triangles"] > 0


def test_directory_usage(map_dir):
    r = run("evaluate", map_dir, "--originals", data("ellipsoid.obj"), data("blob.off"))
    assert r.returncode == 2 and "a map directory takes --inputs" in r.stderr
    r = run("evaluate", data("ellipsoid.obj"), data("blob.off"), "--inputs", data("ellipsoid.obj"))
    assert r.returncode == 2 and "two meshes take --originals" in r.stderr
    r = run("evaluate", "--help")
    assert r.returncode == 0 and "MAPDIR" in r.stdout and "exact_<j>.vtp" in r.stdout
