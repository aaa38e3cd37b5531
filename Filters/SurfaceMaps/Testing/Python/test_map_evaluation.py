"""vtkSurfaceMapEvaluation: metrics of DESIGN.md section 6 from a VTK pipeline."""

import os

import numpy as np
import pytest

import surfacemaps
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

DATA = os.environ.get("SURFACEMAPS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Data"))


def data(name):
    return os.path.join(DATA, name)


def with_points(mesh, points):
    copy = vtkPolyData()
    copy.DeepCopy(mesh)
    copy.GetPoints().SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=True))
    return copy


def evaluate(source, target, *originals):
    e = surfacemaps.vtkSurfaceMapEvaluation()
    errors = []
    e.AddObserver(vtkCommand.ErrorEvent, lambda o, ev, text=None: errors.append(ev))
    e.SetInputData(0, source)
    e.SetInputData(1, target)
    for k, o in enumerate(originals):
        e.SetInputData(2 + k, o)
    e.Update()
    return e, errors


def test_identity_and_known_stretch():
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    e, errors = evaluate(mesh, mesh)
    assert not errors
    assert e.GetSummaryValue("SymmetricDirichlet") == pytest.approx(1.0, abs=1e-12)
    assert e.GetSummaryValue("MaxDistortion") == pytest.approx(1.0, abs=1e-9)
    assert e.GetSummaryValue("AreaBelow1.5") == 1.0
    p = vtk_to_numpy(mesh.GetPoints().GetData()).copy()
    stretched = with_points(mesh, p * np.array([2.0, 1.0, 1.0]))
    e, _ = evaluate(mesh, stretched)
    assert e.GetSummaryValue("SymmetricDirichlet") > 1.01
    d = vtk_to_numpy(e.GetOutput().GetCellData().GetArray("MaxStretch"))
    assert d.shape == (1280,) and (d >= 1.0 - 1e-12).all()
    curve = vtk_to_numpy(e.GetOutput().GetFieldData().GetArray("DistortionCurve"))
    assert curve.shape == (201, 2) and (np.diff(curve[:, 1]) >= 0).all() and curve[-1, 1] <= 1.0


def test_independent_numpy_computation():
    # Symmetric Dirichlet of DESIGN.md section 6 with numpy SVDs, on a smooth deformation.
    mesh = surfacemaps.read_mesh(data("blob.off"))
    p = vtk_to_numpy(mesh.GetPoints().GetData()).copy()
    q = np.column_stack([p[:, 0] * (1 + 0.3 * p[:, 2]), 0.7 * p[:, 1] + 0.2 * p[:, 0] ** 2,
                         p[:, 2] + 0.25 * np.sin(3 * p[:, 0])])
    e, _ = evaluate(mesh, with_points(mesh, q))
    tri = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)

    def unit(x):
        a = 0.5 * np.linalg.norm(np.cross(x[tri[:, 1]] - x[tri[:, 0]], x[tri[:, 2]] - x[tri[:, 0]]), axis=1)
        c = (a[:, None] * x[tri].mean(axis=1)).sum(axis=0) / a.sum()
        return (x - c) / np.sqrt(a.sum())

    P, Q = unit(p), unit(q)
    EP = np.stack([P[tri[:, 1]] - P[tri[:, 0]], P[tri[:, 2]] - P[tri[:, 0]]], axis=2)
    EQ = np.stack([Q[tri[:, 1]] - Q[tri[:, 0]], Q[tri[:, 2]] - Q[tri[:, 0]]], axis=2)
    J = EQ @ np.linalg.pinv(EP)
    s = np.linalg.svd(J, compute_uv=False)[:, :2]
    aP = 0.5 * np.linalg.norm(np.cross(EP[:, :, 0], EP[:, :, 1]), axis=1)
    aQ = 0.5 * np.linalg.norm(np.cross(EQ[:, :, 0], EQ[:, :, 1]), axis=1)
    sd = 0.25 * (aQ * (s ** 2).sum(axis=1) + aP * (s ** -2).sum(axis=1)).sum()
    assert e.GetSummaryValue("SymmetricDirichlet") == pytest.approx(sd, rel=1e-3)
    assert e.GetSummaryValue("MaxDistortion") == pytest.approx(np.maximum(s[:, 0], 1 / s[:, 1]).max(), rel=1e-9)


def test_embedding_distortion_agrees_and_certificate():
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    embedded = surfacemaps.embed_on_sphere(mesh)
    on_sphere = with_points(embedded, vtk_to_numpy(embedded.GetPointData().GetArray("SpherePosition")))
    e, _ = evaluate(embedded, on_sphere, mesh)
    assert e.GetSummaryValue("SymmetricDirichlet") == pytest.approx(
        embedded.GetFieldData().GetArray("EmbeddingDistortion").GetValue(0), rel=1e-12)
    assert e.GetSummaryValue("Bijective") == 1.0
    assert e.GetSummaryValue("HausdorffSource") == pytest.approx(0.0, abs=1e-12)


def test_degenerate_and_mismatched():
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    p = vtk_to_numpy(mesh.GetPoints().GetData()).copy()
    tri = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    p[tri[0, 1]] = p[tri[0, 0]]
    e, errors = evaluate(mesh, with_points(mesh, p))
    assert not errors
    assert e.GetSummaryValue("DegenerateTriangles") > 0
    assert np.isinf(e.GetSummaryValue("MaxDistortion"))
    e, errors = evaluate(mesh, surfacemaps.read_mesh(data("limbs.ply")))
    assert errors and e.GetOutput().GetNumberOfPoints() == 0


def test_inverted_triangle_is_reported():
    # A fold in one sphere embedding: the certificate fails and says how many triangles.
    good = surfacemaps.embed_on_sphere(surfacemaps.read_mesh(data("ellipsoid.obj")))
    folded = vtkPolyData()
    folded.DeepCopy(good)
    s = vtk_to_numpy(folded.GetPointData().GetArray("SpherePosition"))
    s[0] = -s[0]  # vertex 0 to the antipode: its triangles turn over
    folded.GetPointData().GetArray("SpherePosition").Modified()
    e, errors = evaluate(good, folded)
    assert not errors
    assert e.GetSummaryValue("Bijective") == 0.0
    assert e.GetSummaryValue("NonPositiveTriangles") >= 5
    e, _ = evaluate(good, good)
    assert e.GetSummaryValue("Bijective") == 1.0
    assert e.GetSummaryValue("NonPositiveTriangles") == 0.0


def test_distances_to_the_originals():
    # The icosphere-like ellipsoid against a coarser ellipsoid of the same
    # shape: both distances are small, positive, and the two-sided one >= H.
    fine = surfacemaps.read_mesh(data("ellipsoid.obj"))
    coarse = surfacemaps.read_mesh(data("ellipsoid_coarse.stl"))
    e, _ = evaluate(fine, fine, coarse, fine)
    h = e.GetSummaryValue("HausdorffSource")
    two = e.GetSummaryValue("TwoSidedDistanceSource")
    assert 0.0 < h < 5.0
    assert two >= h
    assert e.GetSummaryValue("HausdorffTarget") == pytest.approx(0.0, abs=1e-12)
    assert e.GetSummaryValue("TwoSidedDistanceTarget") == pytest.approx(0.0, abs=1e-9)


def test_distances_agree_with_vtk_implicit_distance():
    # H and the two-sided distance against VTK's own closest-point distance
    # (vtkImplicitPolyDataDistance), point by point over the same samples:
    # vertices, edge midpoints and centroids. Thousands of samples, so the
    # evaluation splits them over its threads.
    from vtkmodules.vtkFiltersCore import vtkImplicitPolyDataDistance

    original = surfacemaps.read_mesh(data("ellipsoid.obj"))
    points = vtk_to_numpy(original.GetPoints().GetData())
    rng = np.random.default_rng(7)
    approximation = with_points(original, points + 0.01 * rng.standard_normal(points.shape))
    e, errors = evaluate(approximation, approximation, original, original)
    assert not errors

    def samples(mesh):
        p = vtk_to_numpy(mesh.GetPoints().GetData())
        t = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
        a, b, c = p[t[:, 0]], p[t[:, 1]], p[t[:, 2]]
        return np.vstack([a, b, c, (a + b) / 2, (b + c) / 2, (a + c) / 2, (a + b + c) / 3])

    def largest(points, surface):
        distance = vtkImplicitPolyDataDistance()
        distance.SetInput(surface)
        return max(abs(distance.EvaluateFunction(*map(float, x))) for x in points)

    diagonal = original.GetLength()
    assert len(samples(original)) > 4 * 1024
    h = 100.0 * largest(vtk_to_numpy(original.GetPoints().GetData()), approximation) / diagonal
    two = max(largest(samples(original), approximation), largest(samples(approximation), original))
    two *= 100.0 / diagonal
    assert h > 0.0
    assert e.GetSummaryValue("HausdorffSource") == pytest.approx(h, rel=1e-9)
    assert e.GetSummaryValue("TwoSidedDistanceSource") == pytest.approx(two, rel=1e-9)
    assert e.GetSummaryValue("HausdorffTarget") == pytest.approx(h, rel=1e-9)


def test_an_upstream_failure_leaves_no_stale_figures(tmp_path):
    # The pattern the package documents: after Update(), check the error code before reading the
    # figures. A reader failing upstream empties the evaluation and sets its error code; it never
    # keeps the previous update's figures.
    import shutil
    from vtkmodules.vtkCommonCore import vtkOutputWindow
    copy = tmp_path / "target.obj"
    shutil.copy(data("ellipsoid.obj"), copy)
    readers = []
    e = surfacemaps.vtkSurfaceMapEvaluation()
    for port, path in enumerate((data("ellipsoid.obj"), str(copy))):
        reader = surfacemaps.vtkSurfaceMeshReader()
        reader.SetFileName(path)
        e.SetInputConnection(port, reader.GetOutputPort())
        readers.append(reader)
    e.Update()
    assert e.GetErrorCode() == 0 and e.GetOutput().GetFieldData().GetArray("SymmetricDirichlet") is not None
    copy.unlink()
    readers[1].Modified()
    window = vtkOutputWindow.GetInstance()
    mode = window.GetDisplayMode()
    window.SetDisplayModeToNever()  # the failure is expected: keep the test's output clean
    try:
        e.Update()
    finally:
        window.SetDisplayMode(mode)
    assert e.GetErrorCode() == surfacemaps.vtkSurfaceMapFilter.InvalidInputError
    assert "was not produced: vtkSurfaceMeshReader failed" in e.GetLastErrorMessage()
    assert e.GetOutput().GetNumberOfPoints() == 0
    assert e.GetOutput().GetFieldData().GetArray("SymmetricDirichlet") is None
