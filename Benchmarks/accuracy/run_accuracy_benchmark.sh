#!/usr/bin/env bash
# The accuracy / time trade-off benchmark (docs/accuracy.md). Not part of the tests: the
# converged reference alone takes several minutes on 2 cores (it is cached in OUT).
#
#   bash Benchmarks/accuracy/run_accuracy_benchmark.sh [BUILD_DIR] [OUT_DIR] [SPP] [FRAMES]
#
# Renders the CT head scene (under its one light and under vtkLightKit) and the synthetic
# shell + plate scenes (a directional and a point light) and dense-ball (dense, nearly
# white labels) at 256x256 with stock
# composite, stock Phong and template illumination over a quality ladder; compares each
# with the Monte Carlo reference; writes OUT/accuracy.csv, OUT/accuracy-<scene>.png (plot),
# OUT/accuracy-strip-<scene>.png and a PNG per configuration.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD="${1:-build}"
OUT="${2:-accuracy-benchmark}"
SPP="${3:-1024}"
FRAMES="${4:-3}"
if [ ! -x "$BUILD/bin/scatterer-bench-accuracy" ]; then
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$BUILD" -j 2 --target scatterer-bench-accuracy
fi
bash scripts/prepare-data.sh

# VTK's own volumetric scattering (VTK 9.2, from ParaView 5.11) as a peer: the Debian
# package python3-paraview conflicts with python3-vtk9 / libvtk9-dev, so it is unpacked
# into $BUILD/paraview-python (never installed); its libraries come from the `paraview`
# package, which installs beside libvtk9-dev (apt-get install paraview). See
# shared/vtk91-notes.md. Without them the peer is left out.
PEER=()
PVDIR="$BUILD/paraview-python"
if dpkg -s paraview > /dev/null 2>&1; then
  bash scripts/unpack-paraview-python.sh "$PVDIR" > /dev/null || true
  if [ -d "$PVDIR/usr/lib/python3/dist-packages/vtkmodules" ]; then
    PEER=(--peer-python "env PYTHONPATH=$(cd "$PVDIR" && pwd)/usr/lib/python3/dist-packages /usr/bin/python3"
          --peer-script "$(pwd)/Benchmarks/accuracy/vtk92_scattering_peer.py")
  fi
else
  echo "paraview is not installed: VTK 9.2 scattering peer left out (apt-get install paraview)" >&2
fi
bash scripts/xvfb.sh "$BUILD/bin/scatterer-bench-accuracy" --size 256x256 --spp "$SPP" \
  --frames "$FRAMES" --out "$OUT" "${PEER[@]}"
