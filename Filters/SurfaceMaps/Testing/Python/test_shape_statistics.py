"""vtkSurfaceShapeStatistics from Python: shape_statistics."""

import os

import numpy as np
import pytest

import surfacemaps
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPolyData

DATA = os.environ.get("SURFACEMAPS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Data"))


def points(mesh):
    return vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)


def with_points(mesh, xyz):
    copy = vtkPolyData()
    copy.DeepCopy(mesh)
    copy.GetPoints().SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=True))
    return copy


def rotation(angle, axis):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def vertex_areas(mesh):
    """A third of the area of the triangles around each vertex, normalised to sum 1."""
    x = points(mesh)
    t = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    a = 0.5 * np.linalg.norm(np.cross(x[t[:, 1]] - x[t[:, 0]], x[t[:, 2]] - x[t[:, 0]]), axis=1)
    areas = np.zeros(len(x))
    for k in range(3):
        np.add.at(areas, t[:, k], a / 3)
    return areas / areas.sum()


@pytest.fixture(scope="module")
def population():
    """12 ellipsoids: two planted radial fields (sd 0.1 and 0.04, uncorrelated), noise, random poses."""
    base = surfacemaps.read_mesh(os.path.join(DATA, "ellipsoid.obj"))
    x = points(base)
    d = x / np.linalg.norm(x, axis=1)[:, None]
    # Mirror-symmetric like the ellipsoid (no rigid motion takes them up),
    # made orthonormal in the area-weighted inner product the filter uses.
    fields = [d * (3 * d[:, 2:] ** 2 - 1), d * (d[:, :1] ** 2 - d[:, 1:2] ** 2)]
    areas = vertex_areas(base)
    dot = lambda u, w: float((areas[:, None] * u * w).sum())  # noqa: E731
    fields[0] = fields[0] / np.sqrt(dot(fields[0], fields[0]))
    fields[1] = fields[1] - dot(fields[1], fields[0]) * fields[0]
    fields[1] = fields[1] / np.sqrt(dot(fields[1], fields[1]))
    rng = np.random.default_rng(18)
    n = 12
    c = rng.standard_normal((n, 2))
    c -= c.mean(axis=0)
    c[:, 1] -= c[:, 1] @ c[:, 0] / (c[:, 0] @ c[:, 0]) * c[:, 0]
    c *= np.array([0.1, 0.04]) / c.std(axis=0)
    meshes = []
    for i in range(n):
        shape = x + c[i, 0] * fields[0] + c[i, 1] * fields[1] + rng.normal(0, 1e-4, x.shape)
        R = rotation(rng.uniform(-0.5, 0.5), rng.normal(size=3))
        meshes.append(with_points(base, shape @ R.T + rng.uniform(-1, 1, 3)))
    return meshes, fields, c


def test_shape_statistics_arrays(population):
    meshes, fields, c = population
    s = surfacemaps.shape_statistics(meshes, modes=4)
    n, v = len(meshes), meshes[0].GetNumberOfPoints()
    assert s.variances.shape == (4,) and s.explained_fractions.shape == (4,)
    assert s.scores.shape == (n, 4) and s.modes.shape == (4, v, 3)
    assert s.standard_deviation.shape == (v,) and s.alignment_rms.shape == (n,)
    assert np.all(np.diff(s.variances) <= 0)
    assert s.explained_fractions.sum() <= 1 + 1e-12
    # The two planted fields carry almost all of the variance, in their ratio.
    planted = c.var(axis=0)
    assert np.allclose(s.variances[:2], planted, rtol=0.05)
    assert s.explained_fractions[:2].sum() > 0.99
    # Scores: the planted coefficients up to the sign; their mean square is the variance.
    for m in range(2):
        assert abs(np.corrcoef(s.scores[:, m], c[:, m])[0, 1]) > 0.99
    assert np.allclose((s.scores ** 2).mean(axis=0), s.variances, rtol=1e-9, atol=1e-18)
    # The mean output is the mean of the aligned meshes and agrees with average_surfaces.
    average = surfacemaps.average_surfaces(meshes)
    assert np.abs(points(average) - points(s.mean)).max() < 1e-12


def test_shape_along_a_mode(population):
    meshes, _, _ = population
    s = surfacemaps.shape_statistics(meshes, modes=2)
    for mode, coefficient in ((1, 2.0), (2, -1.5)):
        moved = s.shape(mode, coefficient)
        expected = points(s.mean) + coefficient * np.sqrt(s.variances[mode - 1]) * s.modes[mode - 1]
        assert np.abs(points(moved) - expected).max() < 1e-12
    with pytest.raises(ValueError, match="mode is 1 to 2"):
        s.shape(3, 1.0)


def test_order_free(population):
    meshes, _, _ = population
    a = surfacemaps.shape_statistics(meshes, align="similarity")
    b = surfacemaps.shape_statistics(meshes[::-1], align="similarity")
    assert np.abs(points(a.mean) - points(b.mean)).max() < 1e-9 * a.mean.GetLength()
    assert np.allclose(a.variances, b.variances, rtol=1e-9)
    assert np.allclose(a.scores, b.scores[::-1], rtol=0, atol=1e-9)


def test_shape_statistics_errors(population):
    meshes, _, _ = population
    other = surfacemaps.read_mesh(os.path.join(DATA, "ellipsoid_coarse.stl"))
    with pytest.raises(surfacemaps.InputError, match=r"input 2 .*does not have the connectivity of input 0"):
        surfacemaps.shape_statistics([meshes[0], meshes[1], other])
    with pytest.raises(surfacemaps.InputError, match="at least 2"):
        surfacemaps.shape_statistics(meshes[:1])
    with pytest.raises(ValueError, match="align"):
        surfacemaps.shape_statistics(meshes, align="affine")


def test_settings_round_trip():
    s = surfacemaps.vtkSurfaceShapeStatistics()
    assert (s.GetNumberOfModes(), s.GetMode(), s.GetCoefficient()) == (3, 1, 0.0)
    assert s.GetAlignMode() == s.ALIGN_RIGID
    s.SetCoefficient(25.0)
    assert s.GetCoefficient() == 10.0  # clamped
    s.SetAlignModeToSimilarity()
    assert s.GetAlignMode() == s.ALIGN_SIMILARITY
