#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: install, build, prepare the real
# CT head, render it with scatterer-template illumination to ct-head.png and
# print the frame times. Extra arguments go to scatterer-render.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh > /tmp/scatterer-build.log 2>&1 || { tail -n 40 /tmp/scatterer-build.log; exit 1; }
bash scripts/prepare-data.sh
bash scripts/xvfb.sh "${BUILD_DIR:-build}/bin/scatterer-render" --mode template --frames 3 \
  --output ct-head.png --json "$@"
