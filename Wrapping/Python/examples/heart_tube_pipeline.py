#!/usr/bin/env python3
"""Average and interpolate a developmental time series of surfaces (the heart-tube workflow).

Input: groups of closed genus-0 surfaces, one group per developmental stage
(e.g. 51 mouse heart tubes in 10 stage groups). Steps:

1. per stage: map the stage's specimens onto each other (one common
   triangulation, star pairs 0-i, landmarks kept) and average the lifted
   meshes (vtkSurfaceAverage): one average surface per stage;
2. map all stage averages together (pairs in sequence: stage k to k+1);
3. interpolate the K keyframes over time (vtkSurfaceSequenceInterpolator,
   keyframe times = stage times) and write the series (.pvd + .vtp, opens
   in ParaView as an animation);
4. pictures of the averages and of interpolated frames; wall times per step
   in timings.json.

Without --input-dir the specimens come from surfacemaps.synthetic: tubes that
bend and loop with time, several noisy specimens per stage with their own
triangulations and three landmarks (both tips and the outer curvature).
With --input-dir DIR every subdirectory of DIR (sorted by name) is a stage
and holds its specimens (.vtp .vtk .obj .off .ply .stl; landmarks as a
"Landmarks" point array or as a landmark file with the mesh's stem and the
suffix .pinned, .vts or .txt).

Each stage's average is an independent job: under MPI (mpi4py, e.g.
``mpirun -n 2``) rank r computes stages r, r + K, r + 2K, ... and rank 0
gathers them and does steps 2-4. Without mpi4py, outside mpirun or with one
rank it runs serially with the same results. Each rank then runs one OpenMP
thread (OMP_NUM_THREADS=1 unless set) for the stages; for the final map rank
0 takes over the cores of the finished ranks on its host (one thread each).

    python3 heart_tube_pipeline.py --output-dir out            # 10 stages x 5 specimens
    python3 heart_tube_pipeline.py --quick --output-dir out    # small, seconds
    mpirun -n 2 python3 heart_tube_pipeline.py --output-dir out

Pictures need a display: run under ``xvfb-run -a`` on a headless machine
(otherwise they are skipped with a note), or pass --no-pictures.

Outputs in --output-dir: averages/stage_KK.vtp (the average of stage k, the
stage's common triangulation, with "Landmarks"), keyframes/keyframe_KK.vtp
(the final map's outputs: one triangulation for all stages), series/
(the interpolated series: surface.pvd + surface_NNNN.vtp), pictures/
(averages.png, frames.png), specimens/ (with --write-specimens), timings.json.
Exit codes: 0 ok, 2 bad usage or input, 3 no certified map, 1 other errors.
"""

import os
import sys

# One OpenMP thread per MPI rank: must be set before the library starts its threads.
# OpenMPI's mpirun gives every rank OMPI_COMM_WORLD_SIZE (PMI_SIZE: MPICH / Slurm).
_WORLD_SIZE = int(os.environ.get("OMPI_COMM_WORLD_SIZE", os.environ.get("PMI_SIZE", "1")))
if _WORLD_SIZE > 1:
    os.environ.setdefault("OMP_NUM_THREADS", "1")

import argparse  # noqa: E402
import json  # noqa: E402
import socket  # noqa: E402
import time  # noqa: E402
import traceback  # noqa: E402

import numpy as np  # noqa: E402

import surfacemaps  # noqa: E402
from surfacemaps import synthetic  # noqa: E402

MESH_SUFFIXES = (".vtp", ".vtk", ".obj", ".off", ".ply", ".stl")
LANDMARK_SUFFIXES = (".pinned", ".vts", ".txt")

QUICK = dict(stages=2, specimens=2, resolution=10, target_error=5e-3, landmark_iterations=10, coarse_iterations=3,
             fine_iterations=3, steps_per_interval=4)


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n", 1)[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--output-dir", required=True, help="where the results go (created)")
    p.add_argument("--input-dir", help="read the stages from DIR's subdirectories instead of generating them")
    p.add_argument("--stage-times", type=float, nargs="+", metavar="T",
                   help="developmental time of each stage (default: the meshes' DevelopmentalTime field, "
                        "else evenly spaced in [0, 1])")
    p.add_argument("--quick", action="store_true",
                   help="small version for tests: 2 stages x 2 coarse specimens, short schedules "
                        "(explicit options still win)")
    g = p.add_argument_group("synthetic specimens")
    g.add_argument("--stages", type=int, help="number of stages (default 10)")
    g.add_argument("--specimens", type=int, help="specimens per stage (default 5)")
    g.add_argument("--resolution", type=int, help="vertices around the tube (default 20; +-25%% per specimen)")
    g.add_argument("--seed", type=int, default=0, help="seed of the series (default 0)")
    g.add_argument("--write-specimens", action="store_true",
                   help="also write the specimens to OUTPUT/specimens/stage_KK/ (readable with --input-dir)")
    g = p.add_argument_group("maps (each stage's and the final one)")
    g.add_argument("--target-error", type=float, help="approximation error, unit-area units (default 2e-3)")
    g.add_argument("--landmark-iterations", type=int, help="landmark phase cap (default: the filter's)")
    g.add_argument("--coarse-iterations", type=int, help="coarse phase iterations (default: the filter's)")
    g.add_argument("--fine-iterations", type=int, help="fine phase iterations (default: the filter's)")
    g.add_argument("--align", choices=("rigid", "similarity", "none"), default="rigid",
                   help="how each stage's lifted meshes are aligned before averaging (default rigid)")
    g = p.add_argument_group("interpolation and output")
    g.add_argument("--steps-per-interval", type=int, help="frames per stage interval (default 10)")
    g.add_argument("--interpolation", choices=("smooth", "linear"), default="smooth",
                   help="smooth (C1 through the keyframes) or piecewise linear in time (default smooth)")
    g.add_argument("--no-pictures", action="store_true", help="write no pictures")
    g.add_argument("--no-mpi", action="store_true", help="run serially even under mpirun")
    args = p.parse_args(argv)
    defaults = dict(stages=10, specimens=5, resolution=20, target_error=2e-3, landmark_iterations=None,
                    coarse_iterations=None, fine_iterations=None, steps_per_interval=10)
    for name, value in defaults.items():
        if getattr(args, name) is None:
            setattr(args, name, QUICK[name] if args.quick else value)
    if args.stages < 1 or args.specimens < 1:
        p.error("--stages and --specimens are at least 1")
    if args.steps_per_interval < 1:
        p.error("--steps-per-interval is at least 1")
    return args


def map_settings(args):
    settings = dict(target_error=args.target_error)
    for option, name in (("landmark_iterations", "LandmarkIterations"), ("coarse_iterations", "CoarseIterations"),
                         ("fine_iterations", "FineIterations")):
        if getattr(args, option) is not None:
            settings[name] = getattr(args, option)
    return settings


# ------------------------------------------------------------------ MPI

class Serial:
    """The part of an mpi4py communicator this script uses, for one process."""
    rank, size = 0, 1

    def gather(self, value, root=0):
        return [value]

    def bcast(self, value, root=0):
        return value


def communicator(args):
    """mpi4py's COMM_WORLD under mpirun with more than one rank, else a serial stand-in.

    None for the ranks other than 0 when the run is serial under mpirun (--no-mpi or no
    mpi4py): rank 0 does all the work alone.
    """
    if _WORLD_SIZE <= 1:
        return Serial()
    if not args.no_mpi:
        try:
            from mpi4py import MPI
            return MPI.COMM_WORLD
        except ImportError:
            print("heart_tube_pipeline: mpi4py is not installed (apt-get install python3-mpi4py): "
                  "rank 0 runs the whole series alone", file=sys.stderr)
    rank = int(os.environ.get("OMPI_COMM_WORLD_RANK", os.environ.get("PMI_RANK", "0")))
    return Serial() if rank == 0 else None


def threads_after_gather(placements):
    """OpenMP threads for rank 0's work after the gather (0: leave OpenMP's default).

    `placements` holds (host, cores) of every rank. Under MPI the other ranks
    are done by then: rank 0 takes over the cores of the ranks on its own host
    (mpirun binds each rank to its core(s), so rank 0 widens its affinity
    first) and runs the final map with one thread per core. Serially nothing
    changes.
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
        print(f"heart_tube_pipeline: cannot use the finished ranks' cores ({e}); the final map runs on "
              f"{len(os.sched_getaffinity(0))}", file=sys.stderr)
        return 0
    return len(cores)


# ------------------------------------------------------------------ data

def portable(mesh):
    """What the later steps need of a mesh, as numpy arrays (sent between ranks)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    landmarks = mesh.GetPointData().GetArray("Landmarks")
    return dict(points=vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64),
                triangles=vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3).astype(np.int64),
                landmarks=None if landmarks is None else vtk_to_numpy(landmarks).astype(np.int32))


def from_portable(data, time=None):
    return synthetic.polydata(data["points"], data["triangles"], landmarks=data["landmarks"], time=time)


def stage_directories(input_dir):
    stages = sorted(e.path for e in os.scandir(input_dir) if e.is_dir())
    if not stages:
        raise surfacemaps.InputError(f"{input_dir} has no stage subdirectories")
    return stages


def read_stage(directory):
    """The specimens in one stage directory, with landmark files beside them when present."""
    meshes = []
    for name in sorted(os.listdir(directory)):
        stem, suffix = os.path.splitext(name)
        if suffix.lower() not in MESH_SUFFIXES:
            continue
        landmarks = next((os.path.join(directory, stem + s) for s in LANDMARK_SUFFIXES
                          if os.path.exists(os.path.join(directory, stem + s))), None)
        meshes.append(surfacemaps.read_mesh(os.path.join(directory, name), landmarks=landmarks))
    if not meshes:
        raise surfacemaps.InputError(f"{directory} holds no meshes ({' '.join(MESH_SUFFIXES)})")
    return meshes


def developmental_time(meshes):
    """The mean of the meshes' "DevelopmentalTime" field, or None when a mesh has none."""
    values = []
    for mesh in meshes:
        array = mesh.GetFieldData().GetArray("DevelopmentalTime")
        if array is None:
            return None
        values.append(array.GetValue(0))
    return float(np.mean(values))


class Stages:
    """The stages' specimens, generated or read on demand (every rank loads only its own)."""

    def __init__(self, args):
        self.args = args
        if args.input_dir:
            self.directories = stage_directories(args.input_dir)
            self.count = len(self.directories)
        else:
            self.count = args.stages
        if args.stage_times is not None and len(args.stage_times) != self.count:
            raise surfacemaps.InputError(f"{self.count} stages but {len(args.stage_times)} --stage-times")

    def specimens(self, k):
        """(time, meshes) of stage k; time None when the files do not say it."""
        if self.args.input_dir:
            meshes = read_stage(self.directories[k])
            t = developmental_time(meshes)
        else:
            t, meshes = synthetic.stage_specimens(k, self.count, self.args.specimens, seed=self.args.seed,
                                                  resolution=self.args.resolution)
        if self.args.stage_times is not None:
            t = self.args.stage_times[k]
        return t, meshes

    def name(self, k):
        return os.path.basename(self.directories[k]) if self.args.input_dir else f"stage_{k:02d}"


# ------------------------------------------------------------------ steps

def average_stage(stages, k, args):
    """Map stage k's specimens (star pairs), average the lifted meshes; result and wall times."""
    clock = time.perf_counter()
    t, meshes = stages.specimens(k)
    generated = time.perf_counter()
    if args.write_specimens:
        for i, mesh in enumerate(meshes):
            surfacemaps.write_mesh(
                mesh, os.path.join(args.output_dir, "specimens", stages.name(k), f"specimen_{i:02d}.vtp"))
    lifted = surfacemaps.map_surfaces(meshes, pairs="star", **map_settings(args))
    mapped = time.perf_counter()
    average = surfacemaps.average_surfaces(lifted, align=args.align)
    averaged = time.perf_counter()
    result = portable(average)
    if result["landmarks"] is None:  # same connectivity as the lifted meshes: take theirs
        result["landmarks"] = portable(lifted[0])["landmarks"]
    result.update(stage=k, time=t, name=stages.name(k), specimens=len(meshes),
                  specimen_vertices=[m.GetNumberOfPoints() for m in meshes],
                  load_s=generated - clock, map_s=mapped - generated, average_s=averaged - mapped,
                  total_s=averaged - clock)
    return result


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
    return f


def reported_time_steps(source):
    """The TIME_STEPS the source reports: the keyframe times and StepsPerInterval - 1 between each."""
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
    source.UpdateInformation()
    steps = source.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    if not steps:
        raise surfacemaps.InputError("the interpolator reports no time steps (see the messages above)")
    return [float(t) for t in steps]


def display_available():
    return sys.platform in ("win32", "darwin") or bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def grid(meshes, pattern, elevation):
    """The meshes in rows of a near-square grid as one vtkPolyData, each with the point array `pattern`.

    Rows run down the screen of a camera raised by `elevation` degrees
    (surfacemaps.render's view); every mesh is centred in its cell.
    """
    import math
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkFiltersCore import vtkAppendPolyData
    columns = math.ceil(math.sqrt(len(meshes)))
    cell = 1.1 * max(np.linalg.norm(np.ptp(vtk_to_numpy(m.GetPoints().GetData()), axis=0)) for m in meshes)
    down = -np.array([0.0, math.cos(math.radians(elevation)), -math.sin(math.radians(elevation))])
    append = vtkAppendPolyData()
    for i, mesh in enumerate(meshes):
        data = portable(mesh)
        row, column = divmod(i, columns)
        data["points"] = data["points"] - data["points"].mean(axis=0) + cell * (column * np.array([1.0, 0, 0])
                                                                                 + row * down)
        copy = from_portable(data)
        array = numpy_to_vtk(np.ascontiguousarray(pattern, dtype=np.float64), deep=True)
        array.SetName("Pattern")
        copy.GetPointData().AddArray(array)
        append.AddInputData(copy)
    append.Update()
    return append.GetOutput(), (columns * 320, math.ceil(len(meshes) / columns) * 320)


def pictures(keyframes, series_source, times, directory):
    """averages.png: the stage averages (final common triangulation); frames.png: interpolated frames.

    Both carry the same checkerboard, keyframe 0's sphere positions, so a
    square follows the same material region through the stages.
    """
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from surfacemaps import render
    os.makedirs(directory, exist_ok=True)
    pattern = vtk_to_numpy(keyframes[0].GetPointData().GetArray("SpherePosition"))
    frames = []
    for t in np.linspace(times[0], times[-1], 6):
        series_source.UpdateTimeStep(t)
        frame = series_source.GetOutput().NewInstance()
        frame.DeepCopy(series_source.GetOutput())
        frames.append(frame)
    paths = []
    for name, meshes in (("averages.png", keyframes), ("frames.png", frames)):
        mesh, size = grid(meshes, pattern, elevation=60.0)
        paths.append(os.path.join(directory, name))
        render.render_checkerboard(mesh, paths[-1], "Pattern", squares=6, size=size, azimuth=0.0, elevation=60.0)
    return paths


def run(args, comm):
    clock = time.perf_counter()
    stages = Stages(args)
    mine = range(comm.rank, stages.count, comm.size)
    results = []
    for k in mine:
        try:
            results.append(average_stage(stages, k, args))
        except Exception as e:  # reported by rank 0; the other ranks must still reach the gather
            kind = "input" if isinstance(e, surfacemaps.InputError) else "map" if isinstance(
                e, surfacemaps.MapError) else "internal"
            results.append(dict(stage=k, name=stages.name(k), error=str(e), kind=kind,
                                traceback=traceback.format_exc()))
        results[-1]["rank"] = comm.rank
        print(f"heart_tube_pipeline: rank {comm.rank}: stage {k} "
              + ("failed" if "error" in results[-1] else f"averaged in {results[-1]['total_s']:.2f} s"),
              file=sys.stderr, flush=True)
    before_gather = time.perf_counter()
    gathered = comm.gather(results, root=0)
    placements = comm.gather((socket.gethostname(), sorted(os.sched_getaffinity(0))), root=0)
    if comm.rank != 0:
        return 0
    final_threads = threads_after_gather(placements)
    gather_s = time.perf_counter() - before_gather
    results = sorted((r for part in gathered for r in part), key=lambda r: r["stage"])
    failed = [r for r in results if "error" in r]
    for r in failed:
        print(f"heart_tube_pipeline: stage {r['name']} (rank {r['rank']}): "
              + {"input": "error: ", "map": "no certified map: ", "internal": "internal error: "}[r["kind"]]
              + r["error"], file=sys.stderr)
        if r["kind"] == "internal":
            print(r["traceback"], file=sys.stderr)
    if failed:
        kinds = {r["kind"] for r in failed}
        return 1 if "internal" in kinds else 3 if "map" in kinds else 2
    stages_s = time.perf_counter() - clock

    times = [r["time"] for r in results]
    if any(t is None for t in times):
        times = synthetic.stage_times(len(results))
    if any(b <= a for a, b in zip(times[:-1], times[1:])):
        raise surfacemaps.InputError(f"the stage times must increase: {times}")
    averages = [from_portable(r, time=t) for r, t in zip(results, times)]
    for r, average in zip(results, averages):
        surfacemaps.write_mesh(average, os.path.join(args.output_dir, "averages", r["name"] + ".vtp"))

    timings = dict(ranks=comm.size, omp_num_threads=os.environ.get("OMP_NUM_THREADS"),
                   stages=[{key: r[key] for key in ("stage", "name", "time", "rank", "specimens", "specimen_vertices",
                                                    "load_s", "map_s", "average_s", "total_s")}
                           | {"average_vertices": len(r["points"])} for r in results],
                   stage_averages_s=stages_s, gather_s=gather_s)

    step = time.perf_counter()
    if len(averages) > 1:
        keyframes = surfacemaps.map_surfaces(averages, pairs="sequence", NumberOfThreads=final_threads,
                                             **map_settings(args))
    else:
        keyframes = averages
    timings["final_map_s"] = time.perf_counter() - step
    timings["final_map_threads"] = final_threads or None
    for k, keyframe in enumerate(keyframes):
        surfacemaps.write_mesh(keyframe, os.path.join(args.output_dir, "keyframes", f"keyframe_{k:02d}.vtp"))
    timings["common_vertices"] = keyframes[0].GetNumberOfPoints()

    step = time.perf_counter()
    frames = []
    source = None
    if len(keyframes) > 1:
        source = interpolator(keyframes, times, args)
        frames = reported_time_steps(source)
        surfacemaps.write_time_series(source, frames, os.path.join(args.output_dir, "series"), name="surface")
    timings["interpolation_s"] = time.perf_counter() - step
    timings["frames"] = len(frames)

    step = time.perf_counter()
    if args.no_pictures or source is None:
        pass
    elif not display_available():
        print("heart_tube_pipeline: no display: pictures skipped (run under xvfb-run -a, or --no-pictures)",
              file=sys.stderr)
    else:
        pictures(keyframes, source, times, os.path.join(args.output_dir, "pictures"))
    timings["pictures_s"] = time.perf_counter() - step
    timings["total_s"] = time.perf_counter() - clock

    with open(os.path.join(args.output_dir, "timings.json"), "w") as f:
        json.dump(timings, f, indent=2)
    report(timings)
    return 0


def report(timings):
    print(f"ranks {timings['ranks']}, OMP_NUM_THREADS {timings['omp_num_threads'] or 'unset'}")
    print(f"{'stage':>8} {'rank':>4} {'specimens':>9} {'load s':>8} {'map s':>8} {'average s':>9} {'total s':>8}")
    for s in timings["stages"]:
        print(f"{s['name']:>8} {s['rank']:>4} {s['specimens']:>9} {s['load_s']:8.2f} {s['map_s']:8.2f} "
              f"{s['average_s']:9.2f} {s['total_s']:8.2f}")
    for key, label in (("stage_averages_s", "stage averages (all ranks, wall)"),
                       ("gather_s", "gather (wait for the other ranks)"),
                       ("final_map_s", f"final map ({timings.get('final_map_threads') or 'default'} threads)"),
                       ("interpolation_s", f"interpolation ({timings['frames']} frames)"),
                       ("pictures_s", "pictures"), ("total_s", "total")):
        print(f"{label:<40} {timings[key]:8.2f} s")


def main(argv=None):
    args = parse_args(argv)
    comm = communicator(args)
    if comm is None:
        return 0
    if comm.rank == 0:
        os.makedirs(args.output_dir, exist_ok=True)
    try:
        return run(args, comm)
    except surfacemaps.InputError as e:
        print(f"heart_tube_pipeline: error: {e}", file=sys.stderr)
        return 2
    except surfacemaps.MapError as e:
        print(f"heart_tube_pipeline: no certified map: {e}", file=sys.stderr)
        return 3
    finally:
        finish(comm)


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


if __name__ == "__main__":
    sys.exit(main())
