"""Renders the CT head with the ScattererTemplate ParaView plugin in pvbatch; writes a PNG.

  bash scripts/build-paraview-plugin.sh && bash scripts/prepare-data.sh
  bash scripts/paraview-env.sh [mpirun -np N] pvbatch Examples/paraview/render_ct_head_pvbatch.py --out ct-head.png

With N ranks the volume is split into N pieces, each with ghost layers as wide as the
illumination reach, and the ranks exchange the light between the pieces
(docs/paraview.md). Prints one JSON line: ranks, the first frame (pipeline update,
ghost exchange, light transport volume) and the median of the next frames in
milliseconds, and what rank 0 held and did: ghost layers, piece size, the light
exchange's milliseconds and bytes, and (frames that move the camera or a light) its
illumination rebuilds and their stages' milliseconds. With --move-light the scene light
moves a little every frame, so every frame rebuilds the illumination and exchanges light.
"""
import argparse
import json
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "ParaView", "Python"))
import scatterer_pvscene as scene_lib  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--data", default=os.path.expanduser("~/.cache/scatterer-template/ct-head.mhd"),
                    help="a 3-D MetaImage (.mhd + raw) volume (default: the prepared CT head)")
parser.add_argument("--plugin", default=scene_lib.default_plugin_path())
parser.add_argument("--out", required=True, help="PNG to write")
parser.add_argument("--size", type=int, nargs=2, default=[512, 512])
parser.add_argument("--representation", default="Scatterer Volume",
                    choices=["Scatterer Volume", "Volume"])
parser.add_argument("--template-radius", type=float, default=0.0,
                    help="mm; 0: automatic (10 x the mean voxel spacing)")
parser.add_argument("--ghost-layers", type=int, default=-1,
                    help="-1: automatic (the illumination reach); 0: none; n: n layers")
parser.add_argument("--frames", type=int, default=5)
parser.add_argument("--move-light", action="store_true",
                    help="move the scene light every frame (a light change per frame)")
parser.add_argument("--light-kit", action="store_true",
                    help="ParaView's default light kit (5 lights that follow the camera) "
                         "instead of the scene's one light")
parser.add_argument("--orbit", action="store_true",
                    help="turn the camera 2 degrees every frame (with --light-kit, a light "
                         "change per frame)")
parser.add_argument("--interactive", action="store_true",
                    help="with --move-light or --orbit: render as while the user drags "
                         "(InteractiveRender)")
parser.add_argument("--light-exchange", type=int, default=1, choices=[0, 1],
                    help="several ranks: exchange the light between the pieces (default 1)")
args = parser.parse_args()

scene_lib.load_plugin(args.plugin)
reader = scene_lib.open_volume(args.data)
view = scene_lib.make_view(args.size)
if args.light_kit:
    view.AdditionalLights = []
    view.UseLight = 1
display = scene_lib.show_volume(reader, view, args.representation)
if args.representation == "Scatterer Volume":
    display.ScattererTemplateRadius = args.template_radius
    display.ScattererGhostLayers = args.ghost_layers
    display.ScattererLightExchange = args.light_exchange
exchange_ms, exchange_bytes = [], []
if args.move_light or args.orbit or args.light_kit:
    # Only what is asked moves: with --light-kit alone, still frames of a still camera
    # (timed_renders nudges the camera, which moves the light kit).
    first, _ = scene_lib.timed_renders(view, 0)
    scatterer = args.representation == "Scatterer Volume"
    info = scene_lib.rank0_info(display) if scatterer else None
    exchanges = info["ScattererLightExchangeInfo"][0] if scatterer else 0
    builds = info["ScattererIlluminationBuildInfo"] if scatterer else None
    rebuilds, medium_rebuilds = [], 0
    frames = []
    for i in range(args.frames):
        if args.move_light:
            light = view.AdditionalLights[0]
            light.Position = [c + (2.0 if i % 2 == 0 else -2.0) for c in light.Position]
        if args.orbit:
            view.GetActiveCamera().Azimuth(2.0)
        start = time.perf_counter()
        view.InteractiveRender() if args.interactive else view.StillRender()
        frames.append((time.perf_counter() - start) * 1000.0)
        if scatterer:
            # The frame's own exchange and rebuild: none when the count stood still.
            info = scene_lib.rank0_info(display)
            count, ms, received, _ = info["ScattererLightExchangeInfo"]
            now = info["ScattererIlluminationBuildInfo"]
            if now[0] > builds[0]:
                rebuilds.append(now[2:])
            medium_rebuilds += int(now[1] - builds[1])
            builds = now
            exchanged = count > exchanges
            exchanges = count
            exchange_ms.append(ms if exchanged else 0.0)
            exchange_bytes.append(received if exchanged else 0.0)
else:
    first, frames = scene_lib.timed_renders(view, args.frames)
scene_lib.save(view, args.out, args.size)

result = {"ranks": scene_lib.number_of_ranks(), "representation": args.representation,
          "size": args.size, "template_radius": args.template_radius,
          "first_frame_ms": round(first, 1),
          "median_frame_ms": round(statistics.median(frames), 1) if frames else None}
if args.representation == "Scatterer Volume":
    info = scene_lib.rank0_info(display)
    result.update({"ghost_layers": info["ScattererRequestedGhostLayersInfo"][0],
                   "rank0_piece_kib": info["ScattererPieceMemoryKiBInfo"][0],
                   "rank0_owned_bounds": info["ScattererOwnedBoundsInfo"],
                   "shader": info["ScattererShaderFeaturesInfo"][0],
                   "light_exchange": args.light_exchange, "interactive": args.interactive,
                   "light_kit": args.light_kit, "orbit": args.orbit,
                   "move_light": args.move_light})
    if frames and (args.move_light or args.orbit or args.light_kit):
        # The frames' own rebuilds (rank 0): how many, how many also redrew the medium's
        # passes, and the median milliseconds of a rebuild and of its stages.
        result["rank0_rebuilds"] = len(rebuilds)
        result["rank0_medium_rebuilds"] = medium_rebuilds
        if rebuilds:
            names = ("rebuild", "medium", "sweeps", "arriving", "gather", "diffusion")
            result["rank0_rebuild_ms"] = {
                name: round(statistics.median(r[i] for r in rebuilds), 1)
                for i, name in enumerate(names)}
    if exchange_ms:  # the frames' own exchanges (the screenshot renders once more, still)
        result["rank0_exchange_ms"] = round(statistics.median(exchange_ms), 1)
        result["rank0_exchange_bytes"] = statistics.median(exchange_bytes)
print("SCATTERER_RESULT " + json.dumps(result))
sys.stdout.flush()
