"""`surfacemap evaluate`: summary, files, connectivity mismatch."""

import csv
import json

from cli import data, run


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


def test_mismatched_connectivity_is_bad_input():
    r = run("evaluate", data("ellipsoid.obj"), data("limbs.ply"))
    assert r.returncode == 2
    assert "do not have the same connectivity (642 vs 2562 points)" in r.stderr


def test_usage():
    assert run("evaluate", data("ellipsoid.obj")).returncode == 2
    r = run("evaluate", "--help")
    assert r.returncode == 0 and "--originals" in r.stdout
