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
# The ParaView plugin's pvbatch tests (1, 2 and 4 MPI ranks; label "paraview"). Under Xvfb
# one rank's X connection is sometimes refused: pvbatch aborts in CreateAWindow before any
# check, or, where a rank of several comes up without its display, ParaView finds remote
# rendering unavailable and would wait forever in its first render (pvbatch_test.py ends
# such a run at once; until 2026-12-06 it hung until the 120 s timeout, five times in a
# row in one CI run). Measured 2 of 40 runs once, but a two-rank case failed in 3 of the 5
# CI runs of 2026-11-30. Up to five more tries; a real failure repeats every time.
bash scripts/xvfb.sh ctest --test-dir "${PV_BUILD_DIR:-build-paraview}" --output-on-failure \
  --repeat until-pass:6 "$@" || status=1
exit $status
