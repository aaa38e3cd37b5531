#!/usr/bin/env bash
# Configures and builds the ParaView plugin (Release) into ./build-paraview,
# against Debian's ParaView 5.11 SDK (.ci/install-paraview.sh). The engine
# has no VTK in it, so when ./build holds the main build (.ci/build.sh) the
# plugin links its engine instead of compiling it again. Safe to re-run.
set -euo pipefail
cd "$(dirname "$0")/.."
engine=()
if [ -f build/SurfaceMapsEngineTargets.cmake ]; then
  engine=(-DSURFACEMAPS_ENGINE_BUILD_DIR="$PWD/build")
fi
cmake -S . -B build-paraview -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DSURFACEMAPS_PARAVIEW_PLUGIN=ON \
  "${engine[@]}"
cmake --build build-paraview -j "$(nproc)"
