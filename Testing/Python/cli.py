"""Shared helpers of the end-to-end tests: run the CLI, find the bundled data."""

import os
import subprocess

CLI = os.environ["SURFACEMAPS_CLI"]
DATA = os.environ["SURFACEMAPS_DATA"]
SHARED = os.environ.get("SURFACEMAPS_SHARED_DATA", "")


def run(*args, timeout=300, cwd=None):
    """Runs `surfacemap ARGS...` (in `cwd` if given); returns the CompletedProcess (text output)."""
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout, cwd=cwd)


def run_headless(*args, xvfb=True, timeout=300):
    """Runs `surfacemap ARGS...` as on a server without a display: DISPLAY unset and, unless
    `xvfb`, no Xvfb to be found on PATH either."""
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    if not xvfb:
        env["PATH"] = "/nonexistent"
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout, env=env)


def assert_virtual_display_stopped(stderr):
    """The command (run with -v) rendered on a virtual display of its own, named in `stderr`,
    and that server is gone: Xvfb removes its lock file when it stops."""
    import re
    found = re.search(r"rendering on the virtual display :(\d+)", stderr)
    assert found, stderr
    assert not os.path.exists(f"/tmp/.X{found.group(1)}-lock"), "the virtual display still runs"


def data(name):
    """Path of a file in Data/."""
    return os.path.join(DATA, name)


# Short schedules for `surfacemap map`: two 642-vertex meshes map in about a second.
SHORT = ("--landmark-iterations", "10", "--coarse-iterations", "3", "--fine-iterations", "3")


def read_vtp(path):
    """A .vtp file as vtkPolyData."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def refresh_report(map_dir, *names):
    """Records the current size and MD5 of the files `names` in map_dir/report.json, as if
    `surfacemap map` had written them: a consistent map directory whose content a test changed."""
    import hashlib
    import json
    path = os.path.join(str(map_dir), "report.json")
    with open(path) as f:
        report = json.load(f)
    for record in report["files"]:
        if record["name"] in names:
            with open(os.path.join(str(map_dir), record["name"]), "rb") as f:
                content = f.read()
            record["bytes"] = len(content)
            record["md5"] = hashlib.md5(content).hexdigest()
    with open(path, "w") as f:
        json.dump(report, f, indent=2)
