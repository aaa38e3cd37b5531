"""Markdown tables of one map benchmark case, for run_benchmarks.sh.

    /usr/bin/python3 Testing/Benchmarks/map_report.py table CASE WORKDIR
        reads WORKDIR/map/report.json (surfacemap map), WORKDIR/map/summary.json
        (surfacemap evaluate) and WORKDIR/time.txt ("seconds peak-KB", as
        /usr/bin/time -f "%e %M" writes it) and prints the tables: time per
        phase, peak memory, T size, the DESIGN.md section 6 metrics of the
        approximating and the exact map, and the reference implementation's
        figures for the case where they are known (issue 5, DESIGN.md section 1).
    /usr/bin/python3 Testing/Benchmarks/map_report.py time FILE -- COMMAND...
        runs COMMAND and writes "seconds peak-KB" to FILE like /usr/bin/time
        (for machines without it); exits with COMMAND's exit code.

Standard library only.
"""

import json
import os
import resource
import subprocess
import sys
import time

# The reference implementation on the same 2-core machine (issue 5 and
# DESIGN.md section 1); None where no figure was published.
REFERENCE = {
    "shrec": {
        "seconds": {"total": 266, "embeddings": 33, "landmarks": 0.3, "coarse": 20, "fine": 213},
        "vertices": 2685,
        "approximating": {"SymmetricDirichlet": 1.241, "AreaBelow1.5": 0.78, "HausdorffSource": 0.25,
                          "HausdorffTarget": 0.47},
        "exact": {"SymmetricDirichlet": 1.283, "AreaBelow1.5": 0.78, "MaxDistortion": 38},
    },
    "hands": {
        "seconds": {"total": 328},
        "vertices": 3122,
        "approximating": {"SymmetricDirichlet": 1.046, "AreaBelow1.5": 0.99, "HausdorffSource": 0.19,
                          "HausdorffTarget": 0.31},
        "exact": {"SymmetricDirichlet": 1.047, "AreaBelow1.5": 0.99},
    },
}

PHASES = ("landmarks", "coarse", "fine")


def figure(value, digits=3):
    """A table cell: blank when unknown, otherwise `digits` significant digits (whole seconds stay whole)."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "yes" if value else "**no**"
    if isinstance(value, int):
        return f"{value:,}".replace(",", " ")
    if abs(value) < 1e-9:
        return "0"  # rounding residue of a distance that is 0
    return f"{value:.{digits}g}" if abs(value) < 10 ** digits else f"{value:.0f}"


def row(cells):
    return "| " + " | ".join(cells) + " |"


def read_time(path):
    """(seconds, peak MB) from a "seconds peak-KB" file (its last line), or (None, None)."""
    try:
        with open(path) as f:
            # /usr/bin/time puts "Command exited with non-zero status N" first on failure.
            seconds, kilobytes = f.read().strip().splitlines()[-1].split()[:2]
        return float(seconds), float(kilobytes) / 1024.0
    except (OSError, ValueError, IndexError):
        return None, None


def timing_table(report, seconds, peak_mb, reference):
    phases = {p["name"]: p for p in report["phases"]}
    embeddings = sum(i["embedding_seconds"] or 0.0 for i in report["inputs"])
    other = report["seconds"]["map"] - sum(p["seconds"] for p in report["phases"])
    header = ["", "whole process (s)", "map (s)", "embeddings (s)"]
    header += [f"{name} (s, iterations)" for name in PHASES]
    header += ["certify + lift (s)", "peak RSS (MB)", "T vertices", "certified"]
    ours = ["this run", figure(seconds), figure(report["seconds"]["total"]), figure(embeddings)]
    for name in PHASES:
        p = phases.get(name)
        ours.append("not run" if p is None else
                    f"{figure(p['seconds'])} ({p['iterations']}{'' if p['converged'] else ', cap'})")
    ours += [figure(other), figure(peak_mb), figure(report["common_triangulation"]["vertices"]),
             figure(report["certificate"]["bijective"])]
    lines = [row(header), row(["---"] * len(header)), row(ours)]
    if reference:
        s = reference["seconds"]
        theirs = ["reference implementation", "", figure(s.get("total")), figure(s.get("embeddings"))]
        theirs += [figure(s.get(name)) for name in PHASES]
        theirs += ["", "", figure(reference["vertices"]), ""]
        lines.append(row(theirs))
    return lines


def metrics_table(summary, reference):
    header = ["map", "SD", "a1.5", "a2", "max", "H A (%)", "H B (%)", "two-sided A / B (%)",
              "angles on A: min / mean min", "angles on B: min / mean min"]
    lines = [row(header), row(["---"] * len(header))]
    m = summary["maps"][0]
    names = {"approximating": "approximating T_A -> T_B", "exact": "exact A -> A on B"}
    for kind in ("approximating", "exact"):
        x = m[f"{kind}_map"]
        lines.append(row([
            names[kind], figure(x["SymmetricDirichlet"], 5), figure(x["AreaBelow1.5"]), figure(x["AreaBelow2"]),
            figure(x["MaxDistortion"]), figure(x["HausdorffSource"]), figure(x["HausdorffTarget"]),
            f"{figure(x['TwoSidedDistanceSource'])} / {figure(x['TwoSidedDistanceTarget'])}",
            f"{figure(x['MinAngleSource'])} / {figure(x['MeanMinAngleSource'])}",
            f"{figure(x['MinAngleTarget'])} / {figure(x['MeanMinAngleTarget'])}"]))
        if reference:
            r = reference[kind]
            lines.append(row([f"{kind}, reference implementation", figure(r.get("SymmetricDirichlet"), 5),
                              figure(r.get("AreaBelow1.5")), "", figure(r.get("MaxDistortion")),
                              figure(r.get("HausdorffSource")), figure(r.get("HausdorffTarget")), "", "", ""]))
    return lines


def table(case, workdir):
    with open(os.path.join(workdir, "map", "report.json")) as f:
        report = json.load(f)
    with open(os.path.join(workdir, "map", "summary.json")) as f:
        summary = json.load(f)
    seconds, peak_mb = read_time(os.path.join(workdir, "time.txt"))
    reference = REFERENCE.get(case)
    lines = timing_table(report, seconds, peak_mb, reference)
    lines.append("")
    lines += metrics_table(summary, reference)
    lines.append("")
    lines.append("Whole process: reading, validation, embeddings, map, certification, the metrics "
                 "`surfacemap map` prints and writing (wall clock); map: embeddings to certified "
                 "result; certify + lift: the map minus its phases. SD symmetric Dirichlet, a1.5 / a2 "
                 "area below distortion 1.5 / 2, H largest distance of an input vertex to the "
                 "approximation in % of the input's bounding-box diagonal (DESIGN.md section 6).")
    print("\n".join(lines))


def timed(path, command):
    start = time.monotonic()
    code = subprocess.call(command)
    seconds = time.monotonic() - start
    kilobytes = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # KB on Linux
    with open(path, "w") as f:
        f.write(f"{seconds:.2f} {kilobytes}\n")
    return code


def main(argv):
    if len(argv) == 3 and argv[0] == "table":
        table(argv[1], argv[2])
        return 0
    if len(argv) >= 4 and argv[0] == "time" and argv[2] == "--":
        return timed(argv[1], argv[3:])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
