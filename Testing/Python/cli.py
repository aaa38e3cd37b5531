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
