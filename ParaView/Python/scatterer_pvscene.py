"""The CT-head benchmark scene (shared/scenes/ct-head.json) in ParaView, for pvbatch.

Used by the pvbatch tests (ParaView/Testing), Examples/paraview/render_ct_head_pvbatch.py
and the ParaView benchmark (Benchmarks/paraview). Opens the
CT head through ParaView's raw "Image Reader" (the header values come from the .mhd
file), because that reader delivers sub-extents with ghost layers to each MPI rank;
ParaView's MetaImage reader puts the whole volume on rank 0.
"""
import os
import time

from paraview import servermanager
from paraview.simple import (AddLight, ColorBy, CreateView, GetColorTransferFunction,
                             GetOpacityTransferFunction, ImageReader, LoadPlugin,
                             SaveScreenshot, SetActiveView, Show)

# The values of shared/scenes/ct-head.json that ParaView needs (the same numbers as
# Examples/Common/ScattererCtHeadScene.cxx): camera, one directional scene light,
# transfer functions in HU. Background black.
CT_HEAD_SCENE = {
    "camera": {"position": [-96.0, 572.0, 252.0], "focal_point": [122.0, 135.0, 75.0],
               "view_up": [0.0, 0.0, 1.0], "view_angle_deg": 30.0},
    "light": {"position": [222.0, 435.0, 319.0], "focal_point": [122.0, 135.0, 75.0],
              "intensity": 1.0},
    "opacity": [[-1024, 0.0], [-600, 0.0], [-450, 0.1], [-50, 0.1], [0, 0.0], [150, 0.0],
                [300, 0.8], [2986, 0.9]],
    "color": [[-1024, 0.8, 0.55, 0.42], [-600, 0.85, 0.6, 0.45], [0, 0.95, 0.75, 0.6],
              [150, 0.95, 0.85, 0.75], [300, 1.0, 1.0, 0.95], [2986, 1.0, 1.0, 1.0]],
    "scalar_opacity_unit_distance": 1.0,
}

# A synthetic scene whose lighting depends on voxels across a piece border: empty
# space, then from x = 52 a translucent slab (value 100) with an opaque sheet (value
# 250) just before x = 64, over the lower half of z, lit along +x and seen from the
# side. Split into two ranks along x, the shadow the sheet casts falls on the other
# rank's piece. Everything between the light and that piece's ghost layers is empty,
# so a piece with ghost layers sees all the matter the light crosses.
SPLIT_SHADOW_DIMS = (128, 40, 48)
SPLIT_SHADOW_SCENE = {
    "camera": {"position": [63.5, -260.0, 23.5], "focal_point": [63.5, 19.5, 23.5],
               "view_up": [0.0, 0.0, 1.0], "view_angle_deg": 30.0},
    "light": {"position": [-100.0, 19.5, 23.5], "focal_point": [0.0, 19.5, 23.5],
              "intensity": 1.0},
    "opacity": [[0, 0.0], [90, 0.0], [100, 0.08], [200, 0.08], [250, 1.0], [255, 1.0]],
    "color": [[0, 1.0, 1.0, 1.0], [255, 1.0, 1.0, 1.0]],
    "scalar_opacity_unit_distance": 1.0,
}


# Shadows farther than any ghost layer: an opaque sheet (value 250) at x = 8..11 over
# the lower half of z, then a translucent slab (value 100) from x = 12 to the end, lit
# along +x. The sheet's shadow and the slab's own attenuation reach every piece of a
# split along x, up to 116 voxels from the sheet; the automatic ghost layers are 37.
LONG_SHADOW_DIMS = (128, 40, 48)
LONG_SHADOW_SCENE = dict(SPLIT_SHADOW_SCENE)
LONG_SHADOW_SCENE["opacity"] = [[0, 0.0], [90, 0.0], [100, 0.03], [200, 0.03], [250, 1.0],
                                [255, 1.0]]
# The same volume lit by a positional light inside it, near its far end (x = 120): its
# light crosses the slab toward every other piece. No cone (180 degrees), no falloff.
POINT_LIGHT_SCENE = dict(LONG_SHADOW_SCENE)
POINT_LIGHT_SCENE["light"] = {"position": [120.0, 19.5, 36.0], "focal_point": [0.0, 19.5, 36.0],
                              "intensity": 1.0, "positional": True}


def write_long_shadow_volume(folder):
    """Writes the long-shadow volume as <folder>/long-shadow.mhd (+ .raw)."""
    return _write_sheet_and_slab(folder, "long-shadow", LONG_SHADOW_DIMS, 12, (8, 12))


def _write_sheet_and_slab(folder, name, dims, slab_from, sheet):
    """An empty volume with a translucent slab (value 100) from x = slab_from to the end
    and an opaque sheet (value 250) over x in [sheet) and the lower half of z, written as
    <folder>/<name>.mhd (+ .raw)."""
    import numpy
    nx, ny, nz = dims
    volume = numpy.zeros((nz, ny, nx), dtype=numpy.uint8)  # [z][y][x], x fastest
    volume[:, :, slab_from:] = 100
    volume[:nz // 2, :, sheet[0]:sheet[1]] = 250
    os.makedirs(folder, exist_ok=True)
    volume.tofile(os.path.join(folder, name + ".raw"))
    path = os.path.join(folder, name + ".mhd")
    with open(path, "w") as f:
        f.write("ObjectType = Image\nNDims = 3\nDimSize = %d %d %d\n" % (nx, ny, nz))
        f.write("ElementType = MET_UCHAR\nElementSpacing = 1 1 1\nOffset = 0 0 0\n")
        f.write("ElementDataFile = %s.raw\n" % name)
    return path


def write_split_shadow_volume(folder):
    """Writes the split-shadow volume as <folder>/split-shadow.mhd (+ .raw)."""
    return _write_sheet_and_slab(folder, "split-shadow", SPLIT_SHADOW_DIMS, 52, (58, 62))


_MET_TYPES = {"MET_SHORT": "short", "MET_USHORT": "unsigned short", "MET_UCHAR": "unsigned char",
              "MET_CHAR": "char", "MET_INT": "int", "MET_UINT": "unsigned int",
              "MET_FLOAT": "float", "MET_DOUBLE": "double"}


def default_plugin_path():
    """The plugin in the source tree's default build folder (build-paraview/)."""
    here = os.path.dirname(os.path.abspath(__file__))
    return os.path.join(here, "..", "..", "build-paraview", "lib", "paraview-5.11", "plugins",
                        "ScattererTemplatePlugin", "ScattererTemplatePlugin.so")


def plugin_loaded(name="ScattererTemplatePlugin"):
    """True when ParaView loaded the plugin already (PV_PLUGIN_PATH, as
    scripts/paraview-env.sh sets it): a second LoadPlugin fails with an error."""
    info = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager() \
        .GetLocalInformation()
    return any(info.GetPluginName(i) == name and info.GetPluginLoaded(i)
               for i in range(info.GetNumberOfPlugins()))


def load_plugin(path):
    if plugin_loaded():
        return
    if not os.path.isfile(path):
        raise SystemExit("ScattererTemplate plugin not found: %s (build it with "
                         "scripts/build-paraview-plugin.sh)" % path)
    LoadPlugin(path, remote=False, ns=globals())


def read_mhd_header(path):
    header = {}
    with open(path) as f:
        for line in f:
            if "=" in line:
                key, value = line.split("=", 1)
                header[key.strip()] = value.strip()
    for key in ("DimSize", "ElementSpacing", "ElementType", "ElementDataFile"):
        if key not in header:
            raise SystemExit("%s: MetaImage header without %s" % (path, key))
    if header.get("NDims", "3") != "3" or header.get("ElementNumberOfChannels", "1") != "1":
        raise SystemExit("%s: only 3-D single-channel MetaImage volumes are supported" % path)
    if header["ElementType"] not in _MET_TYPES:
        raise SystemExit("%s: element type %s is not supported" % (path, header["ElementType"]))
    return header


def open_volume(mhd_path):
    """ParaView's raw Image Reader on the data file the .mhd header names."""
    h = read_mhd_header(mhd_path)
    dims = [int(v) for v in h["DimSize"].split()]
    raw = os.path.join(os.path.dirname(os.path.abspath(mhd_path)), h["ElementDataFile"])
    if not os.path.isfile(raw):
        raise SystemExit("%s: data file %s not found" % (mhd_path, raw))
    reader = ImageReader(FileNames=[raw])
    reader.DataScalarType = _MET_TYPES[h["ElementType"]]
    msb = h.get("ElementByteOrderMSB", h.get("BinaryDataByteOrderMSB", "False"))
    reader.DataByteOrder = "BigEndian" if msb.lower() == "true" else "LittleEndian"
    reader.DataExtent = [0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1]
    reader.DataSpacing = [float(v) for v in h["ElementSpacing"].split()]
    reader.DataOrigin = [float(v) for v in h.get("Offset", "0 0 0").split()]
    return reader


def make_view(size, scene=CT_HEAD_SCENE):
    """Render view with a black background and the scene's one light (directional,
    or positional without cone when the scene says so); scene None: ParaView's own
    lights (the light kit)."""
    view = CreateView("RenderView")
    SetActiveView(view)
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    if scene is None:
        return view
    view.UseLight = 0  # no light kit: the scene's single directional light only
    light = AddLight(view=view)
    light.Coords = "Scene"
    if scene["light"].get("positional"):
        light.Type = "Positional"
        light.ConeAngle = 180.0
    else:
        light.Type = "Directional"
    light.Position = scene["light"]["position"]
    light.FocalPoint = scene["light"]["focal_point"]
    light.Intensity = scene["light"]["intensity"]
    return view


def apply_camera(view, scene=CT_HEAD_SCENE):
    """The scene's camera; after Show, which may reset the camera to the data."""
    cam = scene["camera"]
    view.CameraPosition = cam["position"]
    view.CameraFocalPoint = cam["focal_point"]
    view.CameraViewUp = cam["view_up"]
    view.CameraViewAngle = cam["view_angle_deg"]
    view.CameraParallelProjection = 0


def show_volume(source, view, representation, scene=CT_HEAD_SCENE, association="POINTS"):
    """Shows `source` as `representation` ("Volume" or "Scatterer Volume") with the
    scene's transfer functions, its array ImageFile taken from `association` ("POINTS"
    or "CELLS")."""
    display = Show(source, view)
    display.SetRepresentationType(representation)
    ColorBy(display, (association, "ImageFile"))
    display.SetScalarBarVisibility(view, False)
    lut = GetColorTransferFunction("ImageFile")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    lut.RGBPoints = [v for point in scene["color"] for v in point]
    pwf = GetOpacityTransferFunction("ImageFile")
    pwf.Points = [v for x, a in scene["opacity"] for v in (x, a, 0.5, 0.0)]
    display.ScalarOpacityUnitDistance = scene["scalar_opacity_unit_distance"]
    display.Shade = 0
    apply_camera(view, scene)
    return display


def timed_renders(view, frames):
    """First frame (pipeline update, ghost exchange, light transport volume) and then
    `frames` more frames with a camera nudge each, so every one really renders.
    view.StillRender, not simple.Render: that one resets the camera on its first call."""
    start = time.perf_counter()
    view.StillRender()
    first = (time.perf_counter() - start) * 1000.0
    times = []
    for i in range(frames):
        view.CameraPosition = [c + (0.001 if i % 2 == 0 else -0.001)
                               for c in view.CameraPosition]
        start = time.perf_counter()
        view.StillRender()
        times.append((time.perf_counter() - start) * 1000.0)
    return first, times


def number_of_ranks():
    return servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


def save(view, path, size):
    SaveScreenshot(path, view, ImageResolution=list(size))


def rank0_info(display):
    """The information-only properties of the Scatterer Volume representation (what
    rank 0 did on the last update and frame), by name."""
    display.SMProxy.UpdatePropertyInformation()
    names = ("ScattererRequestedGhostLayersInfo", "ScattererRendersOwnedPartOnlyInfo",
             "ScattererOwnedBoundsInfo", "ScattererPieceMemoryKiBInfo",
             "ScattererShaderFeaturesInfo", "ScattererLightExchangeInfo",
             "ScattererIlluminationBuildInfo")
    info = {}
    for name in names:
        prop = display.SMProxy.GetProperty(name)
        info[name] = [prop.GetElement(i) for i in range(prop.GetNumberOfElements())]
    return info
