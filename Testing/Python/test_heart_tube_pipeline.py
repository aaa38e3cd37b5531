"""The heart-tube example (Wrapping/Python/examples/heart_tube_pipeline.py), small version.

Serially: outputs, frame count, averages on their stage's common
triangulation, interpolation through the final map's keyframes. Under
``mpirun -n 2``: the same averages and keyframes as the serial run.
"""

import json
import os
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

import surfacemaps
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.environ.get("SURFACEMAPS_EXAMPLES",
                          os.path.join(HERE, "..", "..", "Wrapping", "Python", "examples"))
SCRIPT = os.path.join(EXAMPLES, "heart_tube_pipeline.py")
QUICK = ["--quick", "--stages", "3"]  # 3 stages x 2 specimens: the two ranks share unevenly
STAGES, STEPS = 3, 4
PNG = b"\x89PNG\r\n\x1a\n"


def pipeline(output, *options, mpi_ranks=None, display=True):
    command = [sys.executable, SCRIPT, *QUICK, "--output-dir", str(output), *map(str, options)]
    env = dict(os.environ)
    if mpi_ranks:
        command = [shutil.which("mpirun"), "--oversubscribe", "-n", str(mpi_ranks), *command]
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        env.pop("OMP_NUM_THREADS", None)  # the script sets one thread per rank itself
    if not display:
        env.pop("DISPLAY", None)
        env.pop("WAYLAND_DISPLAY", None)
    result = subprocess.run(command, capture_output=True, text=True, timeout=300, env=env)
    assert result.returncode == 0, result.stdout + result.stderr
    return result


def points(mesh):
    return vtk_to_numpy(mesh.GetPoints().GetData())


def triangles(mesh):
    return vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)


def read(path):
    return surfacemaps.read_mesh(str(path))


def pvd_frames(path):
    """(time, file) of every DataSet of a .pvd, in order."""
    text = path.read_text()
    frames = re.findall(r'<DataSet[^>]*timestep="([^"]+)"[^>]*file="([^"]+)"', text)
    return [(float(t), path.parent / f) for t, f in frames]


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    output = tmp_path_factory.mktemp("serial")
    result = pipeline(output, "--write-specimens")
    return output, result


def test_outputs(serial):
    output, result = serial
    for k in range(STAGES):
        assert (output / "averages" / f"stage_{k:02d}.vtp").exists()
        assert (output / "keyframes" / f"keyframe_{k:02d}.vtp").exists()
        assert len(list((output / "specimens" / f"stage_{k:02d}").glob("*.vtp"))) == 2
    timings = json.loads((output / "timings.json").read_text())
    assert timings["ranks"] == 1 and [s["stage"] for s in timings["stages"]] == list(range(STAGES))
    for s in timings["stages"]:
        assert s["specimens"] == 2 and s["map_s"] > 0.0 and s["average_s"] >= 0.0
    assert timings["frames"] == (STAGES - 1) * STEPS + 1
    assert "final map" in result.stdout and "stage_02" in result.stdout
    if os.environ.get("DISPLAY"):
        for name in ("averages.png", "frames.png"):
            assert (output / "pictures" / name).read_bytes()[:8] == PNG


def test_series_lists_every_frame(serial):
    output, _ = serial
    frames = pvd_frames(output / "series" / "surface.pvd")
    assert len(frames) == (STAGES - 1) * STEPS + 1
    times = [t for t, _ in frames]
    assert times[0] == 0.0 and times[-1] == 1.0 and all(b > a for a, b in zip(times[:-1], times[1:]))
    keyframe = read(output / "keyframes" / "keyframe_00.vtp")
    for _, path in frames:
        assert np.array_equal(triangles(read(path)), triangles(keyframe))


def test_averages_are_closed_on_their_stage_triangulation(serial):
    output, _ = serial
    averages = [read(output / "averages" / f"stage_{k:02d}.vtp") for k in range(STAGES)]
    for row in surfacemaps.validate(*averages):
        assert row["Valid"] and row["Genus"] == 0, row["defects"]
    # Stage 1 again from its written specimens, with the example's settings: the average has the
    # stage map's triangulation and is the average of the lifted meshes.
    specimens = sorted((output / "specimens" / "stage_01").glob("*.vtp"))
    lifted = surfacemaps.map_surfaces([read(p) for p in specimens], pairs="star", target_error=5e-3,
                                      LandmarkIterations=10, CoarseIterations=3, FineIterations=3)
    assert np.array_equal(triangles(averages[1]), triangles(lifted[0]))
    assert np.array_equal(points(averages[1]), points(surfacemaps.average_surfaces(lifted)))
    landmarks = vtk_to_numpy(averages[1].GetPointData().GetArray("Landmarks"))
    assert sorted(landmarks[landmarks >= 0]) == [0, 1, 2]


def test_interpolation_passes_through_the_keyframes(serial):
    output, _ = serial
    frames = pvd_frames(output / "series" / "surface.pvd")
    keyframes = [read(output / "keyframes" / f"keyframe_{k:02d}.vtp") for k in range(STAGES)]
    assert len({len(triangles(k)) for k in keyframes}) == 1
    size = np.ptp(points(keyframes[0]), axis=0).max()
    for k, keyframe in enumerate(keyframes):
        t, path = frames[k * STEPS]
        assert t == pytest.approx(k / (STAGES - 1))
        assert np.allclose(points(read(path)), points(keyframe), rtol=0.0, atol=1e-9 * size)
    # Between keyframes the frames move: not a copy of either neighbour.
    middle = points(read(frames[STEPS // 2][1]))
    for neighbour in keyframes[:2]:
        assert np.abs(middle - points(neighbour)).max() > 1e-3 * size


def test_input_directory_reproduces_the_averages(serial, tmp_path):
    output, _ = serial
    pipeline(tmp_path, "--input-dir", output / "specimens", "--no-pictures")
    for k in range(STAGES):
        a = read(output / "averages" / f"stage_{k:02d}.vtp")
        b = read(tmp_path / "averages" / f"stage_{k:02d}.vtp")
        assert np.array_equal(points(a), points(b)) and np.array_equal(triangles(a), triangles(b))
    # The stage times came from the specimens' DevelopmentalTime (their mean), not the evenly spaced ones.
    times = [s["time"] for s in json.loads((tmp_path / "timings.json").read_text())["stages"]]
    assert times != [0.0, 0.5, 1.0] and all(b > a for a, b in zip(times[:-1], times[1:]))


def test_no_display_skips_pictures(tmp_path):
    result = pipeline(tmp_path, "--stages", "2", display=False)
    assert "pictures skipped" in result.stderr
    assert not (tmp_path / "pictures").exists()
    assert (tmp_path / "series" / "surface.pvd").exists()


@pytest.mark.skipif(shutil.which("mpirun") is None, reason="mpirun not installed (openmpi-bin)")
def test_two_mpi_ranks_give_the_serial_results(serial, tmp_path):
    output, _ = serial
    result = pipeline(tmp_path, "--no-pictures", mpi_ranks=2)
    timings = json.loads((tmp_path / "timings.json").read_text())
    assert timings["ranks"] == 2 and timings["omp_num_threads"] == "1"
    assert [s["rank"] for s in timings["stages"]] == [0, 1, 0]
    assert "rank 1: stage 1" in result.stderr
    # The map is deterministic for any thread count (serial: all threads; MPI: one per rank), so the
    # averages and the final map's keyframes are identical, not just close.
    for k in range(STAGES):
        for path in (f"averages/stage_{k:02d}.vtp", f"keyframes/keyframe_{k:02d}.vtp"):
            a, b = read(output / path), read(tmp_path / path)
            assert np.array_equal(triangles(a), triangles(b)), path
            assert np.array_equal(points(a), points(b)), path
