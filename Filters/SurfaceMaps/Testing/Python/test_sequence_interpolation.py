"""vtkSurfaceSequenceInterpolator on a synthetic heart-tube series whose stages are turned against each other:
no rolling and no shrinking between the keyframes."""

import math

import numpy as np
import pytest

import surfacemaps
from surfacemaps import synthetic
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkMassProperties

RINGS, AROUND = 41, 16  # one connectivity for every stage: the rings of the sweep, then the two tips


def tube(t):
    """The synthetic heart tube at developmental time t (surfacemaps.synthetic's centre curve and radius),
    swept with a fixed number of rings and a pole at each tip, so that every stage has the same
    connectivity and vertex v is the same material point."""
    s, centre, tangents, normals, binormals = synthetic.centre_curve(t, samples=RINGS)
    a = 2.0 * math.pi * np.arange(AROUND) / AROUND
    r = synthetic.radius(t, s)
    rings = centre[:, None, :] + r[:, None, None] * (np.cos(a)[None, :, None] * normals[:, None, :]
                                                     + np.sin(a)[None, :, None] * binormals[:, None, :])
    points = np.vstack([centre[0] - r[0] * tangents[0], rings.reshape(-1, 3), centre[-1] + r[-1] * tangents[-1]])
    ring = lambda j, i: 1 + j * AROUND + i % AROUND  # noqa: E731
    last = len(points) - 1
    triangles = [(0, ring(0, i + 1), ring(0, i)) for i in range(AROUND)]
    for j in range(RINGS - 1):
        for i in range(AROUND):
            triangles += [(ring(j, i), ring(j, i + 1), ring(j + 1, i)), (ring(j, i + 1), ring(j + 1, i + 1), ring(j + 1, i))]
    triangles += [(last, ring(RINGS - 1, i), ring(RINGS - 1, i + 1)) for i in range(AROUND)]
    triangles = np.array(triangles)
    signed = np.einsum("ij,ij->i", points[triangles[:, 0]], np.cross(points[triangles[:, 1]], points[triangles[:, 2]]))
    if signed.sum() < 0.0:  # outward
        triangles = triangles[:, ::-1]
    return points, triangles


def turned(points, angle, axis, shift):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    R = np.eye(3) + math.sin(angle) * K + (1.0 - math.cos(angle)) * K @ K
    return points @ R.T + np.asarray(shift, float)


def volume(mesh):
    mass = vtkMassProperties()
    mass.SetInputData(mesh)
    mass.Update()
    return mass.GetVolume()


def series(times, angles):
    """The tubes at `times`, stage k turned by angles[k] degrees about its own axis and moved."""
    axes = [(1.0, 2.0, 3.0), (0.0, 1.0, 0.2), (3.0, -1.0, 1.0), (1.0, 0.0, 0.0)]
    keyframes = []
    for k, (t, angle) in enumerate(zip(times, angles)):
        points, triangles = tube(t)
        keyframes.append(synthetic.polydata(turned(points, math.radians(angle), axes[k % 4], (k, -2.0 * k, 0.5)),
                                            triangles))
    return keyframes


def midpoint_volumes(keyframes, times, **settings):
    """(keyframe volumes, the volumes half-way between consecutive keyframes) of the interpolated series."""
    interpolator = surfacemaps.vtkSurfaceSequenceInterpolator()
    for k, (mesh, t) in enumerate(zip(keyframes, times)):
        interpolator.AddInputData(mesh)
        interpolator.SetKeyframeTime(k, t)
    for name, value in settings.items():
        getattr(interpolator, "Set" + name)(value)
    volumes = []
    for t in times:
        interpolator.UpdateTimeStep(t)
        volumes.append(volume(interpolator.GetOutput()))
    middles = []
    for a, b in zip(times[:-1], times[1:]):
        interpolator.UpdateTimeStep(0.5 * (a + b))
        output = interpolator.GetOutput()
        assert output.GetNumberOfPoints() == keyframes[0].GetNumberOfPoints()
        middles.append(volume(output))
    return np.array(volumes), np.array(middles)


def relative_change(volumes, middles):
    """Per interval: how far the volume half-way is from the mean of its two keyframes' volumes."""
    return np.abs(middles / (0.5 * (volumes[:-1] + volumes[1:])) - 1.0)


STAGES = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
ANGLES = [0.0, 120.0, 230.0, 75.0]


@pytest.mark.parametrize("mode", ["Smooth", "Linear"])
def test_rotated_stages_keep_their_volume(mode):
    keyframes = series(STAGES, ANGLES)
    given = [volume(m) for m in keyframes]
    volumes, middles = midpoint_volumes(keyframes, STAGES, InterpolationMode=getattr(
        surfacemaps.vtkSurfaceSequenceInterpolator, "INTERPOLATE_" + mode.upper()))
    assert np.allclose(volumes, given, rtol=1e-9)  # a rigid alignment keeps the keyframes' volumes
    assert relative_change(volumes, middles).max() < 0.05, (volumes, middles)


def test_vertex_blend_of_rotated_stages_shrinks():
    """The same series blended vertex by vertex in the poses given loses far more than 5 %: the check
    above can fail."""
    keyframes = series(STAGES, ANGLES)
    volumes, middles = midpoint_volumes(keyframes, STAGES, KeyframeAlignment=0, ShapeBlending=0)
    assert relative_change(volumes, middles).max() > 0.2, (volumes, middles)


def test_a_tube_bent_into_a_loop_between_two_keyframes():
    """Straight at t = 0, bent by 225 degrees at t = 1: aligned but blended vertex by vertex the tube
    collapses half-way; blended by rotations it keeps its volume, also unaligned, where its end turns
    by more than a half turn (the rotations must keep turning the same way along the tube)."""
    keyframes = series([0.0, 1.0], [0.0, 0.0])
    for alignment in (1, 0):
        volumes, middles = midpoint_volumes(keyframes, [0.0, 1.0], KeyframeAlignment=alignment)
        assert relative_change(volumes, middles).max() < 0.05, (alignment, volumes, middles)
    volumes, middles = midpoint_volumes(keyframes, [0.0, 1.0], ShapeBlending=0)
    assert relative_change(volumes, middles).max() > 0.1, (volumes, middles)


def test_alignment_fields_map_the_keyframes_onto_the_output():
    keyframes = series(STAGES, ANGLES)
    interpolator = surfacemaps.vtkSurfaceSequenceInterpolator()
    for mesh in keyframes:
        interpolator.AddInputData(mesh)
    for k, mesh in enumerate(keyframes):
        interpolator.UpdateTimeStep(float(k))
        output = interpolator.GetOutput()
        matrix = vtk_to_numpy(output.GetFieldData().GetArray("AlignmentTransform")).reshape(-1, 3, 4)[k]
        given = vtk_to_numpy(mesh.GetPoints().GetData())
        assert np.allclose(given @ matrix[:, :3].T + matrix[:, 3], vtk_to_numpy(output.GetPoints().GetData()),
                           rtol=0, atol=1e-12 * np.ptp(given))
