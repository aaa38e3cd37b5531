"""Reliability of the command line: checked writes, temporary files removed on
failures and signals, and the one input validation (64-bit ids, evaluate's
inputs, the dynamic range, the Landmarks array) in every command."""

import os
import resource
import select
import signal
import subprocess

import pytest

from cli import CLI, SHORT, data, read_vtp, run


def limited_run(limit_bytes, *args, timeout=300):
    """`surfacemap ARGS...` with files limited to `limit_bytes` (RLIMIT_FSIZE): a full disk
    without root or a tmpfs. SIGXFSZ stays at its default, the program must handle it."""
    def limit():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit_bytes, limit_bytes))
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout,
                          preexec_fn=limit)


def leftovers(directory):
    return [name for name in os.listdir(directory) if ".tmp." in name]


# Defect 1: writes are checked end to end.

def test_embed_into_a_full_disk_fails_and_leaves_nothing(tmp_path):
    out = tmp_path / "embedded.vtp"
    r = limited_run(8192, "embed", data("ellipsoid.obj"), "-o", out)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"cannot write '{out}'" in r.stderr
    assert "written to" not in r.stdout
    assert not out.exists()
    assert leftovers(tmp_path) == []


def test_evaluate_into_a_full_disk_fails_and_leaves_no_broken_file(tmp_path):
    out = tmp_path / "evaluation"
    r = limited_run(4096, "evaluate", data("blob.vtp"), data("blob.vtp"), "--output-dir", out)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "cannot write" in r.stderr and "triangles.csv" in r.stderr
    # What is there is complete: summary.json was small enough to fit.
    if (out / "summary.json").exists():
        assert (out / "summary.json").read_text().rstrip().endswith("}")
    assert not (out / "triangles.csv").exists()
    assert not out.exists() or leftovers(out) == []


def test_map_into_a_full_disk_leaves_no_broken_file(tmp_path):
    out = tmp_path / "map"
    r = limited_run(16384, "map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", out, *SHORT)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "cannot write" in r.stderr
    if out.exists():
        assert leftovers(out) == []
        for name in os.listdir(out):
            if name.endswith(".vtp"):
                assert read_vtp(out / name).GetNumberOfPoints() > 0, name


def test_transfer_into_a_full_disk_leaves_nothing(tmp_path):
    mapdir = tmp_path / "map"
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", mapdir, *SHORT)
    assert r.returncode == 0, r.stderr
    out = tmp_path / "transferred.vtp"
    r = limited_run(2048, "transfer", mapdir, "--from", 0, "--to", 1, "-o", out)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"cannot write '{out}'" in r.stderr
    assert not out.exists()
    assert leftovers(tmp_path) == []


def test_stdout_write_error_is_reported():
    with open("/dev/full", "w") as full:
        r = subprocess.run([CLI, "check", data("ellipsoid.obj")], stdout=full, stderr=subprocess.PIPE,
                           text=True, timeout=60)
    assert r.returncode == 2
    assert "cannot write to standard output" in r.stderr


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "SIGINT"])
def test_signal_removes_the_temporary_file(tmp_path, signum):
    """A FIFO stands in for the temporary file of common_0.vtp in the run's staging directory
    (made while the map computes): the map blocks writing it (a 4 KiB pipe nobody reads), so
    the signal arrives while the temporary file exists. The staging directory goes with it."""
    import time
    out = tmp_path / "map"
    out.mkdir()
    process = subprocess.Popen([CLI, "map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", out,
                                *SHORT], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    staging = tmp_path / f"map.tmp.{process.pid}"
    fifo = staging / f"common_0.vtp.tmp.{process.pid}"
    reader = None
    try:
        deadline = time.monotonic() + 120
        while process.poll() is None and not staging.exists() and time.monotonic() < deadline:
            time.sleep(0.001)
        os.mkfifo(fifo)
        reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
        import fcntl
        fcntl.fcntl(reader, 1031, 4096)  # F_SETPIPE_SZ: the writer blocks after 4 KiB
        ready, _, _ = select.select([reader], [], [], 120)
        assert ready, "the map never started writing"
        assert fifo.exists()
        process.send_signal(signum)
        process.wait(timeout=60)
    finally:
        if reader is not None:
            os.close(reader)
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == -signum, process.stderr.read()
    assert not fifo.exists()
    assert not staging.exists()
    assert os.listdir(out) == []


# Defect 2: 64-bit vertex ids are rejected, never wrapped.

def write_vtp_with_index(source, path, position, value):
    """`source` (a Data mesh) as a .vtp whose connectivity holds `value` at `position` (64-bit ids)."""
    from vtkmodules.vtkCommonCore import vtkIdTypeArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    import surfacemaps
    mesh = surfacemaps.read_mesh(source)
    offsets, connectivity = vtkIdTypeArray(), vtkIdTypeArray()
    offsets.DeepCopy(mesh.GetPolys().GetOffsetsArray())
    connectivity.DeepCopy(mesh.GetPolys().GetConnectivityArray())
    connectivity.SetValue(position, value)
    polys = vtkCellArray()
    polys.SetData(offsets, connectivity)
    out = vtkPolyData()
    out.SetPoints(mesh.GetPoints())
    out.SetPolys(polys)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(out)
    writer.SetHeaderTypeToUInt64()
    writer.SetIdTypeToInt64()
    assert writer.Write() == 1
    return path


@pytest.mark.parametrize("command", ["check", "embed", "map"])
def test_wide_index_is_rejected_by_every_command(tmp_path, command):
    wide = write_vtp_with_index(data("ellipsoid.obj"), tmp_path / "wide.vtp", 4, 2**32 + 3)
    args = {"check": ["check", wide],
            "embed": ["embed", wide, "-o", tmp_path / "out.vtp"],
            "map": ["map", wide, data("blob.off"), "--output-dir", tmp_path / "map", *SHORT]}[command]
    r = run(*args)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{wide}" in r.stderr
    assert "face 1 uses vertex index 4294967299" in r.stderr
    assert not (tmp_path / "out.vtp").exists()
    assert not (tmp_path / "map" / "common_0.vtp").exists()


def test_huge_index_is_rejected_by_evaluate(tmp_path):
    huge = write_vtp_with_index(data("blob.vtp"), tmp_path / "huge.vtp", 0, 10**12)
    r = run("evaluate", huge, data("blob.vtp"))
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{huge}" in r.stderr and "uses vertex index 1000000000000" in r.stderr


# Defect 3: evaluate validates its inputs.

def test_evaluate_rejects_negative_and_out_of_range_indices(tmp_path):
    for value in (-3, 5000):
        bad = write_vtp_with_index(data("blob.vtp"), tmp_path / f"bad{value}.vtp", 7, value)
        r = run("evaluate", bad, bad)
        assert r.returncode == 2, (value, r.stdout, r.stderr)
        assert f"face 2 uses vertex index {value}" in r.stderr
        assert "SymmetricDirichlet" not in r.stdout


def test_evaluate_rejects_points_without_triangles(tmp_path):
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    import surfacemaps
    points = vtkPolyData()
    points.SetPoints(surfacemaps.read_mesh(data("blob.vtp")).GetPoints())
    path = tmp_path / "points.vtp"
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(points)
    assert writer.Write() == 1
    r = run("evaluate", path, path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{path} contains no triangles" in r.stderr


def test_evaluate_rejects_nan_in_originals():
    r = run("evaluate", data("ellipsoid.obj"), data("ellipsoid.obj"), "--originals",
            data("bad/nan_vertex.obj"), data("ellipsoid.obj"))
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert (data("bad/nan_vertex.obj") + " has 1 vertex with non-finite coordinates (first: vertex 4"
            in r.stderr)
    assert "TwoSidedDistance" not in r.stdout


# Defect 5: coordinates outside the dynamic range.

def scaled_obj(tmp_path, factor, only_vertex=None):
    lines = open(data("ellipsoid.obj")).read().splitlines()
    out, k = [], 0
    for line in lines:
        if line.startswith("v "):
            x, y, z = map(float, line.split()[1:4])
            if only_vertex is None or k == only_vertex:
                x, y, z = x * factor, y * factor, z * factor
            line = f"v {x!r} {y!r} {z!r}"
            k += 1
        out.append(line)
    path = tmp_path / f"scaled_{factor:g}_{only_vertex}.obj"
    path.write_text("\n".join(out) + "\n")
    return path


@pytest.mark.parametrize("command", ["check", "embed", "map", "evaluate"])
def test_overflowing_coordinates_are_rejected(tmp_path, command):
    mesh = scaled_obj(tmp_path, 1e200)
    args = {"check": ["check", mesh],
            "embed": ["embed", mesh, "-o", tmp_path / "out.vtp"],
            "map": ["map", mesh, data("blob.off"), "--output-dir", tmp_path / "map", *SHORT],
            "evaluate": ["evaluate", mesh, mesh]}[command]
    r = run(*args)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{mesh}" in r.stderr
    assert "has 642 vertices outside the valid coordinate range |x|, |y|, |z| <= 1e+50" in r.stderr
    assert "first: vertex 0" in r.stderr
    assert "certified" not in r.stdout


def test_one_vertex_at_1e308_is_named(tmp_path):
    mesh = scaled_obj(tmp_path, 1e308, only_vertex=9)
    r = run("check", mesh)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "has 1 vertex outside the valid coordinate range" in r.stderr
    assert "first: vertex 9" in r.stderr


def test_tiny_scale_is_rejected(tmp_path):
    r = run("check", scaled_obj(tmp_path, 1e-60))
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "has a bounding-box diagonal of" in r.stderr and "at least 1e-50" in r.stderr


def test_large_but_valid_scale_is_accepted(tmp_path):
    r = run("check", scaled_obj(tmp_path, 1e40))
    assert r.returncode == 0, r.stderr


# Defect 7: the Landmarks array's shape and values.

def write_with_landmarks(tmp_path, name, array, values=()):
    """ellipsoid.obj as a .vtp with `array` as its Landmarks: -1 everywhere but (vertex, value) in `values`."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    import surfacemaps
    mesh = surfacemaps.read_mesh(data("ellipsoid.obj"))
    array.SetName("Landmarks")
    array.SetNumberOfTuples(mesh.GetNumberOfPoints())
    for c in range(array.GetNumberOfComponents()):
        array.FillComponent(c, -1)
    for vertex, value in values:
        array.SetComponent(vertex, 0, value)
    mesh.GetPointData().AddArray(array)
    path = tmp_path / name
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(mesh)
    assert writer.Write() == 1
    return path


@pytest.mark.parametrize("command", ["check", "embed", "map"])
def test_two_component_landmarks_are_rejected(tmp_path, command):
    from vtkmodules.vtkCommonCore import vtkIntArray
    array = vtkIntArray()
    array.SetNumberOfComponents(2)
    path = write_with_landmarks(tmp_path, "two.vtp", array, [(5, 0)])
    args = {"check": ["check", path],
            "embed": ["embed", path, "-o", tmp_path / "out.vtp"],
            "map": ["map", path, data("blob.off"), "--output-dir", tmp_path / "map", *SHORT]}[command]
    r = run(*args)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "Landmarks array with 2 components" in r.stderr and f"{path}" in r.stderr
    assert not (tmp_path / "out.vtp").exists()


def test_non_integer_landmark_ids_are_rejected(tmp_path):
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    whole = write_with_landmarks(tmp_path, "whole.vtp", vtkDoubleArray(), [(11, 2.0)])
    r = run("check", whole)
    assert r.returncode == 0, r.stderr  # integer-valued floats are ids
    assert "landmarks 1" in r.stdout
    half = write_with_landmarks(tmp_path, "half.vtp", vtkDoubleArray(), [(11, 2.5)])
    r = run("check", half)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{half} has a landmark id that is not an integer (2.5 at vertex 11)" in r.stderr


# Defect 4: VTK's legacy reader is never handed an index it would crash on.

def legacy_with_index(tmp_path, name, index):
    """limbs_coarse.vtk (legacy 4.2, ASCII) with the first POLYGONS cell's second index replaced."""
    lines = open(data("limbs_coarse.vtk")).read().split("\n")
    polygons = next(i for i, line in enumerate(lines) if line.startswith("POLYGONS"))
    cell = lines[polygons + 1].split()
    cell[2] = str(index)
    lines[polygons + 1] = " ".join(cell)
    path = tmp_path / name
    path.write_text("\n".join(lines))
    return path, polygons + 2


@pytest.mark.parametrize("index", [2**32 + 5, -1, 642])
def test_legacy_polygon_index_out_of_range_is_named(tmp_path, index):
    path, line = legacy_with_index(tmp_path, "wide.vtk", index)
    r = run("check", path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{path}:{line}: polygons cell 0 uses point index {index}, out of range for 642 points" in r.stderr


def test_legacy_huge_point_count_is_not_allocated(tmp_path):
    text = open(data("limbs_coarse.vtk")).read().replace("POINTS 642 double", "POINTS 4294967296000 double")
    path = tmp_path / "huge.vtk"
    path.write_text(text)
    r = run("check", path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{path}:5: declares a point count of 4294967296000, more than the file's" in r.stderr


# Weak spots: a directory or a device given as a mesh or landmark file.

def test_directory_as_mesh_is_named_as_such(tmp_path):
    r = run("check", tmp_path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{tmp_path}: is a directory, not a file" in r.stderr


@pytest.mark.parametrize("name", ["zero.obj", "zero.vtp", "zero.vtk"])
def test_device_as_mesh_is_refused_at_once(tmp_path, name):
    link = tmp_path / name
    os.symlink("/dev/zero", link)
    r = run("check", link, timeout=20)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{link}: is not a regular file" in r.stderr


def test_device_as_landmark_file_is_refused_at_once(tmp_path):
    link = tmp_path / "zero.pinned"
    os.symlink("/dev/zero", link)
    r = run("check", data("ellipsoid.obj"), "--landmarks", link, timeout=20)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{link}: is not a regular file" in r.stderr


# Defect 8: every refinement loop is bounded.

def icosphere_42(path):
    """An icosahedron subdivided once onto the unit sphere: 42 vertices, 80 triangles (OBJ)."""
    t = (1 + 5 ** 0.5) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
              (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    middle = {}

    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in middle:
            middle[key] = len(points)
            points.append(tuple((p + q) / 2 for p, q in zip(points[a], points[b])))
        return middle[key]

    fine = []
    for a, b, c in faces:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        fine += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    with open(path, "w") as f:
        for p in points:
            n = sum(x * x for x in p) ** 0.5
            f.write("v %r %r %r\n" % tuple(x / n for x in p))
        for face in fine:
            f.write("f %d %d %d\n" % tuple(v + 1 for v in face))
    return path


def test_small_max_error_ends_at_the_vertex_budget(tmp_path):
    sphere = icosphere_42(tmp_path / "ico42.obj")
    assert "vertices 42, faces 80" in run("check", sphere).stdout
    out = tmp_path / "map"
    r = run("map", sphere, "--max-error", "1e-6", "--max-vertices", "400", "--output-dir", out, *SHORT,
            timeout=120)
    assert r.returncode == 3, (r.stdout, r.stderr)
    assert "reached its vertex budget" in r.stderr and "budget 400 (MaxVertices, --max-vertices)" in r.stderr
    assert not (out / "common_0.vtp").exists()


def test_error_bound_rounds_are_bounded(tmp_path):
    sphere = icosphere_42(tmp_path / "ico42.obj")
    r = run("map", sphere, "--max-error", "1e-6", "--bound-refinement-rounds", "1",
            "--bound-refinement-iterations", "1", "--output-dir", tmp_path / "map", *SHORT, timeout=120)
    assert r.returncode == 3, (r.stdout, r.stderr)
    assert "could not be met after 1 refinement rounds" in r.stderr


# Defect 6: a map directory is one consistent set of files, or refused.

@pytest.fixture(scope="module")
def two_maps(tmp_path_factory):
    """Two maps of the same inputs (different runs: different map ids and embeddings)."""
    maps = []
    for k in range(2):
        out = tmp_path_factory.mktemp(f"map{k}")
        r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", out, "--overwrite",
                "--fine-iterations", str(3 + k), *SHORT[:4])
        assert r.returncode == 0, r.stderr
        maps.append(out)
    return maps


def copy_map(source, target):
    import shutil
    shutil.copytree(source, target)
    return target


def test_report_names_every_file_with_size_checksum_and_map_id(two_maps):
    import hashlib
    import json
    import surfacemaps
    report = json.loads((two_maps[0] / "report.json").read_text())
    names = {f"{kind}_{i}.vtp" for kind in ("common", "mapped", "embedding") for i in (0, 1)}
    assert {record["name"] for record in report["files"]} == names | {"correspondences.npz", "fit.csv"}
    for record in report["files"]:
        content = (two_maps[0] / record["name"]).read_bytes()
        assert record["bytes"] == len(content)
        assert record["md5"] == hashlib.md5(content).hexdigest()
        path = two_maps[0] / record["name"]
        if path.suffix == ".vtp":  # the meshes carry the map's stamp; the table and archive do not
            assert surfacemaps.map_file_stamp(path, "MapId") == report["map_id"]
            assert surfacemaps.map_file_stamp(path, "MapFile") == record["name"]
    other = json.loads((two_maps[1] / "report.json").read_text())
    assert len(report["map_id"]) == 32 and other["map_id"] != report["map_id"]


def transfer_and_evaluate(directory, tmp_path):
    out = tmp_path / "out.vtp"
    return (run("transfer", directory, "--from", "0", "--to", "1", "-o", out),
            run("evaluate", directory, "--output-dir", tmp_path / "evaluation"))


def test_a_stale_file_from_another_map_is_refused(two_maps, tmp_path):
    import shutil
    mixed = copy_map(two_maps[0], tmp_path / "mixed")
    for name in ("embedding_1.vtp", "common_1.vtp"):
        shutil.copy(two_maps[1] / name, mixed / name)
    shutil.copy(two_maps[1] / "mapped_1.vtp", mixed / "mapped_1.vtp")
    for r in transfer_and_evaluate(mixed, tmp_path):
        assert r.returncode == 2, (r.stdout, r.stderr)
        assert "belongs to another map" in r.stderr and "a stale or copied file" in r.stderr
    assert not (tmp_path / "out.vtp").exists()


def test_swapped_embeddings_are_refused(two_maps, tmp_path):
    swapped = copy_map(two_maps[0], tmp_path / "swapped")
    (swapped / "embedding_0.vtp").rename(swapped / "tmp.vtp")
    (swapped / "embedding_1.vtp").rename(swapped / "embedding_0.vtp")
    (swapped / "tmp.vtp").rename(swapped / "embedding_1.vtp")
    r = run("transfer", swapped, "--from", "0", "--to", "1", "-o", tmp_path / "out.vtp")
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "is embedding_0.vtp of this map, not embedding_1.vtp: swapped or renamed" in r.stderr


def test_a_rotated_embedding_is_refused(two_maps, tmp_path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    rotated = copy_map(two_maps[0], tmp_path / "rotated")
    mesh = read_vtp(rotated / "embedding_1.vtp")
    sphere = mesh.GetPointData().GetArray("SpherePosition")
    for v in range(sphere.GetNumberOfTuples()):
        x, y, z = sphere.GetTuple3(v)
        sphere.SetTuple3(v, -y, x, z)  # 90 degrees about z: still a bijective embedding
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(rotated / "embedding_1.vtp"))
    assert writer.Write() == 1
    r = run("transfer", rotated, "--from", "0", "--to", "1", "-o", tmp_path / "out.vtp")
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{rotated / 'embedding_1.vtp'} was changed after the map was written" in r.stderr


def test_missing_report_or_file_is_refused(two_maps, tmp_path):
    incomplete = copy_map(two_maps[0], tmp_path / "incomplete")
    (incomplete / "report.json").unlink()
    for r in transfer_and_evaluate(incomplete, tmp_path):
        assert r.returncode == 2, (r.stdout, r.stderr)
        assert (f"{incomplete} holds an interrupted run (common_/mapped_/embedding_ files, no report.json): "
                "give --overwrite or remove it") in r.stderr


def test_map_refuses_an_earlier_map_without_overwrite(two_maps, tmp_path):
    import json
    target = copy_map(two_maps[0], tmp_path / "again")
    before = (target / "report.json").read_text()
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", target, *SHORT)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "holds an earlier map" in r.stderr and "--overwrite" in r.stderr
    assert (target / "report.json").read_text() == before
    # With --overwrite the earlier map is replaced as a whole: a third input's files go too.
    (target / "common_2.vtp").write_bytes((target / "common_1.vtp").read_bytes())
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", target, "--overwrite", *SHORT)
    assert r.returncode == 0, r.stderr
    assert not (target / "common_2.vtp").exists()
    report = json.loads((target / "report.json").read_text())
    assert report["map_id"] != json.loads(before)["map_id"]
    r, e = transfer_and_evaluate(target, tmp_path)
    assert r.returncode == 0 and e.returncode == 0, (r.stderr, e.stderr)


# Maps whose content does not matter here: the embeddings and T = input 0, no phase runs
# (0.5 s instead of 3 s; these tests also run under the sanitizers).
NO_ITERATIONS = ("--landmark-iterations", "0", "--coarse-iterations", "0", "--fine-iterations", "0",
                 "--refinement-rounds", "0")


def siblings_left_behind(parent):
    """Staging (DIR.tmp.<pid>) or moved-aside (DIR.old.<pid>) directories of a map run."""
    return [name for name in os.listdir(parent) if ".tmp." in name or ".old." in name]


def test_a_failing_overwrite_leaves_the_earlier_map(two_maps, tmp_path):
    """The new map fails while being written (a file size limit: a full disk): the earlier
    map is untouched and usable, and no staging directory is left."""
    target = copy_map(two_maps[0], tmp_path / "kept")
    (target / "notes.txt").write_text("mine")
    before = {name: (target / name).read_bytes() for name in os.listdir(target)}
    r = limited_run(16384, "map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", target,
                    "--overwrite", *NO_ITERATIONS)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "cannot write" in r.stderr
    assert {name: (target / name).read_bytes() for name in os.listdir(target)} == before
    assert siblings_left_behind(tmp_path) == []
    checks = tmp_path / "checks"
    checks.mkdir()
    r, e = transfer_and_evaluate(target, checks)
    assert r.returncode == 0 and e.returncode == 0, (r.stderr, e.stderr)


def test_sigterm_while_the_new_map_is_staged_leaves_the_earlier_map(two_maps, tmp_path):
    """SIGTERM as soon as the staging directory DIR.tmp.<pid> appears (polled every ms): the
    earlier map is still there, byte for byte, and nothing is left beside it. Should the run
    finish before the signal lands, the new map must be complete instead."""
    import time
    target = copy_map(two_maps[0], tmp_path / "kept")
    before = {name: (target / name).read_bytes() for name in os.listdir(target)}
    process = subprocess.Popen([CLI, "map", data("ellipsoid.obj"), data("blob.off"), "--output-dir",
                                target, "--overwrite", *NO_ITERATIONS], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True)
    staging = tmp_path / f"kept.tmp.{process.pid}"
    try:
        deadline = time.monotonic() + 240
        while process.poll() is None and not staging.exists() and time.monotonic() < deadline:
            time.sleep(0.001)
        staged = staging.exists()
        process.send_signal(signal.SIGTERM)
        process.wait(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert siblings_left_behind(tmp_path) == []
    if process.returncode == -signal.SIGTERM:
        assert staged, "the signal came before the staging directory"
        assert {name: (target / name).read_bytes() for name in os.listdir(target)} == before
    else:
        assert process.returncode == 0, process.stderr.read()
    checks = tmp_path / "checks"
    checks.mkdir()
    r, e = transfer_and_evaluate(target, checks)
    assert r.returncode == 0 and e.returncode == 0, (r.stderr, e.stderr)


def test_overwrite_swaps_in_a_complete_map_and_keeps_other_files(two_maps, tmp_path):
    import json
    target = copy_map(two_maps[0], tmp_path / "replaced")
    (target / "notes.txt").write_text("mine")
    old_id = json.loads((target / "report.json").read_text())["map_id"]
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", target, "--overwrite", *NO_ITERATIONS)
    assert r.returncode == 0, r.stderr
    assert "note:" not in r.stderr  # replaced as a whole, not in place
    report = json.loads((target / "report.json").read_text())
    assert report["map_id"] != old_id
    assert (target / "notes.txt").read_text() == "mine"
    assert sorted(os.listdir(target)) == sorted([record["name"] for record in report["files"]]
                                                + ["report.json", "notes.txt"])
    assert siblings_left_behind(tmp_path) == []
    checks = tmp_path / "checks"
    checks.mkdir()
    r, e = transfer_and_evaluate(target, checks)
    assert r.returncode == 0 and e.returncode == 0, (r.stderr, e.stderr)


# One writer per map directory: every run stages its map beside the directory and publishes it
# as a whole; a second run is refused, and nothing is left half written or beside it.

def map_process(out, *meshes, schedule=NO_ITERATIONS, extra=()):
    """`surfacemap map MESHES --output-dir OUT`, started (not waited for)."""
    return subprocess.Popen([CLI, "map", *map(str, meshes), "--output-dir", str(out), *schedule, *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def wait_for(path, process, seconds=240):
    """Polls (every ms) until `path` exists or `process` ends; whether it exists."""
    import time
    deadline = time.monotonic() + seconds
    while process.poll() is None and not os.path.exists(path) and time.monotonic() < deadline:
        time.sleep(0.001)
    return os.path.exists(path)


def complete_map(directory):
    """The report of the one complete map `directory` holds: exactly the files report.json lists
    (and report.json), each of the recorded size and checksum."""
    import hashlib
    import json
    report = json.loads((directory / "report.json").read_text())
    names = {record["name"] for record in report["files"]}
    assert sorted(os.listdir(directory)) == sorted(names | {"report.json"})
    for record in report["files"]:
        content = (directory / record["name"]).read_bytes()
        assert (len(content), hashlib.md5(content).hexdigest()) == (record["bytes"], record["md5"]), record
    return report


def test_two_runs_into_one_new_directory_leave_one_complete_map(tmp_path):
    """`map A B --output-dir D & map A C --output-dir D` (both started at once), 20 rounds, or
    as many as fit in 120 s (the sanitizer build is slower): D holds exactly one complete map,
    that of the run that exits 0; the other exits 2 saying why; nothing is left beside D."""
    import time
    second = [data("blob.off"), data("ellipsoid_coarse.stl")]
    deadline = time.monotonic() + 120
    rounds = 0
    while rounds < 20 and time.monotonic() < deadline:
        out = tmp_path / f"D{rounds}"
        processes = [map_process(out, data("ellipsoid.obj"), mesh) for mesh in second]
        results = [(p.communicate(timeout=240), p.returncode) for p in processes]
        codes = [code for _, code in results]
        assert sorted(codes) == [0, 2], results
        winner = codes.index(0)
        refusal = results[1 - winner][0][1]
        assert any(reason in refusal for reason in (
            "another 'surfacemap map' (pid", "holds an earlier map", "now holds a map that another run wrote")), refusal
        report = complete_map(out)
        assert report["inputs"][1]["file"] == os.path.abspath(second[winner])
        assert siblings_left_behind(tmp_path) == []
        rounds += 1
    assert rounds >= 5


def test_a_second_run_is_refused_while_the_first_computes(tmp_path):
    target = tmp_path / "D"
    first = map_process(target, data("ellipsoid.obj"), data("blob.off"), schedule=SHORT)
    assert wait_for(tmp_path / f"D.tmp.{first.pid}", first)
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", target, *NO_ITERATIONS)
    still_running = first.poll() is None
    _, err = first.communicate(timeout=240)
    assert first.returncode == 0, err
    assert r.returncode == 2, (r.stdout, r.stderr)
    if still_running:  # otherwise the first had published its map: "holds an earlier map"
        assert (f"another 'surfacemap map' (pid {first.pid}) is writing a map into {target}: wait for it "
                "to finish, or choose another --output-dir") in r.stderr, r.stderr
        assert "map of" not in r.stdout  # refused before computing
    complete_map(target)
    assert siblings_left_behind(tmp_path) == []


def test_a_map_that_appears_while_a_run_computes_is_not_replaced(two_maps, tmp_path):
    """Another map is put at D (not by a surfacemap run) while a run for D computes: the run
    refuses to replace it without --overwrite, and leaves it byte for byte."""
    import shutil
    target = tmp_path / "D"
    process = map_process(target, data("ellipsoid.obj"), data("blob.off"), schedule=SHORT)
    assert wait_for(tmp_path / f"D.tmp.{process.pid}", process)
    other = copy_map(two_maps[1], tmp_path / "other")
    before = {name: (other / name).read_bytes() for name in os.listdir(other)}
    try:
        os.rename(other, target)
        placed = True
    except OSError:  # the run was first
        placed = False
        shutil.rmtree(other)
    _, err = process.communicate(timeout=240)
    assert siblings_left_behind(tmp_path) == []
    if not placed:
        assert process.returncode == 0, err
        complete_map(target)
        return
    assert process.returncode == 2, err
    assert (f"{target} now holds a map that another run wrote while this one computed: this map is not "
            "written (give --overwrite to replace that one)") in err
    assert {name: (target / name).read_bytes() for name in os.listdir(target)} == before


def test_what_killed_runs_left_beside_the_directory_is_cleaned_up(two_maps, tmp_path):
    """SIGKILL (no handler runs) leaves the staging directory D.tmp.<pid>: the next run removes
    it, with a note. A run killed between exchanging D and carrying the user's files over left
    them in D.tmp.<pid> with the earlier map: they come back into D. An earlier version killed
    between its two renames left no D and the earlier map in D.old.<pid>: it becomes D again."""
    target = tmp_path / "D"
    process = map_process(target, data("ellipsoid.obj"), data("blob.off"))
    staging = tmp_path / f"D.tmp.{process.pid}"
    assert wait_for(staging, process)
    process.kill()
    process.communicate()
    if process.returncode == -signal.SIGKILL:
        assert staging.exists()
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", target, "--overwrite",
            *NO_ITERATIONS)
    assert r.returncode == 0, r.stderr
    if process.returncode == -signal.SIGKILL:
        assert (f"note: removed {staging}, left by an interrupted 'surfacemap map' (pid {process.pid})"
                in r.stderr), r.stderr
    assert siblings_left_behind(tmp_path) == []
    complete_map(target)

    left = copy_map(two_maps[1], tmp_path / "D.tmp.999999999")
    (left / "notes.txt").write_text("mine")
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", target, "--overwrite",
            *NO_ITERATIONS)
    assert r.returncode == 0, r.stderr
    assert f"note: removed {left}" in r.stderr, r.stderr
    assert (target / "notes.txt").read_text() == "mine"
    assert siblings_left_behind(tmp_path) == []

    import shutil
    shutil.rmtree(target)
    old = copy_map(two_maps[0], tmp_path / "D.old.999999998")
    before = {name: (old / name).read_bytes() for name in os.listdir(old)}
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", target, *NO_ITERATIONS)
    assert r.returncode == 2, r.stderr
    assert f"note: restored {target} from {old}" in r.stderr, r.stderr
    assert "holds an earlier map" in r.stderr
    assert {name: (target / name).read_bytes() for name in os.listdir(target)} == before
    assert siblings_left_behind(tmp_path) == []


def test_an_interrupted_run_is_named_as_such_everywhere(two_maps, tmp_path):
    """Map files without report.json (a run interrupted where it writes in place, or files put
    there by hand): every command says "interrupted run", and --overwrite replaces them."""
    interrupted = copy_map(two_maps[0], tmp_path / "interrupted")
    (interrupted / "report.json").unlink()
    message = (f"{interrupted} holds an interrupted run (common_/mapped_/embedding_ files, no report.json): "
               "give --overwrite or remove it")
    for r in (*transfer_and_evaluate(interrupted, tmp_path),
              run("statistics", interrupted, "--output-dir", tmp_path / "statistics"),
              run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", interrupted, *NO_ITERATIONS)):
        assert r.returncode == 2, (r.args, r.stdout, r.stderr)
        assert message in r.stderr, (r.args, r.stderr)
        assert "map of" not in r.stdout
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--output-dir", interrupted, "--overwrite",
            *NO_ITERATIONS)
    assert r.returncode == 0, r.stderr
    complete_map(interrupted)


def test_a_truncated_or_deleted_map_file_is_named(two_maps, tmp_path):
    damaged = copy_map(two_maps[0], tmp_path / "damaged")
    content = (damaged / "common_1.vtp").read_bytes()
    (damaged / "common_1.vtp").write_bytes(content[:len(content) // 2])
    for r in transfer_and_evaluate(damaged, tmp_path):
        assert r.returncode == 2, (r.stdout, r.stderr)
        assert f"{damaged / 'common_1.vtp'} is damaged or truncated: it does not read as a mesh" in r.stderr
    (damaged / "common_1.vtp").unlink()
    r = run("evaluate", damaged, "--output-dir", tmp_path / "evaluation")
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{damaged / 'common_1.vtp'} is missing ({damaged}/report.json lists it)" in r.stderr


# Every reader of a map directory checks what it reads: statistics as evaluate does.

def test_statistics_refuses_a_swapped_or_stale_common_file(two_maps, tmp_path):
    import shutil
    swapped = copy_map(two_maps[0], tmp_path / "swapped")
    shutil.copy(swapped / "common_0.vtp", swapped / "common_1.vtp")
    r = run("statistics", swapped, "--output-dir", tmp_path / "stats")
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{swapped / 'common_1.vtp'} is common_0.vtp of this map, not common_1.vtp: swapped or renamed" in r.stderr
    assert "total variance" not in r.stdout
    stale = copy_map(two_maps[0], tmp_path / "stale")
    shutil.copy(two_maps[1] / "common_1.vtp", stale / "common_1.vtp")
    r = run("statistics", stale, "--output-dir", tmp_path / "stats")
    assert r.returncode == 2 and "belongs to another map" in r.stderr, r.stderr
    assert not (tmp_path / "stats").exists()
    r = run("statistics", two_maps[0], "--output-dir", tmp_path / "stats")
    assert r.returncode == 0, r.stderr


# Weak spot: landmarks that are the mirror image of input 0's are warned about, by name.

def mirrored_blob(tmp_path):
    """blob.off mirrored in x (triangles reversed, so it stays outward oriented) and its
    landmarks (blob.vts's vertices) as a .pinned file: the same surface seen in a mirror."""
    lines = [line for line in open(data("blob.off")).read().splitlines()
             if line.strip() and not line.startswith("#")]
    vertices, faces = map(int, lines[1].split()[:2])
    out = ["OFF", lines[1]]
    for line in lines[2:2 + vertices]:
        x, y, z = map(float, line.split()[:3])
        out.append(f"{-x!r} {y!r} {z!r}")
    for line in lines[2 + vertices:2 + vertices + faces]:
        count, *corners = line.split()
        out.append(" ".join([count, *reversed(corners)]))
    mesh = tmp_path / "blob_mirrored.off"
    mesh.write_text("\n".join(out) + "\n")
    landmarks = tmp_path / "blob_mirrored.pinned"
    landmarks.write_text("".join(f"lk {line.split()[0]}\n"
                                 for line in open(data("blob.vts")).read().splitlines() if line.strip()))
    return mesh, landmarks


def test_mirror_image_landmarks_are_warned_about(tmp_path):
    mesh, landmarks = mirrored_blob(tmp_path)
    r = run("map", data("ellipsoid.obj"), mesh, "--landmarks", data("ellipsoid.pinned"), landmarks,
            "--output-dir", tmp_path / "mirrored", *NO_ITERATIONS)
    assert (f"surfacemap: warning: the landmarks of input 1 ({mesh}) are the mirror image of those "
            f"of input 0 ({data('ellipsoid.obj')})") in r.stderr, (r.returncode, r.stderr)
    # The same landmarks on the unmirrored blob: no warning.
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), "--output-dir", tmp_path / "plain", *NO_ITERATIONS)
    assert r.returncode == 0, r.stderr
    assert "mirror image" not in r.stderr, r.stderr


def test_python_transfer_refuses_what_the_command_line_refuses(two_maps, tmp_path):
    import shutil
    import surfacemaps
    mixed = copy_map(two_maps[0], tmp_path / "mixed")
    shutil.copy(two_maps[1] / "embedding_1.vtp", mixed / "embedding_1.vtp")
    with pytest.raises(surfacemaps.InputError, match="embedding_1.vtp belongs to another map"):
        surfacemaps.transfer(mixed, 0, 1)
    (mixed / "report.json").unlink()
    with pytest.raises(surfacemaps.InputError, match="holds an interrupted run .* give --overwrite or remove it"):
        surfacemaps.transfer(mixed, 0, 1)
    assert surfacemaps.transfer(two_maps[0], 0, 1).GetNumberOfPoints() > 0


# Weak spot: a truncated binary STL is named truncated, not "not closed".

def test_truncated_binary_stl_is_named_truncated(tmp_path):
    from vtkmodules.vtkIOGeometry import vtkSTLReader, vtkSTLWriter
    reader = vtkSTLReader()
    reader.SetFileName(data("ellipsoid_coarse.stl"))
    writer = vtkSTLWriter()
    writer.SetInputConnection(reader.GetOutputPort())
    writer.SetFileTypeToBinary()
    whole = tmp_path / "whole.stl"
    writer.SetFileName(str(whole))
    assert writer.Write() == 1
    assert run("check", whole).returncode == 0
    content = whole.read_bytes()
    cut = tmp_path / "cut.stl"
    cut.write_bytes(content[:-30])
    r = run("check", cut)
    assert r.returncode == 2, (r.stdout, r.stderr)
    triangles = (len(content) - 84) // 50
    assert (f"{cut}: the binary STL header declares {triangles} triangles ({len(content)} bytes), "
            f"but the file has {len(content) - 30} bytes; it is truncated or corrupt") in r.stderr


# Weak spots: transfer -o into the map's own files; --landmarks before the meshes; the pillow;
# embed --reference without landmarks.

def test_transfer_output_cannot_overwrite_the_map(two_maps, tmp_path):
    mine = copy_map(two_maps[0], tmp_path / "mine")
    before = (mine / "common_1.vtp").read_bytes()
    for name in ("common_1.vtp", "report.json"):
        r = run("transfer", mine, "--from", "0", "--to", "1", "-o", mine / name)
        assert r.returncode == 2, (r.stdout, r.stderr)
        assert f"would overwrite a file of the map in {mine}" in r.stderr
    assert (mine / "common_1.vtp").read_bytes() == before


@pytest.mark.parametrize("command", ["check", "map"])
def test_landmarks_before_the_meshes_are_explained(tmp_path, command):
    args = [command, "--landmarks", data("ellipsoid.pinned"), data("blob.vts")]
    if command == "map":
        args += ["--output-dir", tmp_path / "map"]
    r = run(*args)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "the meshes come before --landmarks" in r.stderr


def test_pillow_is_refused_by_check(tmp_path):
    pillow = tmp_path / "pillow.obj"
    pillow.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n")
    r = run("check", pillow)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "has only 2 triangles; a closed surface needs at least 4 (a tetrahedron)" in r.stderr


def test_embed_reference_needs_landmarks(tmp_path):
    reference = tmp_path / "reference.vtp"
    assert run("embed", data("ellipsoid.obj"), "--landmarks", data("ellipsoid.pinned"), "-o", reference).returncode == 0
    r = run("embed", data("ellipsoid.obj"), "--reference", reference, "-o", tmp_path / "out.vtp")
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "--reference turns the embedding" in r.stderr and "give --landmarks" in r.stderr
    assert not (tmp_path / "out.vtp").exists()
