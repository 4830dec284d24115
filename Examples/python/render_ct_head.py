#!/usr/bin/python3
"""Renders the real CT head with scatterer-template illumination to a PNG, from Python.

    bash scripts/prepare-data.sh      # once: writes ~/.cache/scatterer-template/ct-head.mhd
    PYTHONPATH=build/lib/python3.11/dist-packages \\
      bash scripts/xvfb.sh /usr/bin/python3 Examples/python/render_ct_head.py --output head.png

The scene is scatterer-render's "ct-head" scene (Examples/Common/ScattererCtHeadScene.cxx):
skin + bone transfer functions, a fixed camera, one directional scene light.
Options: --input PATH, --output FILE.png, --size WxH, --mode template|stock,
--no-shadows, --no-bleeding, --strength S, --cut-mask (a binary mask removes the skull cap
and the quarter facing the camera: masked-out matter neither shows nor casts shadow). After `cmake --install`, the package is on
Python's path (/usr/local/lib/python3.X/dist-packages) and PYTHONPATH is not needed.
"""
import argparse
import os
import sys
import time

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkLight,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)

from scatterertemplate import vtkScattererTemplateVolumeMapper, vtkScattererVolumeReader


def data_directory():
    if os.environ.get("SCATTERER_DATA_DIR"):
        return os.environ["SCATTERER_DATA_DIR"]
    if os.environ.get("XDG_CACHE_HOME"):
        return os.path.join(os.environ["XDG_CACHE_HOME"], "scatterer-template")
    return os.path.join(os.path.expanduser("~"), ".cache", "scatterer-template")


def ct_head_property():
    """Skin and bone, piecewise linear in HU (opacity per 1 mm); shading off."""
    opacity = vtkPiecewiseFunction()
    for x, y in [(-1024, 0.0), (-600, 0.0), (-450, 0.1), (-50, 0.1), (0, 0.0), (150, 0.0),
                 (300, 0.8), (2986, 0.9)]:
        opacity.AddPoint(x, y)
    color = vtkColorTransferFunction()
    for x, r, g, b in [(-1024, 0.8, 0.55, 0.42), (-600, 0.85, 0.6, 0.45), (0, 0.95, 0.75, 0.6),
                       (150, 0.95, 0.85, 0.75), (300, 1.0, 1.0, 0.95), (2986, 1.0, 1.0, 1.0)]:
        color.AddRGBPoint(x, r, g, b)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetInterpolationTypeToLinear()
    prop.SetScalarOpacityUnitDistance(1.0)
    prop.SetAmbient(0.1)
    prop.SetDiffuse(0.9)
    prop.SetSpecular(0.2)
    prop.SetSpecularPower(10.0)
    prop.ShadeOff()
    return prop


def apply_ct_head_view(renderer):
    """The scene's camera and its one directional scene light (white ambient, diffuse and
    specular colours, as ScattererCtHeadScene.cxx); returns the light."""
    camera = renderer.GetActiveCamera()
    camera.SetPosition(-96.0, 572.0, 252.0)
    camera.SetFocalPoint(122.0, 135.0, 75.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetViewAngle(30.0)
    camera.SetClippingRange(200.0, 1200.0)
    # Template illumination follows scene lights.
    renderer.AutomaticLightCreationOff()
    renderer.RemoveAllLights()
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.PositionalOff()
    light.SetPosition(222.0, 435.0, 319.0)
    light.SetFocalPoint(122.0, 135.0, 75.0)
    light.SetIntensity(1.0)
    light.SetAmbientColor(1.0, 1.0, 1.0)
    light.SetDiffuseColor(1.0, 1.0, 1.0)
    light.SetSpecularColor(1.0, 1.0, 1.0)
    renderer.AddLight(light)
    renderer.TwoSidedLightingOn()
    return light


def write_window_png(window, path):
    """The window's last frame (back buffer) to a PNG."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def quarter_cut_mask(image):
    """A binary mask on the image's grid: 0 (masked out) in the top third of the slices and,
    below, where x is below the middle and y above it (the quarter that faces the scene's
    camera); 255 elsewhere. The scene's light comes from above, so it enters the cut."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    import numpy

    nx, ny, nz = image.GetDimensions()
    keep = numpy.full((nz, ny, nx), 255, dtype=numpy.uint8)
    keep[2 * nz // 3:, :, :] = 0
    keep[:, ny // 2:, :nx // 2] = 0
    mask = vtkImageData()
    mask.CopyStructure(image)
    mask.GetPointData().SetScalars(numpy_to_vtk(keep.ravel(), deep=True))
    return mask


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--input", default=os.path.join(data_directory(), "ct-head.mhd"))
    parser.add_argument("--output", default="ct-head-python.png")
    parser.add_argument("--size", default="512x512", help="WxH")
    parser.add_argument("--mode", choices=["template", "stock"], default="template")
    parser.add_argument("--no-shadows", action="store_true")
    parser.add_argument("--no-bleeding", action="store_true")
    parser.add_argument("--strength", type=float, default=1.0, help="OcclusionStrength")
    parser.add_argument("--cut-mask", action="store_true",
                        help="a binary mask that removes the skull cap and the quarter facing the camera")
    args = parser.parse_args(argv)
    width, height = (int(v) for v in args.size.lower().split("x"))
    if not os.environ.get("DISPLAY"):
        sys.exit("render_ct_head.py: no X display; run under bash scripts/xvfb.sh")

    reader = vtkScattererVolumeReader()
    reader.SetFileName(args.input)
    reader.Update()
    if reader.GetErrorMessage():
        sys.exit("render_ct_head.py: %s\nThe CT head is prepared by: bash scripts/prepare-data.sh"
                 % reader.GetErrorMessage())

    mapper = vtkScattererTemplateVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetBlendModeToComposite()
    mapper.AutoAdjustSampleDistancesOff()
    mapper.LockSampleDistanceToInputSpacingOff()
    mapper.SetSampleDistance(0.5)
    mapper.SetImageSampleDistance(1.0)
    mapper.UseJitteringOff()
    mapper.SetIlluminationEnabled(args.mode == "template")
    mapper.SetShadowsEnabled(not args.no_shadows)
    mapper.SetColorBleedingEnabled(not args.no_bleeding)
    mapper.SetOcclusionStrength(args.strength)
    if args.cut_mask:
        mask = quarter_cut_mask(reader.GetOutput())
        mapper.SetMaskInput(mask)
        mapper.SetMaskTypeToBinary()

    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(ct_head_property())

    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(0.0, 0.0, 0.0)
    apply_ct_head_view(renderer)

    window = vtkRenderWindow()
    window.SetSize(width, height)
    window.SetMultiSamples(0)
    window.SetDesiredUpdateRate(0.0001)  # a still (full-quality) frame
    window.AddRenderer(renderer)
    start = time.perf_counter()
    window.Render()
    elapsed_ms = 1000.0 * (time.perf_counter() - start)

    write_window_png(window, args.output)
    print("%s: %dx%d, %s, first frame %.0f ms (shader: %s)"
          % (args.output, width, height, args.mode, elapsed_ms, mapper.GetLastShaderFeatures()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
