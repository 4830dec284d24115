#!/usr/bin/env bash
# Render benchmark on the real CT head scene (512x512): stock composite, stock
# Phong, and template illumination per effect set (cached and per-sample), all
# in one process. Writes <out>/render.csv and one PNG per configuration.
#   usage: Benchmarks/render/run_render_benchmark.sh [build-dir] [out-dir] [frames]
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build}"
out="${2:-render-benchmark}"
frames="${3:-5}"
bash scripts/prepare-data.sh
bash scripts/xvfb.sh "$build/bin/scatterer-bench-render" --frames "$frames" --out "$out"
