#!/usr/bin/env bash
# Configures and builds SurfaceMaps (Release) into ./build. Used by .ci/run and
# .ci/quickstart; safe to re-run (incremental).
set -euo pipefail
cd "$(dirname "$0")/.."
# Debian's VTK Python package belongs to /usr/bin/python3, not to a pyenv or
# virtualenv python that may come first on PATH.
cmake -S . -B build -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build -j "$(nproc)"
