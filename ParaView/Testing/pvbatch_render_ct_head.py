"""Renders the CT head with the ScattererTemplate plugin in pvbatch and writes a PNG.

  [mpirun -np N] pvbatch pvbatch_render_ct_head.py --out ct-head.png [options]

Prints one JSON line: ranks, representation, first-frame and median frame
milliseconds, and (for "Scatterer Volume") the ghost layers rank 0 asked for and the
piece it rendered. With --stock-too, also renders the same scene as ParaView's own
"Volume" representation into <out>-stock.png.
"""
import argparse
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scatterer_pvscene as scene_lib  # noqa: E402
from paraview.simple import Delete, Hide  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--data", default=os.path.expanduser("~/.cache/scatterer-template/ct-head.mhd"))
parser.add_argument("--plugin", default=scene_lib.default_plugin_path())
parser.add_argument("--out", required=True)
parser.add_argument("--size", type=int, nargs=2, default=[200, 200])
parser.add_argument("--representation", default="Scatterer Volume")
parser.add_argument("--ghost-layers", type=int, default=-1,
                    help="-1: automatic (the illumination reach); 0: none; n: n layers")
parser.add_argument("--frames", type=int, default=3)
parser.add_argument("--stock-too", action="store_true")
args = parser.parse_args()

scene_lib.load_plugin(args.plugin)
reader = scene_lib.open_volume(args.data)
view = scene_lib.make_view(args.size)
display = scene_lib.show_volume(reader, view, args.representation)
if args.representation == "Scatterer Volume":
    display.ScattererGhostLayers = args.ghost_layers
first, frames = scene_lib.timed_renders(view, args.frames)
scene_lib.save(view, args.out, args.size)

result = {"ranks": scene_lib.number_of_ranks(), "representation": args.representation,
          "size": args.size, "first_frame_ms": round(first, 1),
          "median_frame_ms": round(statistics.median(frames), 1) if frames else None}
if args.representation == "Scatterer Volume":
    info = scene_lib.rank0_info(display)
    result.update({"ghost_layers_requested": info["ScattererRequestedGhostLayersInfo"][0],
                   "rank0_renders_owned_part_only": bool(info["ScattererRendersOwnedPartOnlyInfo"][0]),
                   "rank0_owned_bounds": info["ScattererOwnedBoundsInfo"],
                   "rank0_piece_kib": info["ScattererPieceMemoryKiBInfo"][0],
                   "shader": info["ScattererShaderFeaturesInfo"][0]})
if args.stock_too:
    Hide(reader, view)
    stock = scene_lib.show_volume(reader, view, "Volume")
    scene_lib.timed_renders(view, 1)
    base, ext = os.path.splitext(args.out)
    scene_lib.save(view, base + "-stock" + ext, args.size)
print("SCATTERER_RESULT " + json.dumps(result))
sys.stdout.flush()
