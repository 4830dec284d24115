# Sourced by the ParaView benchmarks (run from the repository root): ParaView's Python
# (unpacked by scripts/build-paraview-plugin.sh), Open MPI as root with more ranks than
# cores, the CT-head pvbatch script they run, and a scratch folder.
PV_BUILD="${PV_BUILD_DIR:-build-paraview}"
export PYTHONPATH="$(cd "$PV_BUILD/paraview-python" && pwd)/usr/lib/python3/dist-packages"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
script=Examples/paraview/render_ct_head_pvbatch.py
tmp="$(mktemp -d)"

# pvbatch_result RANKS ARGS...: runs the script on RANKS ranks with ARGS and prints its
# SCATTERER_RESULT JSON. pvbatch under Xvfb sometimes fails to open its window
# (docs/paraview.md, Troubleshooting): up to three tries.
pvbatch_result() {
  local ranks="$1" launch=(pvbatch) line=""
  shift
  [ "$ranks" -gt 1 ] && launch=(mpirun -np "$ranks" -x PYTHONPATH pvbatch)
  for try in 1 2 3; do
    line="$(timeout 300 bash scripts/xvfb.sh "${launch[@]}" "$script" --out "$tmp/out.png" "$@" \
      2>/dev/null | grep '^SCATTERER_RESULT ' || true)"
    [ -n "$line" ] && break
  done
  [ -n "$line" ] || { echo "no result for $ranks ranks: $*" >&2; return 1; }
  echo "${line#SCATTERER_RESULT }"
}
