#!/usr/bin/env bash
# The sanitizer stage of .ci/run: builds SurfaceMaps with AddressSanitizer and
# UndefinedBehaviorSanitizer (-DSURFACEMAPS_SANITIZE=ON) into ./build-sanitize
# and runs the tests labelled "sanitize": every C++ test (engine and filters),
# the reader fuzz test (Filters.ReaderFuzz) and the command-line tests
# (Testing/Python/test_cli_*.py driving the instrumented `surfacemap`).
#
# Not built here: the benchmarks and the Python package, so the Python
# package's own tests (Python.*) do not run under the sanitizers. An
# uninstrumented interpreter can import an instrumented extension module only
# with libasan preloaded (LD_PRELOAD), and then the interpreter's and VTK's
# Python modules' allocations all go through AddressSanitizer, whose leak
# check reports the interpreter's objects that live until exit; every
# `surfacemap` started from such a test would inherit the preload and the
# leak check would have to be off for them too. The command-line tests'
# helpers (reading and writing test meshes) use the package of the normal
# build in ./build (SURFACEMAPS_TEST_PYTHON_PACKAGE_DIR), so .ci/build.sh
# must have run first; the programs under test are the instrumented ones.
#
# Suppressions (with a reason per entry) are in CMake/Sanitizers/.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
package_init=$(find "$PWD/build/lib" -path '*/surfacemaps/__init__.py' -print -quit 2>/dev/null || true)
if [ -z "$package_init" ]; then
  echo "build-sanitize: run .ci/build.sh first (the command-line tests use build/'s Python package)" >&2
  exit 1
fi
cmake -S . -B build-sanitize -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DSURFACEMAPS_SANITIZE=ON \
  -DSURFACEMAPS_WRAP_PYTHON=OFF \
  -DSURFACEMAPS_BENCHMARKS=OFF \
  -DSURFACEMAPS_TEST_PYTHON_PACKAGE_DIR="$(dirname "$(dirname "$package_init")")" \
  -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build-sanitize -j "$(nproc)" --target \
  surfacemap SurfaceMapsCoreTests SurfaceMapsFiltersTests SurfaceMapsReaderFuzz
built=$(date +%s)

suppressions="$PWD/CMake/Sanitizers"
export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$suppressions/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$suppressions/ubsan.supp"
ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)" -L sanitize
end=$(date +%s)
echo "sanitizer stage: build $((built - start)) s, tests $((end - built)) s, total $((end - start)) s"
