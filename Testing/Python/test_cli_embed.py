"""`surfacemap embed`: certified output file, bad input, unwritable output."""

import math
import os
import re

from cli import data, run


def test_embed_writes_a_valid_mesh_with_sphere_positions(tmp_path):
    out = tmp_path / "blob_sphere.vtp"
    r = run("embed", data("blob.off"), "-o", str(out), "--landmarks", data("blob.vts"))
    assert r.returncode == 0, r.stderr
    assert "certified bijective sphere embedding of 642 vertices" in r.stdout
    assert out.exists()
    assert not [p for p in os.listdir(tmp_path) if ".tmp." in p]
    # The written file is itself a valid input with the landmarks kept.
    r = run("check", str(out))
    assert r.returncode == 0 and "landmarks 4" in r.stdout


def test_on_sphere(tmp_path):
    out = tmp_path / "s.vtp"
    r = run("embed", data("ellipsoid.obj"), "--on-sphere", "-o", str(out))
    assert r.returncode == 0, r.stderr
    r = run("check", str(out))
    assert r.returncode == 0
    # Chord triangles of the unit sphere: area just under 4 pi, diagonal just under 2 sqrt 3.
    area = float(re.search(r"area ([0-9.]+)", r.stdout).group(1))
    diagonal = float(re.search(r"bbox diagonal ([0-9.]+)", r.stdout).group(1))
    assert 12.0 < area < 4 * math.pi
    assert 3.3 < diagonal <= 2 * math.sqrt(3)


def test_bad_input_writes_nothing(tmp_path):
    out = tmp_path / "t.vtp"
    r = run("embed", data("bad/torus.obj"), "-o", str(out))
    assert r.returncode == 2
    assert "has genus 1" in r.stderr
    assert not out.exists()


def test_unwritable_output_is_reported_before_computing(tmp_path):
    r = run("embed", data("ellipsoid.obj"), "-o", str(tmp_path / "no" / "such" / "dir.vtp"))
    assert r.returncode == 2
    assert "cannot write" in r.stderr


def test_usage():
    assert run("embed").returncode == 2
    r = run("embed", data("ellipsoid.obj"))
    assert r.returncode == 2 and "no output file" in r.stderr
    r = run("embed", "--help")
    assert r.returncode == 0 and "--on-sphere" in r.stdout


def test_rotation_onto_a_reference(tmp_path):
    ref = tmp_path / "ellipsoid.vtp"
    assert run("embed", data("ellipsoid.obj"), "--landmarks", data("ellipsoid.pinned"), "-o", ref).returncode == 0
    out = tmp_path / "blob.vtp"
    r = run("embed", data("blob.off"), "--landmarks", data("blob.vts"), "--reference", ref, "-o", out)
    assert r.returncode == 0, r.stderr
    assert "rotated onto" in r.stdout and "rad (RMS)" in r.stdout
    r = run("embed", data("blob.off"), "--reference", data("ellipsoid.obj"), "-o", out)
    assert r.returncode == 2 and "no SpherePosition array" in r.stderr


def test_obj_output_keeps_corner_texture_coordinates_and_normals(tmp_path):
    # spot.obj has 'vt' and 'vn' per corner: written back as OBJ, both round-trip exactly.
    import surfacemaps
    out = tmp_path / "spot_again.obj"
    r = run("embed", data("spot.obj"), "-o", out)
    assert r.returncode == 0, r.stderr
    before, after = surfacemaps.read_mesh(data("spot.obj")), surfacemaps.read_mesh(out)
    assert after.GetNumberOfPoints() == before.GetNumberOfPoints()
    assert all(after.GetPoint(v) == before.GetPoint(v) for v in range(before.GetNumberOfPoints()))
    for name in ("CornerTCoords", "CornerNormals"):
        a, b = before.GetCellData().GetArray(name), after.GetCellData().GetArray(name)
        assert a is not None and b is not None, name
        assert all(a.GetTuple(c) == b.GetTuple(c) for c in range(a.GetNumberOfTuples())), name
    text = out.read_text()
    assert "\nvt " in text and "\nvn " in text and "SpherePosition" not in text


def test_settings_are_flags_from_the_list(tmp_path):
    import surfacemaps
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from cli import read_vtp
    S = surfacemaps.vtkSurfaceMapsSettings
    table = S.SPHERE_EMBEDDING_SETTINGS
    n = S.GetNumberOfSettings(table)
    help_text = run("embed", "--help").stdout
    for i in range(n):
        assert S.GetHelp(table, i) in help_text, S.GetFlag(table, i)

    def embed(name, *flags):
        out = tmp_path / name
        r = run("embed", data("blob.off"), "-o", out, *flags)
        assert r.returncode == 0, r.stderr
        iterations = int(re.search(r"(\d+) Newton iterations", r.stdout).group(1))
        return vtk_to_numpy(read_vtp(out).GetPointData().GetArray("SpherePosition")), iterations

    # Every flag at its default, as the codec writes it, is the embedding without flags.
    defaults = [text for i in range(n)
                for text in ("--" + S.GetFlag(table, i), S.Format(table, i, S.GetDefault(table, i)))]
    plain, iterations = embed("plain.vtp")
    flagged, _ = embed("defaults.vtp", *defaults)
    assert (plain == flagged).all()
    # A flag reaches the filter: no final iterations, fewer in all.
    _, fewer = embed("fewer.vtp", "--final-iterations", "0", "--squeezed-final-iterations", "0")
    assert fewer < iterations
    for flag, value, message in (("--final-tolerance", "x", "--final-tolerance needs a number from 0 to 1, not 'x'"),
                                 ("--barrier-weight", "0", "--barrier-weight needs a number from 1e-6 to 1000"),
                                 ("--level-iterations", "2.5", "needs a whole number")):
        r = run("embed", data("blob.off"), "-o", tmp_path / "bad.vtp", flag, value)
        assert r.returncode == 2 and message in r.stderr, (flag, r.stderr)
    r = run("embed", data("blob.off"), "-o", tmp_path / "bad.vtp", "--final-tolerance")
    assert r.returncode == 2 and "--final-tolerance needs a value" in r.stderr
