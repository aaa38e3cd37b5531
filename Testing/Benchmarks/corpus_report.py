"""Maps every pair of the benchmark corpus (../shared/corpus.json) with the
default settings and prints one Markdown table: per pair our figures beside
the reference implementation's recorded ones (whole-process time, T after the
landmark and coarse phases and at the end, approximating SD and a1.5, H per
input, exact-map SD, the fine and refine phases' Newton steps that stalled at
a kink), the ratios, and their geometric means over the corpus.

    /usr/bin/python3 Testing/Benchmarks/corpus_report.py [--build build]
        [--corpus ../shared/corpus.json] [--pairs NAME,...] [--work DIR] [-o REPORT.md]
        [--map-args "--mesh-weight 1 ..."]

Each pair runs `surfacemap map A B --landmarks LA LB --output-dir DIR` (the
default schedule, landmarks kept, plus any --map-args), timed by /usr/bin/time; the metrics are
those `surfacemap map` writes to report.json (DESIGN.md section 6). Run it on
an otherwise idle machine: the times are wall times of the whole process.
The last column lists the targets of issue 17 a pair misses (SD, a1.5 - 0.01,
H per input and exact SD against the reference's; T at most twice its size;
a tenth of its time). Exit code 0 when every pair mapped and certified, 1
otherwise.
"""

import argparse
import json
import math
import os
import shlex
import subprocess
import sys


def run_map(surfacemap, arguments, out):
    """Runs `surfacemap map ARGUMENTS --output-dir OUT/map --overwrite` timed by
    /usr/bin/time, its output in OUT/map.txt; returns (report.json dict or None,
    seconds, peak MB, error text)."""
    os.makedirs(out, exist_ok=True)
    timing = os.path.join(out, "time.txt")
    command = (["/usr/bin/time", "-f", "%e %M", "-o", timing, surfacemap, "map"] + arguments +
               ["--output-dir", os.path.join(out, "map"), "--overwrite"])
    with open(os.path.join(out, "map.txt"), "w") as log:
        status = subprocess.call(command, stdout=log, stderr=subprocess.STDOUT)
    seconds = peak = None
    try:
        with open(timing) as f:
            seconds, kilobytes = f.read().strip().splitlines()[-1].split()[:2]
            seconds, peak = float(seconds), float(kilobytes) / 1024.0
    except (OSError, ValueError, IndexError):
        pass
    if status != 0:
        return None, seconds, peak, f"surfacemap map exited with {status} (see {out}/map.txt)"
    with open(os.path.join(out, "map", "report.json")) as f:
        return json.load(f), seconds, peak, None


def run_pair(pair, shared, surfacemap, work, extra, swap=False):
    """Maps one pair (B onto A with `swap`); returns what run_map returns."""
    path = lambda key: os.path.join(shared, pair[key])
    first, second = ("b", "a") if swap else ("a", "b")
    return run_map(surfacemap, [path(first), path(second), "--landmarks", path("landmarks_" + first),
                                path("landmarks_" + second)] + extra, os.path.join(work, pair["name"]))


def ours(report, seconds, swap=False):
    """Our figures under the corpus' reference keys. A map of B onto A (`swap`)
    gives H per input in the corpus' order and SD (symmetric), but no a1.5 and
    exact map: those measure the other direction and are left out (None)."""
    phases = {p["name"]: p for p in report["phases"]}
    approximating, exact = report["approximating_map"][0], report["exact_map"][0]
    h = (approximating["HausdorffTarget"], approximating["HausdorffSource"]) if swap else \
        (approximating["HausdorffSource"], approximating["HausdorffTarget"])
    return {
        "seconds": seconds,
        "T_vertices_after_landmark_phase": phases.get("landmarks", {}).get("vertices"),
        "T_vertices_after_coarse_phase": phases.get("coarse", {}).get("vertices"),
        "vertices": report["common_triangulation"]["vertices"],
        "symmetric_dirichlet": approximating["SymmetricDirichlet"],
        "area_below_1.5": None if swap else approximating["AreaBelow1.5"],
        "hausdorff_input_to_T_a_pct": h[0],
        "hausdorff_input_to_T_b_pct": h[1],
        "exact_symmetric_dirichlet": None if swap else exact["SymmetricDirichlet"],
        "exact_area_below_1.5": None if swap else exact["AreaBelow1.5"],
        "certified": report["certificate"]["bijective"],
        # Newton steps a kink held back, over the fine and refine phases.
        "stalled": sum(p.get("stalled_iterations", 0) for p in report["phases"] if p["name"] in ("fine", "refine")),
        "optimised": sum(p["iterations"] for p in report["phases"] if p["name"] in ("fine", "refine")),
        "landmark_error": report["landmark_error"],
    }


def write_report(path, text):
    """Writes `text` to `path` through a temporary file beside it, so that a
    report is either the old one or the new one, never half-written."""
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def number(value, digits=4):
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.{digits}g}" if abs(value) < 1e4 else f"{value:.0f}"
    return str(value)


def missed_targets(mine, reference):
    """The Done-when targets of issue 17 this pair misses (of those measured)."""
    missed = []
    if mine["symmetric_dirichlet"] > reference["symmetric_dirichlet"]:
        missed.append("SD")
    if mine["area_below_1.5"] is not None and mine["area_below_1.5"] < reference["area_below_1.5"] - 0.01:
        missed.append("a1.5")
    for side in ("a", "b"):
        key = f"hausdorff_input_to_T_{side}_pct"
        if mine[key] > reference[key]:
            missed.append("H " + side.upper())
    if mine["exact_symmetric_dirichlet"] is not None and \
            mine["exact_symmetric_dirichlet"] > reference["exact_symmetric_dirichlet"]:
        missed.append("exact SD")
    if mine["vertices"] > 2 * reference["vertices"]:
        missed.append("T")
    if mine["seconds"] is None or mine["seconds"] > reference["seconds"] / 10:
        missed.append("time")
    if not mine["certified"]:
        missed.append("certificate")
    return ", ".join(missed) or "none"


def pair_row(name, mine, reference):
    """One table row: ours / reference for every figure, and the ratios that decide."""
    def both(key, digits=4):
        return f"{number(mine.get(key), digits)} / {number(reference.get(key), digits)}"
    speedup = reference["seconds"] / mine["seconds"] if mine.get("seconds") else None
    cells = [
        name,
        f"{number(mine['seconds'], 3)} / {number(reference['seconds'], 4)} ({number(speedup, 3)}x)",
        f"{number(mine['T_vertices_after_landmark_phase'])} / {number(reference.get('T_vertices_after_landmark_phase'))}, "
        f"{number(mine['T_vertices_after_coarse_phase'])} / {number(reference.get('T_vertices_after_coarse_phase'))}, "
        f"{both('vertices')} ({number(mine['vertices'] / reference['vertices'], 3)}x)",
        both("symmetric_dirichlet"),
        both("area_below_1.5", 3),
        f"{both('hausdorff_input_to_T_a_pct', 3)}; {both('hausdorff_input_to_T_b_pct', 3)}",
        both("exact_symmetric_dirichlet"),
        f"{mine['stalled']} / {mine['optimised']}",
        "yes" if mine["certified"] else "NO",
        missed_targets(mine, reference),
    ]
    return "| " + " | ".join(cells) + " |"


def geometric_mean(values):
    values = [v for v in values if v and v > 0]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else None


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default="build", help="build directory with bin/surfacemap")
    parser.add_argument("--corpus", default="../shared/corpus.json")
    parser.add_argument("--pairs", help="comma-separated pair names (default: all)")
    parser.add_argument("--work", help="where the maps go (default BUILD/benchmarks/corpus)")
    parser.add_argument("-o", "--output", help="also write the table to this Markdown file")
    parser.add_argument("--map-args", default="", help="extra `surfacemap map` options for every pair (experiments)")
    parser.add_argument("--swap", action="store_true",
                        help="map B onto A instead (another optimisation path: a second sample of each pair; "
                             "a1.5 and the exact map then measure the other direction and are not reported)")
    args = parser.parse_args(argv)

    surfacemap = os.path.join(args.build, "bin", "surfacemap")
    if not os.access(surfacemap, os.X_OK):
        print(f"no {surfacemap}: build first (bash .ci/build.sh)", file=sys.stderr)
        return 2
    with open(args.corpus) as f:
        corpus = json.load(f)
    shared = os.path.dirname(os.path.abspath(args.corpus))
    wanted = set(args.pairs.split(",")) if args.pairs else None
    pairs = [p for p in corpus["pairs"] if wanted is None or p["name"] in wanted]
    if wanted and len(pairs) != len(wanted):
        print(f"unknown pairs: {sorted(wanted - {p['name'] for p in pairs})}", file=sys.stderr)
        return 2
    work = args.work or os.path.join(args.build, "benchmarks", "corpus")

    lines = [
        "| pair | time ours / ref (speed-up) | T after landmarks, coarse, end: ours / ref (end ratio) "
        "| SD | a1.5 | H A; H B (%) | exact SD | stalled / fine+refine iterations | certified | targets missed |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    sd_ratios, exact_ratios, speedups, size_ratios, failures = [], [], [], [], 0
    for pair in pairs:
        report, seconds, peak, error = run_pair(pair, shared, surfacemap, work, shlex.split(args.map_args), args.swap)
        if error:
            lines.append(f"| {pair['name']} | {error} |||||||||")
            failures += 1
            continue
        mine, reference = ours(report, seconds, args.swap), pair["reference"]
        lines.append(pair_row(pair["name"], mine, reference))
        failures += not mine["certified"]
        sd_ratios.append(mine["symmetric_dirichlet"] / reference["symmetric_dirichlet"])
        if mine["exact_symmetric_dirichlet"] is not None:
            exact_ratios.append(mine["exact_symmetric_dirichlet"] / reference["exact_symmetric_dirichlet"])
        speedups.append(reference["seconds"] / seconds if seconds else None)
        size_ratios.append(mine["vertices"] / reference["vertices"])
        print(f"{pair['name']}: {number(seconds, 3)} s, peak {number(peak, 3)} MB, T {mine['vertices']}, "
              f"SD {mine['symmetric_dirichlet']:.4f} (ref {reference['symmetric_dirichlet']:.4f})",
              file=sys.stderr, flush=True)
    means = (f"Geometric means over {len(sd_ratios)} pairs: SD ours / ref {number(geometric_mean(sd_ratios), 4)}, "
             f"exact SD ours / ref {number(geometric_mean(exact_ratios), 4)}, "
             f"T ours / ref {number(geometric_mean(size_ratios), 3)}, "
             f"speed-up {number(geometric_mean(speedups), 3)}x.")
    text = "\n".join(lines) + "\n\n" + means + "\n"
    print(text)
    if args.output:
        write_report(args.output, text)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
