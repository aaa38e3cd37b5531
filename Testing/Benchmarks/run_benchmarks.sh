#!/usr/bin/env bash
# Runs the benchmarks and writes one Markdown report (default
# build/benchmarks/report.md): the engine benchmark, the sphere embedding on
# the bundled meshes and, when ../shared/data exists, on the larger real
# meshes, then the surface map cases (surfacemap map with the default
# schedule, landmarks kept, timed for wall time and peak memory, then
# surfacemap evaluate): Data/ ellipsoid <-> blob always, and with
# ../shared/data shrec 61 <-> 248 and hand plain <-> vulcan, each with the
# reference implementation's figures beside ours. Also the README pictures in
# Testing/Benchmarks/images (map_*.png) from 61 <-> 248, or from the Data/
# pair when that case did not run. With ../shared/corpus.json, the corpus case
# maps every corpus pair and tabulates it beside the reference implementation's
# figures (Testing/Benchmarks/corpus_report.py). Run it on an otherwise idle
# machine; the figures in the README's performance section come from it.
#
#   bash Testing/Benchmarks/run_benchmarks.sh [REPORT.md]
#
# Environment:
#   SURFACEMAPS_BENCHMARK_CASES  which parts to run, separated by commas or
#                                spaces: engine, embedding, data, shrec, hands,
#                                corpus (default all; e.g. "data" for a quick
#                                run, "corpus" for the corpus table alone)
#   SURFACEMAPS_BUILD_DIR        the build directory (default build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${SURFACEMAPS_BUILD_DIR:-build}
report=${1:-$build/benchmarks/report.md}
bin=$build/bin
[ -x "$bin/surfacemap" ] || { echo "build first: bash .ci/build.sh (or set SURFACEMAPS_BUILD_DIR)" >&2; exit 2; }

all_cases="engine embedding data shrec hands corpus"
cases=${SURFACEMAPS_BENCHMARK_CASES:-all}
[ "$cases" = all ] && cases=$all_cases
cases=${cases//,/ }
for c in $cases; do
  [[ " $all_cases " == *" $c "* ]] || { echo "unknown benchmark case '$c' (known: $all_cases)" >&2; exit 2; }
done
wanted() { [[ " $cases " == *" $1 "* ]]; }
shared=../shared/data
for c in shrec hands corpus; do
  if wanted "$c" && [ ! -d "$shared" ]; then
    echo "note: $shared does not exist; skipping the $c case" >&2
  fi
done

mkdir -p "$(dirname "$report")"
export PYTHONPATH="$PWD/$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
python=/usr/bin/python3
pictures=Testing/Benchmarks/images
ran_maps=()

# map_case NAME TITLE A B LANDMARKS_A LANDMARKS_B: one map benchmark case in
# $build/benchmarks/map_NAME, its tables on stdout.
map_case() {
  local name=$1 title=$2 a=$3 b=$4 la=$5 lb=$6
  local work=$build/benchmarks/map_$name
  rm -rf "$work"
  mkdir -p "$work"
  # Wall time and peak RSS of the map process: GNU time, or Python's resource module without it.
  local timing=("$python" Testing/Benchmarks/map_report.py time "$work/time.txt" --)
  if [ -x /usr/bin/time ]; then
    timing=(/usr/bin/time -f "%e %M" -o "$work/time.txt")
  fi
  echo
  echo "## Map: $title"
  echo
  echo "\`surfacemap map $a $b --landmarks $la $lb --output-dir DIR\` (default schedule, landmarks kept),"
  echo "then \`surfacemap evaluate DIR\`."
  echo
  local status=0
  "${timing[@]}" "$bin/surfacemap" map "$a" "$b" --landmarks "$la" "$lb" --output-dir "$work/map" --overwrite \
    > "$work/map.txt" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    echo "**surfacemap map failed (exit $status):**"
    echo '```'
    cat "$work/map.txt"
    echo '```'
    return 0
  fi
  "$bin/surfacemap" evaluate "$work/map" > "$work/evaluate.txt" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    echo "**surfacemap evaluate failed (exit $status):**"
    echo '```'
    cat "$work/evaluate.txt"
    echo '```'
    return 0
  fi
  "$python" Testing/Benchmarks/map_report.py table "$name" "$work"
  echo
  echo '```'
  cat "$work/map.txt" "$work/evaluate.txt"
  echo '```'
  ran_maps+=("$name")
}

{
  echo "# SurfaceMaps benchmarks"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown), cases: $cases"
  if wanted engine; then
    echo
    "$bin/BenchmarkEngine" --repeat 40
    echo
    echo "With nested-dissection ordering (\`--nested-dissection\`):"
    echo
    "$bin/BenchmarkEngine" --repeat 40 --nested-dissection | grep -E "^\| (full|of which)"
  fi
  if wanted embedding; then
    echo
    echo "## Sphere embedding, bundled meshes"
    echo
    "$bin/BenchmarkEmbedding" Data/ellipsoid.obj Data/blob.off Data/limbs.ply Data/spot.obj
    if [ -d "$shared" ]; then
      echo
      echo "## Sphere embedding, ../shared/data"
      echo
      "$bin/BenchmarkEmbedding" "$shared/shrec/61.off" "$shared/shrec/248.off" \
        "$shared/hand/hand_plain.obj" "$shared/hand/hand_vulcan.obj"
    fi
  fi
  if wanted data; then
    map_case data "Data/ellipsoid.obj <-> Data/blob.off (642 + 642 vertices, 4 landmarks)" \
      Data/ellipsoid.obj Data/blob.off Data/ellipsoid.pinned Data/blob.vts
  fi
  if wanted shrec && [ -d "$shared" ]; then
    map_case shrec "shrec 61.off <-> 248.off (5 400 + 11 790 vertices, 3 landmarks)" \
      "$shared/shrec/61.off" "$shared/shrec/248.off" "$shared/shrec/61.pinned" "$shared/shrec/248.pinned"
  fi
  if wanted hands && [ -d "$shared" ]; then
    map_case hands "hand_plain.obj <-> hand_vulcan.obj (3 202 + 6 094 vertices, hand_vulcan_0.pinned)" \
      "$shared/hand/hand_plain.obj" "$shared/hand/hand_vulcan.obj" \
      "$shared/hand/hand_plain.pinned" "$shared/hand/hand_vulcan_0.pinned"
  fi

  if wanted corpus && [ -f "$shared/../corpus.json" ]; then
    echo
    echo "## Corpus: every pair of ../shared/corpus.json, default settings"
    echo
    echo "Ours / the reference implementation's figures (corpus.json), \`surfacemap map\` with landmarks kept."
    echo
    "$python" Testing/Benchmarks/corpus_report.py --build "$build" --corpus "$shared/../corpus.json" ||
      echo "**Some corpus pair failed or was not certified (see $build/benchmarks/corpus).**"
  fi

  # README pictures: 61 <-> 248 when it ran, otherwise the Data/ pair.
  picture_case=""
  if [[ " ${ran_maps[*]} " == *" shrec "* ]]; then
    picture_case=shrec
  elif [[ " ${ran_maps[*]} " == *" data "* ]]; then
    picture_case=data
  fi
  if [ -n "$picture_case" ]; then
    dir=$build/benchmarks/map_$picture_case/map
    label="ellipsoid <-> blob"
    if [ "$picture_case" = shrec ]; then
      label="61 <-> 248"
    fi
    mkdir -p "$pictures"
    "$python" -m surfacemaps.plots "$dir/approximating_1_distortion_curve.csv" "$dir/exact_1_distortion_curve.csv" \
      --labels "approximating map T_A -> T_B" "exact map A -> A on B" \
      --title "Cumulative distortion, $label" -o "$pictures/map_curves.png"
    "$python" -m surfacemaps.render "$dir/approximating_1.vtp" --max 2 \
      -o "$pictures/map_distortion.png"
    "$python" -m surfacemaps.render "$dir/approximating_1.vtp" --checkerboard SourcePosition \
      -o "$pictures/map_checkerboard.png"
    "$python" -m surfacemaps.render "$dir/approximating_1.vtp" --checkerboard SourcePosition \
      --points-from "$dir/common_0.vtp" -o "$pictures/map_checkerboard_source.png"
    echo
    echo "Pictures in $pictures (map_curves, map_distortion, map_checkerboard, map_checkerboard_source) from the $label case."
  fi
} > "$report.tmp"
mv "$report.tmp" "$report"
echo "benchmark report written to $report; pictures in $pictures"
