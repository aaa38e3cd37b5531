"""`surfacemap check` on a sample of the reader fuzz test's mutants, one process each.

The in-process fuzz test (Filters.ReaderFuzz, SurfaceMapsReaderFuzz) covers
2 000+ mutants; this sample checks the command line's side of the contract:
exit 0 with "valid", or exit 2 with an error naming the file; never a crash,
a sanitizer report or a hang (each run is bounded in time).
"""

import os
import subprocess

import pytest

from cli import CLI, DATA

FUZZ = os.environ["SURFACEMAPS_FUZZ"]
# Seconds per `surfacemap check`; a valid seed takes well under one second,
# an instrumented build a few.
TIME_BOUND = 60


@pytest.fixture(scope="module")
def mutants(tmp_path_factory):
    scratch = tmp_path_factory.mktemp("scratch")
    sample = tmp_path_factory.mktemp("sample")
    # Every 40th of the same fixed-seed mutants the in-process test reads.
    subprocess.run([FUZZ, DATA, str(scratch), "--emit", str(sample), "--every", "40"],
                   check=True, capture_output=True, text=True, timeout=1800)
    files = sorted(os.listdir(sample))
    return sample, files


def test_sample_is_large_and_covers_every_format(mutants):
    sample, files = mutants
    meshes = [f for f in files if "_lm" not in f]
    assert len(meshes) >= 90
    extensions = {os.path.splitext(f)[1] for f in files}
    assert extensions >= {".obj", ".off", ".ply", ".stl", ".vtp", ".vtk", ".pinned", ".vts"}


def test_every_mutant_is_valid_or_rejected_by_name(mutants):
    sample, files = mutants
    broken = []
    for name in files:
        if "_lm_mesh" in name:
            continue
        path = os.path.join(sample, name)
        if "_lm." in name:
            stem = name.split("_lm.")[0]
            mesh = next(f for f in files if f.startswith(stem + "_lm_mesh"))
            args = ["check", os.path.join(sample, mesh), "--landmarks", path]
        else:
            args = ["check", path]
        try:
            # Bytes: messages quote the mutated file's content, which need not be UTF-8.
            r = subprocess.run([CLI, *args], capture_output=True, timeout=TIME_BOUND)
        except subprocess.TimeoutExpired:
            broken.append(f"{name}: no answer within {TIME_BOUND} s")
            continue
        r.stdout = r.stdout.decode("utf-8", "replace")
        r.stderr = r.stderr.decode("utf-8", "replace")
        if "Sanitizer" in r.stderr or "runtime error" in r.stderr:
            broken.append(f"{name}: sanitizer report\n{r.stderr[-2000:]}")
        elif r.returncode == 0:
            if ": valid" not in r.stdout:
                broken.append(f"{name}: exit 0 without 'valid'")
        elif r.returncode == 2:
            if "error:" not in r.stderr or name not in r.stderr:
                broken.append(f"{name}: exit 2 without an error naming the file: {r.stderr!r}")
        else:
            broken.append(f"{name}: exit {r.returncode}: {r.stderr[-2000:]!r}")
    assert not broken, "\n".join(broken)
