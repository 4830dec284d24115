#!/usr/bin/env bash
# Render benchmark on the real CT head scene (512x512) and on the CT head resampled
# to 383x383x161 and 511x511x215: stock composite, stock Phong, the light transport
# volume still and orbiting under the headlight (rebuilt every frame), the per-sample
# photon test, a point light circling the head (camera still); at every size the orbit
# under ParaView's light kit (5 lights). Frame-time
# ratios are measured in one process per volume size; the build_*_ms columns say where
# each rebuild's time goes. Then the headline ratios from frames alternating with stock's
# (the median of 15 pairs; PAIRS=N for another count), and peak memory, one configuration
# per process, at 511x511x215.
# Writes <out>/render.csv, <out>/paired.csv, <out>/memory.csv and one PNG per configuration.
#   usage: Benchmarks/render/run_render_benchmark.sh [build-dir] [out-dir] [frames]
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build}"
out="${2:-render-benchmark}"
frames="${3:-5}"
bash scripts/prepare-data.sh
bench="$build/bin/scatterer-bench-render"
mkdir -p "$out"
rm -f "$out/render.csv"
bash scripts/xvfb.sh "$bench" --frames "$frames" --out "$out" --append
for dims in 383x383x161 511x511x215; do
  bash scripts/xvfb.sh "$bench" --frames "$frames" --out "$out" --resample "$dims" --append \
    --only stock_composite,stock_composite_orbit,transport_still,transport_orbit_headlight,transport_orbit_headlight_interactive,transport_orbit_lightkit
done
# The headline ratios again, each configuration's frames alternating with its stock
# counterpart's in one process (--pairs), at the three sizes: the median of 15 pairs'
# ratios, which the machine's drift over a run does not move (paired.csv).
rm -f "$out/paired.csv"
pairs=${PAIRS:-15}
for dims in "" 383x383x161 511x511x215; do
  resample=()
  [ -n "$dims" ] && resample=(--resample "$dims")
  bash scripts/xvfb.sh "$bench" --pairs "$pairs" --out "$out" "${resample[@]}" --append \
    --only transport_still,transport_orbit_headlight,transport_orbit_headlight_interactive,transport_orbit_lightkit
done
# Memory: a fresh process per configuration; column peak_rss_mib is its peak RSS.
mkdir -p "$out/memory"
rm -f "$out/memory/render.csv"
for config in stock_composite transport_orbit_headlight; do
  bash scripts/xvfb.sh "$bench" --frames 3 --out "$out/memory" --resample 511x511x215 --append \
    --only "$config"
done
cp "$out/memory/render.csv" "$out/memory.csv"
echo "wrote $out/render.csv, $out/paired.csv and $out/memory.csv"
