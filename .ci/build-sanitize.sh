#!/usr/bin/env bash
# The sanitizer stage of .ci/run: builds SurfaceMaps with AddressSanitizer and
# UndefinedBehaviorSanitizer (-DSURFACEMAPS_SANITIZE=ON) into ./build-sanitize
# and runs the tests labelled "sanitize": every C++ test (engine and filters),
# the reader fuzz test (Filters.ReaderFuzz) and the command-line tests
# (Testing/Python/test_cli_*.py driving the instrumented `surfacemap`).
#
# Not built here: the benchmarks and the Python package. A Python interpreter
# can only import an instrumented extension module with libasan preloaded
# (LD_PRELOAD), and then every allocation of the interpreter and of VTK's own
# Python modules runs through AddressSanitizer with leak reports about the
# interpreter's lifetime objects; the parts of the command-line tests that
# import `surfacemaps` in-process skip themselves under
# SURFACEMAPS_SANITIZED=1 and run in the normal build.
#
# Suppressions (with a reason per entry) are in CMake/Sanitizers/.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
cmake -S . -B build-sanitize -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DSURFACEMAPS_SANITIZE=ON \
  -DSURFACEMAPS_WRAP_PYTHON=OFF \
  -DSURFACEMAPS_BENCHMARKS=OFF \
  -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build-sanitize -j "$(nproc)" --target \
  surfacemap SurfaceMapsCoreTests SurfaceMapsFiltersTests SurfaceMapsReaderFuzz
built=$(date +%s)

suppressions="$PWD/CMake/Sanitizers"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=0:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$suppressions/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$suppressions/ubsan.supp"
export SURFACEMAPS_SANITIZED=1
ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)" -L sanitize
end=$(date +%s)
echo "sanitizer stage: build $((built - start)) s, tests $((end - built)) s, total $((end - start)) s"
