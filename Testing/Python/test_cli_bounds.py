"""Every numeric option of every command has bounds, says them in --help and refuses a value
outside them (exit 2, before anything is read or computed): map and embed (the settings list),
statistics, transfer, --threads, and the Python entry points population and render."""

import re
import subprocess
import sys

import pytest

from cli import data, run

# "  --target-error X\n      doc ... Default 0.001, range 1e-06 to 1." (Setting::help)
SETTING_HELP = re.compile(r"^  --([a-z-]+) ([NX])\n((?:      .*\n)+)", re.MULTILINE)


def numeric_settings(command):
    """(flag, kind, lowest, highest) of every numeric setting in `surfacemap COMMAND --help`, the
    bounds as the help prints them."""
    r = run(command, "--help")
    assert r.returncode == 0, r.stderr
    found = []
    for flag, kind, text in SETTING_HELP.findall(r.stdout):
        bounds = re.search(r"range (\S+) to (\S+)\.$", " ".join(text.split()))
        assert bounds, f"--{flag} has no range in 'surfacemap {command} --help': {text}"
        found.append((flag, kind, *bounds.groups()))
    return found


@pytest.mark.parametrize("command, table", [("map", "MAP_SETTINGS"), ("embed", "SPHERE_EMBEDDING_SETTINGS")])
def test_every_numeric_setting_is_bounded_in_help_and_enforced(command, table, tmp_path):
    import surfacemaps
    settings = surfacemaps.vtkSurfaceMapsSettings
    t = getattr(settings, table)
    numeric = {"--" + settings.GetFlag(t, k) for k in range(settings.GetNumberOfSettings(t))
               if settings.GetType(t, k) in (settings.REAL, settings.COUNT)}
    documented = numeric_settings(command)
    assert {"--" + flag for flag, *_ in documented} == numeric
    inputs = [data("ellipsoid.obj"), data("blob.off")] if command == "map" else [data("ellipsoid.obj")]
    out = ["--output-dir", tmp_path / "map"] if command == "map" else ["-o", tmp_path / "sphere.vtp"]
    for flag, kind, lowest, highest in documented:
        above = str(int(highest) + 1) if kind == "N" else repr(float(highest) * 10)
        r = run(command, *inputs, f"--{flag}", above, *out)
        what = "a whole number" if kind == "N" else "a number"
        assert r.returncode == 2, (flag, r.stdout, r.stderr)
        assert f"--{flag} needs {what} from {lowest} to {highest}, not '{above}'" in r.stderr, r.stderr
    assert not (tmp_path / "map").exists() and not (tmp_path / "sphere.vtp").exists()


def test_statistics_modes_are_bounded(tmp_path):
    out = tmp_path / "stats"
    for value in ("0", "101", "1000000000", "3x"):
        r = run("statistics", data("ellipsoid.obj"), data("blob.off"), "--output-dir", out, "--modes", value)
        assert r.returncode == 2, r.stderr
        assert f"--modes needs an integer from 1 to 100, not '{value}'" in r.stderr
    assert not out.exists()
    assert "(default 3, from 1 to 100;" in run("statistics", "--help").stdout


def test_transfer_indices_and_threads_are_bounded(tmp_path):
    r = run("transfer", tmp_path, "--from", "0", "--to", "1000001", "-o", tmp_path / "out.vtp")
    assert r.returncode == 2 and "--to needs an input index (0, 1, ...), not '1000001'" in r.stderr
    assert "0 to N - 1 for N inputs" in run("transfer", "--help").stdout
    for value in ("0", "1025", "-1", "2.5"):
        r = run("--threads", value, "check", data("ellipsoid.obj"))
        assert r.returncode == 2 and f"--threads needs a whole number from 1 to 1024, not '{value}'" in r.stderr
    assert "--threads N  compute on at most N threads (1 to 1024" in run("--help").stdout


def python_entry(module, *args):
    return subprocess.run([sys.executable, "-m", f"surfacemaps.{module}", *map(str, args)],
                          capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("flag, value, message", [
    ("--modes", "0", "needs a whole number from 1 to 100, not '0'"),
    ("--modes", "101", "needs a whole number from 1 to 100, not '101'"),
    ("--steps-per-interval", "1000000000", "needs a whole number from 1 to 1000, not '1000000000'"),
    ("--stage-times", "nan", "needs a number from -1e+12 to 1e+12, not 'nan'"),
])
def test_population_options_are_bounded(flag, value, message, tmp_path):
    r = python_entry("population", tmp_path, "--output-dir", tmp_path / "out", flag, value)
    assert r.returncode == 2 and f"argument {flag}: {message}" in r.stderr, r.stderr
    assert not (tmp_path / "out").exists()


def test_population_and_render_say_their_bounds():
    assert "(default 3, from 1 to 100)" in " ".join(python_entry("population", "--help").stdout.split())
    assert "(default 10, from 1 to 1000)" in " ".join(python_entry("population", "--help").stdout.split())
    r = python_entry("render", data("ellipsoid.obj"), "-o", "x.png", "--max", "1")
    assert r.returncode == 2 and "argument --max: needs a number above 1 up to 1e6, not '1'" in r.stderr
    assert "(default 3, above 1 up to 1e6)" in " ".join(python_entry("render", "--help").stdout.split())


def test_error_bound_rounds_show_at_v_and_end_with_exit_3(tmp_path):
    # A vertex budget far beyond what the rounds can reach: -v shows each round, and the rounds'
    # bound (not the budget) ends the run.
    r = run("-v", "map", data("ellipsoid_coarse.stl"), "--max-error", "1e-6", "--max-vertices", "1000000000",
            "--bound-refinement-rounds", "1", "--bound-refinement-iterations", "1",
            "--landmark-iterations", "0", "--coarse-iterations", "2", "--fine-iterations", "2",
            "--output-dir", tmp_path / "map", timeout=120)
    assert r.returncode == 3, (r.stdout, r.stderr)
    assert "error bound 1e-06 of the bounding-box diagonal: " in r.stderr and "input vertices beyond" in r.stderr
    assert "fine phase: 2 iterations" in r.stderr, r.stderr
    assert "could not be met after 1 refinement rounds" in r.stderr
