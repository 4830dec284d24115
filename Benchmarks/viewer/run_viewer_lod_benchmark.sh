#!/usr/bin/env bash
# Frame times of scatterer-viewer while dragging and when still, at 600x600 with the
# default illumination on (issue 16: dragging at least 2x faster than a still frame).
#
#   bash Benchmarks/viewer/run_viewer_lod_benchmark.sh [build-dir] [out-dir] [size]
#
# Plays one recording per volume: three left-button rotation drags of 12 moves each,
# each followed by the still frame the viewer renders on release. Writes
# <out-dir>/viewer_lod.csv (volume, frame, kind, ms, rays) and prints, per volume, the
# median drag and still frame times, their ratio and the ray counts, all from one
# process per volume. Volumes: the CT head (its benchmark scene, fixed scene light),
# the Colin27 MRI and the CT angiography "stent" (automatic scene, headlight: the
# light moves with the camera, so the transport volume is rebuilt on every frame).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$here/../.."
build="$(cd "${1:-$root/build}" && pwd)"
out="${2:-/tmp/scatterer-viewer-lod}"
size="${3:-600x600}"
mkdir -p "$out"
cache="${SCATTERER_DATA_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/scatterer-template}"

events="$out/drags.events"
{
  echo "# StreamVersion 1.1"
  echo "EnterEvent 200 200 0 0 0 0"
  for drag in 1 2 3; do
    echo "MouseMoveEvent 200 200 0 0 0 0"
    echo "LeftButtonPressEvent 200 200 0 0 0 0"
    for step in $(seq 1 12); do
      echo "MouseMoveEvent $((200 + 6 * step)) $((200 + 2 * step)) 0 0 0 0"
    done
    echo "LeftButtonReleaseEvent $((200 + 72)) $((200 + 24)) 0 0 0 0"
  done
} > "$events"

csv="$out/viewer_lod.csv"
echo "volume,frame,kind,ms,rays" > "$csv"
run() {
  local name="$1"
  shift
  local log="$out/$name.log"
  bash "$root/scripts/xvfb.sh" "$build/bin/scatterer-viewer" "$@" --size "$size" \
    --play-events "$events" --test --output "$out/$name.png" > "$log" 2>&1 || {
    cat "$log"
    return 1
  }
  # "frame 3: interactive 266 ms, 90000 rays, ..." -> CSV; the first frame (shader
  # compilation, first transport build) is left out.
  sed -n 's/^frame \([0-9]*\): \([a-z]*\) \([0-9]*\) ms, \([0-9]*\) rays.*/\1,\2,\3,\4/p' "$log" |
    awk -F, -v v="$name" '$1 > 1 { print v "," $0 }' >> "$csv"
}
run ct-head
[ -f /usr/share/mricron/templates/ch2.nii.gz ] &&
  run mri --input /usr/share/mricron/templates/ch2.nii.gz
[ -f "$cache/stent.mhd" ] && run stent --input "$cache/stent.mhd"

/usr/bin/python3 - "$csv" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("volume   still ms  drag ms  still/drag  still rays  drag rays")
for volume in dict.fromkeys(r["volume"] for r in rows):
    def median(kind, key):
        values = [float(r[key]) for r in rows if r["volume"] == volume and r["kind"] == kind]
        return statistics.median(values) if values else float("nan")
    still, drag = median("still", "ms"), median("interactive", "ms")
    print(f"{volume:8s} {still:8.0f} {drag:8.0f} {still / drag:10.2f} {median('still', 'rays'):11.0f}"
          f" {median('interactive', 'rays'):10.0f}")
PY
echo "CSV: $csv"
