"""The Python package uses the module's one input validation: evaluate_map's
inputs, the Landmarks array's shape and values, and landmark lists."""

import os

import pytest

import surfacemaps
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIntArray
from vtkmodules.vtkCommonDataModel import vtkPolyData

DATA = os.environ.get("SURFACEMAPS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Data"))


def data(name):
    return os.path.join(DATA, name)


def with_landmarks(array, values):
    """ellipsoid.obj with `array` as its Landmarks: -1 but (vertex, value) in `values`."""
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    array.SetName("Landmarks")
    array.SetNumberOfTuples(mesh.GetNumberOfPoints())
    for c in range(array.GetNumberOfComponents()):
        array.FillComponent(c, -1)
    for vertex, value in values:
        array.SetComponent(vertex, 0, value)
    mesh.GetPointData().AddArray(array)
    return mesh


def test_evaluate_map_of_empty_meshes_is_an_error():
    with pytest.raises(surfacemaps.InputError, match="contains no vertices"):
        surfacemaps.evaluate_map(vtkPolyData(), vtkPolyData())


def test_evaluate_map_of_points_only_is_an_error():
    points = vtkPolyData()
    points.SetPoints(surfacemaps.read_mesh(data("ellipsoid.obj")).GetPoints())
    with pytest.raises(surfacemaps.InputError, match="contains no triangles"):
        surfacemaps.evaluate_map(points, points)


def test_evaluate_map_rejects_a_nan_original():
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    with pytest.raises(surfacemaps.InputError, match="non-finite coordinates"):
        surfacemaps.evaluate_map(mesh, mesh, surfacemaps.read_mesh(data("bad/nan_vertex.obj")), mesh)
    assert surfacemaps.evaluate_map(mesh, mesh, mesh, mesh)["SymmetricDirichlet"] == pytest.approx(1.0)


def test_two_component_landmarks_are_rejected():
    array = vtkIntArray()
    array.SetNumberOfComponents(2)
    mesh = with_landmarks(array, [(5, 0)])
    [row] = surfacemaps.validate(mesh)
    assert not row["Valid"]
    assert any("Landmarks array with 2 components" in d for d in row["defects"])
    with pytest.raises(surfacemaps.InputError, match="2 components"):
        surfacemaps.map_surfaces([mesh, surfacemaps.read_mesh(data("blob.off"))])
    with pytest.raises(surfacemaps.InputError, match="2 components"):
        surfacemaps.embed_on_sphere(mesh)


def test_float_landmark_ids_must_be_integers():
    [row] = surfacemaps.validate(with_landmarks(vtkDoubleArray(), [(5, 3.0)]))
    assert row["Valid"] and row["Landmarks"] == 1
    [row] = surfacemaps.validate(with_landmarks(vtkDoubleArray(), [(5, 3.7)]))
    assert not row["Valid"]
    assert any("not an integer (3.7 at vertex 5)" in d for d in row["defects"])


def test_landmark_lists_name_integer_distinct_vertices():
    meshes = [data("ellipsoid.obj"), data("blob.off")]
    with pytest.raises(surfacemaps.InputError, match="same vertex 7"):
        surfacemaps.map_surfaces(meshes, landmarks=[[7, 20, 7], [1, 2, 3]])
    with pytest.raises(surfacemaps.InputError, match="not an integer"):
        surfacemaps.map_surfaces(meshes, landmarks=[[7.5, 20, 30], [1, 2, 3]])
    with pytest.raises(surfacemaps.InputError, match="not an integer"):
        surfacemaps.map_surfaces(meshes, landmarks=[["7", 20, 30], [1, 2, 3]])


def test_write_mesh_into_a_full_disk_raises_and_leaves_nothing(tmp_path):
    """RLIMIT_FSIZE stands in for a full disk; the writer's Write() still returns 1 there."""
    import subprocess
    import sys
    script = (
        "import resource, signal, sys, surfacemaps\n"
        "signal.signal(signal.SIGXFSZ, signal.SIG_IGN)\n"
        "resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))\n"
        "mesh = surfacemaps.read_mesh(sys.argv[1])\n"
        "try:\n"
        "    surfacemaps.write_mesh(mesh, sys.argv[2])\n"
        "except OSError as e:\n"
        "    print('OSError', e)\n")
    out = tmp_path / "mesh.vtp"
    r = subprocess.run([sys.executable, "-c", script, data("limbs.ply"), str(out)], capture_output=True,
                       text=True, timeout=120, env=os.environ)
    assert r.returncode == 0, r.stderr
    assert f"OSError cannot write {out}" in r.stdout
    assert os.listdir(tmp_path) == []


def test_map_surfaces_takes_a_list_of_meshes():
    with pytest.raises(TypeError, match="meshes is a list of meshes or file names"):
        surfacemaps.map_surfaces(data("ellipsoid.obj"))


@pytest.mark.parametrize("setting,value", [("MapWeight", float("nan")), ("MeshWeight", -1.0),
                                           ("CoarseIterations", -3), ("target_error", float("inf"))])
def test_map_settings_outside_their_range_are_refused(setting, value):
    kwargs = {setting: value}
    with pytest.raises(ValueError, match="must be a finite number in"):
        surfacemaps.map_surfaces([data("ellipsoid.obj")], **kwargs)


def _two_component_landmarks():
    array = vtkIntArray()
    array.SetNumberOfComponents(2)
    return with_landmarks(array, [(5, 0)])


@pytest.mark.parametrize("call, match", [
    (lambda: surfacemaps.read_mesh(data("no_such_mesh.obj")), "no_such_mesh.obj"),
    (lambda: surfacemaps.evaluate_map(vtkPolyData(), vtkPolyData()), "contains no vertices"),
    (lambda: surfacemaps.embed_on_sphere(vtkPolyData()), "no vertices|empty"),
    (lambda: surfacemaps.map_surfaces([_two_component_landmarks(),
                                       surfacemaps.read_mesh(data("blob.off"))]), "2 components"),
    (lambda: surfacemaps.average_surfaces([data("ellipsoid_coarse.stl"), data("blob.off")]), "input 1"),
    (lambda: surfacemaps.shape_statistics([data("ellipsoid_coarse.stl"), data("blob.off")]), "input 1"),
], ids=["read_mesh", "evaluate_map", "embed_on_sphere", "map_surfaces", "average_surfaces",
        "shape_statistics"])
def test_the_python_error_is_the_only_message(capfd, call, match):
    """VTK's executive adds "Algorithm ... returned failure for request" (and the request) on
    stderr after a failed update; the Python API raises the filter's error and prints nothing."""
    capfd.readouterr()
    with pytest.raises(surfacemaps.InputError, match=match):
        call()
    err = capfd.readouterr().err
    assert err == "", err


def test_mirror_image_landmarks_raise_a_python_warning(tmp_path, capfd):
    """blob.off mirrored in x with blob.vts's landmark vertices, against ellipsoid.obj and its
    landmarks: a SurfaceMapsWarning naming both inputs (not VTK's output window), and the map
    still runs."""
    lines = [line for line in open(data("blob.off")).read().splitlines()
             if line.strip() and not line.startswith("#")]
    vertices, faces = map(int, lines[1].split()[:2])
    out = ["OFF", lines[1]]
    for line in lines[2:2 + vertices]:
        x, y, z = map(float, line.split()[:3])
        out.append(f"{-x!r} {y!r} {z!r}")
    for line in lines[2 + vertices:2 + vertices + faces]:
        count, *corners = line.split()
        out.append(" ".join([count, *reversed(corners)]))
    mirrored = tmp_path / "blob_mirrored.off"
    mirrored.write_text("\n".join(out) + "\n")
    blob_landmarks = [int(line.split()[0]) for line in open(data("blob.vts")) if line.strip()]
    ellipsoid_landmarks = [int(line.split()[-1]) for line in open(data("ellipsoid.pinned")) if line.strip()]
    capfd.readouterr()
    with pytest.warns(surfacemaps.SurfaceMapsWarning,
                      match=r"landmarks of input 1 \(\S*blob_mirrored.off\) are the mirror image of "
                            r"those of input 0 \(\S*ellipsoid.obj\)"):
        common = surfacemaps.map_surfaces([data("ellipsoid.obj"), str(mirrored)],
                                          landmarks=[ellipsoid_landmarks, blob_landmarks],
                                          LandmarkIterations=10, CoarseIterations=3, FineIterations=3,
                                          RefinementRounds=0)
    assert len(common) == 2 and common[0].GetNumberOfPoints() > 0
    err = capfd.readouterr().err
    assert "mirror image" not in err and "Warning: In" not in err, err
