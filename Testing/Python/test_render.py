"""Pictures: distortion heat map, checkerboard and texture, rendered offscreen (CTest runs this file
under xvfb-run; without a display the module starts Xvfb itself), and the view they share."""

import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

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


def test_pictures_without_a_display(tmp_path):
    """Without a display the module starts Xvfb itself; with neither it says what to install."""
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    command = [sys.executable, "-m", "surfacemaps.render", data("spot.obj"), "--texture"]
    if shutil.which("Xvfb"):
        r = subprocess.run([*command, "-o", tmp_path / "spot.png"], capture_output=True, text=True, env=env,
                           timeout=120)
        assert r.returncode == 0, r.stderr
        assert distinct_colours(tmp_path / "spot.png") > 20
    r = subprocess.run([*command, "-o", tmp_path / "none.png"], capture_output=True, text=True,
                       env=dict(env, PATH="/nonexistent"), timeout=120)
    assert r.returncode == 2 and "Debian package xvfb" in r.stderr, r.stderr
    assert not (tmp_path / "none.png").exists()
    if not shutil.which("Xvfb"):
        pytest.skip("Xvfb is not installed: only the refusal was tested")


def ellipsoid_with_positions():
    """Data/ellipsoid.obj with the point array "P": its positions scaled into [-1, 1]."""
    import surfacemaps
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    positions = (points - points.mean(axis=0)) / np.abs(points - points.mean(axis=0)).max()
    array = numpy_to_vtk(positions, deep=1)
    array.SetName("P")
    mesh.GetPointData().AddArray(array)
    return mesh


def area(mesh):
    from vtkmodules.vtkFiltersCore import vtkTriangleFilter
    from vtkmodules.vtkFiltersVerdict import vtkMeshQuality
    triangles = vtkTriangleFilter()
    triangles.SetInputData(mesh)
    quality = vtkMeshQuality()
    quality.SetInputConnection(triangles.GetOutputPort())
    quality.SetTriangleQualityMeasureToArea()
    quality.Update()
    from vtkmodules.util.numpy_support import vtk_to_numpy
    return vtk_to_numpy(quality.GetOutput().GetCellData().GetArray("Quality")).sum()


def test_checkerboard_squares_have_straight_edges():
    """checkered() cuts every triangle along the squares' planes: each piece lies in one cube of
    the coordinates (its parity the cell array), and the pieces cover the surface."""
    from surfacemaps.render import checkered
    from vtkmodules.util.numpy_support import vtk_to_numpy
    mesh = ellipsoid_with_positions()
    squares = 8
    cut = checkered(mesh, "P", squares)
    # Coordinates in units of a square, shifted as checkered() does (cubes counted from -2).
    positions = (vtk_to_numpy(cut.GetPointData().GetArray("P")) + 2.0) * squares / 2.0
    parity = vtk_to_numpy(cut.GetCellData().GetArray("Checkerboard"))
    assert cut.GetNumberOfCells() > 2 * mesh.GetNumberOfCells() and set(parity) == {0.0, 1.0}
    points = vtk_to_numpy(cut.GetPoints().GetData()).astype(float)
    for c in range(cut.GetNumberOfCells()):
        ids = [cut.GetCell(c).GetPointId(k) for k in range(cut.GetCell(c).GetNumberOfPoints())]
        if np.linalg.norm(np.cross(points[ids[1]] - points[ids[0]], points[ids[2]] - points[ids[0]])) < 1e-12:
            continue  # a sliver of no area where a cut meets a vertex: not drawn
        corners = positions[ids]
        cube = np.floor(corners.mean(axis=0))
        assert np.all(corners >= cube - 1e-6) and np.all(corners <= cube + 1 + 1e-6), c
        assert parity[c] == cube.astype(int).sum() % 2
    assert abs(area(cut) - area(mesh)) < 1e-9 * area(mesh)


def test_principal_axes_longest_first_signed():
    from surfacemaps.render import principal_axes
    rng = np.random.default_rng(0)
    points = rng.normal(size=(500, 3)) * [1.0, 3.0, 9.0]
    axes = principal_axes(-points)  # the sign of the data does not flip the axes
    assert np.allclose(np.abs(axes), np.eye(3)[[2, 1, 0]], atol=0.05)
    assert all(axis[np.argmax(np.abs(axis))] > 0 for axis in axes)


def test_panels_share_one_camera_and_fit(tmp_path):
    """Two copies of one surface, the second moved far away, look the same; twice as large, it is
    drawn larger (one scale for all panels); no panel crops its surface."""
    from surfacemaps.render import Panel, checkered, configure_checkerboard, render_panels
    from vtkmodules.vtkCommonTransforms import vtkTransform
    from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy

    def transformed(mesh, scale, shift):
        transform = vtkTransform()
        transform.Translate(shift, 0.0, 0.0)
        transform.Scale(scale, scale, scale)
        moved = vtkTransformPolyDataFilter()
        moved.SetTransform(transform)
        moved.SetInputData(mesh)
        moved.Update()
        return moved.GetOutput()

    def panels_of(path):
        reader = vtkPNGReader()
        reader.SetFileName(str(path))
        reader.Update()
        width, height, _ = reader.GetOutput().GetDimensions()
        pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].reshape(height, width, 3)
        return pixels[:, : width // 2], pixels[:, width // 2:]

    mesh = checkered(ellipsoid_with_positions(), "P", 4)
    for scale, name in ((1.0, "same.png"), (2.0, "larger.png")):
        render_panels([Panel(mesh, configure_checkerboard), Panel(transformed(mesh, scale, 100.0),
                                                                  configure_checkerboard)], str(tmp_path / name))
    first, second = panels_of(tmp_path / "same.png")
    assert (np.abs(first.astype(int) - second.astype(int)).max(axis=2) > 30).mean() < 0.005
    first, second = panels_of(tmp_path / "larger.png")
    drawn = [np.any(panel < 235, axis=2).mean() for panel in (first, second)]
    assert drawn[1] > 3.0 * drawn[0] > 0.0, drawn
    for panel in (first, second):
        border = np.concatenate([panel[0], panel[-1], panel[:, 0], panel[:, -1]])
        assert np.all(border >= 235)
