"""`surfacemap map --add-to DIR` and map_surfaces(add_to=...): specimens added to an existing map
without mapping its inputs again; the existing map's files checked first, nothing half-written."""

import hashlib
import json
import os

import pytest

from cli import SHORT, data, read_vtp, run

POPULATION = ("--preset", "population", *SHORT)


def new_specimen(tmp_path):
    """The ellipsoid stretched and bumped (its landmark file ellipsoid.pinned names vertices)."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    import surfacemaps
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    points = mesh.GetPoints()
    for v in range(points.GetNumberOfPoints()):
        x, y, z = points.GetPoint(v)
        points.SetPoint(v, 1.3 * x, 0.9 * y, z * (1.0 + 0.2 * max(0.0, z) ** 2))
    path = tmp_path / "stretched.vtp"
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(mesh)
    assert writer.Write() == 1
    return path


@pytest.fixture(scope="module")
def existing(tmp_path_factory):
    """A map of two specimens with the population preset."""
    out = tmp_path_factory.mktemp("existing") / "map"
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *POPULATION, "-o", out)
    assert r.returncode == 0, r.stderr
    return out


def digests(directory):
    return {name: hashlib.md5((directory / name).read_bytes()).hexdigest() for name in os.listdir(directory)}


def test_add_to_writes_the_map_of_every_input_and_keeps_the_existing_maps(existing, tmp_path):
    before = digests(existing)
    specimen = new_specimen(tmp_path)
    out = tmp_path / "added"
    r = run("map", "--add-to", existing, specimen, "--landmarks", data("ellipsoid.pinned"), "-o", out)
    assert r.returncode == 0, r.stderr
    assert "map of 3 surfaces: certified bijective" in r.stdout
    assert digests(existing) == before  # untouched
    old = json.loads((existing / "report.json").read_text())
    report = json.loads((out / "report.json").read_text())
    # The existing inputs' entries (their files), then the new one; the settings the existing map's.
    assert report["inputs"][:2] == old["inputs"]
    assert report["inputs"][2]["file"] == str(specimen)
    assert report["added_to"] == {"directory": str(existing), "map_id": old["map_id"], "inputs": 2}
    assert report["settings"] == old["settings"] and report["preset"] == "population"
    assert [s["name"] for s in report["specimens"]] == ["ellipsoid", "blob", "stretched"]
    assert len((out / "fit.csv").read_text().strip().split("\n")) == 4
    import numpy as np
    npz = np.load(out / "correspondences.npz")
    assert npz["points"].shape == (3, report["common_triangulation"]["vertices"], 3)
    # Every existing input's T keeps its vertices (the splits add vertices after them).
    for j in range(2):
        was, now = read_vtp(existing / f"common_{j}.vtp"), read_vtp(out / f"common_{j}.vtp")
        assert now.GetNumberOfPoints() >= was.GetNumberOfPoints()
        for v in range(0, was.GetNumberOfPoints(), 7):
            assert now.GetPoint(v) == pytest.approx(was.GetPoint(v), abs=1e-12)
    assert report["certificate"]["bijective"] is True
    assert report["exact_map"][1]["SymmetricDirichlet"] < 3.0
    assert report["specimens"][2]["landmark_error"] == pytest.approx(0.0, abs=1e-6)
    # The new directory is a map like any: its readers check it and accept it.
    assert run("evaluate", out, "-o", tmp_path / "evaluation").returncode == 0


def test_flags_override_the_existing_maps_settings(existing, tmp_path):
    out = tmp_path / "added"
    r = run("map", "--add-to", existing, new_specimen(tmp_path), "--landmarks", data("ellipsoid.pinned"),
            "--fine-iterations", "1", "-o", out)
    assert r.returncode == 0, r.stderr
    report = json.loads((out / "report.json").read_text())
    assert report["settings"]["fine_iterations"] == 1
    # The new specimen's fine phase (mapped alone against the mean shape).
    assert [p["iterations"] for p in report["phases"] if p["name"] == "fine"] == [1]


def test_a_changed_existing_file_is_refused_by_name(existing, tmp_path):
    import shutil
    copy = tmp_path / "copy"
    shutil.copytree(existing, copy)
    with open(copy / "embedding_1.vtp", "ab") as f:
        f.write(b"\n")
    out = tmp_path / "added"
    r = run("map", "--add-to", copy, new_specimen(tmp_path), "--landmarks", data("ellipsoid.pinned"), "-o", out)
    assert r.returncode == 2
    assert "embedding_1.vtp" in r.stderr and "changed" in r.stderr
    assert not out.exists()


def test_missing_landmarks_and_refinement_are_refused(existing, tmp_path):
    out = tmp_path / "added"
    r = run("map", "--add-to", existing, new_specimen(tmp_path), "-o", out)
    assert r.returncode == 2
    assert "input 2" in r.stderr and "landmarks" in r.stderr
    r = run("map", "--add-to", existing, new_specimen(tmp_path), "--landmarks", data("ellipsoid.pinned"),
            "--refinement-rounds", "1", "-o", out)
    assert r.returncode == 2 and "refinement rounds" in r.stderr
    assert not out.exists()


def test_replacing_the_existing_map_needs_overwrite(existing, tmp_path):
    import shutil
    copy = tmp_path / "copy"
    shutil.copytree(existing, copy)
    before = digests(copy)
    args = ("map", "--add-to", copy, new_specimen(tmp_path), "--landmarks", data("ellipsoid.pinned"), "-o", copy)
    r = run(*args)
    assert r.returncode == 2 and digests(copy) == before
    r = run(*args, "--overwrite")
    assert r.returncode == 0, r.stderr
    assert len(json.loads((copy / "report.json").read_text())["inputs"]) == 3


def test_python_adds_to_a_directory_or_a_map_in_memory(existing, tmp_path):
    import surfacemaps
    specimen = surfacemaps.read_mesh(str(new_specimen(tmp_path)), landmarks=data("ellipsoid.pinned"))
    from_directory = surfacemaps.map_surfaces([specimen], add_to=existing)
    assert len(from_directory) == 3
    assert from_directory[0].GetNumberOfPoints() >= read_vtp(existing / "common_0.vtp").GetNumberOfPoints()
    first = surfacemaps.map_surfaces([data("ellipsoid.obj"), data("blob.off")],
                                     landmarks=[data("ellipsoid.pinned"), data("blob.vts")], preset="population",
                                     LandmarkIterations=10, CoarseIterations=3, FineIterations=3)
    added = surfacemaps.map_surfaces([specimen], add_to=first)
    assert len(added) == 3 and added[2].GetFieldData().GetArray("Bijective").GetValue(0) == 1
    n = first[0].GetNumberOfPoints()
    for j in range(2):
        assert added[j].GetPoint(n - 1) == pytest.approx(first[j].GetPoint(n - 1), abs=1e-12)
    with pytest.raises(surfacemaps.InputError, match="input 2 .*has 0"):
        surfacemaps.map_surfaces([data("ellipsoid.obj")], add_to=first)
