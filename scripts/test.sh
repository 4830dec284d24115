#!/usr/bin/env bash
# Runs the whole test suite on a fresh Debian 12 machine: install, build,
# prepare the real CT head, then CTest under a virtual X server: the VTK 9.1
# build (build/) and the ParaView plugin's pvbatch tests (build-paraview/).
# Extra arguments go to ctest (e.g. -L unit, -R Identity).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh > /tmp/scatterer-build.log 2>&1 || { tail -n 60 /tmp/scatterer-build.log; exit 1; }
bash scripts/build-paraview-plugin.sh > /tmp/scatterer-build-paraview.log 2>&1 ||
  { tail -n 60 /tmp/scatterer-build-paraview.log; exit 1; }
bash scripts/prepare-data.sh
status=0
# --repeat until-pass:2: a rendering test whose X connection is refused under
# parallel load (EAGAIN; VTK then aborts) gets one more try; real failures repeat.
bash scripts/xvfb.sh ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure -j 2 \
  --repeat until-pass:2 "$@" || status=1
# The ParaView plugin's pvbatch tests (1 and 2 MPI ranks; label "paraview"). Under Xvfb
# one rank's X connection is refused in about 1 of 20 two-rank runs (measured: 2 of 40;
# pvbatch then aborts before any check): up to two more tries. A real failure repeats.
bash scripts/xvfb.sh ctest --test-dir "${PV_BUILD_DIR:-build-paraview}" --output-on-failure \
  --repeat until-pass:3 "$@" || status=1
exit $status
