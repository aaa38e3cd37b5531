"""vtkSurfaceMapFilter from Python: ports before Update, a three-input pipeline, map_surfaces."""

import os

import numpy as np
import pytest

import surfacemaps
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonExecutionModel import vtkTrivialProducer
from vtkmodules.util.numpy_support import vtk_to_numpy

DATA = os.environ.get("SURFACEMAPS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Data"))

# Short schedules keep every map here around a second.
SHORT = dict(LandmarkIterations=10, CoarseIterations=3, FineIterations=3)


def data(name):
    return os.path.join(DATA, name)


def triangles(mesh):
    return vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)


def signed_volumes(points, tri):
    a, b, c = points[tri[:, 0]], points[tri[:, 1]], points[tri[:, 2]]
    return np.einsum("ij,ij->i", a, np.cross(b, c))


def test_output_ports_follow_the_connections_before_update():
    f = surfacemaps.vtkSurfaceMapFilter()
    assert f.GetNumberOfOutputPorts() == 1
    producers = []
    for name in ("ellipsoid_coarse.stl", "blob.off"):
        p = vtkTrivialProducer()
        p.SetOutput(surfacemaps.read_mesh(data(name)))
        producers.append(p)
        f.AddInputConnection(p.GetOutputPort())
    assert f.GetNumberOfOutputPorts() == 2
    f.AddInputData(surfacemaps.read_mesh(data("limbs_coarse.vtk")))
    assert f.GetNumberOfOutputPorts() == 3
    assert f.GetOutputPort(2) is not None and f.GetOutputPort(2).GetIndex() == 2
    f.RemoveInputConnection(0, producers[1].GetOutputPort())
    assert f.GetNumberOfOutputPorts() == 2
    f.SetInputConnection(producers[0].GetOutputPort())
    assert f.GetNumberOfOutputPorts() == 1


def test_three_input_pipeline():
    readers = []
    f = surfacemaps.vtkSurfaceMapFilter()
    for key, value in SHORT.items():
        getattr(f, "Set" + key)(value)
    for name in ("ellipsoid_coarse.stl", "blob.off", "limbs_coarse.vtk"):
        reader = surfacemaps.vtkSurfaceMeshReader()
        reader.SetFileName(data(name))
        f.AddInputConnection(reader.GetOutputPort())
        readers.append(reader)
    progress, errors = [], []
    f.AddObserver(vtkCommand.ProgressEvent, lambda o, e: progress.append(o.GetProgress()))
    f.AddObserver(vtkCommand.ErrorEvent, lambda o, e: errors.append(e))

    # Connected downstream before the first update: map 0 -> 2 measured.
    evaluation = surfacemaps.vtkSurfaceMapEvaluation()
    evaluation.SetSourceConnection(f.GetOutputPort(0))
    evaluation.SetTargetConnection(f.GetOutputPort(2))
    evaluation.SetSourceOriginalConnection(readers[0].GetOutputPort())
    evaluation.SetTargetOriginalConnection(readers[2].GetOutputPort())
    evaluation.Update()
    assert not errors
    assert evaluation.GetSummaryValue("Bijective") == 1.0
    assert evaluation.GetSummaryValue("SymmetricDirichlet") >= 1.0
    assert 0.0 < evaluation.GetSummaryValue("HausdorffTarget") < 5.0

    outputs = [f.GetOutput(i) for i in range(3)]
    tri = triangles(outputs[0])
    assert len(tri) > 4
    for i, out in enumerate(outputs):
        assert np.array_equal(triangles(out), tri)
        s = vtk_to_numpy(out.GetPointData().GetArray("SpherePosition"))
        assert np.allclose(np.linalg.norm(s, axis=1), 1.0)
        assert (signed_volumes(s, tri) > 0).all()
        cells = vtk_to_numpy(out.GetPointData().GetArray("SourceCellId"))
        weights = vtk_to_numpy(out.GetPointData().GetArray("SourceBarycentric"))
        source = readers[i].GetOutput()
        corners = vtk_to_numpy(source.GetPoints().GetData())[triangles(source)[cells]]
        assert np.allclose(np.einsum("ij,ijk->ik", weights, corners),
                           vtk_to_numpy(out.GetPoints().GetData()), atol=1e-9 * source.GetLength())
        assert out.GetCellData().GetArray("Distortion").GetNumberOfTuples() == len(tri)
        fields = out.GetFieldData()
        assert fields.GetArray("Bijective").GetValue(0) == 1
        assert fields.GetArray("InputIndex").GetValue(0) == i
        assert fields.GetAbstractArray("FileName").GetValue(0) == source.GetFieldData().GetAbstractArray(
            "FileName").GetValue(0)
        phases = fields.GetAbstractArray("PhaseName")
        names = [phases.GetValue(k) for k in range(phases.GetNumberOfValues())]
        # Refinement rounds (at most 3) where the exact map is distorted.
        assert names[:2] == ["coarse", "fine"] and set(names[2:]) <= {"refine"} and len(names) <= 5
        assert all(fields.GetArray("PhaseIterations").GetValue(k) <= 3 for k in range(1, len(names)))
    assert progress == sorted(progress) and progress[-1] == 1.0


def test_map_surfaces_from_files_with_landmarks():
    common, mapped = surfacemaps.map_surfaces([data("ellipsoid.obj"), data("blob.off")],
                                              landmarks=[data("ellipsoid.pinned"), data("blob.vts")],
                                              mapped=True, **SHORT)
    assert len(common) == 2 and len(mapped) == 2
    assert np.array_equal(triangles(common[0]), triangles(common[1]))
    assert common[0].GetFieldData().GetAbstractArray("PhaseName").GetValue(0) == "landmarks"
    # Landmarks held exactly: T's landmark vertices sit on the inputs' landmark vertices.
    blob = surfacemaps.read_mesh(data("blob.off"), landmarks=data("blob.vts"))
    blob_ids = vtk_to_numpy(blob.GetPointData().GetArray("Landmarks"))
    blob_points = vtk_to_numpy(blob.GetPoints().GetData())
    ids = vtk_to_numpy(common[1].GetPointData().GetArray("Landmarks"))
    points = vtk_to_numpy(common[1].GetPoints().GetData())
    assert sorted(ids[ids >= 0]) == [0, 1, 2, 3]
    for v in np.flatnonzero(ids >= 0):
        assert np.allclose(points[v], blob_points[blob_ids == ids[v]][0], atol=1e-12)
    # The exact map: the ellipsoid's connectivity, its landmarks onto blob's.
    ellipsoid = surfacemaps.read_mesh(data("ellipsoid.obj"))
    assert np.array_equal(triangles(mapped[1]), triangles(ellipsoid))
    mapped_ids = vtk_to_numpy(mapped[1].GetPointData().GetArray("Landmarks"))
    mapped_points = vtk_to_numpy(mapped[1].GetPoints().GetData())
    for v in np.flatnonzero(mapped_ids >= 0):
        assert np.allclose(mapped_points[v], blob_points[blob_ids == mapped_ids[v]][0], atol=1e-9)
    assert surfacemaps.evaluate_map(mapped[0], mapped[1])["SymmetricDirichlet"] >= 1.0


def test_map_surfaces_landmarks_as_vertex_ids():
    a = surfacemaps.read_mesh(data("ellipsoid_coarse.stl"))
    b = surfacemaps.read_mesh(data("limbs_coarse.vtk"))
    ends = [[int(np.argmax(vtk_to_numpy(m.GetPoints().GetData())[:, k])) for k in range(3)] for m in (a, b)]
    (out_a, out_b) = surfacemaps.map_surfaces([a, b], landmarks=ends, **SHORT)
    assert a.GetPointData().GetArray("Landmarks") is None  # the caller's mesh is untouched
    ids = vtk_to_numpy(out_b.GetPointData().GetArray("Landmarks"))
    assert sorted(ids[ids >= 0]) == [0, 1, 2]
    with pytest.raises(surfacemaps.InputError, match="landmark 1 is vertex 100000"):
        surfacemaps.map_surfaces([a, b], landmarks=[[0, 100000], [0, 1]])


def test_map_surfaces_array_modes():
    from vtkmodules.util.numpy_support import numpy_to_vtk
    rng = np.random.default_rng(3)
    meshes = []
    for name in ("ellipsoid_coarse.stl", "limbs_coarse.vtk"):
        mesh = surfacemaps.read_mesh(data(name))
        for array_name in ("Label", "Percent"):
            array = numpy_to_vtk(rng.choice([0, 100], mesh.GetNumberOfPoints()).astype(np.int32), deep=True)
            array.SetName(array_name)
            mesh.GetPointData().AddArray(array)
        meshes.append(mesh)
    common = surfacemaps.map_surfaces(meshes, continuous=["Percent"], **SHORT)
    for out in common:
        labels = vtk_to_numpy(out.GetPointData().GetArray("Label"))
        percents = vtk_to_numpy(out.GetPointData().GetArray("Percent"))
        assert set(np.unique(labels)) <= {0, 100}  # categorical by type: no invented labels
        assert len(set(np.unique(percents)) - {0, 100}) > 0  # chosen continuous: interpolated
    with pytest.raises(ValueError, match="both categorical and continuous"):
        surfacemaps.map_surfaces(meshes, categorical=["Label"], continuous=["Label"])
    with pytest.raises(TypeError, match="lists of array names"):
        surfacemaps.map_surfaces(meshes, categorical="Label")


def test_map_surfaces_population_preset():
    names = ("ellipsoid_coarse.stl", "limbs_coarse.vtk", "blob.off")
    assert set(surfacemaps.presets()) == {"pair", "population"}
    assert "RefinementRounds 0" in surfacemaps.presets()["population"]
    common = surfacemaps.map_surfaces([data(n) for n in names], preset="population", BlockSolveInputs=3,
                                      **SHORT)
    fields = common[0].GetFieldData()
    assert fields.GetArray("Bijective").GetValue(0) == 1
    assert len({out.GetNumberOfPoints() for out in common}) == 1
    with pytest.raises(ValueError, match="preset is one of"):
        surfacemaps.map_surfaces([data(names[0])], preset="crowd")


def test_map_surfaces_errors():
    with pytest.raises(surfacemaps.InputError, match=r"input 1 \(.*torus.obj\) has genus 1"):
        surfacemaps.map_surfaces([data("ellipsoid_coarse.stl"), surfacemaps.read_mesh(data("bad/torus.obj"))])
    with pytest.raises(TypeError, match="no setting 'Iterations'"):
        surfacemaps.map_surfaces([data("ellipsoid_coarse.stl")], Iterations=3)
    with pytest.raises(surfacemaps.InputError, match="no meshes"):
        surfacemaps.map_surfaces([])
    with pytest.raises(ValueError, match="pairs"):
        surfacemaps.map_surfaces([data("ellipsoid_coarse.stl")], pairs="ring")


def test_settings_round_trip_and_clamp():
    f = surfacemaps.vtkSurfaceMapFilter()
    assert f.GetTargetError() == 1e-3 and f.GetFineIterations() == 50 and f.GetKeepLandmarks()
    f.SetPairModeToSequence()
    assert f.GetPairMode() == surfacemaps.vtkSurfaceMapFilter.PAIRS_SEQUENCE
    f.SetOutputMode(5)
    assert f.GetOutputMode() == surfacemaps.vtkSurfaceMapFilter.INPUT_EMBEDDINGS
    f.SetMappedInput(-1)
    assert f.GetMappedInput() == 0
    f.SetTargetError(10.0)
    assert f.GetTargetError() == 1.0


def test_settings_table_is_the_filters():
    rows = surfacemaps.settings_table()
    f = surfacemaps.vtkSurfaceMapFilter()
    assert len(rows) == f.GetNumberOfSettings() >= 30
    by_name = {row["name"]: row for row in rows}
    assert by_name["PairMode"]["choices"] == ["star", "sequence", "cycle", "all", "mean"]
    assert by_name["KeepLandmarks"]["type"] == "switch"
    for row in rows:
        assert getattr(f, "Get" + row["name"])() == row["default"], row["name"]
        assert row["minimum"] <= row["default"] <= row["maximum"], row["name"]
    with pytest.raises(TypeError):
        surfacemaps.map_surfaces(["never_read.obj"], KinkRetries=1)  # removed setting


def test_docstrings_and_tables_come_from_the_list():
    S = surfacemaps.vtkSurfaceMapsSettings
    for of, table, function in (("map", S.MAP_SETTINGS, surfacemaps.map_surfaces),
                                ("sphere_embedding", S.SPHERE_EMBEDDING_SETTINGS, surfacemaps.embed_on_sphere)):
        rows = surfacemaps.settings_table(of)
        assert [row["name"] for row in rows] == [S.GetName(table, i) for i in range(S.GetNumberOfSettings(table))]
        doc = " ".join(function.__doc__.split())
        for row in rows:
            assert f"``{row['name']}``: {row['description']}" in doc, row["name"]
    f = surfacemaps.vtkSphereEmbeddingFilter()
    for row in surfacemaps.settings_table("sphere_embedding"):
        assert getattr(f, "Get" + row["name"])() == row["default"], row["name"]
