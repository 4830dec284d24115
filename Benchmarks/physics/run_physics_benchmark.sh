#!/usr/bin/env bash
# Runs the physics micro-benchmark and writes CSV (median/mean/stddev of 10 repetitions).
#   usage: run_physics_benchmark.sh [build-dir] [out.csv]
# The binary is looked up in <build-dir>/bin (top-level build) or anywhere below it.
set -euo pipefail
build="${1:-build}"
out="${2:-physics-benchmark.csv}"
bin="$(find "$build" -type f -name ScattererPhysicsBenchmark -perm -u+x | head -n 1)"
if [[ -z "$bin" ]]; then
  echo "ScattererPhysicsBenchmark not found under $build (build it first)" >&2
  exit 1
fi
"$bin" --benchmark_repetitions=10 --benchmark_report_aggregates_only=true \
  --benchmark_out="$out" --benchmark_out_format=csv
echo "wrote $out"
