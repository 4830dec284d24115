#!/usr/bin/env bash
# What a light change costs in pvbatch, and what the light exchange between pieces adds
# to it: the CT head scene (llvmpipe) on 1, 2 and 4 MPI ranks.
#   - scene light moving every frame (512x512): every frame rebuilds the illumination
#     and, with several ranks, exchanges light; with the exchange off for comparison;
#     still frames and frames rendered as while the user drags (coarser maps);
#   - ParaView's default light kit (600x600, 5 lights that follow the camera): still
#     frames of a still camera, and an orbit (2 degrees a frame), still and interactive.
# One CSV row per run:
#   ranks,size,lights,motion,render,light_exchange,rank0_exchange_ms,rank0_exchange_bytes,first_frame_ms,median_frame_ms
# rank0_exchange_ms and _bytes: medians over the frames of rank 0's exchange (its maps,
# the AllGathers, the sums) and of what it received.
# Usage: Benchmarks/paraview/run_light_exchange_benchmark.sh [out.csv] [frames]
# (needs scripts/build-paraview-plugin.sh and scripts/prepare-data.sh first)
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT="${1:-build-paraview/light-exchange-benchmark.csv}"
FRAMES="${2:-7}"
source Benchmarks/paraview/benchmark-env.sh
echo "ranks,size,lights,motion,render,light_exchange,rank0_exchange_ms,rank0_exchange_bytes,first_frame_ms,median_frame_ms" > "$OUT"
run() { # ranks size exchange [script options]
  local ranks="$1" size="$2" exchange="$3"
  shift 3
  pvbatch_result "$ranks" --frames "$FRAMES" --size "$size" "$size" --light-exchange "$exchange" "$@" |
    /usr/bin/python3 -c '
import json, sys
r = json.loads(sys.stdin.read())
motion = "light-moving" if r["move_light"] else ("orbit" if r["orbit"] else "none")
print(",".join(str(x) for x in (r["ranks"], r["size"][0], "light-kit" if r["light_kit"] else "scene",
      motion, "interactive" if r["interactive"] else "still", r["light_exchange"],
      r.get("rank0_exchange_ms", 0), int(r.get("rank0_exchange_bytes", 0)),
      r["first_frame_ms"], r["median_frame_ms"])))' >> "$OUT"
}
run 1 512 1 --move-light
for ranks in 2 4; do
  run "$ranks" 512 1 --move-light
  run "$ranks" 512 0 --move-light
  run "$ranks" 512 1 --move-light --interactive
done
for ranks in 1 2; do
  run "$ranks" 600 1 --light-kit
  run "$ranks" 600 1 --light-kit --orbit
  run "$ranks" 600 1 --light-kit --orbit --interactive
done
rm -rf "$tmp"
column -s, -t < "$OUT"
