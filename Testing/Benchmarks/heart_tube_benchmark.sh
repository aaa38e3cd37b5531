#!/usr/bin/env bash
# The heart-tube example (Wrapping/Python/examples/heart_tube_pipeline.py, a
# thin call of `python3 -m surfacemaps.population`) at full size, by default 10 stages x 5 synthetic specimens with the filter's
# default schedule: once as one process (OpenMP on all cores) and once with
# `mpirun -n 2` (one OpenMP thread per rank), then a table of the wall time
# of every step and every stage for both runs (also written to
# OUTPUT/report.md). Run it on an otherwise idle machine.
#
#   bash Testing/Benchmarks/heart_tube_benchmark.sh [OUTPUT] [-- EXAMPLE OPTIONS]
#
# e.g. `bash Testing/Benchmarks/heart_tube_benchmark.sh /tmp/ht -- --quick` for
# a check in seconds. Default OUTPUT: build/benchmarks/heart_tube. A run with
# the default series (no EXAMPLE OPTIONS) also refreshes the README's pictures
# Testing/Benchmarks/images/heart_tube_<picture>.png (stage means, frames,
# spread, mode 1, explained variance, scores).
# Environment:
#   SURFACEMAPS_BUILD_DIR   the build directory (default build)
#   SURFACEMAPS_MPI_RANKS   ranks of the MPI run (default 2; 0 skips it)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${SURFACEMAPS_BUILD_DIR:-build}
out=build/benchmarks/heart_tube
if [ $# -gt 0 ] && [ "$1" != "--" ]; then out=$1; shift; fi
[ "${1:-}" = "--" ] && shift
ranks=${SURFACEMAPS_MPI_RANKS:-2}

package=$(find "$build/lib" -maxdepth 4 -type d -name surfacemaps -path "*-packages/*" 2>/dev/null | head -n 1)
[ -n "$package" ] || { echo "build first: bash .ci/build.sh (or set SURFACEMAPS_BUILD_DIR)" >&2; exit 2; }
export PYTHONPATH=$(cd "$(dirname "$package")" && pwd)
python=/usr/bin/python3
example=Wrapping/Python/examples/heart_tube_pipeline.py

# Without a display the surface pictures go to an Xvfb the module starts itself.
mkdir -p "$out"
echo "== one process (OMP_NUM_THREADS=${OMP_NUM_THREADS:-all cores})" >&2
"$python" "$example" --output-dir "$out/serial" "$@"

if [ "$ranks" -gt 0 ]; then
  command -v mpirun > /dev/null || { echo "mpirun not found: apt-get install openmpi-bin python3-mpi4py" >&2; exit 2; }
  echo "== mpirun -n $ranks (one OpenMP thread per rank)" >&2
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 \
    mpirun --oversubscribe -n "$ranks" "$python" "$example" --output-dir "$out/mpi" "$@"
fi

if [ $# -eq 0 ]; then
  for picture in stage_means frames spread mode_1 explained_variance scores; do
    if [ -f "$out/serial/pictures/$picture.png" ]; then
      cp "$out/serial/pictures/$picture.png" "Testing/Benchmarks/images/heart_tube_$picture.png"
    fi
  done
fi

"$python" - "$out" << 'EOF'
import json, os, sys
out = sys.argv[1]
runs = [(label, json.load(open(os.path.join(out, d, "report.json"))))
        for label, d in (("1 process", "serial"), ("MPI", "mpi")) if os.path.exists(os.path.join(out, d, "report.json"))]
labels = [f"{label} ({t['ranks']} rank{'s' if t['ranks'] > 1 else ''})" if label == "MPI" else label for label, t in runs]
lines = ["| step | " + " | ".join(labels) + " |", "|---|" + "---:|" * len(runs)]
first = runs[0][1]
for s in first["stages"]:
    cells = []
    for _, t in runs:
        r = next(x for x in t["stages"] if x["stage"] == s["stage"])
        cells.append(f"{r['total_s']:.1f} s (map {r['map_s']:.1f}, rank {r['rank']})")
    lines.append(f"| {s['name']}: {s['specimens']} specimens, {min(s['specimen_vertices'])}-"
                 f"{max(s['specimen_vertices'])} vertices -> mean {s['mean_vertices']}, spread {s['spread_rms']:.3f} | " + " | ".join(cells) + " |")
for key, label in (("stage_maps_s", "all stage maps and means"), ("final_map_s", "final map of the means"),
                   ("statistics_s", "statistics over all specimens"),
                   ("interpolation_s", "interpolation + writing the series"), ("pictures_s", "pictures"),
                   ("total_s", "total")):
    lines.append(f"| {label} | " + " | ".join(f"{t['timings'][key]:.1f} s" for _, t in runs) + " |")
fractions = ", ".join(f"{100 * f:.1f} %" for f in first["statistics"]["explained_fractions"])
lines.append(f"\nExplained variance over {first['statistics']['specimens']} specimens: {fractions}.")
lines.append(f"\n{len(first['stages'])} stages, final triangulation {first['common_vertices']} vertices, "
             f"{first['frames']} frames.")
text = "\n".join(lines) + "\n"
open(os.path.join(out, "report.md"), "w").write(text)
print(text)
EOF
