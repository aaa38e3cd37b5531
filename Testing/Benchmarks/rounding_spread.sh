#!/usr/bin/env bash
# How much the map's quality depends on rounding: the shared benchmark pairs
# (shrec 61 <-> 248, hand plain <-> vulcan, landmarks kept, default schedule)
# mapped by BenchmarkMap from two builds of the same sources that round
# differently: the normal build and one with -march=native and
# SURFACEMAPS_PORTABLE_ARITHMETIC=OFF (FMA contractions, AVX-512 packets in
# Eigen; with the option on, the default, a native build computes the normal
# build's maps bit for bit). Each build is deterministic; a change to the
# optimisation should improve both rows of a pair, not one lucky path. Extra
# arguments go to BenchmarkMap (e.g. --coarse-barrier-weight 1e-2). Needs
# ../shared/data; run on an idle machine.
#
#   bash Testing/Benchmarks/rounding_spread.sh [BENCHMARKMAP OPTIONS]
#   bash Testing/Benchmarks/rounding_spread.sh --corpus [CORPUS_REPORT OPTIONS]
#
# With --corpus: every pair of ../shared/corpus.json mapped by `surfacemap map`
# (default settings) from both builds, each build's table beside the reference
# implementation's figures (Testing/Benchmarks/corpus_report.py), then the
# same with the inputs swapped (B onto A: two more optimisation paths, so four
# samples of each pair). Further options go to corpus_report.py, e.g.
# --map-args "--refinement-rounds 1" to measure a candidate default.
#
# Environment:
#   SURFACEMAPS_BUILD_DIR         the normal build (default build)
#   SURFACEMAPS_NATIVE_BUILD_DIR  the -march=native build without portable
#                                 arithmetic, configured and built here
#                                 (default build-native)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${SURFACEMAPS_BUILD_DIR:-build}
native=${SURFACEMAPS_NATIVE_BUILD_DIR:-build-native}
shared=../shared/data
[ -d "$shared" ] || { echo "$shared does not exist: nothing to measure" >&2; exit 2; }
[ -x "$build/bin/BenchmarkMap" ] || { echo "build first: bash .ci/build.sh" >&2; exit 2; }
# Configured every time: a tree made before SURFACEMAPS_PORTABLE_ARITHMETIC
# existed would otherwise take its default (on) and round like the normal one.
if [ -f "$native/CMakeCache.txt" ]; then
  cmake -S . -B "$native" -DSURFACEMAPS_PORTABLE_ARITHMETIC=OFF > /dev/null
else
  cmake -S . -B "$native" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-march=native \
    -DSURFACEMAPS_PORTABLE_ARITHMETIC=OFF -DBUILD_TESTING=OFF -DSURFACEMAPS_WRAP_PYTHON=OFF \
    -DPython3_EXECUTABLE=/usr/bin/python3 > /dev/null
fi
if [ "${1:-}" = --corpus ]; then
  shift
  cmake --build "$native" -j "$(nproc)" --target surfacemap > /dev/null
  status=0
  for order in "" --swap; do
    for b in "$build" "$native"; do
      echo "## $b ${order:+(B onto A)}"
      echo
      /usr/bin/python3 Testing/Benchmarks/corpus_report.py --build "$b" \
        --work "$b/benchmarks/corpus${order}" $order "$@" || status=1
    done
  done
  exit $status
fi
cmake --build "$native" -j "$(nproc)" --target BenchmarkMap > /dev/null

echo "| build | pair | approximating SD / a1.5 / max | exact SD / a1.5 / max | whole run |"
echo "|---|---|---|---|---|"
for b in "$build" "$native"; do
  for pair in shrec hands; do
    if [ $pair = shrec ]; then
      args=("$shared/shrec/61.off" "$shared/shrec/248.off" --landmarks
        "$shared/shrec/61.pinned" "$shared/shrec/248.pinned")
    else
      args=("$shared/hand/hand_plain.obj" "$shared/hand/hand_vulcan.obj" --landmarks
        "$shared/hand/hand_plain.pinned" "$shared/hand/hand_vulcan_0.pinned")
    fi
    out=$("$b/bin/BenchmarkMap" "${args[@]}" "$@" 2>&1)
    row() { echo "$out" | grep -E "^\| $1" | cut -d'|' -f3,4,6 | sed 's/ *| */ \/ /g; s/^ *//; s/ *$//'; }
    echo "| $b | $pair | $(row 'T_0 -> T_1') | $(row 'input 0 -> 1') | $(echo "$out" | grep -E '^total' | cut -d: -f1 | sed 's/total //') |"
  done
done
