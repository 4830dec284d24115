#!/usr/bin/env bash
# What the light exchange between pieces costs per light change: the CT head scene
# (512x512, llvmpipe) in pvbatch on 1, 2 and 4 MPI ranks with the scene light moving
# every frame, so every frame rebuilds the illumination and exchanges light; with the
# exchange off for comparison. One CSV row per run:
#   ranks,light_exchange,rank0_exchange_ms,rank0_exchange_bytes,first_frame_ms,median_frame_ms
# rank0_exchange_ms: the median over the frames of rank 0's exchange (its maps, the
# AllGathers, the sums); bytes: what rank 0 received per light change.
# Usage: Benchmarks/paraview/run_light_exchange_benchmark.sh [out.csv] [frames]
# (needs scripts/build-paraview-plugin.sh and scripts/prepare-data.sh first)
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT="${1:-build-paraview/light-exchange-benchmark.csv}"
FRAMES="${2:-7}"
PV_BUILD="${PV_BUILD_DIR:-build-paraview}"
export PYTHONPATH="$(cd "$PV_BUILD/paraview-python" && pwd)/usr/lib/python3/dist-packages"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
script=Examples/paraview/render_ct_head_pvbatch.py
tmp="$(mktemp -d)"
echo "ranks,light_exchange,rank0_exchange_ms,rank0_exchange_bytes,first_frame_ms,median_frame_ms" > "$OUT"
run() { # ranks exchange
  local launch=(pvbatch) line=""
  [ "$1" -gt 1 ] && launch=(mpirun -np "$1" -x PYTHONPATH pvbatch)
  # pvbatch under Xvfb sometimes fails to open its window (docs/paraview.md): retry.
  for try in 1 2 3; do
    line="$(timeout 300 bash scripts/xvfb.sh "${launch[@]}" "$script" --out "$tmp/out.png" \
      --frames "$FRAMES" --move-light --light-exchange "$2" 2>/dev/null |
      grep '^SCATTERER_RESULT ' || true)"
    [ -n "$line" ] && break
  done
  [ -n "$line" ] || { echo "no result for $1 ranks, exchange $2" >&2; return 1; }
  echo "${line#SCATTERER_RESULT }" | /usr/bin/python3 -c '
import json, sys
r = json.loads(sys.stdin.read())
print(",".join(str(x) for x in (r["ranks"], r["light_exchange"], r.get("rank0_exchange_ms", 0),
      int(r["rank0_exchange_bytes"]), r["first_frame_ms"], r["median_frame_ms"])))' >> "$OUT"
}
run 1 1
for ranks in 2 4; do
  run "$ranks" 1
  run "$ranks" 0
done
rm -rf "$tmp"
column -s, -t < "$OUT"
