"""vtkSphereEmbeddingFilter from Python: output arrays, options, errors, abort."""

import os

import numpy as np
import pytest

import surfacemaps
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.util.numpy_support import vtk_to_numpy

DATA = os.environ.get("SURFACEMAPS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Data"))


def data(name):
    return os.path.join(DATA, name)


def embed(mesh, **settings):
    f = surfacemaps.vtkSphereEmbeddingFilter()
    errors = []
    f.AddObserver(vtkCommand.ErrorEvent, lambda o, e, text=None: errors.append(e))
    for key, value in settings.items():
        getattr(f, "Set" + key)(value)
    f.SetInputData(mesh)
    f.Update()
    return f, f.GetOutput(), errors


def signed_volumes(points, polys):
    tri = vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3)
    a, b, c = points[tri[:, 0]], points[tri[:, 1]], points[tri[:, 2]]
    return np.einsum("ij,ij->i", a, np.cross(b, c))


@pytest.mark.parametrize("name", ["ellipsoid_coarse.stl", "blob.vtp", "limbs_coarse.vtk"])
def test_every_format_embeds(name):
    mesh = surfacemaps.read_mesh(data(name))
    _, out, errors = embed(mesh)
    assert not errors
    s = vtk_to_numpy(out.GetPointData().GetArray("SpherePosition"))
    assert s.shape == (mesh.GetNumberOfPoints(), 3)
    assert np.allclose(np.linalg.norm(s, axis=1), 1.0)
    assert (signed_volumes(s, out.GetPolys()) > 0).all()
    # The input's geometry and arrays are kept; the input itself is untouched.
    assert np.array_equal(vtk_to_numpy(out.GetPoints().GetData()), vtk_to_numpy(mesh.GetPoints().GetData()))
    assert mesh.GetPointData().GetArray("SpherePosition") is None
    assert out.GetFieldData().GetArray("EmbeddingDistortion").GetValue(0) >= 1.0
    assert out.GetFieldData().GetAbstractArray("FileName").GetValue(0) == data(name)
    if name == "blob.vtp":
        assert out.GetPointData().GetArray("Landmarks") is not None


def test_points_on_sphere():
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    _, out, _ = embed(mesh, OutputPointsOnSphere=True)
    p = vtk_to_numpy(out.GetPoints().GetData())
    assert np.allclose(np.linalg.norm(p, axis=1), 1.0)
    original = vtk_to_numpy(out.GetPointData().GetArray("InputPosition"))
    assert np.array_equal(original, vtk_to_numpy(mesh.GetPoints().GetData()))


def test_settings_round_trip_and_clamp():
    f = surfacemaps.vtkSphereEmbeddingFilter()
    assert f.GetBarrierWeight() == 0.1 and f.GetFinalIterations() == 50
    f.SetBarrierWeight(1e9)
    assert f.GetBarrierWeight() == 1e3
    f.SetFinalIterations(3)
    assert f.GetFinalIterations() == 3


def test_bad_input_is_an_error_with_empty_output():
    mesh = surfacemaps.read_mesh(data("bad/torus.obj"))
    f, out, errors = embed(mesh)
    assert errors
    assert out.GetNumberOfPoints() == 0


def test_abort_leaves_the_output_empty():
    mesh = surfacemaps.read_mesh(data("limbs.ply"))
    f = surfacemaps.vtkSphereEmbeddingFilter()
    progress = []

    def on_progress(obj, event):
        progress.append(obj.GetProgress())
        if obj.GetProgress() > 0.2:
            obj.AbortExecuteOn()

    f.AddObserver(vtkCommand.ProgressEvent, on_progress)
    f.SetInputData(mesh)
    f.Update()
    assert f.GetOutput().GetNumberOfPoints() == 0
    assert progress == sorted(progress)


def landmark_sphere_positions(mesh):
    ids = vtk_to_numpy(mesh.GetPointData().GetArray("Landmarks"))
    s = vtk_to_numpy(mesh.GetPointData().GetArray("SpherePosition"))
    return {int(i): s[v] for v, i in enumerate(ids) if i >= 0}


def test_rotation_onto_reference_landmarks():
    a = surfacemaps.read_mesh(data("ellipsoid.obj"), landmarks=data("ellipsoid.pinned"))
    b = surfacemaps.read_mesh(data("blob.off"), landmarks=data("blob.vts"))
    reference = surfacemaps.embed_on_sphere(a)
    plain = surfacemaps.embed_on_sphere(b)
    f = surfacemaps.vtkSphereEmbeddingFilter()
    f.SetInputData(b)
    f.SetReferenceData(reference)
    f.Update()
    aligned = f.GetOutput()
    ref = landmark_sphere_positions(reference)

    def rms_angle(mesh):
        own = landmark_sphere_positions(mesh)
        angles = [np.arccos(np.clip(np.dot(own[k], ref[k]), -1, 1)) for k in ref]
        return float(np.sqrt(np.mean(np.square(angles))))

    error = aligned.GetFieldData().GetArray("LandmarkAlignmentError").GetValue(0)
    assert error == pytest.approx(rms_angle(aligned), rel=1e-9)
    assert rms_angle(aligned) <= rms_angle(plain) + 1e-12
    assert rms_angle(aligned) < 0.5  # same landmark layout on both shapes
    # Still a certified embedding: rotating keeps every triangle positive.
    s = vtk_to_numpy(aligned.GetPointData().GetArray("SpherePosition"))
    assert (signed_volumes(s, aligned.GetPolys()) > 0).all()
