"""`surfacemap check`: every good mesh accepted, every bad input rejected with its message."""

import os

import pytest

from cli import SHARED, data, run


GOOD = ["ellipsoid.obj", "ellipsoid_coarse.stl", "blob.off", "blob.vtp", "limbs.ply",
        "limbs_coarse.vtk", "spot.obj"]


@pytest.mark.parametrize("name", GOOD)
def test_good_meshes_are_valid(name):
    r = run("check", data(name))
    assert r.returncode == 0, r.stderr
    assert f"{data(name)}: valid" in r.stdout
    assert "genus 0, components 1, boundary edges 0" in r.stdout
    assert r.stderr == ""


def test_statistics_are_printed():
    r = run("check", data("ellipsoid.obj"))
    assert "vertices 642, faces 1280, edges 1920" in r.stdout
    assert "min angle" in r.stdout and "bbox diagonal" in r.stdout and "landmarks 0" in r.stdout


# (file, landmark file or None, expected message in stderr)
BAD = [
    ("bad/torus.obj", None, "bad/torus.obj has genus 1"),
    ("bad/hemisphere.obj", None, "bad/hemisphere.obj is not closed: 24 boundary edges"),
    ("bad/two_spheres.obj", None, "has 2 connected components"),
    ("bad/bowtie.obj", None, "has 1 non-manifold vertex"),
    ("bad/nonmanifold_edge.obj", None, "has 1 non-manifold edge"),
    ("bad/nan_vertex.obj", None, "has 1 vertex with non-finite coordinates (first: vertex 4"),
    ("bad/degenerate_triangle.obj", None, "has 1 zero-area triangle (first: face 0"),
    ("bad/quads.obj", None, "is not a triangle mesh: 6 of 6 polygons are not triangles"),
    ("bad/truncated.obj", None, "bad/truncated.obj:164: face has 1 vertex"),
    ("bad/truncated.off", None, "declares 162 vertices, but the file ends after 81; it looks truncated"),
    ("bad/truncated.ply", None, "the file looks truncated"),
    ("bad/truncated.vtk", None, "bad/truncated.vtk:90: POINTS: the file ends after 254 of 486 values; it is truncated"),
    ("bad/empty.obj", None, "bad/empty.obj: the file is empty"),
    ("bad/garbage.ply", None, "bad/garbage.ply: not a PLY file"),
    ("bad/duplicate_vertex.obj", None, "has 1 duplicate vertex (first: vertices 0 and 6"),
    ("bad/unused_vertex.off", None, "has 1 vertex not used by any triangle (first: vertex 6)"),
    ("bad/flipped_face.obj", None, "is not consistently oriented"),
    ("does_not_exist.obj", None, "cannot open"),
    ("ellipsoid.obj", "bad/ellipsoid_out_of_range.pinned",
     "landmark 2 is vertex 5000, out of range for a mesh with 642 vertices"),
]


@pytest.mark.parametrize("name,landmarks,message", BAD, ids=[b[0] + ("+" + b[1] if b[1] else "") for b in BAD])
def test_bad_inputs_are_rejected_with_their_message(name, landmarks, message):
    args = ["check", data(name)]
    if landmarks:
        args += ["--landmarks", data(landmarks)]
    r = run(*args)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert message in r.stderr, r.stderr
    assert "surfacemap: error: " in r.stderr
    assert data(name) in r.stderr  # the file is named
    assert "vtkExecutive" not in r.stderr and "ERR|" not in r.stderr  # no VTK noise


def test_every_bad_file_is_covered():
    covered = {b[0] for b in BAD} | {b[1] for b in BAD if b[1]} | {"bad/five_landmarks.pinned"}
    present = {"bad/" + f for f in os.listdir(data("bad"))}
    assert present <= covered, present - covered


def test_one_bad_mesh_among_good_ones_fails_the_run():
    r = run("check", data("ellipsoid.obj"), data("bad/torus.obj"), data("blob.off"))
    assert r.returncode == 2
    assert f"{data('ellipsoid.obj')}: valid" in r.stdout
    assert f"{data('bad/torus.obj')}: INVALID" in r.stdout
    assert f"{data('blob.off')}: valid" in r.stdout


def test_landmarks_matching_and_not():
    r = run("check", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"))
    assert r.returncode == 0, r.stderr
    assert r.stdout.count("landmarks 4") == 2
    r = run("check", data("ellipsoid.obj"), data("limbs.ply"), "--landmarks", data("ellipsoid.pinned"),
            data("bad/five_landmarks.pinned"))
    assert r.returncode == 2
    assert "landmark counts do not match" in r.stderr


def test_without_landmark_files_meshes_are_checked_on_their_own():
    # blob.vtp carries 4 landmarks in its own array; ellipsoid.obj has none.
    r = run("check", data("ellipsoid.obj"), data("blob.vtp"))
    assert r.returncode == 0, r.stderr


def test_usage_errors():
    r = run("check")
    assert r.returncode == 2 and "no mesh given" in r.stderr
    r = run("check", data("ellipsoid.obj"), "--landmarks")
    assert r.returncode == 2 and "one file per mesh" in r.stderr
    r = run("check", "--frobnicate", data("ellipsoid.obj"))
    assert r.returncode == 2 and "unknown option '--frobnicate'" in r.stderr
    r = run("frobnicate")
    assert r.returncode == 2 and "unknown command 'frobnicate'" in r.stderr
    r = run()
    assert r.returncode == 2 and "usage: surfacemap" in r.stderr


def test_help():
    r = run("--help")
    assert r.returncode == 0 and "check" in r.stdout and "exit codes" in r.stdout
    r = run("check", "--help")
    assert r.returncode == 0 and "--landmarks" in r.stdout


SHARED_MESHES = [("spot/spot.obj", None), ("shrec/61.off", "shrec/61.pinned"),
                 ("shrec/248.off", "shrec/248.pinned"), ("hand/hand_plain.obj", "hand/hand_plain.pinned"),
                 ("hand/hand_vulcan.obj", "hand/hand_vulcan_0.pinned")]


@pytest.mark.skipif(not os.path.isdir(SHARED), reason="../shared/data not present")
@pytest.mark.parametrize("name,landmarks", SHARED_MESHES, ids=[m[0] for m in SHARED_MESHES])
def test_shared_meshes_are_valid(name, landmarks):
    args = ["check", os.path.join(SHARED, name)]
    if landmarks:
        args += ["--landmarks", os.path.join(SHARED, landmarks)]
    r = run(*args)
    assert r.returncode == 0, r.stderr
    assert "genus 0" in r.stdout
