"""Times several builds of `surfacemap` on the benchmark corpus in one
interleaved run, so that they share the machine's drift: each round maps
every pair with every build in turn (the builds' order rotating from pair to
pair and round to round), and the table compares each build's corpus total
with the first build's as a ratio (median over rounds), with its peak memory
and whether its maps are the first build's bit for bit (compare_maps.py).

    /usr/bin/python3 Testing/Benchmarks/interleaved_corpus.py
        --build LABEL=DIR [--build LABEL=DIR ...] [--rounds 2]
        [--corpus ../shared/corpus.json] [--pairs NAME,...] [--work DIR]
        [--map-args "..."] [--variant-args LABEL="..."]
        [--population-sizes 4,8] [--population-data DIR]
        [-o REPORT.md]

DIR is a build directory with bin/surfacemap (the first --build is the one
the others are compared with). With --population-sizes, each round also maps
the first N four-legged animals of --population-data in one population map
(`surfacemap map --preset population`, their landmarks kept) per size.
Run it on an otherwise idle machine.
"""

import argparse
import json
import os
import shlex
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_maps  # noqa: E402
import corpus_report  # noqa: E402
import population_benchmark  # noqa: E402


def population_cases(data, sizes):
    """(name, map arguments) per population size: the first N animals of
    DATA (sorted by name) with landmarks (MESH.off beside MESH.vts)."""
    meshes = population_benchmark.specimens(data)
    cases = []
    for n in sizes:
        if len(meshes) < n:
            raise SystemExit(f"{data} holds {len(meshes)} meshes with landmarks, fewer than {n}")
        cases.append((f"population_{n}", population_benchmark.population_arguments(meshes[:n])))
    return cases


def corpus_cases(corpus_path, pairs):
    """(name, map arguments) per corpus pair, as corpus_report.py maps them."""
    with open(corpus_path) as f:
        corpus = json.load(f)
    shared = os.path.dirname(os.path.abspath(corpus_path))
    wanted = set(pairs.split(",")) if pairs else None
    cases = []
    for pair in corpus["pairs"]:
        if wanted is None or pair["name"] in wanted:
            path = lambda key: os.path.join(shared, pair[key])  # noqa: E731
            cases.append((pair["name"], [path("a"), path("b"), "--landmarks", path("landmarks_a"),
                                         path("landmarks_b")]))
    return cases


def run_rounds(builds, cases, rounds, work, extra, variant_args):
    """seconds[label][case] and peak[label][case] as lists over rounds; the
    first error met per build and case, if any."""
    seconds = {label: {name: [] for name, _ in cases} for label, _ in builds}
    peak = {label: {name: [] for name, _ in cases} for label, _ in builds}
    errors = {}
    turn = 0
    for r in range(rounds):
        for name, arguments in cases:
            order = builds[turn % len(builds):] + builds[:turn % len(builds)]
            turn += 1
            for label, build in order:
                out = os.path.join(work, label, name)
                report, s, p, error = corpus_report.run_map(os.path.join(build, "bin", "surfacemap"),
                                                            arguments + extra + variant_args.get(label, []),
                                                            out)
                if error:
                    errors.setdefault((label, name), error)
                    continue
                seconds[label][name].append(s)
                peak[label][name].append(p)
                print(f"round {r + 1} {name} {label}: {s:.2f} s, {p:.0f} MB", file=sys.stderr, flush=True)
    return seconds, peak, errors


def table(builds, cases, seconds, peak, errors, work):
    first = builds[0][0]
    lines = ["| build | total of the cases, median of rounds (s) | / " + first + " | per case / " + first +
             " | peak MB | maps the same as " + first + " |",
             "|---|---|---|---|---|---|"]
    total = {}
    for label, _ in builds:
        rounds = min((len(v) for v in seconds[label].values()), default=0)
        per_round = [sum(seconds[label][name][r] for name, _ in cases) for r in range(rounds)]
        total[label] = statistics.median(per_round) if per_round else None
    for label, _ in builds:
        if total[label] is None or total[first] is None:
            lines.append(f"| {label} | failed: {sorted(errors.get(k) for k in errors if k[0] == label)} |||||")
            continue
        ratios = [f"{name} {statistics.median(seconds[label][name]) / statistics.median(seconds[first][name]):.3f}"
                  for name, _ in cases]
        same = all(not compare_maps.differences(os.path.join(work, first, name, "map"),
                                                os.path.join(work, label, name, "map")) for name, _ in cases)
        top = max(max(v) for v in peak[label].values())
        lines.append(f"| {label} | {total[label]:.1f} | {total[label] / total[first]:.3f} | {', '.join(ratios)} | "
                     f"{top:.0f} | {'yes' if same else 'NO'} |")
    return "\n".join(lines) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", action="append", required=True, help="LABEL=DIR, one per build")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--corpus", default="../shared/corpus.json")
    parser.add_argument("--pairs", help="comma-separated corpus pair names (default: all; 'none' for no pairs)")
    parser.add_argument("--population-sizes", default="", help="comma-separated population sizes (default: none)")
    parser.add_argument("--population-data", default="../shared/data/fourleg")
    parser.add_argument("--work", default="/tmp/surfacemaps-interleaved")
    parser.add_argument("--map-args", default="", help="extra `surfacemap map` options for every case")
    parser.add_argument("--variant-args", action="append", default=[],
                        help="LABEL=ARGS: extra `surfacemap map` options for one build's label only (a --build "
                             "may name the same DIR under two labels to compare a setting)")
    parser.add_argument("-o", "--output", help="also write the table to this Markdown file")
    args = parser.parse_args(argv)

    builds = []
    for item in args.build:
        label, _, build = item.partition("=")
        if not build or not os.access(os.path.join(build, "bin", "surfacemap"), os.X_OK):
            print(f"--build {item}: expected LABEL=DIR with DIR/bin/surfacemap", file=sys.stderr)
            return 2
        builds.append((label, build))
    cases = [] if args.pairs == "none" else corpus_cases(args.corpus, args.pairs)
    sizes = [int(n) for n in args.population_sizes.split(",") if n]
    cases += population_cases(args.population_data, sizes)
    variant_args = {}
    for item in args.variant_args:
        label, _, options = item.partition("=")
        variant_args[label] = shlex.split(options)
    seconds, peak, errors = run_rounds(builds, cases, args.rounds, args.work, shlex.split(args.map_args),
                                       variant_args)
    text = table(builds, cases, seconds, peak, errors, args.work)
    print(text)
    if args.output:
        corpus_report.write_report(args.output, text)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
