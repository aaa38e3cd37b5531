"""Shared helpers of the end-to-end tests: run the CLI, find the bundled data."""

import os
import subprocess

CLI = os.environ["SURFACEMAPS_CLI"]
DATA = os.environ["SURFACEMAPS_DATA"]
SHARED = os.environ.get("SURFACEMAPS_SHARED_DATA", "")


def run(*args, timeout=300, cwd=None):
    """Runs `surfacemap ARGS...` (in `cwd` if given); returns the CompletedProcess (text output)."""
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout, cwd=cwd)


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
