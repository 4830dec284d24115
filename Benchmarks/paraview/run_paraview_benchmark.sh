#!/usr/bin/env bash
# What distributing the illumination costs: the CT head scene (512x512, llvmpipe) in
# pvbatch on 1 and 2 MPI ranks, for three template radii, with ParaView's own Volume
# representation for scale. One CSV row per run:
#   ranks,representation,template_radius_mm,ghost_layers,rank0_piece_kib,first_frame_ms,median_frame_ms
# Usage: Benchmarks/paraview/run_paraview_benchmark.sh [out.csv] [frames]
# (needs scripts/build-paraview-plugin.sh and scripts/prepare-data.sh first)
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT="${1:-build-paraview/paraview-benchmark.csv}"
FRAMES="${2:-9}"
source Benchmarks/paraview/benchmark-env.sh
echo "ranks,representation,template_radius_mm,ghost_layers,rank0_piece_kib,first_frame_ms,median_frame_ms" > "$OUT"
run() { # ranks representation radius
  pvbatch_result "$1" --frames "$FRAMES" --representation "$2" --template-radius "$3" |
    /usr/bin/python3 -c '
import json, sys
r = json.loads(sys.stdin.read())
print(",".join(str(x) for x in (r["ranks"], r["representation"].replace(" ", "_"),
      r["template_radius"], r.get("ghost_layers", 0), r.get("rank0_piece_kib", ""),
      r["first_frame_ms"], r["median_frame_ms"])))' >> "$OUT"
}
for ranks in 1 2; do
  run "$ranks" Volume 0
  # 0 = automatic (10 x mean spacing = 11.4 mm on the CT head); 5.7 and 22.8 mm: half, double.
  for radius in 5.7 0 22.8; do
    run "$ranks" "Scatterer Volume" "$radius"
  done
done
rm -rf "$tmp"
column -s, -t < "$OUT"
