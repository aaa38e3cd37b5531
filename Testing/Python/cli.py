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


def sphere_arrays(mesh):
    """(SpherePosition, triangles) of a vtkPolyData as numpy arrays (n x 3 each)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    sphere = vtk_to_numpy(mesh.GetPointData().GetArray("SpherePosition")).reshape(-1, 3)
    triangles = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return sphere, triangles


def locate_on_sphere(mesh, q):
    """(triangle, barycentric) of the unit vector q in the sphere embedding of `mesh`: the ray
    0 -> q through the flat chord triangle (DESIGN.md section 1.1), as the map locates points."""
    import numpy
    sphere, triangles = sphere_arrays(mesh)
    a, b, c = (sphere[triangles[:, k]] for k in range(3))
    denominator = numpy.einsum("c,tc->t", q, numpy.cross(c - a, c - b))
    alpha = numpy.einsum("c,tc->t", q, numpy.cross(c, c - b)) / denominator
    beta = numpy.einsum("c,tc->t", q, numpy.cross(c - a, c)) / denominator
    gamma = 1.0 - alpha - beta
    facing = numpy.einsum("c,tc->t", q, a + b + c) > 0.0
    inside = numpy.flatnonzero(facing & (alpha >= 0) & (beta >= 0) & (gamma >= 0))
    t = int(inside[0])
    return t, (alpha[t], beta[t], gamma[t])
