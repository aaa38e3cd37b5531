"""Plots of SurfaceMaps results (matplotlib, no display needed).

Cumulative distortion curves, the way map quality is usually compared: for
each run, the fraction of the source's area whose distortion max(s1, 1/s2) is
below x, for x from 1 upwards (higher and further left is better).

From the command line::

    /usr/bin/python3 -m surfacemaps.plots run1/distortion_curve.csv \\
        run2/distortion_curve.csv --labels ours reference -o curves.png

The CSV files are those `surfacemap evaluate --output-dir` writes.
"""

import argparse
import csv
import os
import sys


def read_curve(path):
    """(distortion values, area fractions) from a distortion_curve.csv file."""
    xs, ys = [], []
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames is None or not {"distortion", "area_fraction_below"} <= set(reader.fieldnames):
            raise ValueError(f"{path}: not a distortion curve (columns distortion, area_fraction_below)")
        for row in reader:
            xs.append(float(row["distortion"]))
            ys.append(float(row["area_fraction_below"]))
    if not xs:
        raise ValueError(f"{path}: the curve has no points")
    return xs, ys


def plot_distortion_curves(curves, output, title="Cumulative distortion"):
    """Plot curves ({label: (xs, ys)}) into the PNG file `output` (written atomically)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4), dpi=120)
    for label, (xs, ys) in curves.items():
        ax.plot(xs, ys, label=label, linewidth=1.8)
    ax.set_xlabel("distortion max(s1, 1/s2)")
    ax.set_ylabel("area fraction below")
    ax.set_ylim(0.0, 1.02)
    ax.set_xlim(1.0, max(xs[-1] for xs, _ in curves.values()))
    ax.grid(True, alpha=0.3)
    ax.set_title(title)
    if len(curves) > 1:
        ax.legend(loc="lower right")
    fig.tight_layout()
    temporary = output + ".tmp.png"
    fig.savefig(temporary)
    plt.close(fig)
    os.replace(temporary, output)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m surfacemaps.plots", description=__doc__.split("\n\n")[1])
    parser.add_argument("curves", nargs="+", help="distortion_curve.csv files")
    parser.add_argument("--labels", nargs="+", help="one label per curve (default: the file's folder)")
    parser.add_argument("-o", "--output", required=True, help="PNG file to write")
    parser.add_argument("--title", default="Cumulative distortion")
    args = parser.parse_args(argv)
    if args.labels and len(args.labels) != len(args.curves):
        parser.error("--labels needs one label per curve")
    labels = args.labels or [os.path.basename(os.path.dirname(os.path.abspath(p))) or p for p in args.curves]
    try:
        curves = {label: read_curve(path) for label, path in zip(labels, args.curves)}
        plot_distortion_curves(curves, args.output, args.title)
    except (OSError, ValueError) as e:
        print(f"surfacemaps.plots: error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
