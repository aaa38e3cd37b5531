"""surfacemaps.synthetic: valid, landmarked, differently triangulated tubes that bend more with time."""

import numpy as np
import pytest

import surfacemaps
from surfacemaps import synthetic
from vtkmodules.util.numpy_support import vtk_to_numpy


def points(mesh):
    return vtk_to_numpy(mesh.GetPoints().GetData())


def triangles(mesh):
    return vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)


def landmarks(mesh):
    return vtk_to_numpy(mesh.GetPointData().GetArray("Landmarks"))


def enclosed_volume(mesh):
    p = points(mesh)[triangles(mesh)]
    return np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0


def landmark_points(mesh):
    ids = landmarks(mesh)
    return {int(ids[v]): points(mesh)[v] for v in np.flatnonzero(ids >= 0)}


def test_specimens_are_valid_inputs():
    series = synthetic.time_series(stages=3, specimens_per_stage=3, seed=4, resolution=14)
    meshes = [m for _, stage in series for m in stage]
    rows = surfacemaps.validate(*meshes)
    for row, mesh in zip(rows, meshes):
        assert row["Valid"], row["defects"]
        assert row["Genus"] == 0 and row["BoundaryEdges"] == 0
        assert enclosed_volume(mesh) > 0.0  # outward, not only consistent
    # The ideal tube and the extremes of the settings too.
    for t in (0.0, 1.0):
        for mesh in (synthetic.tube_mesh(t, around=6), synthetic.tube_mesh(t, around=40, seed=1, shape_noise=0.08,
                                                                           jitter=0.5, pose_noise=0.2)):
            row, = surfacemaps.validate(mesh)
            assert row["Valid"], row["defects"]


def test_landmarks_correspond():
    series = synthetic.time_series(stages=2, specimens_per_stage=4, seed=2, resolution=12)
    for t, stage in series:
        for mesh in stage:
            ids = landmarks(mesh)
            assert ids.dtype == np.int32
            assert sorted(ids[ids >= 0]) == [0, 1, 2]
        # Same id, same place: across specimens (noise, pose) a landmark moves far less than the
        # distance between different landmarks (positions relative to the centroid: no translation).
        found = [{k: p - points(mesh).mean(axis=0) for k, p in landmark_points(mesh).items()} for mesh in stage]
        size = min(np.linalg.norm(f[0] - f[1]) for f in found)
        for landmark in (0, 1, 2):
            spread = max(np.linalg.norm(f[landmark] - g[landmark]) for f in found for g in found)
            assert spread < 0.2 * size, (t, landmark, spread, size)
        # validate checks that ids match across the stage's meshes
        assert all(row["Valid"] for row in surfacemaps.validate(*stage))
    # The outer-curvature landmark is on the convex side of the bend: farther from the chord than the centre.
    mesh = synthetic.tube_mesh(1.0)
    tips = landmark_points(mesh)
    centre = points(mesh).mean(axis=0)
    chord_middle = 0.5 * (tips[0] + tips[1])
    assert np.linalg.norm(tips[2] - chord_middle) > np.linalg.norm(centre - chord_middle)


def test_specimens_have_different_triangulations():
    stage = synthetic.specimens(0.5, 4, seed=9, resolution=16)
    counts = {(m.GetNumberOfPoints(), m.GetNumberOfPolys()) for m in stage}
    assert len(counts) >= 3
    # Even at the same vertex count the connectivity and positions differ (ring offsets, jitter).
    a = synthetic.tube_mesh(0.5, around=16, seed=1, jitter=0.3)
    b = synthetic.tube_mesh(0.5, around=16, seed=2, jitter=0.3)
    assert a.GetNumberOfPoints() == b.GetNumberOfPoints()
    assert not np.array_equal(triangles(a), triangles(b))
    assert not np.allclose(points(a), points(b))


def test_deterministic_per_seed():
    a = synthetic.time_series(stages=2, specimens_per_stage=2, seed=5, resolution=12)
    b = synthetic.time_series(stages=2, specimens_per_stage=2, seed=5, resolution=12)
    c = synthetic.time_series(stages=2, specimens_per_stage=2, seed=6, resolution=12)
    for (ta, sa), (tb, sb), (_, sc) in zip(a, b, c):
        assert ta == tb
        for ma, mb, mc in zip(sa, sb, sc):
            assert np.array_equal(points(ma), points(mb))
            assert np.array_equal(triangles(ma), triangles(mb))
            assert not np.array_equal(points(ma), points(mc))
    t = a[1][1][0].GetFieldData().GetArray("DevelopmentalTime").GetValue(0)
    assert abs(t - 1.0) < 0.1
    assert a[1][1][1].GetFieldData().GetArray("Specimen").GetValue(0) == 1
    assert a[1][1][1].GetFieldData().GetArray("Stage").GetValue(0) == 1
    t1, alone = synthetic.stage_specimens(1, 2, specimens_per_stage=2, seed=5, resolution=12)
    assert t1 == a[1][0] and all(np.array_equal(points(m), points(n)) for m, n in zip(alone, a[1][1]))


def bending(mesh):
    """Largest distance of the surface from the straight line through the two tips, over the tips' distance."""
    tips = landmark_points(mesh)
    axis = (tips[1] - tips[0]) / np.linalg.norm(tips[1] - tips[0])
    d = points(mesh) - tips[0]
    off_axis = d - np.outer(d @ axis, axis)
    return np.linalg.norm(off_axis, axis=1).max() / np.linalg.norm(tips[1] - tips[0])


def test_bending_grows_with_time():
    ideal = [bending(synthetic.tube_mesh(t)) for t in np.linspace(0.0, 1.0, 6)]
    assert all(b > a for a, b in zip(ideal[:-1], ideal[1:])), ideal
    assert ideal[0] < 0.15 and ideal[-1] > 0.6  # straight (only the radius off the axis) to looped
    # The noisy specimens' stage means follow.
    means = [np.mean([bending(m) for m in stage])
             for _, stage in synthetic.time_series(stages=4, specimens_per_stage=3, seed=3, resolution=12)]
    assert all(b > a for a, b in zip(means[:-1], means[1:])), means
    # ... while the tube stays one piece of the expected length.
    for t in (0.0, 1.0):
        extent = np.ptp(points(synthetic.tube_mesh(t)), axis=0).max()
        assert extent < synthetic.tube_length(t) + 0.5


def test_bad_settings():
    with pytest.raises(ValueError, match="around"):
        synthetic.tube_mesh(0.5, around=4)
    with pytest.raises(ValueError, match="jitter"):
        synthetic.tube_mesh(0.5, jitter=0.8)
