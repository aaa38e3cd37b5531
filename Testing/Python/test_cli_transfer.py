"""`surfacemap transfer` (and surfacemaps.transfer) on the files of `surfacemap map`."""

import os
import shutil

import pytest

from cli import SHORT, data, read_vtp, refresh_report, run


def write_vtp(mesh, path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(path))
    assert writer.Write() == 1


LABELS = (-5, 3, 17, 42, 1000)


def with_coordinates(path, landmarks, out, corner_tcoords=False, labels=False):
    """The mesh at `path` with the point array "Coordinates" (its own points) and, if asked, a
    synthetic per-corner "CornerTCoords" with a seam at every vertex (u = triangle id, v = corner)
    and random "Label" (int, values from LABELS) and "Mask" (float, 0 or 1) point arrays."""
    import random
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray, vtkIntArray
    import surfacemaps
    mesh = surfacemaps.read_mesh(path, landmarks=landmarks)
    if labels:
        pick = random.Random(19)
        label, mask = vtkIntArray(), vtkFloatArray()
        label.SetName("Label")
        mask.SetName("Mask")
        for v in range(mesh.GetNumberOfPoints()):
            label.InsertNextValue(pick.choice(LABELS))
            mask.InsertNextValue(pick.choice((0.0, 1.0)))
        mesh.GetPointData().AddArray(label)
        mesh.GetPointData().AddArray(mask)
    coordinates = vtkDoubleArray()
    coordinates.SetName("Coordinates")
    coordinates.SetNumberOfComponents(3)
    for v in range(mesh.GetNumberOfPoints()):
        coordinates.InsertNextTuple(mesh.GetPoint(v))
    mesh.GetPointData().AddArray(coordinates)
    if corner_tcoords:
        tcoords = vtkDoubleArray()
        tcoords.SetName("CornerTCoords")
        tcoords.SetNumberOfComponents(6)
        for t in range(mesh.GetNumberOfCells()):
            tcoords.InsertNextTuple([t / 1000.0, 0.0, t / 1000.0, 0.5, t / 1000.0, 1.0])
        mesh.GetCellData().AddArray(tcoords)
    write_vtp(mesh, out)
    return mesh


@pytest.fixture(scope="module")
def map_dir(tmp_path_factory):
    """A map of ellipsoid (input 0, with Coordinates and CornerTCoords) and blob (input 1, with
    Coordinates, Label and Mask), both with landmarks."""
    root = tmp_path_factory.mktemp("transfer")
    with_coordinates(data("ellipsoid.obj"), data("ellipsoid.pinned"), root / "ellipsoid.vtp", corner_tcoords=True)
    with_coordinates(data("blob.off"), data("blob.vts"), root / "blob.vtp", labels=True)
    out = root / "map"
    r = run("map", root / "ellipsoid.vtp", root / "blob.vtp", *SHORT, "--output-dir", out)
    assert r.returncode == 0, r.stderr
    return out


def surface_distance(mesh):
    """Closest-point distance to `mesh`."""
    from vtkmodules.vtkCommonCore import reference
    from vtkmodules.vtkCommonDataModel import vtkGenericCell, vtkStaticCellLocator
    locator = vtkStaticCellLocator()
    locator.SetDataSet(mesh)
    locator.BuildLocator()
    cell = vtkGenericCell()

    def distance(p):
        closest = [0.0, 0.0, 0.0]
        cell_id, sub_id, d2 = reference(0), reference(0), reference(0.0)
        locator.FindClosestPoint(p, closest, cell, cell_id, sub_id, d2)
        return d2.get() ** 0.5
    return distance


def test_map_writes_the_embeddings(map_dir):
    for i, vertices in enumerate((642, 642)):
        embedding = read_vtp(map_dir / f"embedding_{i}.vtp")
        assert embedding.GetNumberOfPoints() == vertices
        sphere = embedding.GetPointData().GetArray("SpherePosition")
        assert sphere is not None and sphere.GetNumberOfComponents() == 3
        assert all(abs(sum(c * c for c in sphere.GetTuple3(v)) - 1.0) < 1e-12 for v in range(vertices))
        assert embedding.GetPointData().GetArray("Coordinates") is not None  # the input's own arrays
    assert read_vtp(map_dir / "embedding_0.vtp").GetCellData().GetArray("CornerTCoords") is not None


def test_coordinates_of_input_0_land_on_input_0(map_dir, tmp_path):
    out = tmp_path / "on_blob.vtp"
    r = run("transfer", map_dir, "--from", "0", "--to", "1", "-o", out)
    assert r.returncode == 0, r.stderr
    assert "input 0 -> input 1: 642 vertices of input 1 received" in r.stdout
    result = read_vtp(out)
    blob = read_vtp(map_dir / "embedding_1.vtp")
    ellipsoid = read_vtp(map_dir / "embedding_0.vtp")
    assert result.GetNumberOfPoints() == blob.GetNumberOfPoints()
    assert [result.GetPoint(v) for v in (0, 100, 641)] == [blob.GetPoint(v) for v in (0, 100, 641)]
    pd = result.GetPointData()
    names = {pd.GetArrayName(a) for a in range(pd.GetNumberOfArrays())}
    assert names == {"Coordinates", "SourceCellId", "SourceBarycentric", "TCoords"}
    assert pd.GetTCoords().GetName() == "TCoords"
    # Every blob vertex receives a point of the ellipsoid's surface ...
    distance = surface_distance(ellipsoid)
    diagonal = ellipsoid.GetLength()
    coordinates = pd.GetArray("Coordinates")
    assert max(distance(coordinates.GetTuple3(v)) for v in range(642)) < 1e-9 * diagonal
    # ... the one SourceCellId and SourceBarycentric name, with the corner texture coordinates
    # of that triangle (u is the triangle id / 1000 on all three corners, v the barycentric mix).
    cells, weights, tcoords = pd.GetArray("SourceCellId"), pd.GetArray("SourceBarycentric"), pd.GetTCoords()
    for v in range(642):
        t, w = int(cells.GetTuple1(v)), weights.GetTuple3(v)
        ids = ellipsoid.GetCell(t).GetPointIds()
        corners = [ellipsoid.GetPoint(ids.GetId(k)) for k in range(3)]
        expected = [sum(w[k] * corners[k][d] for k in range(3)) for d in range(3)]
        assert max(abs(a - b) for a, b in zip(coordinates.GetTuple3(v), expected)) < 1e-12 * diagonal
        assert tcoords.GetTuple2(v) == pytest.approx((t / 1000.0, 0.5 * w[1] + w[2]), abs=1e-12)


def corner_tcoords(mesh):
    array = mesh.GetCellData().GetArray("CornerTCoords")
    assert array is not None and array.GetNumberOfComponents() == 6
    return [array.GetTuple(c) for c in range(array.GetNumberOfTuples())]


def test_corner_texture_coordinates_as_obj_and_split(map_dir, tmp_path):
    import surfacemaps
    vtp, obj, split = tmp_path / "on_blob.vtp", tmp_path / "on_blob.obj", tmp_path / "split.vtp"
    for out, extra in ((vtp, ()), (obj, ()), (split, ("--split-seams",))):
        r = run("transfer", map_dir, "--from", "0", "--to", "1", *extra, "-o", out)
        assert r.returncode == 0, r.stderr
    result = read_vtp(vtp)
    corners = corner_tcoords(result)
    assert len(corners) == result.GetNumberOfPolys() == 1280
    # The OBJ holds the same points, triangles and per-corner coordinates ('vt' per corner).
    text = obj.read_text()
    assert text.count("\nv ") == 642 and text.count("\nf ") == 1280 and "\nvt " in text
    back = surfacemaps.read_mesh(obj)
    assert [back.GetPoint(v) for v in range(642)] == [result.GetPoint(v) for v in range(642)]
    assert corner_tcoords(back) == corners
    # Split: each corner's value on a point of its own, copies of the blob's vertices.
    parted = read_vtp(split)
    original = parted.GetPointData().GetArray("OriginalPointId")
    tcoords = parted.GetPointData().GetTCoords()
    assert parted.GetNumberOfPoints() > 642 and parted.GetNumberOfPolys() == 1280
    for c in range(1280):
        ids = parted.GetCell(c).GetPointIds()
        before = result.GetCell(c).GetPointIds()
        for k in range(3):
            p = ids.GetId(k)
            assert int(original.GetTuple1(p)) == before.GetId(k)
            assert parted.GetPoint(p) == result.GetPoint(before.GetId(k))
            assert tcoords.GetTuple2(p) == corners[c][2 * k:2 * k + 2]


def test_transfer_is_the_map_of_the_mapped_outputs(map_dir, tmp_path):
    # mapped_1 is input 0 carried onto input 1 by the exact map: carrying input 1's coordinates
    # back onto input 0's vertices gives the same points.
    out = tmp_path / "on_ellipsoid.vtp"
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--arrays", "Coordinates", "-o", out)
    assert r.returncode == 0, r.stderr
    result = read_vtp(out)
    mapped = read_vtp(map_dir / "mapped_1.vtp")
    pd = result.GetPointData()
    assert {pd.GetArrayName(a) for a in range(pd.GetNumberOfArrays())} == {
        "Coordinates", "SourceCellId", "SourceBarycentric"}
    coordinates = pd.GetArray("Coordinates")
    for v in range(result.GetNumberOfPoints()):
        assert coordinates.GetTuple3(v) == pytest.approx(mapped.GetPoint(v), abs=1e-12)
        assert pd.GetArray("SourceCellId").GetTuple1(v) == mapped.GetPointData().GetArray("SourceCellId").GetTuple1(v)


def test_python_helper(map_dir):
    import surfacemaps
    result = surfacemaps.transfer(map_dir, source=0, target=1, arrays=["Coordinates"])
    assert result.GetNumberOfPoints() == 642
    assert result.GetPointData().GetArray("Coordinates") is not None
    assert result.GetPointData().GetTCoords() is not None
    with pytest.raises(surfacemaps.InputError, match="has no point array 'Nope'"):
        surfacemaps.transfer(map_dir, 0, 1, arrays=["Nope"])
    with pytest.raises(surfacemaps.InputError, match="has no common_7.vtp, embedding_7.vtp"):
        surfacemaps.transfer(map_dir, 7, 1)
    with pytest.raises(TypeError):
        surfacemaps.transfer(map_dir, "0", 1)


def values(mesh, name):
    array = mesh.GetPointData().GetArray(name)
    assert array is not None, name
    return {array.GetTuple1(v) for v in range(array.GetNumberOfTuples())}


def test_labels_are_categorical_and_flags_choose_per_array(map_dir, tmp_path):
    blob = read_vtp(map_dir / "embedding_1.vtp")
    # By type: the int labels keep to the blob's values, the float mask is interpolated.
    out = tmp_path / "by_type.vtp"
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "-o", out)
    assert r.returncode == 0, r.stderr
    assert "Label (categorical)" in r.stdout and "Mask (continuous)" in r.stdout
    result = read_vtp(out)
    assert values(blob, "Label") == set(map(float, LABELS))
    assert 1 < len(values(result, "Label")) and values(result, "Label") <= values(blob, "Label")
    assert len(values(result, "Mask")) > 2
    # Both the other way.
    out = tmp_path / "chosen.vtp"
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--continuous", "Label", "--categorical", "Mask",
            "-o", out)
    assert r.returncode == 0, r.stderr
    assert "Label (continuous)" in r.stdout and "Mask (categorical)" in r.stdout
    result = read_vtp(out)
    labels = values(result, "Label")
    assert not labels <= set(map(float, LABELS))  # interpolated labels are invented
    assert all(label == round(label) for label in labels)
    assert values(result, "Mask") == {0.0, 1.0}
    assert result.GetPointData().GetArray("Mask").GetDataType() == blob.GetPointData().GetArray("Mask").GetDataType()


def test_array_transfer_flags_are_checked(map_dir, tmp_path):
    out = tmp_path / "out.vtp"
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--categorical", "Nope", "-o", out)
    assert r.returncode == 2
    assert "input 1 (embedding_1.vtp) has no point array 'Nope'" in r.stderr
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--categorical", "Label", "--continuous", "Label",
            "-o", out)
    assert r.returncode == 2 and "'Label' is given both as --categorical and as --continuous" in r.stderr
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "-o", out, "--continuous")
    assert r.returncode == 2 and "--continuous needs a point array name" in r.stderr
    assert not out.exists()
    r = run("transfer", "--help")
    assert "--categorical NAME" in r.stdout and "--continuous NAME" in r.stdout


def test_python_helper_array_modes(map_dir):
    import surfacemaps
    labels = set(map(float, LABELS))
    result = surfacemaps.transfer(map_dir, source=1, target=0)
    assert values(result, "Label") == labels
    result = surfacemaps.transfer(map_dir, source=1, target=0, categorical=["Mask"], continuous=["Label"])
    assert values(result, "Mask") == {0.0, 1.0}
    assert not values(result, "Label") <= labels
    with pytest.raises(ValueError, match="both categorical and continuous"):
        surfacemaps.transfer(map_dir, 1, 0, categorical=["Mask"], continuous=["Mask"])
    with pytest.raises(TypeError):
        surfacemaps.transfer(map_dir, 1, 0, categorical="Mask")  # a list of names, not one string


def test_missing_map_files_are_named(map_dir, tmp_path):
    r = run("transfer", map_dir, "--from", "0", "--to", "5", "-o", tmp_path / "out.vtp")
    assert r.returncode == 2
    assert "has no embedding_5.vtp, common_5.vtp" in r.stderr
    copy = tmp_path / "copy"
    shutil.copytree(map_dir, copy)
    (copy / "embedding_0.vtp").unlink()
    r = run("transfer", copy, "--from", "0", "--to", "1", "-o", tmp_path / "out.vtp")
    assert r.returncode == 2
    assert "has no embedding_0.vtp" in r.stderr and "common_" not in r.stderr
    r = run("transfer", tmp_path / "nowhere", "--from", "0", "--to", "1", "-o", tmp_path / "out.vtp")
    assert r.returncode == 2 and "is not a directory" in r.stderr
    assert not (tmp_path / "out.vtp").exists()


def test_files_that_do_not_fit_are_bad_input(map_dir, tmp_path):
    # common_1 replaced by input 1 itself: not the same triangulation as common_0.
    copy = tmp_path / "copy"
    shutil.copytree(map_dir, copy)
    shutil.copy(copy / "embedding_1.vtp", copy / "common_1.vtp")
    refresh_report(copy, "common_1.vtp")  # consistent as a directory, not as a map
    r = run("transfer", copy, "--from", "1", "--to", "0", "-o", tmp_path / "out.vtp")
    assert r.returncode == 2
    assert "common_1.vtp" in r.stderr and "do not hold the same common triangulation" in r.stderr
    assert not (tmp_path / "out.vtp").exists()


def test_unknown_arrays_and_usage(map_dir, tmp_path):
    out = tmp_path / "out.vtp"
    r = run("transfer", map_dir, "--from", "0", "--to", "1", "--arrays", "Coordinates", "Nope", "-o", out)
    assert r.returncode == 2
    assert "has no point array 'Nope'" in r.stderr and "Coordinates" in r.stderr
    assert run("transfer").returncode == 2
    r = run("transfer", map_dir, "--to", "1", "-o", out)
    assert r.returncode == 2 and "--from I --to J" in r.stderr
    r = run("transfer", map_dir, "--from", "x", "--to", "1", "-o", out)
    assert r.returncode == 2 and "--from needs an input index" in r.stderr
    r = run("transfer", map_dir, "--from", "0", "--to", "1")
    assert r.returncode == 2 and "no output file" in r.stderr
    r = run("transfer", map_dir, "--from", "0", "--to", "1", "--arrays", "-o", out)
    assert r.returncode == 2 and "--arrays needs at least one array name" in r.stderr
    r = run("transfer", map_dir, "--from", "0", "--to", "1", "--bogus", "-o", out)
    assert r.returncode == 2 and "unknown option '--bogus'" in r.stderr
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    r = run("transfer", map_dir, "--from", "0", "--to", "1", "-o", blocker / "out.vtp")
    assert r.returncode == 2 and "cannot write" in r.stderr
    assert not out.exists()
    r = run("transfer", "--help")
    assert r.returncode == 0 and "embedding_I.vtp" in r.stdout and "--arrays" in r.stdout
    assert "transfer" in run("--help").stdout
    assert not [p for p in os.listdir(tmp_path) if ".tmp." in p]


def test_source_data_carries_a_new_array(map_dir, tmp_path):
    import surfacemaps
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    # Input 1's mesh as read from its own file, with an array the map never saw.
    blob = surfacemaps.read_mesh(data("blob.off"))
    temperature = vtkDoubleArray()
    temperature.SetName("Temperature")
    for v in range(blob.GetNumberOfPoints()):
        temperature.InsertNextValue(blob.GetPoint(v)[0])
    blob.GetPointData().AddArray(temperature)
    write_vtp(blob, tmp_path / "blob_temperature.vtp")
    out = tmp_path / "temperature_on_ellipsoid.vtp"
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--source-data", tmp_path / "blob_temperature.vtp",
            "-o", out)
    assert r.returncode == 0, r.stderr
    assert "Temperature (continuous)" in r.stdout
    result = read_vtp(out).GetPointData()
    names = {result.GetArrayName(a) for a in range(result.GetNumberOfArrays())}
    assert names == {"Temperature", "SourceCellId", "SourceBarycentric"}  # not the map-time Label, Mask
    # The same values as input 1's own x coordinates carried by the same map.
    plain = tmp_path / "coordinates_on_ellipsoid.vtp"
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--arrays", "Coordinates", "-o", plain)
    assert r.returncode == 0, r.stderr
    coordinates = read_vtp(plain).GetPointData().GetArray("Coordinates")
    values = result.GetArray("Temperature")
    assert values.GetNumberOfTuples() == 642
    for v in range(642):
        assert values.GetValue(v) == pytest.approx(coordinates.GetTuple3(v)[0], abs=1e-12)


def test_source_data_must_have_the_inputs_connectivity(map_dir, tmp_path):
    import surfacemaps
    out = tmp_path / "out.vtp"
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--source-data", data("ellipsoid_coarse.stl"),
            "-o", out)
    assert r.returncode == 2
    assert (f"--source-data {data('ellipsoid_coarse.stl')} has 162 vertices, input 1 (embedding_1.vtp) has 642: "
            "not the connectivity of input 1") in r.stderr
    # One triangle turned round: same vertex count, other triangles.
    from vtkmodules.vtkCommonCore import vtkIdList
    blob = surfacemaps.read_mesh(data("blob.off"))
    ids = vtkIdList()
    blob.GetCellPoints(5, ids)
    a, b, c = (ids.GetId(k) for k in range(3))
    blob.ReplaceCell(5, 3, [a, c, b])
    write_vtp(blob, tmp_path / "turned.vtp")
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--source-data", tmp_path / "turned.vtp", "-o", out)
    assert r.returncode == 2
    assert (f"--source-data {tmp_path / 'turned.vtp'} has triangle 5 as ({a}, {c}, {b}), input 1 "
            f"(embedding_1.vtp) has ({a}, {b}, {c}): not the connectivity of input 1") in r.stderr
    r = run("transfer", map_dir, "--from", "1", "--to", "0", "--source-data", tmp_path / "missing.vtp", "-o", out)
    assert r.returncode == 2 and "missing.vtp" in r.stderr
    assert not out.exists()
    assert "--source-data MESH" in run("transfer", "--help").stdout


# ---- surfacemaps.transfer in memory and with source_data

SHORT_SETTINGS = dict(LandmarkIterations=10, CoarseIterations=3, FineIterations=3)  # as SHORT


@pytest.fixture(scope="module")
def in_memory(map_dir):
    """map_surfaces on the inputs of map_dir with the same settings: the same map, in memory."""
    import surfacemaps
    root = map_dir.parent
    return surfacemaps.map_surfaces([str(root / "ellipsoid.vtp"), str(root / "blob.vtp")], **SHORT_SETTINGS)


def assert_same_point_arrays(a, b):
    import numpy as np
    import surfacemaps
    mine, theirs = surfacemaps.point_arrays(a), surfacemaps.point_arrays(b)
    assert sorted(mine) == sorted(theirs)
    for name in mine:
        assert mine[name].dtype == theirs[name].dtype, name
        assert np.allclose(mine[name], theirs[name], rtol=0, atol=1e-12), name


def test_in_memory_transfer_equals_the_map_directory(map_dir, in_memory):
    import numpy as np
    import surfacemaps
    from vtkmodules.util.numpy_support import vtk_to_numpy
    # The premise: the CLI and map_surfaces computed the same map.
    for i in (0, 1):
        saved = vtk_to_numpy(read_vtp(map_dir / f"common_{i}.vtp").GetPoints().GetData())
        assert np.array_equal(vtk_to_numpy(in_memory[i].GetPoints().GetData()), saved)
    for source, target in ((1, 0), (0, 1)):
        from_files = surfacemaps.transfer(map_dir, source, target)
        for mapping in (in_memory, in_memory.filter):
            result = surfacemaps.transfer(mapping, source, target)
            assert result.GetNumberOfPoints() == from_files.GetNumberOfPoints() == 642
            assert_same_point_arrays(result, from_files)
    names = set(surfacemaps.point_arrays(surfacemaps.transfer(in_memory, 1, 0)))
    assert {"Label", "Mask", "Coordinates", "SourceCellId", "SourceBarycentric"} <= names
    # The filter is left in its mode, its outputs and the returned list untouched.
    assert in_memory.filter.GetOutputMode() == surfacemaps.vtkSurfaceMapFilter.COMMON_TRIANGULATION
    assert in_memory.filter.GetOutput(1).GetCellData().GetArray("Distortion") is not None
    assert in_memory[1].GetNumberOfPoints() == in_memory.filter.GetOutput(1).GetNumberOfPoints()


def test_in_memory_transfer_restores_the_filters_mode(map_dir):
    import surfacemaps
    root = map_dir.parent
    common, mapped = surfacemaps.map_surfaces([str(root / "ellipsoid.vtp"), str(root / "blob.vtp")],
                                              mapped=True, **SHORT_SETTINGS)
    f = mapped.filter
    result = surfacemaps.transfer(mapped, 1, 0, arrays=["Coordinates"])
    assert_same_point_arrays(result, surfacemaps.transfer(map_dir, 1, 0, arrays=["Coordinates"]))
    assert f.GetOutputMode() == f.MAPPED_INPUT
    # Output 1 is input 0 mapped onto input 1 again (input 0's cells, with Distortion).
    assert f.GetOutput(1).GetNumberOfCells() == 1280
    assert f.GetOutput(1).GetCellData().GetArray("Distortion") is not None
    with pytest.raises(surfacemaps.InputError, match="target is input 2, but the map has 2 inputs"):
        surfacemaps.transfer(common, 0, 2)
    with pytest.raises(TypeError, match="not int"):
        surfacemaps.transfer(3, 0, 1)
    # A map that fails: its error, and the mode stays the user's.
    bad = surfacemaps.vtkSurfaceMapFilter()
    bad.AddInputData(surfacemaps.read_mesh(data("ellipsoid.obj")))
    bad.AddInputData(surfacemaps.read_mesh(data("bad/hemisphere.obj")))
    bad.SetOutputModeToMappedFirstInput()
    with pytest.raises(surfacemaps.InputError, match="input 1 .*is not closed"):
        surfacemaps.transfer(bad, 0, 1)
    assert bad.GetOutputMode() == bad.MAPPED_INPUT


def blob_arrays():
    """New data for input 1 (blob): its z coordinates (float) and random labels (int)."""
    import numpy as np
    import random
    blob = read_vtp_points(data("blob.off"))
    pick = random.Random(7)
    labels = np.array([pick.choice(LABELS) for _ in range(len(blob))], dtype=np.int64)
    return blob, {"Height": blob[:, 2].copy(), "Region": labels, "Pair": blob[:, :2].astype(np.float32)}


def read_vtp_points(path):
    import surfacemaps
    from vtkmodules.util.numpy_support import vtk_to_numpy
    return vtk_to_numpy(surfacemaps.read_mesh(path).GetPoints().GetData()).copy()


@pytest.mark.parametrize("memory", [False, True], ids=["map_dir", "in_memory"])
def test_numpy_source_data_replaces_the_arrays(map_dir, in_memory, memory):
    import numpy as np
    import surfacemaps
    blob, arrays = blob_arrays()
    mapping = in_memory if memory else map_dir
    result = surfacemaps.transfer(mapping, 1, 0, source_data=arrays, as_numpy=True)
    # Instead of the arrays input 1 had at map time (Label, Mask, Coordinates).
    assert set(result) == {"Height", "Region", "Pair", "SourceCellId", "SourceBarycentric"}
    # Continuous: the z of the blob point each ellipsoid vertex is sent to, as Coordinates says.
    coordinates = surfacemaps.transfer(map_dir, 1, 0, arrays=["Coordinates"], as_numpy=True)["Coordinates"]
    assert result["Height"].shape == (642,) and result["Height"].dtype == np.float64
    assert np.allclose(result["Height"], coordinates[:, 2], rtol=0, atol=1e-12)
    assert result["Pair"].shape == (642, 2) and result["Pair"].dtype == np.float32
    assert np.allclose(result["Pair"], coordinates[:, :2], rtol=0, atol=1e-5)
    # Integer labels stay integer, hence categorical: only values the source has.
    assert result["Region"].dtype.kind == "i"
    assert 2 < len(set(result["Region"])) and set(result["Region"]) <= set(arrays["Region"])
    # Asked to interpolate them, labels are invented: the check above could fail.
    blended = surfacemaps.transfer(mapping, 1, 0, source_data=arrays, continuous=["Region"], as_numpy=True)
    assert not set(blended["Region"]) <= set(arrays["Region"])


def test_numpy_source_data_is_checked(map_dir, in_memory):
    import numpy as np
    import surfacemaps
    blob, arrays = blob_arrays()
    with pytest.raises(surfacemaps.InputError, match=r"source_data array 'Height' has 641 rows, "
                       r"input 1 \(embedding_1.vtp\) has 642 vertices: one row per vertex"):
        surfacemaps.transfer(map_dir, 1, 0, source_data={"Height": arrays["Height"][:-1]})
    with pytest.raises(surfacemaps.InputError, match="source_data array 'Height' has 643 rows, input 1 has 642"):
        surfacemaps.transfer(in_memory, 1, 0, source_data={"Height": np.append(arrays["Height"], 0.0)})
    with pytest.raises(surfacemaps.InputError, match="source_data array 'Name' has dtype <U1: not numeric"):
        surfacemaps.transfer(map_dir, 1, 0, source_data={"Name": np.array(["a"] * 642)})
    with pytest.raises(surfacemaps.InputError, match="source_data array 'Flag' has dtype bool: not numeric"):
        surfacemaps.transfer(map_dir, 1, 0, source_data={"Flag": np.ones(642, dtype=bool)})
    with pytest.raises(surfacemaps.InputError, match=r"source_data array 'Cube' has shape \(642, 2, 2\)"):
        surfacemaps.transfer(map_dir, 1, 0, source_data={"Cube": np.zeros((642, 2, 2))})
    with pytest.raises(surfacemaps.InputError, match="source_data has no point array 'Label'"):
        surfacemaps.transfer(map_dir, 1, 0, source_data=arrays, categorical=["Label"])
    with pytest.raises(surfacemaps.InputError, match="cannot replace 'SpherePosition'"):
        surfacemaps.transfer(map_dir, 1, 0, source_data={"SpherePosition": blob})
    with pytest.raises(TypeError, match="source_data is a dict"):
        surfacemaps.transfer(map_dir, 1, 0, source_data=[arrays["Height"]])


def test_polydata_source_data(map_dir, in_memory):
    import numpy as np
    import surfacemaps
    from vtkmodules.vtkCommonCore import vtkIdList
    from vtkmodules.util.numpy_support import numpy_to_vtk
    blob, arrays = blob_arrays()
    mesh = surfacemaps.read_mesh(data("blob.off"))  # input 1 with a new array
    height = numpy_to_vtk(arrays["Height"], deep=True)
    height.SetName("Height")
    mesh.GetPointData().AddArray(height)
    expected = surfacemaps.transfer(map_dir, 1, 0, source_data={"Height": arrays["Height"]}, as_numpy=True)
    for mapping in (map_dir, in_memory):
        result = surfacemaps.transfer(mapping, 1, 0, source_data=mesh, as_numpy=True)
        assert set(result) == {"Height", "SourceCellId", "SourceBarycentric"}
        assert np.array_equal(result["Height"], expected["Height"])
    # Other vertex count, then one triangle turned round: named as the command line names them.
    with pytest.raises(surfacemaps.InputError, match=r"source_data has 162 vertices, input 1 \(embedding_1.vtp\) "
                       "has 642: not the connectivity of input 1"):
        surfacemaps.transfer(map_dir, 1, 0, source_data=surfacemaps.read_mesh(data("ellipsoid_coarse.stl")))
    ids = vtkIdList()
    mesh.GetCellPoints(5, ids)
    a, b, c = (ids.GetId(k) for k in range(3))
    mesh.ReplaceCell(5, 3, [a, c, b])
    with pytest.raises(surfacemaps.InputError, match=rf"source_data has triangle 5 as \({a}, {c}, {b}\), input 1 "
                       rf"has \({a}, {b}, {c}\): not the connectivity of input 1"):
        surfacemaps.transfer(in_memory, 1, 0, source_data=mesh)
    # The same triangle starting at another corner is the same connectivity.
    mesh.ReplaceCell(5, 3, [b, c, a])
    assert surfacemaps.transfer(in_memory, 1, 0, source_data=mesh).GetNumberOfPoints() == 642
