"""How well a population map maps every specimen: the shared four-legged
animals (../shared/data/fourleg, 21 landmarks each) in one common
triangulation with the population preset, and per specimen the figures of
its pair with the first specimen beside those of the same pair mapped alone
with the pair preset (what is achievable); then how far the population's
mean moves when the specimens are given in other orders.

    /usr/bin/python3 Testing/Benchmarks/population_quality.py [--build build]
        [--data ../shared/data/fourleg] [--work DIR] [--map-args "..."]
        [--orders file,reversed,shifted] [--no-pairs] [-o REPORT.md]

Runs (each `surfacemap map`, timed by /usr/bin/time: whole process, peak
resident memory):
- the population in file-name order: `map M_0 .. M_{N-1} --landmarks ...
  --preset population MAP-ARGS`; input 0 is every measured pair's source
  (the preset's mean-shape pairing privileges none);
- each pair (0, i) alone at the defaults (the pair preset), kept in
  WORK/pairs and reused while the surfacemap binary and the arguments are
  the same (they do not depend on MAP-ARGS);
- the population again in each further order of --orders (reversed: the
  files backwards; shifted: starting at the middle file), and `surfacemap
  statistics` of every order's map; the mean's move is the distance between
  the means (vtkDistancePolyDataFilter both ways, in % of the file-order
  mean's bounding-box diagonal): the largest and the area-weighted mean.

Per specimen i (DESIGN.md section 6): the approximating map (common_0 ->
common_i) SD, a1.5 and H on i; the exact map (input 0 -> mapped_i) SD and
its maximum distortion; H on the centre (input 0 against common_0, the same
for every i); and the pair alone's approximating and exact SD and H. A row
meets issue 44's targets when exact SD <= 2 x approximating SD, exact SD <=
1.5 x the pair alone's, and H on i and on the centre <= 1 %. Run it on an
otherwise idle machine. Exit code 0 when every map certified, 1 otherwise.
"""

import argparse
import json
import os
import platform
import shlex
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus_report  # noqa: E402
from landmark_robustness import read_vtp  # noqa: E402
from population_benchmark import run_population, specimens  # noqa: E402

TARGETS = dict(exact_over_approximating=2.0, exact_over_alone=1.5, hausdorff=1.0)


def ordered(meshes, order):
    if order == "file":
        return list(meshes)
    if order == "reversed":
        return list(reversed(meshes))
    if order == "shifted":
        middle = len(meshes) // 2
        return meshes[middle:] + meshes[:middle]
    raise ValueError(f"unknown order {order!r} (file, reversed, shifted)")


def pair_alone(centre, other, surfacemap, work):
    """The pair (centre, other) at the defaults; reused from WORK while the binary and arguments are the same."""
    out = os.path.join(work, "pairs", os.path.splitext(os.path.basename(other[0]))[0])
    arguments = [centre[0], other[0], "--landmarks", centre[1], other[1]]
    binary = os.stat(surfacemap)
    stamp = json.dumps(dict(arguments=arguments, binary=[surfacemap, binary.st_size, binary.st_mtime]))
    stamp_path = os.path.join(out, "stamp.json")
    try:
        with open(stamp_path) as f, open(os.path.join(out, "map", "report.json")) as r:
            if f.read() == stamp:
                return json.load(r)
    except OSError:
        pass
    report, _, _, error = corpus_report.run_map(surfacemap, arguments, out)
    if report is None:
        raise RuntimeError(f"pair {os.path.basename(other[0])} alone: {error}")
    corpus_report.write_report(stamp_path, stamp)
    return report


def mean_shape(surfacemap, map_directory, out):
    """`surfacemap statistics MAPDIR`'s mean.vtp path."""
    with open(out + ".txt", "w") as log:
        status = subprocess.call([surfacemap, "statistics", map_directory, "--output-dir", out, "--modes", "1"],
                                 stdout=log, stderr=subprocess.STDOUT)
    if status != 0:
        raise RuntimeError(f"surfacemap statistics {map_directory} exited with {status} (see {out}.txt)")
    return os.path.join(out, "mean.vtp")


def mean_move(first, second):
    """(largest, area-weighted mean) distance between two surfaces, both ways, in % of the
    first one's bounding-box diagonal."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkFiltersCore import vtkCellDataToPointData
    from vtkmodules.vtkFiltersGeneral import vtkDistancePolyDataFilter
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
    meshes = [read_vtp(p) for p in (first, second)]
    bounds = np.array(meshes[0].GetBounds()).reshape(3, 2)
    diagonal = float(np.linalg.norm(bounds[:, 1] - bounds[:, 0]))
    largest, weighted, total = 0.0, 0.0, 0.0
    for a, b in ((meshes[0], meshes[1]), (meshes[1], meshes[0])):
        distance = vtkDistancePolyDataFilter()
        distance.SetInputData(0, a)
        distance.SetInputData(1, b)
        distance.SignedDistanceOff()
        distance.ComputeSecondDistanceOff()
        distance.Update()
        values = np.abs(vtk_to_numpy(distance.GetOutput().GetPointData().GetArray("Distance")))
        sizes = vtkCellSizeFilter()
        sizes.SetInputData(a)
        sizes.Update()
        to_points = vtkCellDataToPointData()
        to_points.SetInputConnection(sizes.GetOutputPort())
        to_points.Update()
        areas = vtk_to_numpy(to_points.GetOutput().GetPointData().GetArray("Area"))
        largest = max(largest, float(values.max()))
        weighted += float(np.dot(values, areas))
        total += float(areas.sum())
    return 100.0 * largest / diagonal, 100.0 * weighted / total / diagonal


def specimen_rows(meshes, report, alone):
    """The per-specimen table's rows and whether every row meets the targets."""
    centre_h = report["approximating_map"][0]["HausdorffSource"]
    rows, met = [], True
    for approximating, exact in zip(report["approximating_map"], report["exact_map"]):
        i = approximating["target"]
        pair = alone.get(i)
        a_sd, e_sd, h = approximating["SymmetricDirichlet"], exact["SymmetricDirichlet"], approximating["HausdorffTarget"]
        alone_sd = pair["exact_map"][0]["SymmetricDirichlet"] if pair else None
        ok = (e_sd <= TARGETS["exact_over_approximating"] * a_sd and h <= TARGETS["hausdorff"]
              and centre_h <= TARGETS["hausdorff"]
              and (alone_sd is None or e_sd <= TARGETS["exact_over_alone"] * alone_sd))
        met = met and ok
        alone_cells = ["-", "-", "-", "-"] if pair is None else [
            f"{pair['approximating_map'][0]['SymmetricDirichlet']:.3f}", f"{alone_sd:.3f}",
            f"{pair['approximating_map'][0]['HausdorffTarget']:.2f}", f"{e_sd / alone_sd:.2f}"]
        rows.append(f"| {i} | {os.path.basename(meshes[i][0])} | {a_sd:.3f} | {approximating['AreaBelow1.5']:.3f} | "
                    f"{e_sd:.3f} | {exact['MaxDistortion']:.1f} | {e_sd / a_sd:.2f} | {h:.2f} | {centre_h:.2f} | "
                    + " | ".join(alone_cells) + f" | {'yes' if ok else 'no'} |")
    return rows, met


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.normpath(os.path.join(here, "..", ".."))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(root, "build"))
    parser.add_argument("--data", default=os.path.normpath(os.path.join(root, "..", "shared", "data", "fourleg")))
    parser.add_argument("--work", default="/tmp/surfacemaps-population-quality")
    parser.add_argument("--map-args", default="", help="further settings of the population maps")
    parser.add_argument("--orders", default="file,reversed", help="orders of the specimens (file first)")
    parser.add_argument("--no-pairs", action="store_true", help="do not map the pairs alone")
    parser.add_argument("-o", "--output")
    args = parser.parse_args(argv)

    surfacemap = os.path.join(args.build, "bin", "surfacemap")
    meshes = specimens(args.data)
    if len(meshes) < 2:
        print(f"population_quality: fewer than two meshes with landmarks in {args.data}", file=sys.stderr)
        return 1
    extra = shlex.split(args.map_args)
    orders = args.orders.split(",")
    if orders[0] != "file":
        orders.insert(0, "file")

    runs = {}
    for order in orders:
        runs[order] = run_population(ordered(meshes, order), surfacemap, os.path.join(args.work, order), extra)
    report, seconds, peak, error = runs["file"]
    if report is None:
        print(f"population_quality: {error}", file=sys.stderr)
        return 1
    alone = {} if args.no_pairs else {i: pair_alone(meshes[0], meshes[i], surfacemap, args.work)
                                      for i in range(1, len(meshes))}

    certified = all(r[0] is not None and r[0]["certificate"]["bijective"] for r in runs.values())
    lines = [f"Machine: {platform.node()}, {os.cpu_count()} cores, {platform.processor() or platform.machine()}; "
             f"{len(meshes)} specimens of {args.data} in file-name order, `surfacemap map ... --preset population "
             f"{args.map_args}`".rstrip() + "`; the pairs alone at the defaults.", "",
             f"Whole process {seconds:.1f} s, peak {peak:.0f} MB, T {report['common_triangulation']['vertices']} "
             f"vertices, certified: {'yes' if certified else 'NO'}; landmark error {report['landmark_error']:.1e}.",
             "", "| i | specimen | approx. SD | a1.5 | exact SD | exact max dist. | exact / approx. | H on i (%) | "
             "H on centre (%) | alone: approx. SD | alone: exact SD | alone: H on i (%) | exact / alone | targets |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    rows, met = specimen_rows(meshes, report, alone)
    lines += rows
    if len(orders) > 1:
        lines += ["", "| order | time (s) | T | mean's move: largest (%) | area-weighted mean (%) |", "|---|---|---|---|---|"]
        means = {}
        for order, (r, s, _, e) in runs.items():
            if r is None:
                lines.append(f"| {order} | {e} |")
                continue
            means[order] = mean_shape(surfacemap, os.path.join(args.work, order, "map"),
                                      os.path.join(args.work, order, "statistics"))
            largest, average = (0.0, 0.0) if order == "file" else mean_move(means["file"], means[order])
            lines.append(f"| {order} | {s:.1f} | {r['common_triangulation']['vertices']} | {largest:.3f} | "
                         f"{average:.3f} |")
    lines += ["", f"Every specimen meets the targets: {'yes' if met else 'no'}."]
    text = "\n".join(lines) + "\n"
    print(text)
    if args.output:
        corpus_report.write_report(args.output, text)
    return 0 if certified else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
