#!/usr/bin/env bash
# Installs what ScattererTemplate needs on Debian 12 (bookworm), non-interactively.
# Packages already installed are skipped, so this is cheap on a prepared machine.
set -euo pipefail

packages=(
  build-essential cmake git                       # toolchain
  libvtk9-dev libglm-dev                          # VTK 9.1 (X11/GLX), GLM
  libvtk-dicom-dev                                # vtk-dicom 0.8 for VTK 9.1: DICOM reading (GDCM codecs)
  libgdcm-tools                                   # gdcmconv: the tests' JPEG / JPEG-LS / JPEG 2000 series
  libcli11-dev                                    # CLI11: the programs' command-line parser
  python3-vtk9                                    # VTK's Python (wrapping, Python tests/example)
  libgtest-dev libbenchmark-dev                   # GoogleTest, Google Benchmark
  clang libclang-rt-14-dev                        # libFuzzer + sanitizer runtimes (scripts/fuzz.sh)
  clang-format-14                                 # each layer's .clang-format (scripts/format.sh)
  xvfb xauth libgl1-mesa-dri                      # headless X + Mesa llvmpipe
  invesalius-examples                             # the real CT head (see docs/data.md)
  mricron-data python3-imageio                    # real MRI (Colin27) and CT angiography (stent), docs/data.md
  python3-numpy mpi-default-bin                   # pvbatch tests: image statistics, mpirun
)
# ParaView 5.11 (plugin, pvbatch tests; docs/paraview.md), without its recommended
# python3-paraview: that one conflicts with python3-vtk9 / libvtk9-dev and is only
# unpacked (scripts/unpack-paraview-python.sh), never installed.
paraview_packages=(paraview paraview-dev)

missing_of() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
mapfile -t missing < <(missing_of "${packages[@]}")
mapfile -t missing_paraview < <(missing_of "${paraview_packages[@]}")
if [ ${#missing[@]} -eq 0 ] && [ ${#missing_paraview[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  $sudo apt-get install -y -qq "${missing[@]}" > /tmp/scatterer-apt.log 2>&1 ||
    { tail -n 30 /tmp/scatterer-apt.log; exit 1; }
fi
if [ ${#missing_paraview[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing_paraview[*]} (without recommends)"
  $sudo apt-get install -y -qq --no-install-recommends "${missing_paraview[@]}" \
    > /tmp/scatterer-apt-paraview.log 2>&1 || { tail -n 30 /tmp/scatterer-apt-paraview.log; exit 1; }
fi
