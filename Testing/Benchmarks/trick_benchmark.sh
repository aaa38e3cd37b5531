#!/usr/bin/env bash
# Measures what each hand-written parallel or memory trick of the engine
# saves: builds `surfacemap` from the committed sources (HEAD) as they are
# and once per patch in Testing/Benchmarks/tricks/ (each patch turns one
# trick off: a trick stays only with its patch, and only while the corpus
# shows it saves 5 % or more; the patches of the tricks that did not are
# gone with them, their figures in the benchmark document), then times them on the benchmark corpus in one interleaved run
# (interleaved_corpus.py), and times the block solves for many inputs
# (--block-solve-inputs, a setting: no build of its own) against direct
# solves on four-legged animal populations. The tables say, per variant, the
# corpus total as a ratio to HEAD's and whether its maps are HEAD's bit for
# bit.
#
#   bash Testing/Benchmarks/trick_benchmark.sh WORK [CXXFLAGS] [ROUNDS] [BASE]
#
# WORK: a new or earlier work folder (sources, builds, maps, the report
# WORK/report.md); CXXFLAGS: e.g. -march=native (default none); ROUNDS:
# interleaved rounds (default 2); BASE: a commit to time beside HEAD in the
# same run (built the same way, labelled base-BASE). Needs ../shared (the corpus and
# ../shared/data/fourleg). Run it on an otherwise idle machine; with ccache
# configured (CMAKE_CXX_COMPILER_LAUNCHER from the environment is passed on),
# the variants' builds compile only the files their patches touch.
set -euo pipefail
shopt -s nullglob
cd "$(dirname "$0")/../.."
root=$PWD
work=${1:?usage: trick_benchmark.sh WORK [CXXFLAGS] [ROUNDS] [BASE]}
flags=${2:-}
rounds=${3:-2}
base=${4:-}
mkdir -p "$work"
work=$(cd "$work" && pwd)
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi

build_variant() { # name [patch [commit]]
  local name=$1 patch=${2:-} commit=${3:-HEAD} src=$work/$1/src
  rm -rf "$src"
  mkdir -p "$src"
  git -C "$root" archive "$commit" | tar -x -C "$src"
  if [ -n "$patch" ]; then
    patch -s -d "$src" -p1 < "$patch"
  fi
  cmake -S "$src" -B "$work/$name/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS="$flags" -DBUILD_TESTING=OFF -DSURFACEMAPS_BENCHMARKS=OFF \
    -DSURFACEMAPS_WRAP_PYTHON=OFF -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" > "$work/$name/configure.txt"
  cmake --build "$work/$name/build" --target surfacemap > "$work/$name/build.txt"
}

builds=(--build "head=$work/head/build")
build_variant head
for patch in Testing/Benchmarks/tricks/*.patch; do
  name=$(basename "$patch" .patch)
  build_variant "$name" "$root/$patch"
  builds+=(--build "$name=$work/$name/build")
done
if [ -n "$base" ]; then
  build_variant "base-$base" "" "$base"
  builds+=(--build "base-$base=$work/base-$base/build")
fi

report=$work/report.md
{
  echo "# Tricks on and off: $(git -C "$root" rev-parse --short HEAD), CXXFLAGS '${flags}', ${rounds} rounds"
  echo
  echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
  echo
  echo "## The corpus"
  echo
} > "$report.tmp"
/usr/bin/python3 Testing/Benchmarks/interleaved_corpus.py "${builds[@]}" --rounds "$rounds" \
  --work "$work/maps" -o "$work/corpus.md"
cat "$work/corpus.md" >> "$report.tmp"
{
  echo
  echo "## Populations: block solves (the default) against direct solves"
  echo
} >> "$report.tmp"
/usr/bin/python3 Testing/Benchmarks/interleaved_corpus.py --pairs none --population-sizes 4,8 \
  --build "head=$work/head/build" --build "direct-solves=$work/head/build" \
  --variant-args "direct-solves=--block-solve-inputs 0" --rounds "$rounds" \
  --work "$work/population" -o "$work/population.md"
cat "$work/population.md" >> "$report.tmp"
mv "$report.tmp" "$report"
echo "written to $report"
