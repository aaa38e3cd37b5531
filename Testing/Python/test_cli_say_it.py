"""Inputs the command line used to accept without a word now get a clear error or warning: OBJ line
and point elements, PLY element counts the file does not hold, a sizing too small to optimise,
zero-area triangles in evaluate, landmark sets in another order."""

from cli import data, run

QUICK = ("--coarse-iterations", "0", "--fine-iterations", "0", "--refinement-rounds", "0")


def test_obj_line_and_point_elements_are_refused(tmp_path):
    mesh = tmp_path / "with_lines.obj"
    mesh.write_text(open(data("ellipsoid.obj")).read().rstrip("\n") + "\nl 1 2\np 3\n")
    r = run("check", mesh)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{mesh}: 2 line or point elements ('l', 'p'); only triangles ('f') are accepted" in r.stderr


def ascii_ply(path, declared_faces, faces):
    """ellipsoid.obj as an ASCII PLY whose header declares `declared_faces` faces and whose data
    holds its first `faces` faces."""
    lines = open(data("ellipsoid.obj")).read().splitlines()
    vertices = [line[2:] for line in lines if line.startswith("v ")]
    triangles = [[int(c) - 1 for c in line.split()[1:]] for line in lines if line.startswith("f ")]
    header = ["ply", "format ascii 1.0", f"element vertex {len(vertices)}", "property double x",
              "property double y", "property double z", f"element face {declared_faces}",
              "property list uchar int vertex_indices", "end_header"]
    body = vertices + ["3 " + " ".join(map(str, t)) for t in triangles[:faces]]
    path.write_text("\n".join(header + body) + "\n")
    return len(triangles)


def test_ply_element_counts_the_file_does_not_hold_are_named(tmp_path):
    mesh = tmp_path / "counts.ply"
    n = ascii_ply(mesh, 1270, 1280)
    r = run("check", mesh)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert (f"{mesh}: the data goes on after the elements the header declares (642 vertex, 1270 face): "
            "the header's counts do not match the file") in r.stderr
    assert "boundary edges" not in r.stderr
    ascii_ply(mesh, n + 10, n)
    r = run("check", mesh)
    assert r.returncode == 2 and f"the header declares {n + 10} face elements, but the data ends" in r.stderr
    ascii_ply(mesh, n, n)
    assert run("check", mesh).returncode == 0


def test_a_sizing_too_small_to_optimise_is_refused(tmp_path):
    sizing = tmp_path / "tiny.txt"
    sizing.write_text("1e-300\n" * 162)
    r = run("map", data("ellipsoid_coarse.stl"), data("ellipsoid_coarse.stl"), "--sizing", sizing, sizing,
            "--output-dir", tmp_path / "map", *QUICK)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "input 0 has a Sizing of 1e-300 at point 0, below the smallest target edge length " \
           "MinEdgeLength (--min-edge-length, 0.001 of the input scaled to unit area" in r.stderr, r.stderr
    assert not (tmp_path / "map" / "report.json").exists()


def test_evaluate_names_zero_area_triangles(tmp_path):
    lines = open(data("ellipsoid.obj")).read().splitlines()
    vertex_lines = [k for k, line in enumerate(lines) if line.startswith("v ")]
    a, b = (int(c) - 1 for c in next(line for line in lines if line.startswith("f ")).split()[1:3])
    lines[vertex_lines[b]] = lines[vertex_lines[a]]  # an edge's ends at one point: its two triangles flat
    flat = tmp_path / "flat.obj"
    flat.write_text("\n".join(lines) + "\n")
    r = run("evaluate", data("ellipsoid.obj"), flat)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{flat} has 2 zero-area triangles (the first is triangle " in r.stderr
    assert "no map's distortion is defined on them" in r.stderr and "null" not in r.stdout


def test_landmarks_in_another_order_are_warned_about(tmp_path):
    forward, backward = tmp_path / "forward.pinned", tmp_path / "backward.pinned"
    forward.write_text("".join(f"{v}\n" for v in range(162)))
    backward.write_text("".join(f"{v}\n" for v in reversed(range(162))))
    mesh = data("ellipsoid_coarse.stl")
    r = run("map", mesh, mesh, "--landmarks", forward, backward, "--landmark-iterations", "5",
            "--output-dir", tmp_path / "reversed", *QUICK)
    assert "surfacemap: warning: the landmark phase ended with a landmark" in r.stderr, (r.returncode, r.stderr)
    assert "the landmark sets may not correspond" in r.stderr
    r = run("map", mesh, mesh, "--landmarks", forward, forward, "--landmark-iterations", "5",
            "--output-dir", tmp_path / "same", *QUICK)
    assert r.returncode == 0, r.stderr
    assert "landmark phase ended" not in r.stderr, r.stderr
