"""`surfacemap statistics` on a small population made here (and on a map directory)."""

import csv
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from cli import SHORT, data, read_vtp, run


def points(mesh):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    return vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)


def point_array(mesh, name):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    array = mesh.GetPointData().GetArray(name)
    assert array is not None, name
    return vtk_to_numpy(array).astype(float)


def write_population(directory, n=6, seed=18):
    """n ellipsoids (Data/ellipsoid.obj's connectivity) with two random radial deformations
    and random poses, as .vtp files; returns their paths."""
    import surfacemaps
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    base = surfacemaps.read_mesh(data("ellipsoid.obj"))
    x = points(base)
    d = x / np.linalg.norm(x, axis=1)[:, None]
    rng = np.random.default_rng(seed)
    paths = []
    for i in range(n):
        a, b = rng.normal(0, [0.1, 0.04])
        shape = x + a * d * (3 * d[:, 2:] ** 2 - 1) + b * d * (d[:, :1] ** 2 - d[:, 1:2] ** 2)
        angle = rng.uniform(-0.4, 0.4)
        R = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
        mesh = vtkPolyData()
        mesh.DeepCopy(base)
        mesh.GetPoints().SetData(numpy_to_vtk(np.ascontiguousarray(shape @ R.T + rng.uniform(-1, 1, 3)), deep=True))
        path = os.path.join(directory, f"specimen_{i}.vtp")
        surfacemaps.write_mesh(mesh, path)
        paths.append(path)
    return paths


@pytest.fixture(scope="module")
def population(tmp_path_factory):
    return write_population(str(tmp_path_factory.mktemp("population")))


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_statistics_writes_every_file(population, tmp_path):
    out = tmp_path / "stats"
    result = run("statistics", *population, "--output-dir", out, "--modes", "3", "--frames", "5")
    assert result.returncode == 0, result.stderr
    assert "mode 1: variance" in result.stdout
    expected = {"mean.vtp", "scores.csv", "variance.csv"} | {f"mode_{m}.pvd" for m in (1, 2, 3)} | \
        {f"mode_{m}" for m in (1, 2, 3)}
    assert set(os.listdir(out)) == expected  # no temporary left, no pictures without --pictures

    mean = read_vtp(out / "mean.vtp")
    n = mean.GetNumberOfPoints()
    assert n == read_vtp(population[0]).GetNumberOfPoints()
    spread = point_array(mean, "StandardDeviation")
    assert spread.shape == (n,) and np.all(spread >= 0) and spread.max() > 0.01

    variance = read_csv(out / "variance.csv")
    assert [int(r["mode"]) for r in variance] == [1, 2, 3]
    variances = [float(r["variance"]) for r in variance]
    assert variances == sorted(variances, reverse=True) and variances[0] > 0
    fractions = [float(r["explained_fraction"]) for r in variance]
    assert sum(fractions[:2]) > 0.95  # two planted deformations
    assert abs(float(variance[-1]["cumulative_fraction"]) - sum(fractions)) < 1e-9
    for r in variance:
        assert abs(float(r["standard_deviation"]) ** 2 - float(r["variance"])) < 1e-9 * float(r["variance"]) + 1e-15

    scores = read_csv(out / "scores.csv")
    assert [r["file"] for r in scores] == population
    table = np.array([[float(r[f"mode_{m}"]) for m in (1, 2, 3)] for r in scores])
    assert np.allclose((table ** 2).mean(axis=0), variances, rtol=1e-6)
    assert all(float(r["alignment_rms"]) > 0 for r in scores)

    for m in (1, 2, 3):
        datasets = ET.parse(out / f"mode_{m}.pvd").getroot().find("Collection").findall("DataSet")
        assert [float(d.get("timestep")) for d in datasets] == [-2.0, -1.0, 0.0, 1.0, 2.0]
        mode = point_array(mean, f"Mode_{m}")
        for dataset in datasets:
            frame = read_vtp(out / dataset.get("file"))
            c = float(dataset.get("timestep"))
            expected_points = points(mean) + c * np.sqrt(variances[m - 1]) * mode
            assert np.abs(points(frame) - expected_points).max() < 1e-6


def test_statistics_of_a_map_directory(tmp_path):
    import surfacemaps
    from vtkmodules.util.numpy_support import numpy_to_vtk
    stretched = surfacemaps.read_mesh(data("ellipsoid_coarse.stl"))
    stretched.GetPoints().SetData(numpy_to_vtk(points(stretched) * [1.0, 1.0, 1.4], deep=True))
    third = str(tmp_path / "stretched.vtp")
    surfacemaps.write_mesh(stretched, third)
    mapped = run("map", data("ellipsoid.obj"), data("ellipsoid_coarse.stl"), third,
                 "--output-dir", tmp_path / "map", *SHORT)
    assert mapped.returncode == 0, mapped.stderr
    result = run("statistics", tmp_path / "map", "--output-dir", tmp_path / "stats", "--modes", "5")
    assert result.returncode == 0, result.stderr
    scores = read_csv(tmp_path / "stats" / "scores.csv")
    assert [os.path.basename(r["file"]) for r in scores] == [f"common_{i}.vtp" for i in range(3)]
    # Three specimens have two modes, whatever --modes asks.
    assert len(read_csv(tmp_path / "stats" / "variance.csv")) == 2
    assert sorted(f for f in os.listdir(tmp_path / "stats") if f.endswith(".pvd")) == ["mode_1.pvd", "mode_2.pvd"]
    mean = read_vtp(tmp_path / "stats" / "mean.vtp")
    assert mean.GetNumberOfPoints() == read_vtp(tmp_path / "map" / "common_0.vtp").GetNumberOfPoints()


def test_statistics_errors(population, tmp_path):
    out = tmp_path / "stats"
    result = run("statistics", population[0], data("ellipsoid_coarse.stl"), "--output-dir", out)
    assert result.returncode == 2
    assert "does not have the connectivity of input 0" in result.stderr
    assert not out.exists()  # created for nothing: removed
    result = run("statistics", population[0], "--output-dir", out)
    assert result.returncode == 2 and "two or more meshes" in result.stderr
    result = run("statistics", *population, "--output-dir", out, "--align", "affine")
    assert result.returncode == 2 and "--align is rigid, similarity or none" in result.stderr
    result = run("statistics", *population, "--output-dir", out, "--frames", "1")
    assert result.returncode == 2 and "--frames needs an integer from 2 to 1000" in result.stderr
    # A bound on what a mistyped number writes, said in --help.
    result = run("statistics", *population, "--output-dir", out, "--frames", "1000000000")
    assert result.returncode == 2 and "--frames needs an integer from 2 to 1000, not '1000000000'" in result.stderr
    assert not out.exists()
    result = run("statistics", *population)
    assert result.returncode == 2 and "--output-dir" in result.stderr
    result = run("statistics", tmp_path, "--output-dir", out)
    assert result.returncode == 2 and "report.json" in result.stderr
    help_text = run("statistics", "--help")
    assert help_text.returncode == 0 and "--pictures" in help_text.stdout and "Xvfb" in help_text.stdout
    assert "(default 9, from 2 to 1000)" in help_text.stdout


def test_an_interrupted_run_leaves_no_frames_without_their_index_files(population, tmp_path):
    """SIGTERM while the frames are being written (polled every ms): the frames were staged
    (DIR/statistics.tmp.<pid>) and go with it; nothing of the run is left in DIR."""
    import signal
    import subprocess
    import time
    from cli import CLI
    out = tmp_path / "stats"
    process = subprocess.Popen([CLI, "statistics", *population, "--output-dir", out, "--frames", "1000"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)

    def frames_written():  # anywhere below DIR: the run decides where frames go
        return any(name.startswith("frame_") for _, _, names in os.walk(out) for name in names)
    deadline = time.monotonic() + 240
    while process.poll() is None and time.monotonic() < deadline and not frames_written():
        time.sleep(0.001)
    process.send_signal(signal.SIGTERM)
    _, err = process.communicate(timeout=60)
    left = sorted(os.listdir(out))
    if process.returncode == -signal.SIGTERM:
        assert left == [], left
    else:  # finished before the signal: everything is there
        assert process.returncode == 0, err
        assert {"mean.vtp", "mode_1", "mode_1.pvd", "scores.csv", "variance.csv"} <= set(left), left
        assert not [name for name in left if ".tmp." in name], left


def test_a_second_run_replaces_the_frames_as_a_whole(population, tmp_path):
    out = tmp_path / "stats"
    for frames in ("5", "3"):
        result = run("statistics", *population, "--output-dir", out, "--frames", frames, "--modes", "1")
        assert result.returncode == 0, result.stderr
    assert sorted(os.listdir(out / "mode_1")) == ["frame_000.vtp", "frame_001.vtp", "frame_002.vtp"]
    assert len(list(ET.parse(out / "mode_1.pvd").getroot().iter("DataSet"))) == 3
    assert not [name for name in os.listdir(out) if ".tmp." in name]


def test_pictures_need_a_display_or_xvfb(population, tmp_path):
    from cli import run_headless
    out = tmp_path / "stats"
    result = run_headless("statistics", *population, "--output-dir", out, "--pictures", xvfb=False)
    assert result.returncode == 2
    assert "DISPLAY is not set" in result.stderr and "Debian package xvfb" in result.stderr
    assert not out.exists()


@pytest.mark.skipif(not os.environ.get("DISPLAY"), reason="needs a display (CTest runs this file under xvfb-run)")
def test_pictures(population, tmp_path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    out = tmp_path / "stats"
    result = run("statistics", *population, "--output-dir", out, "--modes", "2", "--pictures")
    assert result.returncode == 0, result.stderr
    for name in ("explained_variance.png", "scores.png", "spread.png"):
        path = out / name
        with open(path, "rb") as f:
            assert f.read(8) == b"\x89PNG\r\n\x1a\n", name
        reader = vtkPNGReader()
        reader.SetFileName(str(path))
        reader.Update()
        image = reader.GetOutput()
        assert image.GetDimensions()[:2] == (800, 600), name
        # Not a blank picture: more than one colour.
        from vtkmodules.util.numpy_support import vtk_to_numpy
        pixels = vtk_to_numpy(image.GetPointData().GetScalars())
        assert len(np.unique(pixels.reshape(len(pixels), -1), axis=0)) > 10, name
