#!/usr/bin/env bash
# The GPU checks of the light transport volume in one run, for a machine with a GPU and
# no display (docs/rendering.md, "On a GPU"): builds the EGL variant of the render
# benchmark, then renders at 1024x1024 the CT head and its 383x383x161 and 511x511x215
# resamples: stock composite (still and orbiting), the transport volume still, orbiting
# under the headlight and under a vtkLightKit, each at still and interactive quality.
# Ratios are measured in one process per volume size. Writes <out>/render-gpu.csv.
#   usage: Benchmarks/render/run_gpu_benchmark.sh [build-dir] [out-dir] [frames] [WxH]
# On the lent device machine: bash Benchmarks/render/run_gpu_benchmark.sh build-gpu "$OUT" 30
# (about 2 minutes of rendering on an H200 once built; the build takes longer).
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build-gpu}"
out="${2:-gpu-benchmark}"
frames="${3:-30}"
size="${4:-1024x1024}"
bash scripts/prepare-data.sh
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSCATTERER_BUILD_EGL_BENCHMARK=ON \
  > "$build.configure.log" 2>&1 || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)" --target scatterer-bench-render-egl
bench="$build/bin/scatterer-bench-render-egl"
configs=stock_composite,stock_composite_orbit,transport_still,transport_orbit_headlight
configs+=,transport_orbit_headlight_interactive,transport_orbit_lightkit
configs+=,transport_orbit_lightkit_interactive
mkdir -p "$out"
rm -f "$out/render.csv"
"$bench" --size "$size" --frames "$frames" --out "$out" --only "$configs" --append
for dims in 383x383x161 511x511x215; do
  "$bench" --size "$size" --frames "$frames" --out "$out" --resample "$dims" --append \
    --only "$configs"
done
mv "$out/render.csv" "$out/render-gpu.csv"
echo "wrote $out/render-gpu.csv"
