"""vtkSurfaceAverage and vtkSurfaceSequenceInterpolator from Python: average_surfaces, write_time_series."""

import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import surfacemaps
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkFiltersCore import vtkImplicitPolyDataDistance
from vtkmodules.vtkFiltersHybrid import vtkTemporalShiftScale
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

DATA = os.environ.get("SURFACEMAPS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Data"))

# A short schedule keeps the map here around a second.
SHORT = dict(LandmarkIterations=10, CoarseIterations=5, FineIterations=5)

# Data/README.md: ellipsoid.obj and ellipsoid_coarse.stl are the same ellipsoid
# (semi-axes 1, 0.75, 0.5) triangulated at two levels.
SEMI_AXES = (1.0, 0.75, 0.5)


def data(name):
    return os.path.join(DATA, name)


def points(mesh):
    return vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)


def triangles(mesh):
    return vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)


def rotation(angle, axis):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def moved(mesh, R, t):
    copy = vtkPolyData()
    copy.DeepCopy(mesh)
    copy.GetPoints().SetData(numpy_to_vtk(points(mesh) @ R.T + t, deep=True))
    return copy


def distances(xyz, surface):
    """Unsigned distances from points to a closed triangle mesh."""
    d = vtkImplicitPolyDataDistance()
    d.SetInput(surface)
    return np.array([abs(d.EvaluateFunction(p)) for p in xyz])


# Copy 2 is the coarse ellipsoid moved rigidly: the average must undo that.
R2 = rotation(0.9, (1.0, 2.0, -0.5))
T2 = np.array([3.0, -1.0, 0.5])


@pytest.fixture(scope="module")
def copies():
    """Three copies of one ellipsoid (two triangulations, one moved) and their common triangulations."""
    fine = surfacemaps.read_mesh(data("ellipsoid.obj"))
    coarse = surfacemaps.read_mesh(data("ellipsoid_coarse.stl"))
    meshes = [fine, coarse, moved(coarse, R2, T2)]
    # Landmarks at the +x, -x, +y, +z extremes rule out the ellipsoid's symmetries.
    ends = [[int(np.argmax(sign * points(m)[:, axis])) for axis, sign in ((0, 1), (0, -1), (1, 1), (2, 1))]
            for m in (fine, coarse, coarse)]
    common = surfacemaps.map_surfaces(meshes, landmarks=ends, **SHORT)
    return meshes, common


def test_average_of_copies_is_the_surface_up_to_the_approximation_error(copies):
    meshes, common = copies
    surface = meshes[0]
    # Each copy's common triangulation put back in input 0's frame by the known
    # motion (independent of the filter's alignment).
    in_frame = [points(common[0]), points(common[1]), (points(common[2]) - T2) @ R2]
    # The measured approximation error: how far a copy's vertices are from the surface.
    error = max(distances(x, surface).max() for x in in_frame)
    # The vertices of different copies need not sit on the same surface point: their
    # mean can sink below the convex surface by the sagitta of the chord between them,
    # at most k l^2 / 8 for a chord of length l where the normal curvature is <= k
    # (the ellipsoid's largest is a / c^2).
    slip = max(np.linalg.norm(x - y, axis=1).max() for x in in_frame for y in in_frame)
    curvature = SEMI_AXES[0] / SEMI_AXES[2] ** 2
    tolerance = error + curvature * slip ** 2 / 8
    assert tolerance < 0.05 * surface.GetLength()  # the map is good enough for the check to mean something

    average = surfacemaps.average_surfaces(common)
    assert average.GetNumberOfPoints() == common[0].GetNumberOfPoints()
    assert np.array_equal(triangles(average), triangles(common[0]))
    # The mean lies between the copies' poses; copy 0's transform takes it back
    # into the surface's frame.
    fields = average.GetFieldData()
    matrices = vtk_to_numpy(fields.GetArray("AlignmentTransform")).reshape(-1, 3, 4)
    to_first = np.linalg.inv(matrices[0][:, :3])

    def in_first_frame(xyz):
        return (xyz - matrices[0][:, 3]) @ to_first.T

    deviation = distances(in_first_frame(points(average)), surface)
    assert deviation.max() <= tolerance, (deviation.max(), error, slip)
    # The filter found the known motion of copy 2 (up to the map's own error).
    rms = vtk_to_numpy(fields.GetArray("AlignmentRMS"))
    assert rms.max() <= slip
    fitted = in_first_frame(points(common[2]) @ matrices[2][:, :3].T + matrices[2][:, 3])
    assert np.linalg.norm(fitted - in_frame[2], axis=1).max() <= 2 * slip

    # The order of the meshes does not matter.
    reversed_order = surfacemaps.average_surfaces(common[::-1])
    assert np.abs(points(reversed_order) - points(average)).max() < 1e-9 * average.GetLength()
    assert np.allclose(vtk_to_numpy(reversed_order.GetFieldData().GetArray("AlignmentRMS")), rms[::-1],
                       rtol=0, atol=1e-9 * average.GetLength())

    # Without alignment copy 2 drags the mean away.
    unaligned = surfacemaps.average_surfaces(common, align="none")
    assert distances(points(unaligned), surface).max() > 10 * tolerance
    # Weight 0 on the moved copy: it is ignored, rigid or not.
    only_first_two = surfacemaps.average_surfaces(common, weights=[1, 1, 0], align="none")
    assert np.allclose(points(only_first_two), 0.5 * (in_frame[0] + in_frame[1]), atol=1e-12)


def test_align_surfaces_moves_each_copy_into_the_means_frame(copies):
    _, common = copies
    aligned = surfacemaps.align_surfaces(common)
    mean = surfacemaps.average_surfaces(common)
    matrices = vtk_to_numpy(mean.GetFieldData().GetArray("AlignmentTransform")).reshape(-1, 3, 4)
    for k, (given, moved_copy) in enumerate(zip(common, aligned)):
        assert np.allclose(points(moved_copy), points(given) @ matrices[k][:, :3].T + matrices[k][:, 3],
                           rtol=0, atol=1e-12 * mean.GetLength())
        assert np.array_equal(triangles(moved_copy), triangles(given))
        assert moved_copy.GetPointData().GetNumberOfArrays() == given.GetPointData().GetNumberOfArrays()
    # Copy 2, moved far by (R2, T2), now lies on the others (up to the map's error).
    assert np.abs(points(aligned[2]) - points(aligned[1])).max() < 0.1 * np.abs(points(common[2]) - points(common[1])).max()
    assert all(np.array_equal(points(a), points(c)) for a, c in zip(surfacemaps.align_surfaces(common, "none"), common))


def test_average_surfaces_errors(copies):
    meshes, common = copies
    with pytest.raises(surfacemaps.InputError, match=r"input 1 \(.*ellipsoid_coarse.stl\) does not have the "
                                                     r"connectivity of input 0.*points instead of"):
        surfacemaps.average_surfaces([common[0], meshes[1]])
    with pytest.raises(surfacemaps.InputError, match=r"weight of input 1 \(.*\) is -1"):
        surfacemaps.average_surfaces(common, weights=[1, -1, 1])
    with pytest.raises(surfacemaps.InputError, match="2 weights"):
        surfacemaps.average_surfaces(common, weights=[1, 1])
    with pytest.raises(ValueError, match="align"):
        surfacemaps.average_surfaces(common, align="affine")
    with pytest.raises(surfacemaps.InputError, match="no meshes"):
        surfacemaps.average_surfaces([])


def with_array(mesh, name, values):
    """A shallow copy of `mesh` with the point array `name` (numpy values, their dtype)."""
    copy = vtkPolyData()
    copy.ShallowCopy(mesh)
    array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
    array.SetName(name)
    copy.GetPointData().AddArray(array)
    return copy


def test_average_surfaces_array_modes(copies):
    _, common = copies
    n = common[0].GetNumberOfPoints()
    v = np.arange(n)
    meshes = [with_array(with_array(c, "Label", (10 * i + v % 3).astype(np.int32)), "Thickness", (i + 1.0) * v)
              for i, c in enumerate(common)]
    label = lambda mesh: vtk_to_numpy(mesh.GetPointData().GetArray("Label"))  # noqa: E731
    thickness = lambda mesh: vtk_to_numpy(mesh.GetPointData().GetArray("Thickness"))  # noqa: E731
    # By type: the int labels are the first mesh's, the double thickness the mean.
    average = surfacemaps.average_surfaces(meshes)
    assert np.array_equal(label(average), v % 3)
    assert np.allclose(thickness(average), 2.0 * v)
    # Chosen the other way: labels averaged (and rounded), thickness the first mesh's.
    average = surfacemaps.average_surfaces(meshes, categorical=["Thickness"], continuous=["Label"])
    assert label(average).dtype == np.int32
    assert np.array_equal(label(average), 10 + v % 3)
    assert np.array_equal(thickness(average), 1.0 * v)
    with pytest.raises(ValueError, match="both categorical and continuous"):
        surfacemaps.average_surfaces(meshes, categorical=["Label"], continuous=["Label"])


def keyframe_sequence(common, times):
    """The interpolator through `common`, poses as given and points blended vertex by vertex (the
    checks below compare with the keyframes and their vertex-wise blend)."""
    interpolator = surfacemaps.vtkSurfaceSequenceInterpolator()
    interpolator.SetKeyframeAlignmentToNone()
    interpolator.SetShapeBlendingToVertices()
    for k, (mesh, t) in enumerate(zip(common, times)):
        interpolator.AddInputData(mesh)
        interpolator.SetKeyframeTime(k, t)
    return interpolator


def test_write_time_series(copies, tmp_path):
    _, common = copies
    keyframes = [common[0], common[1], surfacemaps.average_surfaces(common)]
    times = [0.0, 1.5, 4.0]
    interpolator = keyframe_sequence(keyframes, times)
    interpolator.SetInterpolationModeToSmooth()
    interpolator.SetStepsPerInterval(2)
    requested = [0.0, 0.75, 1.5, 2.75, 4.0]
    paths = surfacemaps.write_time_series(interpolator, requested, tmp_path / "series", name="heart")
    directory = tmp_path / "series"
    assert paths[-1] == os.path.join(directory, "heart.pvd")
    assert [os.path.basename(p) for p in paths[:-1]] == [f"heart_{k:04d}.vtp" for k in range(5)]
    assert sorted(os.listdir(directory)) == sorted(os.path.basename(p) for p in paths)  # no temporary left

    collection = ET.parse(paths[-1]).getroot()
    assert collection.get("type") == "Collection"
    datasets = collection.find("Collection").findall("DataSet")
    assert [float(d.get("timestep")) for d in datasets] == requested
    for k, dataset in enumerate(datasets):
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(directory, dataset.get("file")))
        reader.Update()
        mesh = reader.GetOutput()
        assert mesh.GetNumberOfPoints() == keyframes[0].GetNumberOfPoints()
        assert np.array_equal(triangles(mesh), triangles(keyframes[0]))
        time = mesh.GetFieldData().GetArray("InterpolationTime").GetValue(0)
        assert time == requested[k]
        if time in times:  # keyframe times reproduce the keyframes exactly
            assert np.array_equal(points(mesh), points(keyframes[times.index(time)]))
        else:
            assert not any(np.allclose(points(mesh), points(m)) for m in keyframes)


def test_interpolator_in_a_temporal_pipeline(copies, tmp_path):
    _, common = copies
    interpolator = keyframe_sequence(common, [0.0, 1.0, 3.0])
    interpolator.SetStepsPerInterval(2)
    interpolator.UpdateInformation()
    info = interpolator.GetOutputInformation(0)
    steps = info.Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    assert list(steps) == [0.0, 0.5, 1.0, 2.0, 3.0]

    # Downstream temporal filter: its time 11 is our time 1, keyframe 1.
    shift = vtkTemporalShiftScale()
    shift.SetPostShift(10.0)
    shift.SetInputConnection(interpolator.GetOutputPort())
    shift.UpdateTimeStep(11.0)
    assert np.array_equal(points(shift.GetOutputDataObject(0)), points(common[1]))
    interpolator.SetInterpolationModeToLinear()
    shift.UpdateTimeStep(12.0)
    assert np.allclose(points(shift.GetOutputDataObject(0)), 0.5 * (points(common[1]) + points(common[2])),
                       atol=1e-12)

    # Non-increasing times: an error naming the keyframe, empty output.
    interpolator.SetKeyframeTime(2, 0.5)
    with pytest.raises(surfacemaps.InputError, match="time of keyframe 2"):
        surfacemaps.write_time_series(interpolator, [0.0], tmp_path)
    assert interpolator.GetOutput().GetNumberOfPoints() == 0
    assert os.listdir(tmp_path) == []


def test_settings_round_trip():
    a = surfacemaps.vtkSurfaceAverage()
    assert a.GetAlignMode() == surfacemaps.vtkSurfaceAverage.ALIGN_RIGID
    a.SetAlignModeToSimilarity()
    assert a.GetAlignMode() == surfacemaps.vtkSurfaceAverage.ALIGN_SIMILARITY
    a.SetInputWeight(2, 0.5)
    assert a.GetInputWeight(2) == 0.5 and a.GetInputWeight(0) == 1.0
    s = surfacemaps.vtkSurfaceSequenceInterpolator()
    assert s.GetInterpolationMode() == s.INTERPOLATE_SMOOTH and s.GetStepsPerInterval() == 1
    assert s.GetKeyframeAlignment() == s.ALIGN_RIGID and s.GetShapeBlending() == s.BLEND_ROTATIONS
    s.SetKeyframeTime(1, 2.5)
    assert s.GetKeyframeTime(1) == 2.5 and s.GetKeyframeTime(3) == 3.0


def test_write_mesh(copies, tmp_path):
    _, common = copies
    path = tmp_path / "new" / "mesh.vtp"  # directory created
    surfacemaps.write_mesh(common[0], path)
    assert os.listdir(tmp_path / "new") == ["mesh.vtp"]  # no temporary left
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    assert np.array_equal(points(reader.GetOutput()), points(common[0]))
    assert np.array_equal(triangles(reader.GetOutput()), triangles(common[0]))
    with pytest.raises(ValueError, match="vtp"):
        surfacemaps.write_mesh(common[0], tmp_path / "mesh.obj")
    (tmp_path / "file").write_text("not a directory")
    with pytest.raises(OSError):
        surfacemaps.write_mesh(common[0], tmp_path / "file" / "mesh.vtp")
