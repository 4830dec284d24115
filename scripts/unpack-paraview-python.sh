#!/usr/bin/env bash
# Unpacks Debian's python3-paraview into $1 (default build-paraview/paraview-python)
# WITHOUT installing it: the package conflicts with python3-vtk9 / libvtk9-dev, which
# this project builds against (installing it would remove them). ParaView's Python
# modules (pvbatch's paraview.simple) and its wrapping hierarchy files (needed to
# build the plugin) then live there; the `paraview` package supplies the libraries.
# Prints the folder. Safe to run again (skips when already unpacked).
set -euo pipefail
dir="${1:-build-paraview/paraview-python}"
if [ ! -d "$dir/usr/lib/python3/dist-packages/paraview" ]; then
  mkdir -p "$dir"
  (cd "$dir" && rm -f python3-paraview_*.deb && apt-get download python3-paraview > /dev/null &&
    dpkg-deb -x python3-paraview_*.deb . && rm -f python3-paraview_*.deb)
fi
cd "$dir" && pwd
