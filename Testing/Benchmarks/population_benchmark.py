"""Maps a population of four-legged animals (../shared/data/fourleg: SHREC 2007
meshes with 21 landmarks each) in one common triangulation with the
population preset, and prints Markdown tables: for N = 2, 4, 8, ... and all
meshes, the whole-process time (embeddings included), T, the Newton
iterations and time per iteration of the coarse and fine phases, the peak
memory; then, for the largest N, the per-phase times and per-pair figures
(approximating and exact SD of (0, i), H on input i).

    /usr/bin/python3 Testing/Benchmarks/population_benchmark.py [--build build]
        [--data ../shared/data/fourleg] [--sizes 2,4,8,14] [--work DIR] [-o REPORT.md]
        [--map-args "--block-solve-inputs 0 ..."]

Each run is `surfacemap map M_0 .. M_{N-1} --landmarks L_0 .. --preset
population --output-dir DIR` timed by /usr/bin/time (wall time and peak
resident memory of the whole process); the meshes are taken in file-name
order. Run it on an otherwise idle machine. Exit code 0 when every run
mapped, certified and kept its landmarks exact, 1 otherwise.
"""

import argparse
import glob
import os
import platform
import shlex
import sys

from corpus_report import run_map


def specimens(data):
    """(mesh, landmark file) of every mesh of DATA (MESH.off beside MESH.vts), in file-name order."""
    return [(m, m[:-4] + ".vts") for m in sorted(glob.glob(os.path.join(data, "*.off")))
            if os.path.exists(m[:-4] + ".vts")]


def population_arguments(meshes):
    """`surfacemap map`'s arguments for `meshes` (pairs of mesh and landmark file), population preset."""
    return [m for m, _ in meshes] + ["--landmarks"] + [l for _, l in meshes] + ["--preset", "population"]


def run_population(meshes, surfacemap, out, extra):
    """Maps `meshes` (pairs of mesh and landmark file); returns what corpus_report.run_map returns."""
    return run_map(surfacemap, population_arguments(meshes) + extra, out)


def defects(report):
    """What makes a run fail the benchmark: not certified, landmarks not exact."""
    found = []
    if not report["certificate"]["bijective"]:
        found.append("not certified")
    if report["landmark_error"] > 1e-12:
        found.append(f"landmark error {report['landmark_error']:.2e}")
    return found


def phase(report, name):
    return next((p for p in report["phases"] if p["name"] == name), None)


def per_iteration(report):
    """Seconds per coarse-and-fine iteration and their iteration count."""
    iterations = seconds = 0
    for name in ("coarse", "fine"):
        p = phase(report, name)
        if p:
            iterations += p["iterations"]
            seconds += p["seconds"]
    return (seconds / iterations if iterations else float("nan")), iterations


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.normpath(os.path.join(here, "..", ".."))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(root, "build"))
    parser.add_argument("--data", default=os.path.normpath(os.path.join(root, "..", "shared", "data", "fourleg")))
    parser.add_argument("--sizes", default="2,4,8,14")
    parser.add_argument("--work", default="/tmp/surfacemaps-population")
    parser.add_argument("--map-args", default="")
    parser.add_argument("-o", "--output")
    args = parser.parse_args(argv)

    surfacemap = os.path.join(args.build, "bin", "surfacemap")
    meshes = specimens(args.data)
    if len(meshes) < 2:
        print(f"population_benchmark: fewer than two meshes with landmarks in {args.data}", file=sys.stderr)
        return 1
    sizes = sorted({min(int(s), len(meshes)) for s in args.sizes.split(",") if s.strip()})
    extra = shlex.split(args.map_args)

    lines = [f"Machine: {platform.node()}, {os.cpu_count()} cores, {platform.processor() or platform.machine()}; "
             f"`surfacemap map ... --preset population {args.map_args}`".rstrip() + "; meshes of "
             f"{args.data} in file-name order.", "",
             "| N | time (s) | embeddings (s, sum over inputs) | T | coarse + fine iterations | "
             "s per iteration | s per iteration / N | peak memory (MB) | certified, landmarks exact |",
             "|---|---|---|---|---|---|---|---|---|"]
    failed = False
    largest = None
    for n in sizes:
        report, seconds, peak, error = run_population(meshes[:n], surfacemap, os.path.join(args.work, f"n{n}"),
                                                      extra)
        if report is None:
            lines.append(f"| {n} | {error} |")
            failed = True
            continue
        found = defects(report)
        failed = failed or bool(found)
        step, iterations = per_iteration(report)
        embedding = sum(i.get("embedding_seconds", 0.0) for i in report["inputs"])
        lines.append(f"| {n} | {seconds:.1f} | {embedding:.1f} | {report['common_triangulation']['vertices']} | "
                     f"{iterations} | {step:.3f} | {step / n:.4f} | {peak:.0f} | {', '.join(found) or 'yes'} |")
        largest = (n, report)

    if largest:
        n, report = largest
        lines += ["", f"N = {n}: phases (seconds; derivatives, solve, remeshing, line search)", "",
                  "| phase | iterations | T after | seconds | derivatives | solve | remeshing | line search |",
                  "|---|---|---|---|---|---|---|---|"]
        for p in report["phases"]:
            lines.append(f"| {p['name']} | {p['iterations']} | {p['vertices']} | {p['seconds']:.1f} | "
                         f"{p['derivative_seconds']:.1f} | {p['solve_seconds']:.1f} | {p['remesh_seconds']:.1f} | "
                         f"{p['line_search_seconds']:.1f} |")
        lines += ["", f"N = {n}: pairs (0, i) of the star, input 0 = {os.path.basename(meshes[0][0])}", "",
                  "| i | mesh | approximating SD | a1.5 | H on input i (%) | exact SD | exact max distortion |",
                  "|---|---|---|---|---|---|---|"]
        for approximating, exact in zip(report["approximating_map"], report["exact_map"]):
            i = approximating["target"]
            lines.append(f"| {i} | {os.path.basename(meshes[i][0])} | {approximating['SymmetricDirichlet']:.3f} | "
                         f"{approximating['AreaBelow1.5']:.3f} | {approximating['HausdorffTarget']:.2f} | "
                         f"{exact['SymmetricDirichlet']:.3f} | {exact['MaxDistortion']:.1f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
