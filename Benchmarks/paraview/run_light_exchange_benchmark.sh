#!/usr/bin/env bash
# What the light exchange between pieces costs per light change: the CT head scene
# (512x512, llvmpipe) in pvbatch on 1, 2 and 4 MPI ranks with the scene light moving
# every frame, so every frame rebuilds the illumination and exchanges light; with the
# exchange off for comparison; still frames, and frames rendered as while the user
# drags (coarser maps). One CSV row per run:
#   ranks,frames,light_exchange,rank0_exchange_ms,rank0_exchange_bytes,first_frame_ms,median_frame_ms
# rank0_exchange_ms: the median over the frames of rank 0's exchange (its maps, the
# AllGathers, the sums); bytes: what rank 0 received per light change.
# Usage: Benchmarks/paraview/run_light_exchange_benchmark.sh [out.csv] [frames]
# (needs scripts/build-paraview-plugin.sh and scripts/prepare-data.sh first)
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT="${1:-build-paraview/light-exchange-benchmark.csv}"
FRAMES="${2:-7}"
source Benchmarks/paraview/benchmark-env.sh
echo "ranks,frames,light_exchange,rank0_exchange_ms,rank0_exchange_bytes,first_frame_ms,median_frame_ms" > "$OUT"
run() { # ranks exchange [--interactive]
  pvbatch_result "$1" --frames "$FRAMES" --move-light --light-exchange "$2" ${3:-} |
    /usr/bin/python3 -c '
import json, sys
r = json.loads(sys.stdin.read())
print(",".join(str(x) for x in (r["ranks"], "interactive" if r["interactive"] else "still",
      r["light_exchange"], r.get("rank0_exchange_ms", 0),
      int(r.get("rank0_exchange_bytes", 0)), r["first_frame_ms"], r["median_frame_ms"])))' >> "$OUT"
}
run 1 1
for ranks in 2 4; do
  run "$ranks" 1
  run "$ranks" 0
  run "$ranks" 1 --interactive
done
rm -rf "$tmp"
column -s, -t < "$OUT"
