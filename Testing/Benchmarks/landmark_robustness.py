"""Whether a map finds the right correspondence from wrong landmarks, and
without any: for each landmarked pair of the benchmark corpus (the hands and
the four-legs), wrong landmark sets made the way users get them wrong, each
mapped with the landmarks released after the landmark phase
(--release-landmarks), and the pair mapped without landmarks; then, for the
RIGHT landmarks, where the map sends them.

    /usr/bin/python3 Testing/Benchmarks/landmark_robustness.py [--build build]
        [--corpus ../shared/corpus.json] [--pairs hands,c393_394,...]
        [--work DIR] [--map-args "..."] [--landmark-index K]
        [--cases right,swap-near,...,none] [--guides] [-o REPORT.md]

A pair not in the corpus may be named A_B for the four-legs
data/fourleg/A.off and B.off with their .vts landmarks (e.g. 385_387).

The wrong sets change B's landmark K (default 0; A's stay right), chosen by
geometry so that any landmarked shape gets them:
  swap-near   K exchanged with the landmark nearest to it (the neighbouring
              finger or leg)
  on-near     K moved onto the neighbourhood of its nearest landmark (two
              landmarks on one finger)
  swap-far    K exchanged with the landmark farthest from it (front and hind
              exchanged)
  far-off     K moved to the vertex of B farthest from it (a slip of the hand)
plus "right" (the right landmarks, released: the baseline) and "none" (no
landmarks at all). With --guides the landmarks are checked against the
shapes and the confirmed ones locked (--landmarks-as-guides) instead.

Where a right landmark goes: its vertex on A is located on common_0 (T on A)
and carried to common_1 (T on B) with the same barycentric coordinates; the
distance to its right partner on B is given in % of B's bounding-box
diagonal. A case finds the correspondence when every right landmark lands
within 5 %. Run it on an otherwise idle machine (the times are wall times).
"""

import argparse
import json
import math
import os
import shlex
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus_report  # noqa: E402

from vtkmodules.vtkCommonCore import mutable  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkGenericCell, vtkStaticCellLocator  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402

FOUND = 5.0  # % of the bounding-box diagonal


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def landmark_vertices(path):
    """Vertex indices of a landmark file (one landmark per line, vertex first;
    .pinned/.txt and SHREC .vts), in file order: landmark k is line k."""
    with open(path) as f:
        return [int(line.split()[0]) for line in f if line.strip()]


def read_points(path):
    """The vertex positions of an OFF or OBJ mesh (enough for distances)."""
    points = []
    with open(path) as f:
        if path.endswith(".off"):
            words = f.read().split()
            start = 1 if words[0] == "OFF" else 0
            count = int(words[start])
            values = words[start + 3:start + 3 + 3 * count]
            return [tuple(float(v) for v in values[3 * i:3 * i + 3]) for i in range(count)]
        for line in f:
            if line.startswith("v "):
                points.append(tuple(float(v) for v in line.split()[1:4]))
    return points


def distance(p, q):
    return math.dist(p, q)


def diagonal(points):
    lo = [min(p[c] for p in points) for c in range(3)]
    hi = [max(p[c] for p in points) for c in range(3)]
    return distance(lo, hi)


def wrong_sets(b_points, landmarks, k):
    """name -> B's landmark vertices with landmark k made wrong (see the module doc)."""
    here = b_points[landmarks[k]]
    others = [j for j in range(len(landmarks)) if j != k]
    near = min(others, key=lambda j: distance(here, b_points[landmarks[j]]))
    far = max(others, key=lambda j: distance(here, b_points[landmarks[j]]))
    sets = {}
    swapped = list(landmarks)
    swapped[k], swapped[near] = swapped[near], swapped[k]
    sets["swap-near"] = swapped
    # The tenth-closest vertex to the near landmark: beside it, not on it.
    target = b_points[landmarks[near]]
    ranked = sorted(range(len(b_points)), key=lambda v: distance(target, b_points[v]))
    on_near = list(landmarks)
    on_near[k] = next(v for v in ranked[10:] if v not in landmarks)
    sets["on-near"] = on_near
    swapped = list(landmarks)
    swapped[k], swapped[far] = swapped[far], swapped[k]
    sets["swap-far"] = swapped
    far_off = list(landmarks)
    far_off[k] = max(range(len(b_points)), key=lambda v: distance(here, b_points[v]))
    sets["far-off"] = far_off
    return sets


def write_landmarks(path, vertices):
    with open(path, "w") as f:
        f.write("".join(f"{v}\n" for v in vertices))


def carried(common0, common1, locator, point):
    """`point` (near T on A) located on common_0 and carried to common_1."""
    closest, cell_id, sub_id, dist2 = [0.0, 0.0, 0.0], mutable(0), mutable(0), mutable(0.0)
    locator.FindClosestPoint(point, closest, vtkGenericCell(), cell_id, sub_id, dist2)
    cell = common0.GetCell(int(cell_id))
    weights, pcoords, found, d2 = [0.0] * 3, [0.0] * 3, [0.0] * 3, mutable(0.0)
    cell.EvaluatePosition(closest, found, mutable(0), pcoords, d2, weights)
    ids = [cell.GetPointId(i) for i in range(3)]
    return tuple(sum(weights[i] * common1.GetPoint(ids[i])[c] for i in range(3)) for c in range(3))


def right_landmark_errors(map_dir, a_points, b_points, right_a, right_b):
    """% of B's diagonal from each right landmark's image to its partner."""
    common0 = read_vtp(os.path.join(map_dir, "common_0.vtp"))
    common1 = read_vtp(os.path.join(map_dir, "common_1.vtp"))
    locator = vtkStaticCellLocator()
    locator.SetDataSet(common0)
    locator.BuildLocator()
    scale = diagonal(b_points)
    return [100.0 * distance(carried(common0, common1, locator, a_points[va]), b_points[vb]) / scale
            for va, vb in zip(right_a, right_b)]


def pair_files(corpus, name):
    """The corpus pair `name`, or the four-legs pair A_B of data/fourleg."""
    if name in corpus:
        return corpus[name]
    a, b = name.split("_")
    return {"a": f"data/fourleg/{a}.off", "b": f"data/fourleg/{b}.off",
            "landmarks_a": f"data/fourleg/{a}.vts", "landmarks_b": f"data/fourleg/{b}.vts"}


def run_case(surfacemap, a, b, landmarks, out, extra, guides):
    handling = ["--landmarks-as-guides"] if guides else ["--release-landmarks"]
    arguments = [a, b] + (["--landmarks"] + landmarks + handling if landmarks else []) + extra
    return corpus_report.run_map(surfacemap, arguments, out)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--corpus", default="../shared/corpus.json")
    parser.add_argument("--pairs", default="hands,c393_394,c396_397,c398_399")
    parser.add_argument("--work", default="/tmp/surfacemaps-landmark-robustness")
    parser.add_argument("--map-args", default="", help="extra `surfacemap map` options for every case")
    parser.add_argument("--landmark-index", type=int, default=0, help="the landmark K the wrong sets change")
    parser.add_argument("--cases", default="right,swap-near,on-near,swap-far,far-off,none",
                        help="the landmark sets to run, in this order")
    parser.add_argument("--guides", action="store_true",
                        help="the landmarks as guides (--landmarks-as-guides) instead of released")
    parser.add_argument("-o", "--output")
    args = parser.parse_args(argv)

    surfacemap = os.path.join(args.build, "bin", "surfacemap")
    with open(args.corpus) as f:
        corpus = {p["name"]: p for p in json.load(f)["pairs"]}
    shared = os.path.dirname(os.path.abspath(args.corpus))
    extra = shlex.split(args.map_args)
    lines = ["| pair | landmarks | right landmarks: median / max distance (% diagonal) | found (all <= 5 %) "
             "| certified | time (s) |", "|---|---|---|---|---|---|"]
    found_count = cases = 0
    for name in args.pairs.split(","):
        pair = pair_files(corpus, name)
        a, b = (os.path.join(shared, pair[key]) for key in ("a", "b"))
        right_a = landmark_vertices(os.path.join(shared, pair["landmarks_a"]))
        right_b = landmark_vertices(os.path.join(shared, pair["landmarks_b"]))
        a_points, b_points = read_points(a), read_points(b)
        work = os.path.join(args.work, name)
        os.makedirs(work, exist_ok=True)
        a_file = os.path.join(work, "a.pinned")
        write_landmarks(a_file, right_a)
        sets = {"right": right_b}
        sets.update(wrong_sets(b_points, right_b, args.landmark_index))
        sets["none"] = None
        for label in args.cases.split(","):
            b_landmarks = sets[label]
            landmarks = None
            if b_landmarks is not None:
                b_file = os.path.join(work, f"b_{label}.pinned")
                write_landmarks(b_file, b_landmarks)
                landmarks = [a_file, b_file]
            out = os.path.join(work, label)
            report, seconds, _, error = run_case(surfacemap, a, b, landmarks, out, extra, args.guides)
            cases += 1
            if error:
                lines.append(f"| {name} | {label} | {error} ||||")
                continue
            errors = right_landmark_errors(os.path.join(out, "map"), a_points, b_points, right_a, right_b)
            found = max(errors) <= FOUND
            found_count += found
            lines.append(f"| {name} | {label} | {statistics.median(errors):.2f} / {max(errors):.2f} | "
                         f"{'yes' if found else 'no'} | {'yes' if report['certificate']['bijective'] else 'NO'} | "
                         f"{seconds:.1f} |")
            print(lines[-1], file=sys.stderr, flush=True)
    text = "\n".join(lines) + f"\n\nFound in {found_count} of {cases} cases.\n"
    print(text)
    if args.output:
        corpus_report.write_report(args.output, text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
