"""Pictures: distortion heat map and checkerboard, rendered offscreen (under xvfb-run)."""

import subprocess
import sys

from cli import data, run

PNG = b"\x89PNG\r\n\x1a\n"


def render(*args):
    return subprocess.run([sys.executable, "-m", "surfacemaps.render", *map(str, args)],
                          capture_output=True, text=True, timeout=120)


def distinct_colours(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy as np
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    return len(np.unique(pixels[:, :3], axis=0))


def test_distortion_and_checkerboard_pictures(tmp_path):
    assert run("embed", data("ellipsoid.obj"), "-o", tmp_path / "e.vtp").returncode == 0
    assert run("embed", data("ellipsoid.obj"), "--on-sphere", "-o", tmp_path / "s.vtp").returncode == 0
    r = run("evaluate", tmp_path / "e.vtp", tmp_path / "s.vtp", "--output-dir", tmp_path)
    assert r.returncode == 0, r.stderr
    r = render(tmp_path / "evaluated.vtp", "-o", tmp_path / "distortion.png")
    assert r.returncode == 0, r.stderr
    r = render(tmp_path / "e.vtp", "--checkerboard", "-o", tmp_path / "checker.png")
    assert r.returncode == 0, r.stderr
    for name in ("distortion.png", "checker.png"):
        assert (tmp_path / name).read_bytes()[:8] == PNG
        assert distinct_colours(tmp_path / name) > 20, f"{name} looks empty"


def test_missing_array_is_an_error(tmp_path):
    r = render(data("ellipsoid.obj"), "-o", tmp_path / "x.png")
    assert r.returncode == 2 and "no MaxStretch cell array" in r.stderr
    assert not (tmp_path / "x.png").exists()


def test_map_checkerboard_on_both_sides(tmp_path):
    out = tmp_path / "map"
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmark-iterations", "10", "--coarse-iterations",
            "3", "--fine-iterations", "3", "--output-dir", out)
    assert r.returncode == 0, r.stderr
    assert run("evaluate", out).returncode == 0
    r = render(out / "approximating_1.vtp", "--checkerboard", "SourcePosition", "-o", tmp_path / "on_b.png")
    assert r.returncode == 0, r.stderr
    r = render(out / "approximating_1.vtp", "--checkerboard", "SourcePosition", "--points-from",
               out / "common_0.vtp", "-o", tmp_path / "on_a.png")
    assert r.returncode == 0, r.stderr
    for name in ("on_b.png", "on_a.png"):
        assert (tmp_path / name).read_bytes()[:8] == PNG
        assert distinct_colours(tmp_path / name) > 20, f"{name} looks empty"
    assert (tmp_path / "on_a.png").read_bytes() != (tmp_path / "on_b.png").read_bytes()
    r = render(out / "approximating_1.vtp", "--points-from", data("limbs.ply"), "-o", tmp_path / "x.png")
    assert r.returncode == 2 and "limbs.ply has 2562 points" in r.stderr
    assert not (tmp_path / "x.png").exists()


def test_texture_pictures(tmp_path):
    # Spot's per-corner coordinates, split at their seams, with the bundled checkerboard and
    # with an image file; a mesh without texture coordinates is an error.
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from surfacemaps.render import checkerboard_texture
    writer = vtkPNGWriter()
    writer.SetInputData(checkerboard_texture(squares=4, size=64))
    writer.SetFileName(str(tmp_path / "image.png"))
    writer.Write()
    r = render(data("spot.obj"), "--texture", "-o", tmp_path / "checker.png")
    assert r.returncode == 0, r.stderr
    r = render(data("spot.obj"), "--texture", tmp_path / "image.png", "-o", tmp_path / "image_on_spot.png")
    assert r.returncode == 0, r.stderr
    for name in ("checker.png", "image_on_spot.png"):
        assert (tmp_path / name).read_bytes()[:8] == PNG
        assert distinct_colours(tmp_path / name) > 20, f"{name} looks empty"
    r = render(data("ellipsoid.obj"), "--texture", "-o", tmp_path / "none.png")
    assert r.returncode == 2 and "no texture coordinates" in r.stderr
    r = render(data("spot.obj"), "--texture", tmp_path / "missing.png", "-o", tmp_path / "none.png")
    assert r.returncode == 2 and "not an image file" in r.stderr
    assert not (tmp_path / "none.png").exists()
