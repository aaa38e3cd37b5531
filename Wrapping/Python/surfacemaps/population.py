"""A population over developmental time: stage means, spread, one map across them, shape statistics.

    python3 -m surfacemaps.population STAGES_DIR --output-dir OUT [options]
    mpirun -n 4 python3 -m surfacemaps.population STAGES_DIR --output-dir OUT

STAGES_DIR holds one subdirectory per stage (sorted by name), each with the
stage's specimens (.vtp .vtk .obj .off .ply .stl; landmarks as a
"Landmarks" point array or as a landmark file with the mesh's stem and the
suffix .pinned, .vts or .txt). Steps:

1. per stage: one map of the stage's specimens (each against their mean shape), the
   order-free mean of the lifted specimens (generalized Procrustes,
   vtkSurfaceAverage) and their per-vertex spread (vtkSurfaceShapeStatistics'
   "StandardDeviation", on the mean);
2. one map across the stage means (pairs in sequence: stage k to k+1;
   with a single stage its own map is the common triangulation);
3. every specimen lifted onto that final common triangulation (through its
   stage map and the final map: the final T's vertex lies in a triangle of
   stage k's triangulation, which has the same barycentric place on each of
   the stage's lifted specimens), and shape statistics over all specimens:
   mean, modes, variances, scores per specimen and stage;
4. the stage means interpolated over time (vtkSurfaceSequenceInterpolator,
   keyframe times = stage times) as a series, after aligning them to each
   other (--keyframe-align), so that the series does not roll or shrink
   between stages;
5. report.json and pictures.

The stage maps are independent jobs: under MPI (mpi4py, ``mpirun -n R``)
rank r computes stages r, r + R, ...; rank 0 gathers them and does steps 2
to 5. The results do not depend on the number of ranks (the map is
deterministic for any thread count). Each rank runs its stages on one thread;
rank 0 then takes over the cores of the finished ranks on its host. Without
mpi4py, outside mpirun or with ``--no-mpi`` it runs serially.

Outputs in OUT: specimens/<name>.vtp (every specimen on the final common triangulation; name: the
file's stem), correspondences.npz (the same as one N x V x 3 array with the triangles and names),
fit.csv (per specimen: distances to the final triangulation and landmark error, the SDs and
distortion of its stage's map from the stage's first specimen), stages/<stage>.vtp (the stage mean on the stage's common
triangulation, with "StandardDeviation", "Landmarks" and the stage map's
"SpherePosition" on sphere 0), keyframes/
keyframe_KK.vtp (the stage means on the final common triangulation, aligned
to each other),
series/surface.pvd (the interpolated series), statistics/ (mean.vtp with
"StandardDeviation" and the modes, mode_<m>.pvd: mean + c sqrt(variance)
mode for c from -2 to 2, scores.csv, variance.csv), pictures/ (the PNGs:
explained_variance.png and scores.png always; stage_means.png, frames.png,
spread.png and mode_1.png need a display, or Xvfb to start a virtual one),
report.json. Exit codes: 0 ok, 2 bad usage or input, 3 no certified map,
1 other errors.
"""

import argparse
import csv
import io
import json
import math
import os
import socket
import sys
import time
import traceback

import numpy as np

import surfacemaps
from surfacemaps import specimens as specimen_files
from surfacemaps import synthetic

MESH_SUFFIXES = (".vtp", ".vtk", ".obj", ".off", ".ply", ".stl")
LANDMARK_SUFFIXES = (".pinned", ".vts", ".txt")
MODE_FRAMES = np.linspace(-2.0, 2.0, 9)


def _world_size():
    # OpenMPI's mpirun gives every rank OMPI_COMM_WORLD_SIZE (PMI_SIZE: MPICH / Slurm).
    return int(os.environ.get("OMPI_COMM_WORLD_SIZE", os.environ.get("PMI_SIZE", "1")))


def parser():
    p = argparse.ArgumentParser(prog="python3 -m surfacemaps.population",
                                description=__doc__.split("\n\n", 1)[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("stages_dir", metavar="STAGES_DIR", help="one subdirectory of specimens per stage")
    p.add_argument("--output-dir", required=True, help="where the results go (created)")
    p.add_argument("--stage-times", type=_bounded(float, -1e12, 1e12), nargs="+", metavar="T",
                   help="developmental time of each stage, from -1e12 to 1e12 (default: the mean of the "
                        "specimens' DevelopmentalTime field, else evenly spaced in [0, 1])")
    g = p.add_argument_group("maps (each stage's and the final one): the settings of `surfacemap map`")
    g.add_argument("--preset", choices=sorted(surfacemaps.presets()),
                   help="settings preset of every map (default: the filter's defaults); the setting flags "
                        "override it")
    add_setting_flags(g)
    g = p.add_argument_group("means and statistics")
    g.add_argument("--align", choices=("rigid", "similarity", "none"), default="rigid",
                   help="alignment before means and statistics (generalized Procrustes; default rigid)")
    g.add_argument("--modes", type=_bounded(int, 1, 100), default=3,
                   help="modes of variation computed (default 3, from 1 to 100)")
    g = p.add_argument_group("interpolation and output")
    g.add_argument("--steps-per-interval", type=_bounded(int, 1, 1000), default=10,
                   help="frames per stage interval (default 10, from 1 to 1000)")
    g.add_argument("--interpolation", choices=("smooth", "linear"), default="smooth",
                   help="smooth (C1 through the keyframes) or piecewise linear in time (default smooth)")
    g.add_argument("--keyframe-align", choices=("rigid", "similarity", "none"), default="rigid",
                   help="alignment of the stage means to each other before they are interpolated (similarity "
                        "also removes growth between the stages; default rigid)")
    g.add_argument("--no-pictures", action="store_true", help="write no pictures")
    g.add_argument("--no-mpi", action="store_true", help="run serially even under mpirun")
    return p


def parse_args(argv=None):
    return parser().parse_args(argv)


def _bounded(kind, lowest, highest):
    """argparse's `type` for a number of `kind` (int or float) from `lowest` to `highest`: every
    numeric option is bounded, so that a mistyped number is refused before anything runs."""
    def parse(text):
        try:
            value = kind(text)
        except ValueError:
            value = None
        if value is None or not lowest <= value <= highest:  # also refuses nan
            what = "a whole number" if kind is int else "a number"
            raise argparse.ArgumentTypeError(f"needs {what} from {lowest:g} to {highest:g}, not '{text}'")
        return value
    return parse


# The map settings as flags: every setting of the engine's list (vtkSurfaceMapsSettings) but the
# pairs, which each map here chooses itself (the mean shape within a stage, a sequence across the stages).
# Flags, help and values come from the list's codec, as for `surfacemap map`.
_SETTINGS = surfacemaps.vtkSurfaceMapsSettings
_TABLE = _SETTINGS.MAP_SETTINGS
_OWN_FLAGS = {"pairs"}


def _setting_indices():
    return [k for k in range(_SETTINGS.GetNumberOfSettings(_TABLE)) if _SETTINGS.GetFlag(_TABLE, k) not in _OWN_FLAGS]


def _setting_value(k):
    """argparse's `type` for setting k: the codec's value of the flag's text (a bool for a switch,
    an int for a count or a choice)."""
    def parse(text):
        flag = "--" + _SETTINGS.GetFlag(_TABLE, k)
        value = _SETTINGS.ParseFlag(_TABLE, k, flag, text)
        if math.isnan(value):
            raise argparse.ArgumentTypeError(_SETTINGS.GetValueError(_TABLE, k, flag, text))
        return value if _SETTINGS.GetType(_TABLE, k) == _SETTINGS.REAL else int(value)
    return parse


def add_setting_flags(group):
    for k in _setting_indices():
        name, flag = _SETTINGS.GetName(_TABLE, k), "--" + _SETTINGS.GetFlag(_TABLE, k)
        doc = _SETTINGS.GetDescription(_TABLE, k).replace("%", "%%")
        if _SETTINGS.GetType(_TABLE, k) == _SETTINGS.SWITCH:
            off = "--" + _SETTINGS.GetOffFlag(_TABLE, k)
            group.add_argument(flag, dest=name, action="store_const", const=True, help=f"{doc} ({off}: off)")
            group.add_argument(off, dest=name, action="store_const", const=False, help=argparse.SUPPRESS)
        else:
            choices = _SETTINGS.GetChoices(_TABLE, k)
            group.add_argument(flag, dest=name, type=_setting_value(k),
                               metavar=choices or ("N" if _SETTINGS.GetType(_TABLE, k) == _SETTINGS.COUNT else "X"),
                               help=doc)


def map_settings(args):
    """The preset and the map settings given as flags, by the filter's names."""
    settings = {_SETTINGS.GetName(_TABLE, k): getattr(args, _SETTINGS.GetName(_TABLE, k)) for k in _setting_indices()}
    return dict(preset=args.preset, **{name: value for name, value in settings.items() if value is not None})


def settings_report(args):
    """The preset and the settings given, as report.json writes them (the keys and values of
    `surfacemap map`'s report)."""
    report = {} if args.preset is None else {"preset": args.preset}
    for k in _setting_indices():
        value = getattr(args, _SETTINGS.GetName(_TABLE, k))
        if value is not None:
            report[_SETTINGS.GetJsonKey(_TABLE, k)] = json.loads(_SETTINGS.ToJson(_TABLE, k, float(value)))
    return report


# ------------------------------------------------------------------ MPI

class Serial:
    """The part of an mpi4py communicator this module uses, for one process."""
    rank, size = 0, 1

    def gather(self, value, root=0):
        return [value]

    def bcast(self, value, root=0):
        return value


def communicator(no_mpi=False):
    """mpi4py's COMM_WORLD under mpirun with more than one rank, else a serial stand-in.

    None for the ranks other than 0 when the run is serial under mpirun
    (`no_mpi` or no mpi4py): rank 0 does all the work alone.
    """
    if _world_size() <= 1:
        return Serial()
    if not no_mpi:
        try:
            from mpi4py import MPI
            return MPI.COMM_WORLD
        except ImportError:
            print("surfacemaps.population: mpi4py is not installed (apt-get install python3-mpi4py): "
                  "rank 0 runs the whole population alone", file=sys.stderr)
    rank = int(os.environ.get("OMPI_COMM_WORLD_RANK", os.environ.get("PMI_RANK", "0")))
    return Serial() if rank == 0 else None


def threads_after_gather(placements):
    """OpenMP threads for rank 0's work after the gather (0: leave OpenMP's default).

    `placements` holds (host, cores) of every rank. Under MPI the other ranks
    are done by then: rank 0 takes over the cores of the ranks on its own host
    (mpirun binds each rank to its core(s), so rank 0 widens its affinity
    first) and runs with one thread per core. Serially nothing changes.
    """
    if len(placements) <= 1:
        return 0
    host = placements[0][0]
    cores = set()
    for other_host, other_cores in placements:
        if other_host == host:
            cores.update(other_cores)
    try:
        os.sched_setaffinity(0, cores)
    except OSError as e:
        print(f"surfacemaps.population: cannot use the finished ranks' cores ({e}); rank 0 runs on "
              f"{len(os.sched_getaffinity(0))}", file=sys.stderr)
        return 0
    return len(cores)


def finish(comm):
    """Ranks other than 0 wait here, asleep, until rank 0 is done.

    A rank that went straight on to MPI_Finalize would busy-poll there and
    take a core away from rank 0's final map.
    """
    if comm.size <= 1:
        return
    # Blocking and nonblocking collectives do not match: Ibarrier on every rank.
    request = comm.Ibarrier()
    if comm.rank == 0:
        request.Wait()
        return
    while not request.Test():
        time.sleep(0.05)


# ------------------------------------------------------------------ data

def portable(mesh):
    """What the later steps need of a mesh, as numpy arrays (sent between ranks)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    landmarks = mesh.GetPointData().GetArray("Landmarks")
    return dict(points=vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64),
                triangles=vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3).astype(np.int64),
                landmarks=None if landmarks is None else vtk_to_numpy(landmarks).astype(np.int32))


def polydata(points, triangles, landmarks=None, point_arrays=None, time=None):
    """A vtkPolyData of triangles with optional "Landmarks", further point arrays and a DevelopmentalTime."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    mesh = synthetic.polydata(points, triangles, landmarks=landmarks, time=time)
    for name, values in (point_arrays or {}).items():
        array = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float64), deep=True)
        array.SetName(name)
        mesh.GetPointData().AddArray(array)
    return mesh


def stage_directories(stages_dir):
    if not os.path.isdir(stages_dir):
        raise surfacemaps.InputError(f"{stages_dir}: not a directory")
    stages = sorted(e.path for e in os.scandir(stages_dir) if e.is_dir())
    if not stages:
        raise surfacemaps.InputError(f"{stages_dir} has no stage subdirectories")
    return stages


def read_stage(directory):
    """(file names, meshes) of one stage directory, with landmark files beside them when present."""
    names, meshes = [], []
    for name in sorted(os.listdir(directory)):
        stem, suffix = os.path.splitext(name)
        if suffix.lower() not in MESH_SUFFIXES:
            continue
        landmarks = next((os.path.join(directory, stem + s) for s in LANDMARK_SUFFIXES
                          if os.path.exists(os.path.join(directory, stem + s))), None)
        meshes.append(surfacemaps.read_mesh(os.path.join(directory, name), landmarks=landmarks))
        names.append(name)
    if not meshes:
        raise surfacemaps.InputError(f"{directory} holds no meshes ({' '.join(MESH_SUFFIXES)})")
    return names, meshes


def developmental_time(meshes):
    """The mean of the meshes' "DevelopmentalTime" field, or None when a mesh has none."""
    values = []
    for mesh in meshes:
        array = mesh.GetFieldData().GetArray("DevelopmentalTime")
        if array is None:
            return None
        values.append(array.GetValue(0))
    return float(np.mean(values))


# ------------------------------------------------------------------ steps

def stage_result(directory, k, args, threads):
    """Map stage k's specimens (against their mean shape), their mean and spread; portable, with wall times."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    clock = time.perf_counter()
    files, meshes = read_stage(directory)
    loaded = time.perf_counter()
    lifted, exact = surfacemaps.map_surfaces(meshes, pairs="mean", mapped=True, NumberOfThreads=threads,
                                             **map_settings(args))
    mapped = time.perf_counter()
    result_fit = specimen_files.map_fit(meshes, lifted, exact)
    if len(lifted) > 1:
        # One alignment for both: the statistics' mean is average_surfaces' order-free mean.
        spread = surfacemaps.shape_statistics(lifted, modes=1, align=args.align)
        result = portable(spread.mean)
        result["spread"], result["spread_rms"] = spread.standard_deviation, math.sqrt(spread.total_variance)
    else:
        result = portable(surfacemaps.average_surfaces(lifted, align=args.align))
        result["spread"], result["spread_rms"] = np.zeros(len(result["points"])), 0.0
    if result["landmarks"] is None:  # same connectivity as the lifted meshes: take theirs
        result["landmarks"] = portable(lifted[0])["landmarks"]
    result["lifted"] = [portable(m)["points"] for m in lifted]
    result["fit"], result["specimens"] = result_fit, [portable(m) for m in meshes]
    result["sphere"] = vtk_to_numpy(lifted[0].GetPointData().GetArray("SpherePosition")).copy()
    averaged = time.perf_counter()
    result.update(stage=k, time=developmental_time(meshes), name=os.path.basename(directory), files=files,
                  specimen_vertices=[m.GetNumberOfPoints() for m in meshes],
                  load_s=loaded - clock, map_s=mapped - loaded, mean_s=averaged - mapped, total_s=averaged - clock)
    return result


def lift_onto(keyframe, stage):
    """Every specimen of `stage` on the final triangulation: the keyframe's vertices are given by
    "SourceCellId" / "SourceBarycentric" in triangles of the stage mean, which has the stage
    triangulation, as do the stage's lifted specimens."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    cells = vtk_to_numpy(keyframe.GetPointData().GetArray("SourceCellId")).astype(np.int64)
    weights = vtk_to_numpy(keyframe.GetPointData().GetArray("SourceBarycentric"))
    corners = stage["triangles"][cells]
    return [np.einsum("vc,vcd->vd", weights, points[corners]) for points in stage["lifted"]]


def statistics_tables(statistics, specimens):
    """variance.csv and scores.csv (the columns of `surfacemap statistics`, plus the stage)."""
    variance = io.StringIO()
    w = csv.writer(variance, lineterminator="\n")
    w.writerow(["mode", "variance", "standard_deviation", "explained_fraction", "cumulative_fraction"])
    cumulative = np.cumsum(statistics.explained_fractions)
    for m, v in enumerate(statistics.variances):
        w.writerow([m + 1, repr(float(v)), repr(math.sqrt(v)), repr(float(statistics.explained_fractions[m])),
                    repr(float(cumulative[m]))])
    scores = io.StringIO()
    w = csv.writer(scores, lineterminator="\n")
    k = len(statistics.variances)
    w.writerow(["specimen", "stage", "file"] + [f"mode_{m + 1}" for m in range(k)] + ["alignment_rms"])
    for i, (stage, name) in enumerate(specimens):
        w.writerow([i, stage, name] + [repr(float(s)) for s in statistics.scores[i]]
                   + [repr(float(statistics.alignment_rms[i]))])
    return variance.getvalue(), scores.getvalue()


def write_text(path, text):
    def write(temporary):
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(text)
    surfacemaps.files.replace_atomically(path, write)


def write_statistics(statistics, specimens, directory):
    """mean.vtp, mode_<m>.pvd with mode_<m>/frame_<k>.vtp, variance.csv, scores.csv; the paths."""
    os.makedirs(directory, exist_ok=True)
    surfacemaps.write_mesh(statistics.mean, os.path.join(directory, "mean.vtp"))
    for m in range(1, len(statistics.variances) + 1):
        frames = [statistics.shape(m, c) for c in MODE_FRAMES]
        surfacemaps.write_collection(frames, MODE_FRAMES, directory, f"mode_{m}", subdirectory=f"mode_{m}",
                                     stem="frame")
    variance, scores = statistics_tables(statistics, specimens)
    write_text(os.path.join(directory, "variance.csv"), variance)
    write_text(os.path.join(directory, "scores.csv"), scores)


def interpolator(keyframes, times, args):
    f = surfacemaps.vtkSurfaceSequenceInterpolator()
    for k, mesh in enumerate(keyframes):
        f.AddInputData(mesh)
        f.SetKeyframeTime(k, times[k])
    if args.interpolation == "smooth":
        f.SetInterpolationModeToSmooth()
    else:
        f.SetInterpolationModeToLinear()
    f.SetStepsPerInterval(args.steps_per_interval)
    f.SetKeyframeAlignmentToNone()  # aligned already (align_surfaces)
    return f


def reported_time_steps(source):
    """The TIME_STEPS the source reports: the keyframe times and StepsPerInterval - 1 between each."""
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
    source.UpdateInformation()
    steps = source.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    if not steps:
        raise surfacemaps.InputError("the interpolator reports no time steps (see the messages above)")
    return [float(t) for t in steps]


# ------------------------------------------------------------------ pictures

def display_available():
    """True if surface pictures can be rendered: on the display, or on a virtual one started for
    this process (surfacemaps.render.ensure_display: Xvfb); otherwise says why on stderr."""
    from surfacemaps import render
    try:
        render.ensure_display()
        return True
    except RuntimeError as e:
        print(f"surfacemaps.population: {e}: surface pictures skipped (install xvfb, or --no-pictures)",
              file=sys.stderr)
        return False


def grid(meshes, pattern, captions):
    """One panel per mesh (surfacemaps.render.Panel): a straight-edged checkerboard of `pattern`
    (per-vertex sphere positions on the common triangulation) under its caption."""
    from surfacemaps import render
    panels = []
    for mesh, caption in zip(meshes, captions):
        data = portable(mesh)
        patterned = polydata(data["points"], data["triangles"], point_arrays={"Pattern": pattern})
        panels.append(render.Panel(render.checkered(patterned, "Pattern", squares=6), render.configure_checkerboard,
                                   caption))
    return panels


def frames_of(source, times):
    frames = []
    for t in times:
        source.UpdateTimeStep(t)
        frame = source.GetOutput().NewInstance()
        frame.DeepCopy(source.GetOutput())
        frames.append(frame)
    return frames


def surface_pictures(keyframes, names, pattern, source, times, statistics, directory):
    """stage_means.png (each stage mean under its stage's name and time), frames.png (six frames of
    the series under their time), both a checkerboard of `pattern` (keyframe 0's sphere positions,
    so a square follows one material region through the stages); spread.png (the per-vertex
    standard deviation over all specimens on their mean) and mode_1.png (mode 1 at -2, 0, +2
    standard deviations); frames.png only for a series. The shapes of a picture share one camera
    facing their broadest side (surfacemaps.render.render_panels)."""
    from surfacemaps import render
    paths = []
    frame_times = np.linspace(times[0], times[-1], 6) if source is not None else []
    series = (("stage_means.png", keyframes, [f"{name}, t = {t:.3g}" for name, t in zip(names, times)]),
              ("frames.png", frames_of(source, frame_times) if source is not None else [],
               [f"t = {t:.3g}" for t in frame_times]))
    for name, meshes, captions in series:
        if len(meshes):
            paths.append(os.path.join(directory, name))
            render.render_panels(grid(meshes, pattern, captions), paths[-1])
    spread = statistics.standard_deviation
    top = float(spread.max()) or 1.0
    paths.append(os.path.join(directory, "spread.png"))
    render.render_point_scalars(statistics.mean, paths[-1], "StandardDeviation", 0.0, top, size=(640, 480),
                                title="standard deviation")
    shapes = [statistics.shape(1, c) for c in (-2.0, 0.0, 2.0)]
    paths.append(os.path.join(directory, "mode_1.png"))
    render.render_panels(grid(shapes, pattern, ["mode 1: -2 sd", "mean", "mode 1: +2 sd"]), paths[-1])
    return paths


def plots(statistics, specimen_stages, stage_names, directory):
    """explained_variance.png and scores.png (modes 1 and 2, one colour per stage), matplotlib;
    legends outside the data, at most about 12 ticks of modes."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator
    paths = [os.path.join(directory, "explained_variance.png"), os.path.join(directory, "scores.png")]
    modes = np.arange(1, len(statistics.variances) + 1)
    figure, axes = plt.subplots(figsize=(5, 3.5))
    axes.bar(modes, 100.0 * statistics.explained_fractions, color="tab:blue", label="per mode")
    axes.plot(modes, 100.0 * np.cumsum(statistics.explained_fractions), "o-", color="tab:red", label="cumulative")
    axes.set_xlabel("mode")
    axes.set_ylabel("explained variance (%)")
    axes.set_ylim(0.0, 105.0)
    axes.xaxis.set_major_locator(MaxNLocator(nbins=12, integer=True))
    axes.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2, frameon=False)
    figure.savefig(paths[0], dpi=120, bbox_inches="tight")
    plt.close(figure)
    figure, axes = plt.subplots(figsize=(5, 4))
    scores = statistics.scores
    second = scores[:, 1] if scores.shape[1] > 1 else np.zeros(len(scores))
    stages = np.asarray(specimen_stages)
    colours = plt.get_cmap("viridis")(np.linspace(0.0, 1.0, max(len(stage_names), 2)))
    for k, name in enumerate(stage_names):
        chosen = stages == k
        axes.scatter(scores[chosen, 0], second[chosen], color=colours[k], label=name)
    axes.set_xlabel(f"mode 1 ({100.0 * statistics.explained_fractions[0]:.0f} %)")
    axes.set_ylabel("mode 2" + (f" ({100.0 * statistics.explained_fractions[1]:.0f} %)"
                                if scores.shape[1] > 1 else " (none)"))
    axes.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False)
    figure.savefig(paths[1], dpi=120, bbox_inches="tight")
    plt.close(figure)
    return paths


# ------------------------------------------------------------------ the run

def run(args, comm):
    """The population of `args.stages_dir` under `comm`; 0 on success, else an exit code."""
    clock = time.perf_counter()
    directories = stage_directories(args.stages_dir)
    if args.stage_times is not None and len(args.stage_times) != len(directories):
        raise surfacemaps.InputError(f"{len(directories)} stages but {len(args.stage_times)} --stage-times")
    threads = 1 if comm.size > 1 else 0
    results = []
    for k in range(comm.rank, len(directories), comm.size):
        try:
            results.append(stage_result(directories[k], k, args, threads))
        except Exception as e:  # reported by rank 0; the other ranks must still reach the gather
            kind = "input" if isinstance(e, surfacemaps.InputError) else "map" if isinstance(
                e, surfacemaps.MapError) else "internal"
            results.append(dict(stage=k, name=os.path.basename(directories[k]), error=str(e), kind=kind,
                                traceback=traceback.format_exc()))
        results[-1]["rank"] = comm.rank
        print(f"surfacemaps.population: rank {comm.rank}: stage {results[-1]['name']} "
              + ("failed" if "error" in results[-1] else f"mapped and averaged in {results[-1]['total_s']:.2f} s"),
              file=sys.stderr, flush=True)
    before_gather = time.perf_counter()
    gathered = comm.gather(results, root=0)
    placements = comm.gather((socket.gethostname(), sorted(os.sched_getaffinity(0))), root=0)
    if comm.rank != 0:
        return 0
    final_threads = threads_after_gather(placements)
    gather_s = time.perf_counter() - before_gather
    stages = sorted((r for part in gathered for r in part), key=lambda r: r["stage"])
    failed = [r for r in stages if "error" in r]
    for r in failed:
        print(f"surfacemaps.population: stage {r['name']} (rank {r['rank']}): "
              + {"input": "error: ", "map": "no certified map: ", "internal": "internal error: "}[r["kind"]]
              + r["error"], file=sys.stderr)
        if r["kind"] == "internal":
            print(r["traceback"], file=sys.stderr)
    if failed:
        kinds = {r["kind"] for r in failed}
        return 1 if "internal" in kinds else 3 if "map" in kinds else 2
    timings = dict(stage_maps_s=time.perf_counter() - clock, gather_s=gather_s)

    times = args.stage_times or [r["time"] for r in stages]
    if any(t is None for t in times):
        times = list(np.linspace(0.0, 1.0, len(stages))) if len(stages) > 1 else [0.0]
    if any(b <= a for a, b in zip(times[:-1], times[1:])):
        raise surfacemaps.InputError(f"the stage times must increase: {times}")
    from vtkmodules.util.numpy_support import vtk_to_numpy
    out = args.output_dir
    # The means as the final map's inputs; written with the stage map's sphere positions too (which
    # the final map would take for a precomputed embedding of the mean, so they stay out of its input).
    means = [polydata(r["points"], r["triangles"], landmarks=r["landmarks"],
                      point_arrays={"StandardDeviation": r["spread"]}, time=t) for r, t in zip(stages, times)]
    for r, t in zip(stages, times):
        surfacemaps.write_mesh(polydata(r["points"], r["triangles"], landmarks=r["landmarks"], time=t,
                                        point_arrays={"StandardDeviation": r["spread"], "SpherePosition": r["sphere"]}),
                               os.path.join(out, "stages", r["name"] + ".vtp"))

    # One stage: its map is the common triangulation already (no final map, no series).
    step = time.perf_counter()
    if len(means) > 1:
        keyframes = surfacemaps.map_surfaces(means, pairs="sequence", NumberOfThreads=final_threads,
                                             **map_settings(args))
        # Aligned to each other, so the series neither rolls nor shrinks where the stages' poses differ.
        keyframes = surfacemaps.align_surfaces(keyframes, align=args.keyframe_align)
        for k, keyframe in enumerate(keyframes):
            surfacemaps.write_mesh(keyframe, os.path.join(out, "keyframes", f"keyframe_{k:02d}.vtp"))
        pattern = vtk_to_numpy(keyframes[0].GetPointData().GetArray("SpherePosition"))
    else:
        keyframes, pattern = means, stages[0]["sphere"]
    timings["final_map_s"] = time.perf_counter() - step

    step = time.perf_counter()
    specimens, specimen_stages, lifted = [], [], []
    for k, (r, keyframe) in enumerate(zip(stages, keyframes)):
        lifted += lift_onto(keyframe, r) if len(means) > 1 else r["lifted"]
        specimens += [(r["name"], name) for name in r["files"]]
        specimen_stages += [k] * len(r["files"])
    triangles = portable(keyframes[0])["triangles"]
    statistics = None
    if len(lifted) > 1:
        statistics = surfacemaps.shape_statistics([polydata(p, triangles) for p in lifted], modes=args.modes,
                                                  align=args.align)
        write_statistics(statistics, specimens, os.path.join(out, "statistics"))
    timings["statistics_s"] = time.perf_counter() - step
    step = time.perf_counter()
    files = [os.path.join(os.path.abspath(args.stages_dir), r["name"], f) for r in stages for f in r["files"]]
    fit = specimen_files.write_specimens(
        out, files, specimen_files.specimen_names(files, [r["name"] for r in stages for _ in r["files"]]),
        [s for r in stages for s in r["specimens"]], [f for r in stages for f in r["fit"]], lifted,
        portable(keyframes[0]))
    timings["specimens_s"] = time.perf_counter() - step

    step = time.perf_counter()
    source, frames = None, []
    if len(keyframes) > 1:
        source = interpolator(keyframes, times, args)
        frames = reported_time_steps(source)
        surfacemaps.write_time_series(source, frames, os.path.join(out, "series"), name="surface")
    timings["interpolation_s"] = time.perf_counter() - step

    step = time.perf_counter()
    pictures = []
    if not args.no_pictures and statistics is not None:
        directory = os.path.join(out, "pictures")
        os.makedirs(directory, exist_ok=True)
        pictures += plots(statistics, specimen_stages, [r["name"] for r in stages], directory)
        if display_available():
            pictures += surface_pictures(keyframes, [r["name"] for r in stages], pattern, source, times,
                                         statistics, directory)
    timings["pictures_s"] = time.perf_counter() - step
    timings["total_s"] = time.perf_counter() - clock

    report = dict(
        stages_dir=os.path.abspath(args.stages_dir), ranks=comm.size, final_map_threads=final_threads or None,
        settings=settings_report(args),
        align=args.align, keyframe_align=args.keyframe_align,
        stages=[dict(stage=r["stage"], name=r["name"], time=float(t), rank=r["rank"], specimens=len(r["files"]),
                     files=r["files"], specimen_vertices=r["specimen_vertices"], mean_vertices=len(r["points"]),
                     spread_rms=r["spread_rms"], load_s=r["load_s"], map_s=r["map_s"], mean_s=r["mean_s"],
                     total_s=r["total_s"]) for r, t in zip(stages, times)],
        common_vertices=keyframes[0].GetNumberOfPoints(), frames=len(frames), specimens=fit,
        statistics=None if statistics is None else dict(
            specimens=len(lifted), variances=statistics.variances.tolist(),
            explained_fractions=statistics.explained_fractions.tolist(),
            total_variance=statistics.total_variance,
            scores=statistics.scores.tolist(), alignment_rms=statistics.alignment_rms.tolist()),
        pictures=[os.path.relpath(p, out) for p in pictures], timings=timings)
    write_text(os.path.join(out, "report.json"), json.dumps(report, indent=2) + "\n")
    summary(report)
    return 0


def summary(report):
    print(f"ranks {report['ranks']}; final common triangulation: {report['common_vertices']} vertices")
    print(f"{'stage':>12} {'rank':>4} {'specimens':>9} {'mean T':>7} {'spread':>9} {'map s':>8} {'total s':>8}")
    for s in report["stages"]:
        print(f"{s['name']:>12} {s['rank']:>4} {s['specimens']:>9} {s['mean_vertices']:>7} {s['spread_rms']:9.4f} "
              f"{s['map_s']:8.2f} {s['total_s']:8.2f}")
    if report["statistics"]:
        fractions = ", ".join(f"{100 * f:.1f} %" for f in report["statistics"]["explained_fractions"])
        print(f"shape statistics over {report['statistics']['specimens']} specimens; explained variance: {fractions}")
    far = max(report["specimens"], key=lambda s: s["hausdorff"])
    sds = [s for s in report["specimens"] if s["exact_sd"] is not None]
    print(f"fit (fit.csv): largest H {far['hausdorff']:.3f} % ({far['name']})"
          + (f", largest exact SD {max(s['exact_sd'] for s in sds):.3f}" if sds else ""))
    t = report["timings"]
    for key, label in (("stage_maps_s", "stage maps and means (all ranks, wall)"),
                       ("gather_s", "gather (wait for the other ranks)"), ("final_map_s", "final map"),
                       ("statistics_s", "statistics"), ("specimens_s", "specimens on T and their fit"),
                       ("interpolation_s", f"interpolation ({report['frames']} frames)"),
                       ("pictures_s", "pictures"), ("total_s", "total")):
        print(f"{label:<40} {t[key]:8.2f} s")


def main(argv=None, comm=None):
    """The command line; `comm` (an mpi4py communicator or Serial) when the caller already has one."""
    args = parse_args(argv)
    comm = comm or communicator(args.no_mpi)
    if comm is None:
        return 0
    try:
        if comm.rank == 0:
            os.makedirs(args.output_dir, exist_ok=True)
        return run(args, comm)
    except surfacemaps.InputError as e:
        print(f"surfacemaps.population: error: {e}", file=sys.stderr)
        return 2
    except surfacemaps.MapError as e:
        print(f"surfacemaps.population: no certified map: {e}", file=sys.stderr)
        return 3
    except OSError as e:
        print(f"surfacemaps.population: error: {e}", file=sys.stderr)
        return 2
    finally:
        finish(comm)


if __name__ == "__main__":
    # The libraries read their thread count when they load, before main(): under mpirun each
    # rank restarts itself once with one OpenMP thread (unless the user chose a count).
    if _world_size() > 1 and "OMP_NUM_THREADS" not in os.environ:
        os.environ["OMP_NUM_THREADS"] = "1"
        os.execv(sys.executable, [sys.executable, "-m", "surfacemaps.population"] + sys.argv[1:])
    sys.exit(main())
