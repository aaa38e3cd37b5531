"""Distortion curve plots from `surfacemap evaluate` output."""

import subprocess
import sys

from cli import data, run


def evaluate(a, b, out):
    r = run("evaluate", data(a), data(b), "--output-dir", out)
    assert r.returncode == 0, r.stderr
    return out / "distortion_curve.csv"


def test_two_curves_on_one_png(tmp_path):
    (tmp_path / "blob").mkdir()
    (tmp_path / "same").mkdir()
    c1 = evaluate("ellipsoid.obj", "blob.off", tmp_path / "blob")
    c2 = evaluate("ellipsoid.obj", "ellipsoid.obj", tmp_path / "same")
    png = tmp_path / "curves.png"
    r = subprocess.run([sys.executable, "-m", "surfacemaps.plots", str(c1), str(c2), "--labels", "blob",
                        "identity", "-o", str(png)], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(data) > 10000  # a real plot, not an empty canvas


def test_bad_curve_file(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("a,b\n1,2\n")
    r = subprocess.run([sys.executable, "-m", "surfacemaps.plots", str(bad), "-o", str(tmp_path / "x.png")],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and "not a distortion curve" in r.stderr
    assert not (tmp_path / "x.png").exists()
