#!/usr/bin/env bash
# Installs what ScattererTemplate needs on Debian 12 (bookworm), non-interactively.
# Packages already installed are skipped, so this is cheap on a prepared machine.
set -euo pipefail

packages=(
  build-essential cmake git                       # toolchain
  libvtk9-dev libglm-dev                          # VTK 9.1 (X11/GLX), GLM
  python3-vtk9                                    # VTK's Python (wrapping, Python tests/example)
  libgtest-dev libbenchmark-dev                   # GoogleTest, Google Benchmark
  clang libclang-rt-14-dev                        # libFuzzer + sanitizer runtimes (scripts/fuzz.sh)
  xvfb xauth libgl1-mesa-dri                      # headless X + Mesa llvmpipe
  invesalius-examples                             # the real CT head (see docs/data.md)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq "${missing[@]}" > /tmp/scatterer-apt.log 2>&1 ||
  { tail -n 30 /tmp/scatterer-apt.log; exit 1; }
