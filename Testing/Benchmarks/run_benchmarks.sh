#!/usr/bin/env bash
# Runs every benchmark and writes one Markdown report (default
# build/benchmarks/report.md): the engine benchmark, then the sphere
# embedding on the bundled meshes and, when ../shared/data exists, on the
# larger real meshes. Run it on an otherwise idle machine; the figures in
# the README's performance section come from it.
#
#   bash Testing/Benchmarks/run_benchmarks.sh [REPORT.md]
set -euo pipefail
cd "$(dirname "$0")/../.."
report=${1:-build/benchmarks/report.md}
mkdir -p "$(dirname "$report")"
bin=build/bin
[ -x "$bin/BenchmarkEngine" ] || { echo "build first: bash .ci/build.sh" >&2; exit 2; }

{
  echo "# SurfaceMaps benchmarks"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo
  "$bin/BenchmarkEngine" --repeat 10
  echo
  echo "## Sphere embedding, bundled meshes"
  echo
  "$bin/BenchmarkEmbedding" Data/ellipsoid.obj Data/blob.off Data/limbs.ply Data/spot.obj
  shared=../shared/data
  if [ -d "$shared" ]; then
    echo
    echo "## Sphere embedding, ../shared/data"
    echo
    "$bin/BenchmarkEmbedding" "$shared/shrec/61.off" "$shared/shrec/248.off" \
      "$shared/hand/hand_plain.obj" "$shared/hand/hand_vulcan.obj"
  fi
  # Pictures for the README: the deformation pair ellipsoid -> blob (same
  # connectivity). They replace the pair 61 <-> 248 once the map exists.
  pictures=Testing/Benchmarks/images
  work=build/benchmarks/deformation
  mkdir -p "$pictures" "$work"
  echo
  echo "## Deformation pair Data/ellipsoid.obj -> Data/blob.off"
  echo
  echo '```'
  "$bin/surfacemap" evaluate Data/ellipsoid.obj Data/blob.off --output-dir "$work"
  echo '```'
  export PYTHONPATH="$PWD/build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
  xvfb=""
  [ -n "${DISPLAY:-}" ] || xvfb="xvfb-run -a"
  /usr/bin/python3 -m surfacemaps.plots "$work/distortion_curve.csv" --labels "ellipsoid -> blob" \
    -o "$pictures/deformation_curve.png"
  $xvfb /usr/bin/python3 -m surfacemaps.render "$work/evaluated.vtp" --max 2 \
    -o "$pictures/deformation_distortion.png"
} > "$report.tmp"
mv "$report.tmp" "$report"
echo "benchmark report written to $report; pictures in Testing/Benchmarks/images"
