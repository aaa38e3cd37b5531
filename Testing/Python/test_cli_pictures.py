"""`surfacemap evaluate --pictures` and `surfacemap transfer --pictures`: the PNGs, on a display
and on a server without one (the command starts Xvfb itself), and the early stop when there is
neither. CTest runs this file under xvfb-run; the pictures on a display are skipped without one,
the headless ones without Xvfb, the stop is tested in any case."""

import os
import shutil

import numpy as np
import pytest

from cli import SHORT, assert_virtual_display_stopped, data, run, run_headless

needs_display = pytest.mark.skipif(not os.environ.get("DISPLAY"),
                                   reason="needs a display (CTest runs this file under xvfb-run)")
needs_xvfb = pytest.mark.skipif(not shutil.which("Xvfb"), reason="needs Xvfb (Debian package xvfb)")


def assert_stopped_without_display_and_xvfb(result):
    assert result.returncode == 2, result.stderr
    assert "DISPLAY is not set" in result.stderr and "Xvfb" in result.stderr, result.stderr
    assert "Debian package xvfb" in result.stderr


def picture(path, size):
    """The PNG at `path` as an (height, width, 3) array, checked: PNG signature, `size`
    (width, height), more than a few colours."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    with open(path, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", path
    assert os.path.getsize(path) > 5000, path
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    image = reader.GetOutput()
    assert image.GetDimensions()[:2] == size, path
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3]
    assert len(np.unique(pixels, axis=0)) > 10, path
    return pixels.reshape(size[1], size[0], 3)


def panels(pixels, legend):
    """The two surface panels of a side-by-side picture (the rightmost 12 % hold the legend when
    there is one)."""
    surfaces = pixels[:, : int(pixels.shape[1] * (0.88 if legend else 1.0))]
    half = surfaces.shape[1] // 2
    return surfaces[:, :half], surfaces[:, half:]


def assert_two_surfaces(pixels, legend, coloured=True):
    """Both panels show a surface (enough pixels that are not the white background) and, if
    `coloured`, in colour: enough saturated pixels, not the grey of an unmapped array."""
    for panel in panels(pixels, legend):
        drawn = np.any(panel < 235, axis=2).mean()
        assert drawn > 0.05, drawn
        if coloured:
            channels = panel.astype(int)
            saturated = (channels.max(axis=2) - channels.min(axis=2) > 50).mean()
            assert saturated > 0.05, saturated


def assert_fits(pixels, legend):
    """No panel is cropped: the outermost rows and columns of each are background."""
    for panel in panels(pixels, legend):
        border = np.concatenate([panel[0], panel[-1], panel[:, 0], panel[:, -1]])
        assert np.all(border >= 235), "a surface touches its panel's edge"


def assert_reddish(pixels):
    """Some pixels on both sides are clearly red (distortion above 1.5 there)."""
    for panel in panels(pixels, legend=True):
        red = (panel[..., 0].astype(int) - panel[..., 2].astype(int)) > 40
        assert red.sum() > 100, red.sum()


def hue_count(panel):
    """How many distinct hues a panel's saturated pixels have: runs of neighbouring 10-degree hue
    steps (on the circle) that each hold more than 1 % of them. Shading changes the brightness of
    a flat colour, not its hue."""
    import colorsys
    channels = panel.reshape(-1, 3).astype(float) / 255.0
    saturated = channels[channels.max(axis=1) - channels.min(axis=1) > 0.2]
    steps = [int(colorsys.rgb_to_hsv(*c)[0] * 36) % 36 for c in saturated[::7]]
    counts = np.bincount(steps, minlength=36)
    used = [counts[h] > 0.01 * len(steps) for h in range(36)]
    return sum(1 for h in range(36) if used[h] and not used[h - 1])


# evaluate SOURCE TARGET

@needs_display
def test_evaluate_pair_pictures(tmp_path):
    out = tmp_path / "new"  # created
    r = run("evaluate", data("ellipsoid.obj"), data("blob.off"), "--output-dir", out, "--pictures")
    assert r.returncode == 0, r.stderr
    assert "distortion.png, checkerboard.png, distortion_curve.png" in r.stdout
    assert sorted(p.name for p in out.iterdir()) == [
        "checkerboard.png", "distortion.png", "distortion_curve.csv", "distortion_curve.png",
        "evaluated.vtp", "summary.json", "triangles.csv"]  # no temporary left
    heat = picture(out / "distortion.png", (1200, 600))
    assert_two_surfaces(heat, legend=True, coloured=False)  # mostly near 1: white
    assert_reddish(heat)
    assert_two_surfaces(picture(out / "checkerboard.png", (1200, 600)), legend=False)
    picture(out / "distortion_curve.png", (800, 600))


def test_evaluate_pair_pictures_need_an_output_dir():
    r = run("evaluate", data("ellipsoid.obj"), data("blob.off"), "--pictures")
    assert r.returncode == 2 and "--pictures needs --output-dir" in r.stderr
    assert "SymmetricDirichlet" not in r.stdout


@needs_xvfb
def test_evaluate_pair_pictures_without_a_display(tmp_path):
    """On a server without a display the command renders on an Xvfb of its own, stopped at exit."""
    out = tmp_path / "new"
    r = run_headless("evaluate", data("ellipsoid.obj"), data("blob.off"), "--output-dir", out, "--pictures",
                     "-v")
    assert r.returncode == 0, r.stderr
    assert_virtual_display_stopped(r.stderr)
    heat = picture(out / "distortion.png", (1200, 600))
    assert_two_surfaces(heat, legend=True, coloured=False)
    assert_reddish(heat)
    checks = picture(out / "checkerboard.png", (1200, 600))
    assert_two_surfaces(checks, legend=False)
    assert_fits(checks, legend=False)
    picture(out / "distortion_curve.png", (800, 600))


def test_evaluate_stops_without_a_display_and_xvfb(tmp_path):
    out = tmp_path / "new"
    r = run_headless("evaluate", data("ellipsoid.obj"), data("blob.off"), "--output-dir", out, "--pictures",
                     xvfb=False)
    assert_stopped_without_display_and_xvfb(r)
    assert "SymmetricDirichlet" not in r.stdout and not out.exists()  # before computing
    help_text = run("evaluate", "--help").stdout
    assert "--pictures" in help_text and "Xvfb" in help_text and "checkerboard.png" in help_text


# Maps: evaluate MAPDIR and transfer.

def labelled_blob(path):
    """blob.off with the point arrays "Region" (int, 4 bands along z, its longest axis, so that
    a side view shows all), "Height" (float, z) and "Position" (3 doubles), written to `path`."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray, vtkIntArray
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    import surfacemaps
    mesh = surfacemaps.read_mesh(data("blob.off"))
    region, height, position = vtkIntArray(), vtkFloatArray(), vtkDoubleArray()
    position.SetNumberOfComponents(3)
    for array, name in ((region, "Region"), (height, "Height"), (position, "Position")):
        array.SetName(name)
        mesh.GetPointData().AddArray(array)
    low, high = mesh.GetBounds()[4:6]
    for v in range(mesh.GetNumberOfPoints()):
        x, y, z = mesh.GetPoint(v)
        region.InsertNextValue(min(3, int(4 * (z - low) / (high - low))) + 7)
        height.InsertNextValue(z)
        position.InsertNextTuple((x, y, z))
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(path))
    assert writer.Write() == 1


@pytest.fixture(scope="module")
def map_dir(tmp_path_factory):
    """A map of ellipsoid (input 0) and the labelled blob (input 1), short schedule."""
    root = tmp_path_factory.mktemp("pictures")
    labelled_blob(root / "blob.vtp")
    out = root / "map"
    r = run("map", data("ellipsoid.obj"), root / "blob.vtp", "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *SHORT, "--output-dir", out)
    assert r.returncode == 0, r.stderr
    return out


@needs_display
def test_evaluate_map_directory_pictures(map_dir, tmp_path):
    out = tmp_path / "evaluation"
    r = run("evaluate", map_dir, "--output-dir", out, "--pictures")
    assert r.returncode == 0, r.stderr
    assert "distortion_curves_<j>.png" in r.stdout
    for kind in ("approximating", "exact"):
        assert_two_surfaces(picture(out / f"{kind}_1_distortion.png", (1200, 600)), legend=True,
                            coloured=False)
        assert_two_surfaces(picture(out / f"{kind}_1_checkerboard.png", (1200, 600)), legend=False)
    picture(out / "distortion_curves_1.png", (800, 600))
    assert not [p for p in os.listdir(out) if ".tmp" in p]


def test_evaluate_map_directory_stops_without_a_display_and_xvfb(map_dir, tmp_path):
    out = tmp_path / "evaluation"
    r = run_headless("evaluate", map_dir, "--output-dir", out, "--pictures", xvfb=False)
    assert_stopped_without_display_and_xvfb(r)
    assert not out.exists()


@needs_display
def test_transfer_pictures(map_dir, tmp_path):
    out = tmp_path / "received.vtp"
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "-o", out, "--pictures")
    assert r.returncode == 0, r.stderr
    names = {"Region", "Height", "Position"}
    # One picture per carried array, none for the bookkeeping arrays.
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        ["received.vtp"] + [f"received_{name}.png" for name in names])
    for name in names:
        assert str(tmp_path / f"received_{name}.png") in r.stdout
    # Continuous arrays (and the categorical one: four labels) have a legend; no side is cropped.
    for name in names:
        pixels = picture(tmp_path / f"received_{name}.png", (1200, 600))
        assert_two_surfaces(pixels, legend=True)
        assert_fits(pixels, legend=True)
    # Labels in flat colours: four hues on the source side, the same on the received side.
    for panel in panels(picture(tmp_path / "received_Region.png", (1200, 600)), legend=True):
        assert hue_count(panel) == 4


def test_transfer_picture_names(map_dir, tmp_path):
    """Array names become file names: other characters than letters, digits, -, _ and . turn to _."""
    from vtkmodules.vtkCommonCore import vtkFloatArray
    import surfacemaps
    source = surfacemaps.read_mesh(str(map_dir / "embedding_1.vtp"))
    odd = vtkFloatArray()
    odd.SetName("a b/c")
    for v in range(source.GetNumberOfPoints()):
        odd.InsertNextValue(float(v))
    source.GetPointData().AddArray(odd)
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(source)
    writer.SetFileName(str(tmp_path / "data.vtp"))
    assert writer.Write() == 1
    if not os.environ.get("DISPLAY"):
        pytest.skip("needs a display (CTest runs this file under xvfb-run)")
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--source-data", tmp_path / "data.vtp",
            "--arrays", "a b/c", "-o", tmp_path / "out.vtp", "--pictures")
    assert r.returncode == 0, r.stderr
    picture(tmp_path / "out_a_b_c.png", (1200, 600))


@needs_display
def test_transfer_texture_picture(map_dir, tmp_path):
    """Per-corner texture coordinates on the source (a planar projection of the blob, through
    --source-data) give OUT_texture.png: both sides textured with the checkerboard."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    import surfacemaps
    source = surfacemaps.read_mesh(str(map_dir / "embedding_1.vtp"))
    bounds = source.GetBounds()
    corners = vtkDoubleArray()
    corners.SetName("CornerTCoords")
    corners.SetNumberOfComponents(6)
    for c in range(source.GetNumberOfCells()):
        ids = source.GetCell(c).GetPointIds()
        tuple_ = []
        for k in range(3):
            x, y, _ = source.GetPoint(ids.GetId(k))
            tuple_ += [(x - bounds[0]) / (bounds[1] - bounds[0]), (y - bounds[2]) / (bounds[3] - bounds[2])]
        corners.InsertNextTuple(tuple_)
    source.GetCellData().AddArray(corners)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(source)
    writer.SetFileName(str(tmp_path / "textured.vtp"))
    assert writer.Write() == 1
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--source-data", tmp_path / "textured.vtp",
            "--arrays", "Height", "-o", tmp_path / "out.vtp", "--pictures")
    assert r.returncode == 0, r.stderr
    assert str(tmp_path / "out_texture.png") in r.stdout
    assert_two_surfaces(picture(tmp_path / "out_texture.png", (1200, 600)), legend=False)


@needs_xvfb
def test_transfer_pictures_without_a_display(map_dir, tmp_path):
    out = tmp_path / "received.vtp"
    r = run_headless("transfer", map_dir, "--from", "1", "--to", "0", "--arrays", "Region", "-o", out,
                     "--pictures", "-v")
    assert r.returncode == 0, r.stderr
    assert_virtual_display_stopped(r.stderr)
    assert_two_surfaces(picture(tmp_path / "received_Region.png", (1200, 600)), legend=True)


def test_transfer_stops_without_a_display_and_xvfb(map_dir, tmp_path):
    out = tmp_path / "received.vtp"
    r = run_headless("transfer", map_dir, "--from", "1", "--to", "0", "-o", out, "--pictures", xvfb=False)
    assert_stopped_without_display_and_xvfb(r)
    assert not out.exists() and not list(tmp_path.iterdir())
    help_text = run("transfer", "--help").stdout
    assert "--pictures" in help_text and "Xvfb" in help_text and "_NAME.png" in help_text
