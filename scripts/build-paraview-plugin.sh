#!/usr/bin/env bash
# Configures and builds the ParaView 5.11 plugin (ParaView/) into ${PV_BUILD_DIR:-build-paraview}
# against Debian's paraview-dev (ParaView's own VTK 9.2). Needs scripts/install-deps.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${PV_BUILD_DIR:-build-paraview}"
mkdir -p "$build"
pvpython_root="$(bash scripts/unpack-paraview-python.sh "$build/paraview-python")"
cmake -S ParaView -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DSCATTERER_PARAVIEW_PYTHON_ROOT="$pvpython_root" ${CMAKE_ARGS:-} > "$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)"
