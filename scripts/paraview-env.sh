#!/usr/bin/env bash
# Runs a ParaView command (paraview, pvbatch, pvpython, mpirun ... pvbatch) with what
# this project's ParaView setup needs (docs/paraview.md):
#   bash scripts/paraview-env.sh paraview --script=Examples/paraview/show_volume_gui.py
#   bash scripts/paraview-env.sh pvbatch Examples/paraview/render_volume_pvbatch.py head.vti head.png
#   bash scripts/paraview-env.sh mpirun -np 2 pvbatch Examples/paraview/render_volume_pvbatch.py head.vti head.png
#   bash scripts/paraview-env.sh pvpython
# - PYTHONPATH: python3-paraview is unpacked, not installed (it conflicts with
#   python3-vtk9), so neither pvbatch nor the GUI's Python (Python shell, --script)
#   finds `paraview` without it.
# - pvpython is not in the `paraview` package. The one in the unpacked package
#   (usr/bin/pvpython) segfaults on `import paraview.simple` here: it puts
#   /usr/lib/python3/dist-packages, where python3-vtk9 keeps VTK 9.1's vtkmodules, ahead
#   of PYTHONPATH. So `pvpython` runs Debian's python3 (the Python ParaView is built
#   with), which finds ParaView's modules on PYTHONPATH first.
# - PV_PLUGIN_PATH: ParaView loads the plugin at start-up (GUI, pvbatch, pvpython).
# - OMPI_*: Open MPI refuses to run as root (containers, CI) unless told twice.
#   mpirun passes only the variables named with -x to the ranks; these are added.
# PV_BUILD_DIR: the plugin's build folder (default build-paraview);
# SCATTERER_PARAVIEW_PYTHON_ROOT: where python3-paraview was unpacked (default
# $PV_BUILD_DIR/paraview-python, as scripts/build-paraview-plugin.sh does).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${PV_BUILD_DIR:-$root/build-paraview}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
pvpython_root="${SCATTERER_PARAVIEW_PYTHON_ROOT:-$build/paraview-python}"
if [ ! -d "$pvpython_root/usr/lib/python3/dist-packages/paraview" ]; then
  echo "paraview-env.sh: $pvpython_root has no ParaView Python modules;" \
    "run scripts/build-paraview-plugin.sh first" >&2
  exit 1
fi
export PYTHONPATH="$pvpython_root/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
export PV_PLUGIN_PATH="$build/lib/paraview-5.11/plugins/ScattererTemplatePlugin${PV_PLUGIN_PATH:+:$PV_PLUGIN_PATH}"
if [ "$(id -u)" = 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
if [ "$#" -eq 0 ]; then
  echo "usage: bash scripts/paraview-env.sh <command> [args...]" >&2
  exit 2
fi
if [ "$(basename "$1")" = mpirun ] || [ "$(basename "$1")" = mpiexec ]; then
  launcher="$1"
  shift
  exec "$launcher" -x PYTHONPATH -x PV_PLUGIN_PATH "$@"
fi
if [ "$1" = pvpython ]; then
  shift
  set -- /usr/bin/python3 "$@"
fi
exec "$@"
