"""The population entry point (python3 -m surfacemaps.population) on a small synthetic series, and
the heart-tube example that calls it.

Serially: every output, stage means on their stage's triangulation with their spread, the final
map's keyframes, statistics over all specimens lifted onto the final triangulation, the series
through the keyframes. Under ``mpirun -n 2``: identical files.
"""

import csv
import json
import os
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

import surfacemaps
from surfacemaps import synthetic
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.environ.get("SURFACEMAPS_EXAMPLES",
                          os.path.join(HERE, "..", "..", "Wrapping", "Python", "examples"))
STAGES, SPECIMENS, STEPS = 3, 2, 4  # 3 stages: the two ranks share unevenly
SCHEDULE = ["--target-error", "5e-3", "--landmark-iterations", "10", "--coarse-iterations", "3",
            "--fine-iterations", "3", "--steps-per-interval", str(STEPS)]
PNG = b"\x89PNG\r\n\x1a\n"


def run(command, mpi_ranks=None, display=True, xvfb=True):
    env = dict(os.environ)
    if mpi_ranks:
        command = [shutil.which("mpirun"), "--oversubscribe", "-n", str(mpi_ranks), *command]
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        env.pop("OMP_NUM_THREADS", None)  # the entry point sets one thread per rank itself
    if not display:
        env.pop("DISPLAY", None)
        env.pop("WAYLAND_DISPLAY", None)
    if not xvfb:
        env["PATH"] = os.pathsep.join(p for p in env.get("PATH", "").split(os.pathsep)
                                      if p and not os.path.exists(os.path.join(p, "Xvfb")))
    return subprocess.run([str(c) for c in command], capture_output=True, text=True, timeout=300, env=env)


def population(stages_dir, output, *options, mpi_ranks=None, display=True, xvfb=True):
    result = run([sys.executable, "-m", "surfacemaps.population", stages_dir, "--output-dir", output,
                  *SCHEDULE, *options], mpi_ranks=mpi_ranks, display=display, xvfb=xvfb)
    assert result.returncode == 0, result.stdout + result.stderr
    return result


def points(mesh):
    return vtk_to_numpy(mesh.GetPoints().GetData())


def triangles(mesh):
    return vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)


def read(path):
    return surfacemaps.read_mesh(str(path))


def distinct_colours(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    return len(np.unique(pixels[:, :3], axis=0))


def pvd_frames(path):
    """(time, file) of every DataSet of a .pvd, in order."""
    frames = re.findall(r'<DataSet[^>]*timestep="([^"]+)"[^>]*file="([^"]+)"', path.read_text())
    return [(float(t), path.parent / f) for t, f in frames]


@pytest.fixture(scope="module")
def stages_dir(tmp_path_factory):
    """3 stages x 2 coarse specimens with landmarks and DevelopmentalTime, as files."""
    directory = tmp_path_factory.mktemp("stages")
    for k in range(STAGES):
        _, meshes = synthetic.stage_specimens(k, STAGES, SPECIMENS, seed=0, resolution=10)
        for i, mesh in enumerate(meshes):
            surfacemaps.write_mesh(mesh, str(directory / f"stage_{k:02d}" / f"specimen_{i:02d}.vtp"))
    return directory


@pytest.fixture(scope="module")
def serial(stages_dir, tmp_path_factory):
    """The serial run, as on a server without a display: its surface pictures on an Xvfb the
    module starts itself (none without Xvfb)."""
    output = tmp_path_factory.mktemp("serial")
    result = population(stages_dir, output, display=False)
    return output, result, json.loads((output / "report.json").read_text())


def test_every_output_is_written(serial):
    output, result, report = serial
    names = [f"stage_{k:02d}" for k in range(STAGES)]
    for k, name in enumerate(names):
        assert (output / "stages" / f"{name}.vtp").exists()
        assert (output / "keyframes" / f"keyframe_{k:02d}.vtp").exists()
    for name in ("mean.vtp", "mode_1.pvd", "scores.csv", "variance.csv"):
        assert (output / "statistics" / name).exists(), name
    assert report["ranks"] == 1 and [s["name"] for s in report["stages"]] == names
    assert all(s["specimens"] == SPECIMENS and s["map_s"] > 0.0 for s in report["stages"])
    assert report["frames"] == (STAGES - 1) * STEPS + 1
    # The stage times are the specimens' DevelopmentalTime means: increasing, not evenly spaced.
    times = [s["time"] for s in report["stages"]]
    assert all(b > a for a, b in zip(times[:-1], times[1:])) and times != [0.0, 0.5, 1.0]
    expected = ["pictures/explained_variance.png", "pictures/scores.png"]
    if shutil.which("Xvfb"):
        expected += ["pictures/stage_means.png", "pictures/frames.png", "pictures/spread.png", "pictures/mode_1.png"]
    assert report["pictures"] == expected
    for name in expected:
        assert (output / name).read_bytes()[:8] == PNG, name
        assert distinct_colours(output / name) > 10, f"{name} looks blank"
    assert "final map" in result.stdout and "stage_02" in result.stdout


def test_stage_means_are_their_specimens_mean_with_spread(serial, stages_dir):
    output, _, report = serial
    means = [read(output / "stages" / f"stage_{k:02d}.vtp") for k in range(STAGES)]
    for row in surfacemaps.validate(*means):
        assert row["Valid"] and row["Genus"] == 0, row["defects"]
    # Stage 1 again from its files with the same settings: the mean has the stage map's
    # triangulation, is the order-free mean of the lifted specimens and carries their spread.
    specimens = [read(p) for p in sorted((stages_dir / "stage_01").glob("*.vtp"))]
    lifted = surfacemaps.map_surfaces(specimens, pairs="mean", target_error=5e-3, LandmarkIterations=10,
                                      CoarseIterations=3, FineIterations=3)
    assert np.array_equal(triangles(means[1]), triangles(lifted[0]))
    assert np.array_equal(points(means[1]), points(surfacemaps.average_surfaces(lifted)))
    spread = vtk_to_numpy(means[1].GetPointData().GetArray("StandardDeviation"))
    expected = surfacemaps.shape_statistics(lifted, modes=1)
    assert np.allclose(spread, expected.standard_deviation, rtol=1e-12, atol=0.0)
    assert spread.max() > 0.0
    assert report["stages"][1]["spread_rms"] == pytest.approx(np.sqrt(expected.total_variance), rel=1e-12)
    landmarks = vtk_to_numpy(means[1].GetPointData().GetArray("Landmarks"))
    assert sorted(landmarks[landmarks >= 0]) == [0, 1, 2]


def test_statistics_cover_every_specimen_on_the_final_triangulation(serial):
    output, _, report = serial
    mean = read(output / "statistics" / "mean.vtp")
    keyframe = read(output / "keyframes" / "keyframe_00.vtp")
    assert np.array_equal(triangles(mean), triangles(keyframe))
    statistics = report["statistics"]
    assert statistics["specimens"] == STAGES * SPECIMENS
    fractions = np.array(statistics["explained_fractions"])
    assert np.all(np.diff(fractions) <= 1e-12) and 0.0 < fractions.sum() <= 1.0 + 1e-12
    with open(output / "statistics" / "scores.csv") as f:
        rows = list(csv.DictReader(f))
    assert [r["stage"] for r in rows] == [f"stage_{k:02d}" for k in range(STAGES) for _ in range(SPECIMENS)]
    scores = np.array([[float(r[f"mode_{m + 1}"]) for m in range(len(fractions))] for r in rows])
    assert np.allclose(scores, statistics["scores"], rtol=1e-12, atol=1e-15)
    # The tubes grow and bend with time: the first mode orders the stages (means of stage scores
    # strictly monotone in one direction).
    stage_means = [scores[k * SPECIMENS:(k + 1) * SPECIMENS, 0].mean() for k in range(STAGES)]
    steps = np.sign(np.diff(stage_means))
    assert abs(steps.sum()) == STAGES - 1, stage_means
    # The mode animation runs from -2 to +2 standard deviations.
    frames = pvd_frames(output / "statistics" / "mode_1.pvd")
    assert [t for t, _ in frames] == pytest.approx(np.linspace(-2.0, 2.0, 9))
    middle = read(frames[4][1])
    assert np.allclose(points(middle), points(mean), rtol=0.0, atol=1e-12)


def test_every_specimen_is_written_on_the_final_triangulation_with_its_fit(serial, stages_dir):
    output, result, report = serial
    keyframe = read(output / "keyframes" / "keyframe_00.vtp")
    # The stems repeat from stage to stage: the stage names tell them apart.
    names = [f"stage_{k:02d}_specimen_{i:02d}" for k in range(STAGES) for i in range(SPECIMENS)]
    with np.load(output / "correspondences.npz", allow_pickle=False) as archive:
        assert archive["names"].tolist() == names
        assert np.array_equal(archive["triangles"], triangles(keyframe))
        lifted = archive["points"]
    assert lifted.shape == (STAGES * SPECIMENS, keyframe.GetNumberOfPoints(), 3)
    for name, expected in zip(names, lifted):
        specimen = read(output / "specimens" / f"{name}.vtp")
        assert np.array_equal(triangles(specimen), triangles(keyframe))
        assert np.array_equal(points(specimen), expected)
    # What the statistics were computed from: their mean is the mean of these.
    assert np.allclose(points(surfacemaps.average_surfaces(
        [synthetic.polydata(p, triangles(keyframe)) for p in lifted])),
        points(read(output / "statistics" / "mean.vtp")), rtol=0.0, atol=1e-9)

    rows = report["specimens"]
    with open(output / "fit.csv") as f:
        table = list(csv.DictReader(f))
    assert [t["name"] for t in table] == [r["name"] for r in rows] == names
    assert [t["file"] for t in table] == [str(stages_dir / f"stage_{k:02d}" / f"specimen_{i:02d}.vtp")
                                          for k in range(STAGES) for i in range(SPECIMENS)]
    for k, (row, line) in enumerate(zip(rows, table)):
        assert 0.0 < row["hausdorff"] <= row["two_sided_distance"] < 10.0
        assert float(line["hausdorff"]) == row["hausdorff"]
        # Landmarks kept: T's landmark vertices on every specimen are its landmark points.
        assert row["landmark_error"] < 1e-6
        if k % SPECIMENS == 0:  # its stage map's source
            assert row["exact_sd"] is None and line["exact_sd"] == ""
        else:
            assert row["exact_sd"] >= 1.0 and row["approximating_sd"] >= 1.0 and row["exact_max_distortion"] >= 1.0
            assert float(line["exact_sd"]) == row["exact_sd"]
    assert "fit (fit.csv): largest H" in result.stdout


def test_series_passes_through_the_keyframes(serial):
    output, _, report = serial
    frames = pvd_frames(output / "series" / "surface.pvd")
    assert len(frames) == (STAGES - 1) * STEPS + 1
    keyframes = [read(output / "keyframes" / f"keyframe_{k:02d}.vtp") for k in range(STAGES)]
    size = np.ptp(points(keyframes[0]), axis=0).max()
    for k, keyframe in enumerate(keyframes):
        t, path = frames[k * STEPS]
        assert t == pytest.approx(report["stages"][k]["time"])
        assert np.array_equal(triangles(read(path)), triangles(keyframe))
        assert np.allclose(points(read(path)), points(keyframe), rtol=0.0, atol=1e-9 * size)


def test_one_stage_is_its_own_common_triangulation(stages_dir, tmp_path):
    shutil.copytree(stages_dir / "stage_00", tmp_path / "stages" / "stage_00")
    population(tmp_path / "stages", tmp_path / "out", "--no-pictures")
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["statistics"]["specimens"] == SPECIMENS and report["frames"] == 0
    assert not (tmp_path / "out" / "keyframes").exists() and not (tmp_path / "out" / "series").exists()
    stage_mean = read(tmp_path / "out" / "stages" / "stage_00.vtp")
    mean = read(tmp_path / "out" / "statistics" / "mean.vtp")
    assert np.array_equal(triangles(mean), triangles(stage_mean))
    # Two specimens: the statistics' spread is the stage's spread.
    assert np.allclose(vtk_to_numpy(mean.GetPointData().GetArray("StandardDeviation")),
                       vtk_to_numpy(stage_mean.GetPointData().GetArray("StandardDeviation")), rtol=1e-9, atol=0.0)


def test_bad_stage_directory_is_named(tmp_path):
    (tmp_path / "stages" / "stage_a").mkdir(parents=True)
    result = run([sys.executable, "-m", "surfacemaps.population", tmp_path / "stages", "--output-dir",
                  tmp_path / "out"])
    assert result.returncode == 2
    assert "stage_a holds no meshes" in result.stderr


def test_no_display_nor_xvfb_skips_surface_pictures_only(stages_dir, tmp_path):
    result = population(stages_dir, tmp_path, display=False, xvfb=False)
    assert "surface pictures skipped" in result.stderr and "Debian package xvfb" in result.stderr
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["pictures"] == ["pictures/explained_variance.png", "pictures/scores.png"]


def test_heart_tube_example_calls_the_entry_point(tmp_path):
    result = run([sys.executable, os.path.join(EXAMPLES, "heart_tube_pipeline.py"), "--quick", "--output-dir",
                  tmp_path, "--no-pictures"])
    assert result.returncode == 0, result.stdout + result.stderr
    report = json.loads((tmp_path / "report.json").read_text())
    # The synthetic stage times, not the specimens' mean times, and the written specimens as input.
    assert [s["time"] for s in report["stages"]] == [0.0, 1.0]
    assert report["stages_dir"] == str(tmp_path / "specimens")
    assert (tmp_path / "series" / "surface.pvd").exists()


@pytest.mark.skipif(shutil.which("mpirun") is None, reason="mpirun not installed (openmpi-bin)")
def test_two_mpi_ranks_give_the_serial_results(serial, stages_dir, tmp_path):
    output, _, _ = serial
    result = population(stages_dir, tmp_path, "--no-pictures", mpi_ranks=2)
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["ranks"] == 2
    assert [s["rank"] for s in report["stages"]] == [0, 1, 0]
    assert "rank 1: stage stage_01" in result.stderr
    # The map is deterministic for any thread count (serial: all threads; MPI: one per rank), so
    # every mesh is identical, not just close.
    for path in [f"stages/stage_{k:02d}.vtp" for k in range(STAGES)] + \
                [f"keyframes/keyframe_{k:02d}.vtp" for k in range(STAGES)] + ["statistics/mean.vtp"]:
        a, b = read(output / path), read(tmp_path / path)
        assert np.array_equal(triangles(a), triangles(b)), path
        assert np.array_equal(points(a), points(b)), path
    for name in ("statistics/scores.csv", "statistics/variance.csv", "fit.csv"):
        assert (output / name).read_text() == (tmp_path / name).read_text()


def test_every_map_setting_but_the_pairs_is_a_flag_of_the_list():
    from surfacemaps import population
    S = surfacemaps.vtkSurfaceMapsSettings
    table = S.MAP_SETTINGS
    text = population.parser().format_help()
    for i in range(S.GetNumberOfSettings(table)):
        flag = "--" + S.GetFlag(table, i)
        assert (flag in text) == (flag != "--pairs"), flag
    args = population.parse_args(["stages", "--output-dir", "out", "--target-error", "5e-3",
                                  "--release-landmarks", "--fine-iterations", "3", "--preset", "population"])
    assert population.map_settings(args) == dict(preset="population", TargetError=5e-3, KeepLandmarks=False,
                                                 FineIterations=3)
    assert population.settings_report(args) == dict(preset="population", target_error=5e-3,
                                                     keep_landmarks=False, fine_iterations=3)
    for bad in (["--target-error", "2"], ["--fine-iterations", "1.5"], ["--pairs", "all"]):
        with pytest.raises(SystemExit):
            population.parse_args(["stages", "--output-dir", "out", *bad])
