#!/usr/bin/env python3
"""The heart-tube workflow on a developmental time series: a thin call of surfacemaps.population.

Input: groups of closed genus-0 surfaces, one group per developmental stage
(e.g. 51 mouse heart tubes in 10 stage groups). With --input-dir DIR every
subdirectory of DIR (sorted by name) is a stage and holds its specimens;
without it the specimens come from surfacemaps.synthetic (tubes that bend and
loop with time, several noisy specimens per stage with their own
triangulations and three landmarks: both tips and the outer curvature) and
are written to OUTPUT/specimens/stage_KK/ first.

Then ``surfacemaps.population`` does the work (see ``python3 -m
surfacemaps.population --help``): per stage one map and the order-free mean
with its spread, one map across the stage means, shape statistics over all
specimens lifted onto it, the interpolated series, pictures and report.json.

    python3 heart_tube_pipeline.py --output-dir out            # 10 stages x 5 specimens
    python3 heart_tube_pipeline.py --quick --output-dir out    # small, seconds
    mpirun -n 2 python3 heart_tube_pipeline.py --output-dir out

Under MPI the stages are spread over the ranks (mpi4py); every rank runs one
OpenMP thread (OMP_NUM_THREADS=1 unless set). Pictures of surfaces need a
display; on a headless machine a virtual one (Xvfb) is started, or pass
--no-pictures. Exit codes: 0 ok, 2 bad usage or input, 3 no certified map,
1 other errors.
"""

import os
import sys

# One OpenMP thread per MPI rank: must be set before the library starts its threads.
if int(os.environ.get("OMPI_COMM_WORLD_SIZE", os.environ.get("PMI_SIZE", "1"))) > 1:
    os.environ.setdefault("OMP_NUM_THREADS", "1")

import argparse  # noqa: E402

import surfacemaps  # noqa: E402
from surfacemaps import population, synthetic  # noqa: E402

QUICK = dict(stages=2, specimens=2, resolution=10, target_error=5e-3, landmark_iterations=10, coarse_iterations=3,
             fine_iterations=3, steps_per_interval=4)
DEFAULTS = dict(stages=10, specimens=5, resolution=20, target_error=2e-3, landmark_iterations=None,
                coarse_iterations=None, fine_iterations=None, steps_per_interval=10)


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n", 1)[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--output-dir", required=True, help="where the results go (created)")
    p.add_argument("--input-dir", help="read the stages from DIR's subdirectories instead of generating them")
    p.add_argument("--quick", action="store_true",
                   help="small version for tests: 2 stages x 2 coarse specimens, short schedules "
                        "(explicit options still win)")
    g = p.add_argument_group("synthetic specimens")
    g.add_argument("--stages", type=int, help="number of stages (default 10)")
    g.add_argument("--specimens", type=int, help="specimens per stage (default 5)")
    g.add_argument("--resolution", type=int, help="vertices around the tube (default 20; +-25%% per specimen)")
    g.add_argument("--seed", type=int, default=0, help="seed of the series (default 0)")
    g = p.add_argument_group("passed to surfacemaps.population")
    g.add_argument("--target-error", type=float, help="approximation error, unit-area units (default 2e-3)")
    g.add_argument("--landmark-iterations", type=int)
    g.add_argument("--coarse-iterations", type=int)
    g.add_argument("--fine-iterations", type=int)
    g.add_argument("--steps-per-interval", type=int, help="frames per stage interval (default 10)")
    args, rest = p.parse_known_args(argv)
    for name, value in DEFAULTS.items():
        if getattr(args, name) is None:
            setattr(args, name, QUICK[name] if args.quick else value)
    if args.stages < 1 or args.specimens < 1:
        p.error("--stages and --specimens are at least 1")
    return args, rest


def write_specimens(args, directory):
    """The synthetic series as stage_KK/specimen_II.vtp; the stage times."""
    times = []
    for k in range(args.stages):
        t, meshes = synthetic.stage_specimens(k, args.stages, args.specimens, seed=args.seed,
                                              resolution=args.resolution)
        times.append(t)
        for i, mesh in enumerate(meshes):
            surfacemaps.write_mesh(mesh, os.path.join(directory, f"stage_{k:02d}", f"specimen_{i:02d}.vtp"))
    return times


def main(argv=None):
    args, rest = parse_args(argv)
    comm = population.communicator("--no-mpi" in rest)
    if comm is None:
        return 0
    stages_dir, times = args.input_dir, None
    if stages_dir is None:
        stages_dir = os.path.join(args.output_dir, "specimens")
        # Rank 0 writes the files; the broadcast holds the other ranks until they exist.
        times = comm.bcast(write_specimens(args, stages_dir) if comm.rank == 0 else None, root=0)
    command = [stages_dir, "--output-dir", args.output_dir, "--steps-per-interval", str(args.steps_per_interval),
               "--target-error", str(args.target_error)]
    for option in ("landmark_iterations", "coarse_iterations", "fine_iterations"):
        if getattr(args, option) is not None:
            command += ["--" + option.replace("_", "-"), str(getattr(args, option))]
    if times is not None and "--stage-times" not in rest:
        command += ["--stage-times"] + [repr(t) for t in times]
    return population.main(command + rest, comm=comm)


if __name__ == "__main__":
    sys.exit(main())
