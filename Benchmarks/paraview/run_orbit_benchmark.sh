#!/usr/bin/env bash
# What orbiting under ParaView's default light kit costs against a still frame (issue
# target: at most 1.5x), in pvbatch, one rank, the CT head at 600x600: PAIRS pairs of
# runs, alternating, so the machine's drift falls on both: still frames of a still
# camera, then an orbit of 2 degrees a frame at still quality (each frame rebuilds the
# illumination for the 5 lights). Each orbit row adds rank 0's rebuilds: how many of the
# frames rebuilt, how many redrew the medium's passes (none should), and the medians of
# the rebuild and its stages (ScattererIlluminationBuildInfo; each stage waits for the
# GPU because ParaView's progress bar observes it). One CSV row per run:
#   pair,motion,median_frame_ms,ratio_to_still,rebuilds,medium_rebuilds,rebuild_ms,sweeps_ms,gather_ms,diffusion_ms
# Usage: Benchmarks/paraview/run_orbit_benchmark.sh [out.csv] [pairs] [frames]
# (needs scripts/build-paraview-plugin.sh and scripts/prepare-data.sh first)
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT="${1:-build-paraview/orbit-benchmark.csv}"
PAIRS="${2:-5}"
FRAMES="${3:-7}"
source Benchmarks/paraview/benchmark-env.sh
echo "pair,motion,median_frame_ms,ratio_to_still,rebuilds,medium_rebuilds,rebuild_ms,sweeps_ms,gather_ms,diffusion_ms" > "$OUT"
for pair in $(seq 1 "$PAIRS"); do
  still="$(pvbatch_result 1 --frames "$FRAMES" --size 600 600 --light-kit)"
  orbit="$(pvbatch_result 1 --frames "$FRAMES" --size 600 600 --light-kit --orbit)"
  /usr/bin/python3 - "$pair" "$still" "$orbit" >> "$OUT" <<'EOF'
import json, sys
pair, still, orbit = sys.argv[1], json.loads(sys.argv[2]), json.loads(sys.argv[3])
base = still["median_frame_ms"]
print("%s,still,%s,1.00,,,,,," % (pair, base))
stages = orbit.get("rank0_rebuild_ms", {})
print(",".join(str(x) for x in (pair, "orbit", orbit["median_frame_ms"],
      "%.2f" % (orbit["median_frame_ms"] / base), orbit["rank0_rebuilds"],
      orbit["rank0_medium_rebuilds"], stages.get("rebuild", ""), stages.get("sweeps", ""),
      stages.get("gather", ""), stages.get("diffusion", ""))))
EOF
done
rm -rf "$tmp"
column -s, -t < "$OUT"
