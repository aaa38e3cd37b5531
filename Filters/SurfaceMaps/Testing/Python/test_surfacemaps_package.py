"""The Python package: import, readers, validation, pipelines."""

import os

import pytest

import surfacemaps
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm

DATA = os.environ.get("SURFACEMAPS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Data"))


def data(name):
    return os.path.join(DATA, name)


def test_classes_are_exported():
    assert issubclass(surfacemaps.vtkSurfaceMeshReader, vtkAlgorithm)
    assert issubclass(surfacemaps.vtkSurfaceMeshValidator, vtkAlgorithm)
    assert surfacemaps.__version__


def test_read_mesh_every_format():
    for name, points in [("ellipsoid.obj", 642), ("blob.off", 642), ("limbs.ply", 2562),
                         ("ellipsoid_coarse.stl", 162), ("blob.vtp", 642), ("limbs_coarse.vtk", 642),
                         ("spot.obj", 2930)]:
        mesh = surfacemaps.read_mesh(data(name))
        assert mesh.GetNumberOfPoints() == points, name


def test_read_mesh_raises_with_the_readers_message():
    with pytest.raises(surfacemaps.InputError, match="looks truncated"):
        surfacemaps.read_mesh(data("bad/truncated.obj"))
    with pytest.raises(surfacemaps.InputError, match="cannot open"):
        surfacemaps.read_mesh(data("no_such_file.off"))


def test_validate_reports_statistics_and_defects():
    good, torus = surfacemaps.validate(surfacemaps.read_mesh(data("ellipsoid.obj", )),
                                       surfacemaps.read_mesh(data("bad/torus.obj")))
    assert good["Valid"] and good["defects"] == []
    assert good["Points"] == 642 and good["Triangles"] == 1280 and good["Genus"] == 0
    assert good["Orientation"] == 1
    assert not torus["Valid"]
    assert torus["Genus"] == 1
    assert any("has genus 1" in d for d in torus["defects"])


def test_landmarks_from_files_and_correspondence():
    a = surfacemaps.read_mesh(data("ellipsoid.obj"), landmarks=data("ellipsoid.pinned"))
    b = surfacemaps.read_mesh(data("blob.off"), landmarks=data("blob.vts"))
    c = surfacemaps.read_mesh(data("limbs.ply"), landmarks=data("bad/five_landmarks.pinned"))
    rows = surfacemaps.validate(a, b, c)
    assert [r["Landmarks"] for r in rows] == [4, 4, 5]
    assert rows[0]["Valid"] and rows[1]["Valid"] and not rows[2]["Valid"]
    assert "landmark counts do not match" in rows[2]["defects"][0]
    assert all(r["Valid"] for r in surfacemaps.validate(a, b, c, check_landmark_correspondence=False))


def test_pipeline_with_repeatable_input():
    validator = surfacemaps.vtkSurfaceMeshValidator()
    for name in ("ellipsoid.obj", "blob.off"):
        reader = surfacemaps.vtkSurfaceMeshReader()
        reader.SetFileName(data(name))
        validator.AddInputConnection(reader.GetOutputPort())
    validator.Update()
    assert validator.GetAllValid()
    table = validator.GetOutput()
    assert table.GetNumberOfRows() == 2
    assert table.GetColumnByName("Input").GetValue(1).endswith("blob.off")


def test_embed_and_evaluate_helpers():
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    embedded = surfacemaps.embed_on_sphere(mesh, FinalIterations=20)
    assert embedded.GetPointData().GetArray("SpherePosition") is not None
    on_sphere = surfacemaps.embed_on_sphere(mesh, OutputPointsOnSphere=True)
    metrics = surfacemaps.evaluate_map(embedded, on_sphere, mesh)
    assert metrics["Bijective"] == 1.0
    assert metrics["SymmetricDirichlet"] >= 1.0
    assert metrics["HausdorffSource"] == pytest.approx(0.0, abs=1e-12)
    with pytest.raises(surfacemaps.InputError, match="genus 1"):
        surfacemaps.embed_on_sphere(surfacemaps.read_mesh(data("bad/torus.obj")))
    with pytest.raises(surfacemaps.InputError, match="same connectivity"):
        surfacemaps.evaluate_map(mesh, surfacemaps.read_mesh(data("limbs.ply")))
    with pytest.raises(TypeError):
        surfacemaps.embed_on_sphere(mesh, NoSuchSetting=1)


def test_read_mesh_snaps_point_landmarks_and_reads_sizing(tmp_path):
    import warnings
    rows = [line.split() for line in open(data("blob.vts"))]
    csv = tmp_path / "points.csv"
    # Ids given in the file (in reverse); the last point 0.3 off its vertex.
    lines = [f"{x},{y},{z},{3 - k}" for k, (_, x, y, z) in enumerate(rows)]
    _, x, y, z = rows[3]
    lines[3] = f"{x},{y},{float(z) + 0.3},0"
    csv.write_text("\n".join(lines) + "\n")
    sizing = tmp_path / "sizing.txt"
    sizing.write_text("0.25\n" * 642)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mesh = surfacemaps.read_mesh(data("blob.off"), landmarks=csv, sizing=sizing)
    assert len(caught) == 1 and f"{csv}:4: landmark 0 lies" in str(caught[0].message)
    landmarks = mesh.GetPointData().GetArray("Landmarks")
    assert [landmarks.GetValue(int(row[0])) for row in rows] == [3, 2, 1, 0]
    distances = mesh.GetFieldData().GetArray("LandmarkSnapDistance")
    assert [round(distances.GetValue(k), 6) for k in range(4)][:3] == [0.0, 0.0, 0.0]
    assert abs(distances.GetValue(3) - 0.3) < 1e-6
    assert mesh.GetPointData().GetArray("Sizing").GetValue(641) == 0.25
    bad = tmp_path / "bad.csv"
    bad.write_text("1,2,3\n1,2\n")
    with pytest.raises(surfacemaps.InputError, match="bad.csv:2: expected x,y,z or x,y,z,id"):
        surfacemaps.read_mesh(data("blob.off"), landmarks=bad)
