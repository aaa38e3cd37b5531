"""A map directory's files agree with each other, not only with report.json: every reader
(evaluate, transfer, statistics, surfacemaps.transfer) refuses an embedding_<j>.vtp that does not
send T's source points to common_<j>.vtp's sphere positions, even when report.json was edited to
vouch for it."""

import shutil

import numpy
import pytest

from cli import SHORT, data, read_vtp, refresh_report, run, sphere_arrays


@pytest.fixture(scope="module")
def map_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("map")
    r = run("map", data("ellipsoid_coarse.stl"), data("blob.off"), "--output-dir", out, "--overwrite", *SHORT)
    assert r.returncode == 0, r.stderr
    return out


def write_vtp(mesh, path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(path))
    assert writer.Write() == 1


def rotated_copy(map_dir, target):
    """The map with embedding_1's sphere turned 90 degrees about z (still a bijective embedding)
    and report.json vouching for the new file."""
    shutil.copytree(map_dir, target)
    mesh = read_vtp(target / "embedding_1.vtp")
    sphere = mesh.GetPointData().GetArray("SpherePosition")
    for v in range(sphere.GetNumberOfTuples()):
        x, y, z = sphere.GetTuple3(v)
        sphere.SetTuple3(v, -y, x, z)
    write_vtp(mesh, target / "embedding_1.vtp")
    refresh_report(target, "embedding_1.vtp")
    return target


def test_a_valid_map_agrees_to_rounding(map_dir):
    # What the check measures, on a valid map: far below its tolerance (1e-6).
    common, embedding = read_vtp(map_dir / "common_1.vtp"), read_vtp(map_dir / "embedding_1.vtp")
    f, triangles = sphere_arrays(embedding)
    g, _ = sphere_arrays(common)
    cells = [int(common.GetPointData().GetArray("SourceCellId").GetTuple1(v)) for v in range(len(g))]
    barycentric = numpy.array([common.GetPointData().GetArray("SourceBarycentric").GetTuple3(v)
                               for v in range(len(g))])
    q = numpy.einsum("vk,vkc->vc", barycentric, f[triangles[cells]])
    q /= numpy.linalg.norm(q, axis=1)[:, None]
    assert numpy.linalg.norm(q - g, axis=1).max() < 1e-12


def test_a_rotated_embedding_with_a_recomputed_checksum_is_refused(map_dir, tmp_path):
    import surfacemaps
    rotated = rotated_copy(map_dir, tmp_path / "rotated")
    message = (f"{rotated / 'embedding_1.vtp'} and {rotated / 'common_1.vtp'} are not one map: at ")
    out = tmp_path / "out.vtp"
    for r in (run("transfer", rotated, "--from", "0", "--to", "1", "-o", out),
              run("evaluate", rotated, "--output-dir", tmp_path / "evaluation"),
              run("statistics", rotated, "--output-dir", tmp_path / "statistics")):
        assert r.returncode == 2, (r.args, r.stdout, r.stderr)
        assert message in r.stderr and "a file was edited, rotated or swapped" in r.stderr, r.stderr
    assert not out.exists() and not (tmp_path / "evaluation").exists()
    assert not (tmp_path / "statistics").exists()
    with pytest.raises(surfacemaps.InputError, match="embedding_1.vtp and .*common_1.vtp are not one map"):
        surfacemaps.transfer(rotated, 0, 1)


def test_evaluate_refuses_swapped_embeddings(map_dir, tmp_path):
    swapped = tmp_path / "swapped"
    shutil.copytree(map_dir, swapped)
    (swapped / "embedding_0.vtp").rename(swapped / "tmp.vtp")
    (swapped / "embedding_1.vtp").rename(swapped / "embedding_0.vtp")
    (swapped / "tmp.vtp").rename(swapped / "embedding_1.vtp")
    r = run("evaluate", swapped, "--output-dir", tmp_path / "evaluation")
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "is embedding_1.vtp of this map, not embedding_0.vtp: swapped or renamed" in r.stderr
    # With report.json edited to vouch for them, the geometry still tells.
    refresh_report(swapped, "embedding_0.vtp", "embedding_1.vtp")
    r = run("evaluate", swapped, "--output-dir", tmp_path / "evaluation")
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert f"{swapped / 'embedding_0.vtp'} and {swapped / 'common_0.vtp'} are not one map" in r.stderr
    assert "maps in" not in r.stdout and not (tmp_path / "evaluation").exists()


def test_common_files_of_another_triangulation_are_refused_by_every_reader(map_dir, tmp_path):
    import surfacemaps
    other = tmp_path / "other"
    shutil.copytree(map_dir, other)
    shutil.copy(other / "embedding_1.vtp", other / "common_1.vtp")  # input 1 itself, not T
    refresh_report(other, "common_1.vtp")
    for r in (run("evaluate", other, "--output-dir", tmp_path / "evaluation"),
              run("statistics", other, "--output-dir", tmp_path / "statistics")):
        assert r.returncode == 2, (r.args, r.stdout, r.stderr)
        assert (f"{other / 'common_1.vtp'} and {other / 'common_0.vtp'} do not hold the same common "
                "triangulation") in r.stderr, r.stderr
    with pytest.raises(surfacemaps.InputError, match="common_1.vtp"):
        surfacemaps.transfer(other, 0, 1)


def test_an_embedding_with_an_index_out_of_range_is_refused_not_read(map_dir, tmp_path):
    import surfacemaps
    from vtkmodules.util.numpy_support import vtk_to_numpy
    broken = tmp_path / "broken"
    shutil.copytree(map_dir, broken)
    mesh = read_vtp(broken / "embedding_1.vtp")
    vtk_to_numpy(mesh.GetPolys().GetConnectivityArray())[:] = 10 ** 6  # every corner past the points
    mesh.GetPolys().Modified()
    write_vtp(mesh, broken / "embedding_1.vtp")
    refresh_report(broken, "embedding_1.vtp")
    for r in (run("transfer", broken, "--from", "0", "--to", "1", "-o", tmp_path / "out.vtp"),
              run("evaluate", broken, "--output-dir", tmp_path / "evaluation")):
        assert r.returncode == 2, (r.args, r.returncode, r.stderr)
        assert f"{broken / 'embedding_1.vtp'}" in r.stderr, r.stderr
    with pytest.raises(surfacemaps.InputError, match="embedding_1.vtp"):
        surfacemaps.transfer(broken, 0, 1)
