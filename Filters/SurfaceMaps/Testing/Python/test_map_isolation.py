"""Maps do not leak into each other: several filters on Python threads give the maps they give one
at a time, and a MapResult refuses to transfer through a map its inputs no longer match."""

import os
import threading

import numpy as np
import pytest

import surfacemaps
from vtkmodules.util.numpy_support import vtk_to_numpy

DATA = os.environ.get("SURFACEMAPS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "Data"))
SHORT = dict(LandmarkIterations=10, CoarseIterations=3, FineIterations=3)


def data(name):
    return os.path.join(DATA, name)


# Different inputs and settings per job, so that no two maps are alike.
JOBS = [("ellipsoid_coarse.stl", "blob.off", 2), ("ellipsoid_coarse.stl", "ellipsoid_coarse.stl", 3)]


def compute(job):
    """Points and sphere positions of both outputs of one map, on a filter of its own."""
    source, target, fine = job
    f = surfacemaps.vtkSurfaceMapFilter()
    for key, value in dict(SHORT, FineIterations=fine).items():
        getattr(f, "Set" + key)(value)
    f.SetNumberOfThreads(1)
    for name in (source, target):
        f.AddInputData(surfacemaps.read_mesh(data(name)))
    f.Update()
    assert f.GetErrorCode() == 0, f.GetLastErrorMessage()
    return [vtk_to_numpy(array).copy() for i in range(2)
            for array in (f.GetOutput(i).GetPoints().GetData(),
                          f.GetOutput(i).GetPointData().GetArray("SpherePosition"))]


def test_maps_on_python_threads_are_the_maps_computed_one_at_a_time():
    alone = [compute(job) for job in JOBS]
    together = [None] * len(JOBS)
    failures = []

    def run(k):
        try:
            together[k] = compute(JOBS[k])
        except BaseException as e:  # reported below, with the job
            failures.append((k, e))

    threads = [threading.Thread(target=run, args=(k,)) for k in range(len(JOBS))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert not failures, failures
    for k, (a, t) in enumerate(zip(alone, together)):
        assert len(a) == len(t) and all(np.array_equal(x, y) for x, y in zip(a, t)), f"job {k}"


def test_transfer_refuses_a_result_whose_input_changed_in_place():
    meshes = [surfacemaps.read_mesh(data("ellipsoid_coarse.stl")) for _ in range(2)]
    result = surfacemaps.map_surfaces(meshes, NumberOfThreads=1, **SHORT)
    assert result.changed_inputs() == []
    assert surfacemaps.transfer(result, 0, 1).GetNumberOfPoints() == meshes[1].GetNumberOfPoints()
    assert result.changed_inputs() == []  # transferring leaves the inputs as they were
    points = meshes[1].GetPoints()
    x, y, z = points.GetPoint(0)
    points.SetPoint(0, 1.01 * x, y, z)
    points.Modified()
    assert result.changed_inputs() == [1]
    with pytest.raises(surfacemaps.InputError, match="input 1 of the map changed after map_surfaces returned"):
        surfacemaps.transfer(result, 0, 1)
