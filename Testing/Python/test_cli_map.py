"""`surfacemap map`: output files and report, bad input, unwritable output, usage."""

import json
import os

import pytest

from cli import SHORT, data, read_vtp, run


def test_map_writes_common_and_mapped_meshes_and_a_report(tmp_path):
    out = tmp_path / "new" / "dir"  # created
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *SHORT, "--output-dir", out)
    assert r.returncode == 0, r.stderr
    assert "map of 2 surfaces: certified bijective" in r.stdout
    assert sorted(os.listdir(out)) == ["common_0.vtp", "common_1.vtp", "correspondences.npz", "embedding_0.vtp",
                                       "embedding_1.vtp", "fit.csv", "mapped_0.vtp", "mapped_1.vtp", "report.json"]

    report = json.loads((out / "report.json").read_text())
    assert report["certificate"]["bijective"] is True
    # Written at full precision: the signed area over 4 pi, 1 up to rounding.
    assert report["certificate"]["spherical_degrees"] == pytest.approx([1.0, 1.0], abs=1e-9)
    assert [i["vertices"] for i in report["inputs"]] == [642, 642]
    names = [p["name"] for p in report["phases"]]
    # Refinement rounds (at most 3, each at most the fine cap) where the exact map is distorted.
    assert names[:3] == ["landmarks", "coarse", "fine"] and set(names[3:]) <= {"refine"} and len(names) <= 6
    assert [p["iterations"] <= cap for p, cap in zip(report["phases"], (10, 3, 3, 3, 3, 3))] == [True] * len(names)
    assert all(p["seconds"] > 0 for p in report["phases"])
    assert all(0 <= p["stalled_iterations"] <= p["iterations"] for p in report["phases"])
    assert report["landmark_error"] < 1e-9  # landmarks kept exactly
    assert report["energy"]["map"] >= 1.0
    approximating, exact = report["approximating_map"][0], report["exact_map"][0]
    for metrics in (approximating, exact):
        assert metrics["target"] == 1
        assert metrics["SymmetricDirichlet"] >= 1.0
        assert 0.0 < metrics["AreaBelow1.5"] <= metrics["AreaBelow2"] <= 1.0
        assert metrics["MaxDistortion"] >= 1.0
        assert 0.0 < metrics["MinAngleTarget"] <= metrics["MeanMinAngleTarget"] <= 60.0
    assert 0.0 < approximating["HausdorffSource"] < 5.0 and 0.0 < approximating["HausdorffTarget"] < 5.0

    common = [read_vtp(out / f"common_{i}.vtp") for i in range(2)]
    mapped = [read_vtp(out / f"mapped_{i}.vtp") for i in range(2)]
    assert common[0].GetNumberOfPoints() == report["common_triangulation"]["vertices"]
    assert common[1].GetNumberOfPolys() == report["common_triangulation"]["triangles"]
    assert mapped[1].GetNumberOfPoints() == 642
    for name in ("SpherePosition", "SourceCellId", "SourceBarycentric", "Landmarks"):
        assert common[1].GetPointData().GetArray(name) is not None, name
    assert common[1].GetCellData().GetArray("Distortion") is not None
    # A written output is itself a valid input.
    assert run("check", out / "common_1.vtp").returncode == 0
    # Landmarks kept: T's landmark vertices lie on the inputs' landmark points.
    assert [s["landmark_error"] for s in report["specimens"]] == pytest.approx([0.0, 0.0], abs=1e-6)


def test_every_input_has_its_fit_and_correspondences(tmp_path):
    import csv
    import numpy as np
    out = tmp_path / "three"
    (tmp_path / "copy").mkdir()
    other = tmp_path / "copy" / "blob.off"  # the same stem as input 1's
    other.write_bytes(open(data("blob.off"), "rb").read())
    r = run("map", data("ellipsoid.obj"), data("blob.off"), other, *SHORT, "-o", out)
    assert r.returncode == 0, r.stderr
    assert "correspondences.npz, fit.csv, report.json" in r.stdout
    report = json.loads((out / "report.json").read_text())
    rows = report["specimens"]
    # Names are the file stems, told apart where two inputs share one.
    assert [(s["input"], s["name"]) for s in rows] == [(0, "ellipsoid"), (1, "blob_1"), (2, "blob_2")]
    assert [s["file"] for s in rows] == [i["file"] for i in report["inputs"]]
    assert rows[0]["approximating_sd"] is None and rows[0]["exact_sd"] is None  # every pair's source
    for s, approximating, exact in zip(rows[1:], report["approximating_map"], report["exact_map"]):
        assert s["approximating_sd"] == approximating["SymmetricDirichlet"] >= 1.0
        assert s["exact_sd"] == exact["SymmetricDirichlet"] >= 1.0
        assert s["exact_max_distortion"] == exact["MaxDistortion"]
        assert s["hausdorff"] == approximating["HausdorffTarget"]
    assert rows[0]["hausdorff"] == report["approximating_map"][0]["HausdorffSource"]
    for s in rows:
        assert 0.0 < s["hausdorff"] <= s["two_sided_distance"] < 5.0
        assert s["landmark_error"] is None  # no landmarks given
    with open(out / "fit.csv", newline="") as f:
        table = list(csv.DictReader(f))
    assert [t["name"] for t in table] == ["ellipsoid", "blob_1", "blob_2"]
    assert table[0]["exact_sd"] == "" and table[0]["landmark_error"] == ""
    assert [float(t["exact_sd"]) for t in table[1:]] == pytest.approx([s["exact_sd"] for s in rows[1:]], rel=1e-8)
    assert [float(t["hausdorff"]) for t in table] == pytest.approx([s["hausdorff"] for s in rows], rel=1e-8)

    # np.load reads the archive without pickles: T's vertices on every input, and T's triangles.
    from vtkmodules.util.numpy_support import vtk_to_numpy
    with np.load(out / "correspondences.npz", allow_pickle=False) as archive:
        assert sorted(archive.files) == ["names", "points", "triangles"]
        assert archive["names"].tolist() == ["ellipsoid", "blob_1", "blob_2"]
        points, triangles = archive["points"], archive["triangles"]
    common = [read_vtp(out / f"common_{i}.vtp") for i in range(3)]
    assert points.shape == (3, common[0].GetNumberOfPoints(), 3) and points.dtype == np.float64
    for i, mesh in enumerate(common):
        assert np.array_equal(points[i], vtk_to_numpy(mesh.GetPoints().GetData()))
    cells = vtk_to_numpy(common[0].GetPolys().GetConnectivityArray()).reshape(-1, 3)
    assert triangles.dtype == np.int64 and np.array_equal(triangles, cells)
    # Recorded in report.json like every file of the map: the readers accept the directory.
    assert {"fit.csv", "correspondences.npz"} <= {f["name"] for f in report["files"]}
    assert run("evaluate", out, "-o", tmp_path / "evaluated").returncode == 0


def test_max_error_bounds_every_input_vertex(tmp_path):
    out = tmp_path / "bounded"
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *SHORT, "--target-error", "1e-2", "--max-error", "2e-3", "--output-dir", out)
    assert r.returncode == 0, r.stderr
    report = json.loads((out / "report.json").read_text())
    assert report["settings"]["max_error"] == 2e-3
    assert [p["name"] for p in report["phases"]][-1] == "bound"
    assert len(report["error_bound"]) == 2
    for entry, name in zip(report["error_bound"], ("ellipsoid.obj", "blob.off")):
        mesh = surfacemaps_read(data(name))
        assert abs(entry["bound"] - 2e-3 * mesh.GetLength()) < 1e-9 * entry["bound"]  # JSON keeps 10 digits
        assert 0.0 < entry["base_distance"] <= entry["bound"]
    assert r.stdout.count("error bound on input") == 2
    # The two-sided sampled distance is reported beside it.
    assert report["approximating_map"][0]["TwoSidedDistanceTarget"] > 0.0


def test_max_error_must_be_a_fraction(tmp_path):
    for value in ("-0.1", "1.5", "x"):
        r = run("map", data("ellipsoid.obj"), "--max-error", value, "--output-dir", tmp_path / "o")
        assert r.returncode == 2 and "--max-error" in r.stderr, (value, r.stderr)
    # 0 is the filter's MaxError 0: no bound (one settings table for both).
    r = run("map", data("ellipsoid.obj"), *SHORT, "--max-error", "0", "--output-dir", tmp_path / "off")
    assert r.returncode == 0, r.stderr
    report = json.loads((tmp_path / "off" / "report.json").read_text())
    assert report["settings"]["max_error"] == 0 and "error_bound" not in report
    assert "bound" not in [p["name"] for p in report["phases"]]


def test_term_weights_are_settings(tmp_path):
    out = tmp_path / "weighted"
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *SHORT, "--mesh-weight", "1", "--map-weight", "2", "--approximation-weight", "4",
            "--output-dir", out)
    assert r.returncode == 0, r.stderr
    settings = json.loads((out / "report.json").read_text())["settings"]
    assert (settings["mesh_weight"], settings["map_weight"], settings["approximation_weight"]) == (1, 2, 4)
    for option in ("--mesh-weight", "--map-weight", "--approximation-weight"):
        for value in ("-1", "x", "2e6"):
            r = run("map", data("ellipsoid.obj"), option, value, "--output-dir", tmp_path / "o")
            assert r.returncode == 2 and option in r.stderr, (option, value, r.stderr)


def test_preset_sets_its_settings_and_flags_override_it(tmp_path):
    out = tmp_path / "population"
    # The flag before --preset still overrides it: the preset applies first.
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *SHORT, "--target-error", "0.02", "--preset", "population",
            "--output-dir", out)
    assert r.returncode == 0, r.stderr
    report = json.loads((out / "report.json").read_text())
    assert report["preset"] == "population"
    settings = report["settings"]
    assert settings["target_error"] == 0.02
    assert settings["refinement_rounds"] == 0 and settings["approximation_weight"] == 2
    r = run("map", data("ellipsoid.obj"), "--preset", "crowd", "--output-dir", tmp_path / "o")
    assert r.returncode == 2 and "--preset is pair or population, not 'crowd'" in r.stderr, r.stderr
    r = run("map", "--help")
    assert "--preset pair|population" in r.stdout


def test_refinement_is_a_setting(tmp_path):
    out = tmp_path / "unrefined"
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *SHORT, "--refinement-rounds", "0", "--output-dir", out)
    assert r.returncode == 0, r.stderr
    report = json.loads((out / "report.json").read_text())
    assert [p["name"] for p in report["phases"]] == ["landmarks", "coarse", "fine"]
    settings = report["settings"]
    import surfacemaps
    defaults = {row["flag"].replace("-", "_"): row["default"] for row in surfacemaps.settings_table()}
    assert settings["refinement_rounds"] == 0
    for key in ("refinement_distortion", "refinement_growth", "squeeze_distortion"):
        assert abs(settings[key] - defaults[key]) <= 1e-9 * defaults[key], key
    out = tmp_path / "refined"
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            data("blob.vts"), *SHORT, "--refinement-rounds", "1", "--refinement-distortion", "1.000001",
            "--output-dir", out)
    assert r.returncode == 0, r.stderr
    report = json.loads((out / "report.json").read_text())
    assert [p["name"] for p in report["phases"]] == ["landmarks", "coarse", "fine", "refine"]
    assert report["settings"]["refinement_distortion"] == 1.000001
    for option, values in (("--refinement-rounds", ("-1", "1.5", "101", "x")),
                           ("--refinement-distortion", ("0.5", "x", "2e12"))):
        for value in values:
            r = run("map", data("ellipsoid.obj"), option, value, "--output-dir", tmp_path / "o")
            assert r.returncode == 2 and option in r.stderr, (option, value, r.stderr)


def surfacemaps_read(path):
    import surfacemaps
    return surfacemaps.read_mesh(path)


def test_report_records_absolute_input_paths(tmp_path):
    # Relative names, run from Data/: `surfacemap evaluate DIR` must find the inputs from anywhere.
    out = tmp_path / "out"
    r = run("map", "ellipsoid.obj", "blob.off", "--landmarks", "ellipsoid.pinned", "blob.vts", *SHORT,
            "--output-dir", out, cwd=data(""))
    assert r.returncode == 0, r.stderr
    report = json.loads((out / "report.json").read_text())
    recorded = [p for i in report["inputs"] for p in (i["file"], i["landmarks"])]
    expected = [data(name) for name in ("ellipsoid.obj", "ellipsoid.pinned", "blob.off", "blob.vts")]
    assert all(os.path.isabs(p) for p in recorded), recorded
    assert [os.path.realpath(p) for p in recorded] == [os.path.realpath(p) for p in expected]


def with_labels(path, out, seed):
    """The mesh at `path` as a .vtp with random "Label" (int: 0 or 100) and "Mask" (float: 0 or 1)."""
    import random
    from vtkmodules.vtkCommonCore import vtkFloatArray, vtkIntArray
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    import surfacemaps
    mesh = surfacemaps.read_mesh(path)
    pick = random.Random(seed)
    label, mask = vtkIntArray(), vtkFloatArray()
    label.SetName("Label")
    mask.SetName("Mask")
    for v in range(mesh.GetNumberOfPoints()):
        label.InsertNextValue(pick.choice((0, 100)))
        mask.InsertNextValue(pick.choice((0.0, 1.0)))
    mesh.GetPointData().AddArray(label)
    mesh.GetPointData().AddArray(mask)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(out))
    assert writer.Write() == 1
    return out


def test_array_transfer_flags(tmp_path):
    a = with_labels(data("ellipsoid.obj"), tmp_path / "a.vtp", 1)
    b = with_labels(data("blob.off"), tmp_path / "b.vtp", 2)
    # A name no input has is bad usage, found before anything is created.
    r = run("map", a, b, *SHORT, "--categorical", "Nope", "--output-dir", tmp_path / "never")
    assert r.returncode == 2 and "no input has a point array 'Nope'" in r.stderr
    assert not (tmp_path / "never").exists()
    r = run("map", a, b, "--continuous", "Mask", "--categorical", "Mask", "--output-dir", tmp_path / "never")
    assert r.returncode == 2 and "given both as --categorical and as --continuous" in r.stderr
    help_text = run("map", "--help").stdout
    assert "--categorical NAME" in help_text and "--continuous NAME" in help_text

    out = tmp_path / "out"
    r = run("map", a, b, *SHORT, "--continuous", "Label", "--categorical", "Mask", "--output-dir", out)
    assert r.returncode == 0, r.stderr
    assert json.loads((out / "report.json").read_text())["array_transfer_modes"] == {
        "Label": "continuous", "Mask": "categorical"}
    for name in ("common_0.vtp", "common_1.vtp", "mapped_1.vtp"):
        mesh = read_vtp(out / name)
        mask, label = mesh.GetPointData().GetArray("Mask"), mesh.GetPointData().GetArray("Label")
        masks = {mask.GetTuple1(v) for v in range(mesh.GetNumberOfPoints())}
        labels = {label.GetTuple1(v) for v in range(mesh.GetNumberOfPoints())}
        assert masks == {0.0, 1.0}, name  # categorical floats keep to the inputs' values
        assert len(labels - {0.0, 100.0}) > 0, name  # continuous integers are interpolated
        assert all(x == round(x) and 0 <= x <= 100 for x in labels), name


def test_bad_input_is_exit_2_and_writes_nothing(tmp_path):
    out = tmp_path / "out"
    r = run("map", data("ellipsoid_coarse.stl"), data("bad/torus.obj"), *SHORT, "--output-dir", out)
    assert r.returncode == 2
    assert "has genus 1" in r.stderr
    assert not out.exists()


def test_landmarks_that_do_not_correspond_are_bad_input(tmp_path):
    r = run("map", data("ellipsoid.obj"), data("limbs.ply"), "--landmarks", data("ellipsoid.pinned"),
            data("bad/five_landmarks.pinned"), "--output-dir", tmp_path)
    assert r.returncode == 2
    assert "landmark counts do not match" in r.stderr


def test_unwritable_output_dir_is_reported_before_computing(tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    r = run("map", data("ellipsoid_coarse.stl"), data("blob.off"), *SHORT, "--output-dir", blocker / "out")
    assert r.returncode == 2
    assert "cannot create the output directory" in r.stderr
    assert "map of" not in r.stdout


def test_usage(tmp_path):
    assert run("map").returncode == 2
    r = run("map", data("ellipsoid.obj"), data("blob.off"))
    assert r.returncode == 2 and "no output directory" in r.stderr
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--pairs", "ring", "--output-dir", tmp_path)
    assert r.returncode == 2 and "--pairs is star, sequence, cycle, all or mean" in r.stderr
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"),
            "--output-dir", tmp_path)
    assert r.returncode == 2 and "one file per mesh" in r.stderr
    r = run("map", data("ellipsoid.obj"), "--fine-iterations", "2.5", "--output-dir", tmp_path)
    assert r.returncode == 2 and "needs a whole number" in r.stderr
    r = run("map", "--help")
    assert r.returncode == 0 and "--release-landmarks" in r.stdout and "mapped_<i>.vtp" in r.stdout
    assert "embedding_<i>.vtp" in r.stdout
    assert os.listdir(tmp_path) == []


def test_report_numbers_read_back_exactly(tmp_path):
    # 17 significant digits: a setting given with more than 10 comes back as the same double.
    out = tmp_path / "out"
    r = run("map", data("ellipsoid.obj"), *SHORT, "--target-error", "0.0012345678901234567",
            "--output-dir", out)
    assert r.returncode == 0, r.stderr
    report = json.loads((out / "report.json").read_text())
    assert report["settings"]["target_error"] == 0.0012345678901234567
    assert isinstance(report["common_triangulation"]["vertices"], int)
    assert all(isinstance(p["seconds"], (int, float)) and isinstance(p["iterations"], int)
               for p in report["phases"])


def test_help_and_report_hold_every_setting(tmp_path):
    import surfacemaps
    f = surfacemaps.vtkSurfaceMapFilter
    n = f.GetNumberOfSettings()
    help_text = run("map", "--help").stdout
    for i in range(n):
        assert "--" + f.GetSettingFlag(i) in help_text, f.GetSettingFlag(i)
    out = tmp_path / "out"
    r = run("map", data("ellipsoid.obj"), *SHORT, "--pairs", "all", "--release-landmarks",
            "--refinement-distortion", "2.5", "--output-dir", out)
    assert r.returncode == 0, r.stderr
    settings = json.loads((out / "report.json").read_text())["settings"]
    keys = {f.GetSettingFlag(i).replace("-", "_"): i for i in range(n)}
    assert set(settings) == set(keys) | {"sizing_mode"}
    given = {"landmark_iterations": 10, "coarse_iterations": 3, "fine_iterations": 3,
             "pairs": "all", "keep_landmarks": False, "refinement_distortion": 2.5}
    for key, i in keys.items():
        default = f.GetSettingDefault(i)
        if f.GetSettingType(i) == f.SETTING_SWITCH:
            default = bool(default)
        elif f.GetSettingType(i) == f.SETTING_CHOICE:
            default = f.GetSettingChoices(i).split("|")[int(default)]
        expected = given.get(key, default)
        if isinstance(expected, float):
            assert abs(settings[key] - expected) <= 1e-9 * abs(expected), key
        else:
            assert settings[key] == expected, key


def test_every_setting_goes_from_its_flag_into_the_report(tmp_path):
    # Each setting at a value other than its default, written as the list's codec writes it: the
    # report holds every one exactly (the codec's JSON), and the sphere embedding's defaults.
    import surfacemaps
    S = surfacemaps.vtkSurfaceMapsSettings
    table = S.MAP_SETTINGS
    short = dict(zip(SHORT[::2], SHORT[1::2]))
    chosen = {"max-vertices": 100000}  # a budget of one vertex more than none would fail the map
    arguments, expected = [], {}
    for i in range(S.GetNumberOfSettings(table)):
        flag, default, kind = S.GetFlag(table, i), S.GetDefault(table, i), S.GetType(table, i)
        low, high = S.GetMinimum(table, i), S.GetMaximum(table, i)
        if kind == S.SWITCH:
            arguments.append("--" + (S.GetOffFlag(table, i) if default else flag))
            expected[S.GetJsonKey(table, i)] = not default
            continue
        if "--" + flag in short:
            value = float(short["--" + flag])
        elif flag in chosen:
            value = float(chosen[flag])
        elif kind == S.CHOICE:
            value = high if default != high else low
        elif kind == S.COUNT:
            value = default + 1 if default + 1 <= high else default - 1
        else:
            value = next(v for v in (default * 1.25, default * 0.8, (low + high) / 2) if low <= v <= high and v != default)
        text = S.Format(table, i, value)
        assert S.Parse(table, i, text) == value, (flag, text)
        arguments += ["--" + flag, text]
        expected[S.GetJsonKey(table, i)] = json.loads(S.ToJson(table, i, value))
    out = tmp_path / "out"
    r = run("map", data("ellipsoid.obj"), *arguments, "--output-dir", out)
    assert r.returncode == 0, (arguments, r.stderr)
    report = json.loads((out / "report.json").read_text())
    settings = report["settings"]
    assert set(settings) == set(expected) | {"sizing_mode"}
    for key, value in expected.items():
        assert settings[key] == value and type(settings[key]) is type(value), key
    embedding = S.SPHERE_EMBEDDING_SETTINGS
    assert report["embedding_settings"] == {
        S.GetJsonKey(embedding, i): json.loads(S.ToJson(embedding, i, S.GetDefault(embedding, i)))
        for i in range(S.GetNumberOfSettings(embedding))}


def test_point_landmarks_are_snapped_and_recorded_in_the_report(tmp_path):
    # blob.vts's landmarks as a Slicer .fcsv of points, 0.001 off their vertices.
    rows = [line.split() for line in open(data("blob.vts"))]
    fcsv = tmp_path / "blob.fcsv"
    fcsv.write_text("# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n" + "".join(
        f"n{k},{float(x) + 1e-3!r},{y},{z},0,0,0,1,1,1,0,F-{k},,\n" for k, (_, x, y, z) in enumerate(rows)))
    out = tmp_path / "out"
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--landmarks", data("ellipsoid.pinned"), fcsv,
            *SHORT, "--output-dir", out)
    assert r.returncode == 0, r.stderr
    assert f"landmarks of {fcsv}: 4 points snapped to the closest vertex" in r.stdout
    report = json.loads((out / "report.json").read_text())
    assert report["inputs"][0]["landmark_snap"] is None  # vertex indices: nothing snapped
    snap = report["inputs"][1]["landmark_snap"]
    assert [s["id"] for s in snap] == [0, 1, 2, 3]
    assert [s["vertex"] for s in snap] == [int(row[0]) for row in rows]
    assert all(abs(s["distance"] - 1e-3) < 1e-6 and 0 < s["percent_of_diagonal"] < 0.1 for s in snap)
    assert report["landmark_error"] < 1e-9


def sizing_sources(tmp_path, small):
    """Input 0 (ellipsoid.obj) as a .vtp with the point array "EdgeLength": `small` where x > 0.5, 1 elsewhere;
    input 1 (blob.off): a sizing file of 1 per vertex. Returns the paths and the number of input-0 vertices."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    mesh = surfacemaps_read(data("ellipsoid.obj"))
    lengths = vtkDoubleArray()
    lengths.SetName("EdgeLength")
    for v in range(mesh.GetNumberOfPoints()):
        lengths.InsertNextValue(small if mesh.GetPoint(v)[0] > 0.5 else 1.0)
    mesh.GetPointData().AddArray(lengths)
    vtp = tmp_path / "ellipsoid_sized.vtp"
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(vtp))
    assert writer.Write() == 1
    sizing = tmp_path / "blob_sizing.txt"
    sizing.write_text("# one target edge length per vertex\n" + "1\n" * 642)
    return vtp, sizing


def vertices_in_region(path):
    """T vertices (common_0: T on input 0) with x > 0.5."""
    common = read_vtp(path)
    return sum(common.GetPoint(v)[0] > 0.5 for v in range(common.GetNumberOfPoints()))


def test_sizing_makes_T_finer_where_it_is_small(tmp_path):
    vtp, sizing = sizing_sources(tmp_path, 0.03)
    plain, sized = tmp_path / "plain", tmp_path / "sized"
    r = run("map", vtp, data("blob.off"), *SHORT, "--output-dir", plain)
    assert r.returncode == 0, r.stderr
    r = run("map", vtp, data("blob.off"), "--sizing", "EdgeLength", sizing, *SHORT, "--output-dir", sized)
    assert r.returncode == 0, r.stderr
    report = json.loads((sized / "report.json").read_text())
    assert [i["sizing"] for i in report["inputs"]] == ["point array EdgeLength", str(sizing)]
    without, with_sizing = vertices_in_region(plain / "common_0.vtp"), vertices_in_region(sized / "common_0.vtp")
    assert with_sizing > 1.5 * without, (without, with_sizing)


@pytest.mark.parametrize("content,message", [
    ("1\n" * 641, "the file ends after 641 values, but the mesh has 642 vertices"),
    ("1\n" * 643, ":643: more values than the mesh's 642 vertices"),
    ("1\n1\n-0.5\n" + "1\n" * 639, ":3: the target edge length '-0.5' (vertex 2) is not a finite positive number"),
    ("1\nnan\n" + "1\n" * 640, ":2: the target edge length 'nan' (vertex 1)"),
    ("1\n1 1\n" + "1\n" * 640, ":2: expected one value per line"),
])
def test_malformed_sizing_files_are_rejected(tmp_path, content, message):
    sizing = tmp_path / "sizing.txt"
    sizing.write_text(content)
    r = run("map", data("ellipsoid.obj"), data("blob.off"), "--sizing", sizing, sizing, *SHORT,
            "--output-dir", tmp_path / "out")
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"surfacemap: error: {sizing}" in r.stderr and message in r.stderr, r.stderr
    assert "sizing of " + data("ellipsoid.obj") in r.stderr
    assert not (tmp_path / "out").exists()


def test_sizing_arrays_and_counts_are_checked(tmp_path):
    out = tmp_path / "out"
    # blob.vtp's Landmarks array is -1 off the landmarks: not a length.
    r = run("map", data("blob.vtp"), data("blob.vtp"), "--sizing", "Landmarks", "Landmarks", *SHORT,
            "--output-dir", out)
    assert r.returncode == 2
    assert "--sizing Landmarks: the point array of " + data("blob.vtp") + " has -1 at vertex 0" in r.stderr
    r = run("map", data("blob.vtp"), data("blob.vtp"), "--sizing", "Nothing", "Nothing", *SHORT,
            "--output-dir", out)
    assert r.returncode == 2 and "--sizing Nothing: no such file, and " in r.stderr
    r = run("map", data("blob.vtp"), data("blob.vtp"), "--sizing", "Landmarks", "--output-dir", out)
    assert r.returncode == 2 and "--sizing needs one file or array name per mesh (2 meshes, 1 sizing" in r.stderr
    assert not out.exists()
    assert "--sizing SA SB" in run("map", "--help").stdout


def test_short_output_dir_and_thread_count(tmp_path):
    out = tmp_path / "out"
    r = run("map", data("ellipsoid.obj"), *SHORT, "-o", out, "--threads", "1")
    assert r.returncode == 0, r.stderr
    report = json.loads((out / "report.json").read_text())
    assert report["threads"] == 1
    help_text = run("map", "--help").stdout
    assert "-o, --output-dir DIR" in help_text and "--threads N" in help_text
    for bad in ("0", "two", "1.5", "2000"):
        r = run("map", data("ellipsoid.obj"), "-o", tmp_path / "bad", "--threads", bad)
        assert r.returncode == 2 and f"--threads needs a whole number from 1 to 1024, not '{bad}'" in r.stderr
    assert not (tmp_path / "bad").exists()


@pytest.mark.parametrize("command", ["check", "embed", "evaluate", "map", "statistics", "transfer"])
def test_every_command_takes_threads(command):
    help_text = run(command, "--help").stdout
    assert "--threads N" in help_text, command


def test_threads_is_taken_before_or_after_the_command():
    assert run("--threads", "1", "check", data("ellipsoid.obj")).returncode == 0
    assert run("check", data("ellipsoid.obj"), "--threads", "2").returncode == 0
    r = run("check", data("ellipsoid.obj"), "--threads")
    assert r.returncode == 2 and "--threads needs a whole number" in r.stderr
