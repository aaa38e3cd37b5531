"""Landmarks given as points (`--landmarks` with .vts without index, .csv, Slicer .fcsv and .mrk.json):
snapped to the closest vertex, the snap distance reported, malformed files rejected with file and line."""

import json
import re

import pytest

from cli import data, read_vtp, run

OFFSET = 1e-3  # every point this far from its vertex, along x


def blob_landmarks():
    """blob.vts: (vertex, x, y, z) of blob.off's four landmarks."""
    rows = []
    with open(data("blob.vts")) as f:
        for line in f:
            i, x, y, z = line.split()
            rows.append((int(i), float(x), float(y), float(z)))
    return rows


def write_formats(directory, offset=OFFSET):
    """blob.vts's landmarks as points, `offset` away along x, in every point format; {format: path}."""
    rows = blob_landmarks()
    files = {}
    vts = "".join(f"{x + offset!r} {y!r} {z!r}\n" for _, x, y, z in rows)
    csv = "x,y,z,id\n" + "".join(f"{x + offset!r},{y!r},{z!r},{k}\n" for k, (_, x, y, z) in enumerate(rows))
    fcsv = ("# Markups fiducial file version = 4.11\n# CoordinateSystem = LPS\n"
            "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n" +
            "".join(f"vtkMRMLMarkupsFiducialNode_{k},{x + offset!r},{y!r},{z!r},0,0,0,1,1,1,0,F-{k + 1},,\n"
                    for k, (_, x, y, z) in enumerate(rows)))
    markups = {"@schema": "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/"
                          "Resources/Schema/markups-schema-v1.0.3.json#",
               "markups": [{"type": "Fiducial", "coordinateSystem": "LPS", "controlPoints": [
                   {"id": str(k), "label": f"F-{k + 1}", "position": [x + offset, y, z], "positionStatus": "defined"}
                   for k, (_, x, y, z) in enumerate(rows)]}]}
    for name, text in (("points.vts", vts), ("points.csv", csv), ("points.fcsv", fcsv),
                       ("points.mrk.json", json.dumps(markups, indent=2))):
        path = directory / name
        path.write_text(text)
        files[name] = path
    return files


@pytest.mark.parametrize("name", ["points.vts", "points.csv", "points.fcsv", "points.mrk.json"])
def test_point_landmarks_snap_and_report_the_distance(tmp_path, name):
    path = write_formats(tmp_path)[name]
    r = run("check", data("blob.off"), data("blob.off"), "--landmarks", data("blob.vts"), path)
    # The same ids on the same vertices as blob.vts: the two correspond.
    assert r.returncode == 0, r.stderr
    assert r.stdout.count(": valid") == 2 and "landmarks 4" in r.stdout
    match = re.search(r"landmarks of (\S+): 4 points snapped to the closest vertex, "
                      r"largest snap distance (\S+) \((\S+) % of the bounding-box diagonal\)", r.stdout)
    assert match, r.stdout
    assert match.group(1) == str(path)
    assert abs(float(match.group(2)) - OFFSET) < 1e-6
    assert "warning" not in r.stderr


def test_a_point_far_from_the_mesh_is_snapped_with_a_warning(tmp_path):
    rows = blob_landmarks()
    lines = [f"{x!r} {y!r} {z!r}" for _, x, y, z in rows]
    _, x, y, z = rows[2]
    lines[2] = f"{x!r} {y + 0.3!r} {z!r}"  # 0.3 off: several % of blob's diagonal
    path = tmp_path / "far.vts"
    path.write_text("\n".join(lines) + "\n")
    r = run("check", data("blob.off"), "--landmarks", path)
    assert r.returncode == 0, r.stderr
    assert f"surfacemap: warning: {path}:3: landmark 2 lies" in r.stderr
    assert "more than 1 %" in r.stderr
    assert "largest snap distance 0.3" in r.stdout


def landmark_ids(path):
    """{vertex: id} of the Landmarks array of a .vtp file."""
    array = read_vtp(path).GetPointData().GetArray("Landmarks")
    return {v: int(array.GetValue(v)) for v in range(array.GetNumberOfTuples()) if array.GetValue(v) >= 0}


def test_ids_are_the_given_integer_ids_or_the_file_order(tmp_path):
    rows = blob_landmarks()
    expected = {vertex: k for k, (vertex, _, _, _) in enumerate(rows)}  # blob.vts: file order
    # Listed in reverse order with Slicer ids "0".."3": the ids given, not the order.
    points = [{"id": str(k), "label": f"L{k}", "position": [x, y, z]} for k, (_, x, y, z) in enumerate(rows)]
    path = tmp_path / "reversed.mrk.json"
    path.write_text(json.dumps({"markups": [{"controlPoints": points[::-1]}]}))
    r = run("embed", data("blob.off"), "--landmarks", path, "-o", tmp_path / "given.vtp")
    assert r.returncode == 0, r.stderr
    assert landmark_ids(tmp_path / "given.vtp") == expected
    # Slicer node names are not ids: the file order counts.
    for k, point in enumerate(points):
        point["id"] = f"vtkMRMLMarkupsFiducialNode_{k}"
    path.write_text(json.dumps({"markups": [{"controlPoints": points[::-1]}]}))
    r = run("embed", data("blob.off"), "--landmarks", path, "-o", tmp_path / "order.vtp")
    assert r.returncode == 0, r.stderr
    assert landmark_ids(tmp_path / "order.vtp") == {vertex: 3 - k for vertex, k in expected.items()}


def test_slicer_files_with_one_unusable_id_are_refused(tmp_path):
    """Ids 3, 2, 1 and one node name (or one id beyond the integer range) used to be read as
    0..3 in file order, silently permuting the landmarks: now the file is refused by line and id."""
    rows = blob_landmarks()
    ids = ["3", "2", "1", "vtkMRMLMarkupsFiducialNode_3"]
    fcsv = tmp_path / "mixed.fcsv"
    fcsv.write_text("# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n" +
                    "".join(f"{i},{x!r},{y!r},{z!r},0,0,0,1,1,1,0,F,,\n" for i, (_, x, y, z) in zip(ids, rows)))
    points = [{"id": i, "position": [x, y, z]} for i, (_, x, y, z) in zip(["3", "2", "1", "99999999999"], rows)]
    markups = tmp_path / "huge.mrk.json"
    markups.write_text(json.dumps({"markups": [{"controlPoints": points}]}, indent=1))
    for path, message in ((fcsv, ":5: the id 'vtkMRMLMarkupsFiducialNode_3' is no landmark id (an integer >= 0), "
                                 "but line 2 gives one (3)"),
                          (markups, ":29: control point 3 has the id '99999999999', which is no landmark id")):
        r = run("check", data("blob.off"), "--landmarks", path)
        assert r.returncode == 2, (r.stdout, r.stderr)
        assert f"surfacemap: error: {path}{message}" in r.stderr, r.stderr


MALFORMED = [
    ("bad.csv", "1,2,3\n1,2\n", ":2: expected x,y,z or x,y,z,id, got 2 values"),
    ("bad.csv", "1,2,3,0\n4,5,6,0\n", ":2: landmark id 0 is given twice (also on line 1)"),
    ("bad.fcsv", "# columns = id,x,y,z\nF1,1,2,oops\n", ":2: expected a coordinate, got 'oops'"),
    ("bad.vts", "0.1 0.2 0.3\n0.1 0.2\n", ":2: expected 'index', 'index x y z' or 'x y z', got 2 values"),
    ("bad.mrk.json", '{"markups": [{"controlPoints": [\n{"position": [0, 0, 0]},\n{"position": [1, 2]}\n]}]}',
     ":3: control point 1 has no \"position\" of three numbers"),
    ("bad.mrk.json", '{"markups": [{"controlPoints": [\n{"position": [0, 0, 0]},\n', ": not valid JSON"),
    ("huge.vts", "0.959 0 0.27\n1e200 0 0\n", ":2: landmark 1 at (1e+200, 0, 0) is too far from every vertex of"),
    ("same_vertex.vts", "0.959 0 0.27\n0.96 0 0.27\n", ":2: landmark 1 falls on vertex 146, which already "
                                                     "carries landmark 0 (line 1)"),
]


@pytest.mark.parametrize("name,text,message", MALFORMED, ids=[m[0] + str(k) for k, m in enumerate(MALFORMED)])
def test_malformed_point_files_are_rejected_with_file_and_line(tmp_path, name, text, message):
    path = tmp_path / name
    path.write_text(text)
    r = run("check", data("blob.off"), "--landmarks", path)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "surfacemap: error: " + str(path) in r.stderr, r.stderr
    assert message in r.stderr, r.stderr
