#!/usr/bin/python3
"""Renders the Colin27 T1 MRI with the AAL atlas (116 regions) as a label-map mask, each
region in its own colour, lit by the scatterer-template illumination, and prints the
frame times.

    apt-get install mricron-data      # (scripts/install-deps.sh installs it)
    PYTHONPATH=build/lib/python3.11/dist-packages \\
      bash scripts/xvfb.sh /usr/bin/python3 Examples/python/render_mri_atlas.py --output atlas.png

The T1 intensities set the opacity (the brain's grey and white matter, not the CSF); the
label of each voxel (aal.nii.gz, on the T1's grid) picks its colour through the volume
property's per-label transfer functions (vtkVolumeProperty::SetLabelColor /
SetLabelScalarOpacity). Outside the atlas (label 0) nothing shows, so the scalp and skull
do not hide the brain. Options: --size WxH, --mode template|stock, --frames N.
"""
import argparse
import colorsys
import os
import statistics
import sys
import time

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
)

from scatterertemplate import vtkScattererTemplateVolumeMapper, vtkScattererVolumeReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_ct_head import write_window_png  # noqa: E402 (after the path is set)

TEMPLATES = "/usr/share/mricron/templates"


def read(path):
    reader = vtkScattererVolumeReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorMessage():
        sys.exit("render_mri_atlas.py: %s" % reader.GetErrorMessage())
    return reader.GetOutput()


def atlas_property(labels):
    """Label 0 transparent; each atlas label its own hue, opacity rising over T1 60..120."""
    prop = vtkVolumeProperty()
    nothing = vtkPiecewiseFunction()
    nothing.AddPoint(0, 0.0)
    nothing.AddPoint(255, 0.0)
    grey = vtkColorTransferFunction()
    grey.AddRGBPoint(0, 0.5, 0.5, 0.5)
    grey.AddRGBPoint(255, 1.0, 1.0, 1.0)
    prop.SetScalarOpacity(nothing)
    prop.SetColor(grey)
    for index, label in enumerate(labels):
        # Golden-ratio hues: neighbouring label numbers get far-apart colours.
        r, g, b = colorsys.hsv_to_rgb((index * 0.618034) % 1.0, 0.55, 0.95)
        color = vtkColorTransferFunction()
        color.AddRGBPoint(0, r, g, b)
        color.AddRGBPoint(255, r, g, b)
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(0, 0.0)
        opacity.AddPoint(60, 0.0)
        opacity.AddPoint(120, 0.6)
        opacity.AddPoint(255, 0.6)
        prop.SetLabelColor(label, color)
        prop.SetLabelScalarOpacity(label, opacity)
    prop.SetInterpolationTypeToLinear()
    prop.SetScalarOpacityUnitDistance(1.0)
    prop.SetAmbient(0.1)
    prop.SetDiffuse(0.9)
    return prop


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", default="mri-atlas.png")
    parser.add_argument("--size", default="512x512", help="WxH")
    parser.add_argument("--mode", choices=["template", "stock"], default="template")
    parser.add_argument("--frames", type=int, default=3, help="timed frames after the first")
    args = parser.parse_args(argv)
    width, height = (int(v) for v in args.size.lower().split("x"))
    if not os.environ.get("DISPLAY"):
        sys.exit("render_mri_atlas.py: no X display; run under bash scripts/xvfb.sh")
    t1 = read(os.path.join(TEMPLATES, "ch2.nii.gz"))
    atlas = read(os.path.join(TEMPLATES, "aal.nii.gz"))
    if t1.GetDimensions() != atlas.GetDimensions():
        sys.exit("render_mri_atlas.py: the atlas is not on the T1's grid")
    low, high = atlas.GetScalarRange()
    labels = list(range(1, int(high) + 1))

    mapper = vtkScattererTemplateVolumeMapper()
    mapper.SetInputData(t1)
    mapper.SetMaskInput(atlas)
    mapper.SetMaskTypeToLabelMap()
    mapper.SetMaskBlendFactor(1.0)
    mapper.SetBlendModeToComposite()
    mapper.AutoAdjustSampleDistancesOff()
    mapper.SetSampleDistance(0.5)
    mapper.UseJitteringOff()
    mapper.SetIlluminationEnabled(args.mode == "template")

    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(atlas_property(labels))
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(0.0, 0.0, 0.0)
    # From the front-left, above (LPS: -y is anterior, +x left, +z up); a headlight.
    camera = renderer.GetActiveCamera()
    bounds = t1.GetBounds()
    center = [0.5 * (bounds[2 * a] + bounds[2 * a + 1]) for a in range(3)]
    camera.SetFocalPoint(center)
    camera.SetPosition(center[0] + 0.6, center[1] - 1.0, center[2] + 0.5)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera(bounds)
    camera.Zoom(1.3)

    window = vtkRenderWindow()
    window.SetSize(width, height)
    window.SetMultiSamples(0)
    window.SetDesiredUpdateRate(0.0001)
    window.AddRenderer(renderer)
    start = time.perf_counter()
    window.Render()
    first_ms = 1000.0 * (time.perf_counter() - start)
    times = []
    for _ in range(max(0, args.frames)):
        camera.Azimuth(1.0)  # the headlight moves with the camera: the light is rebuilt
        start = time.perf_counter()
        window.Render()
        times.append(1000.0 * (time.perf_counter() - start))
    camera.Azimuth(-float(max(0, args.frames)))
    window.Render()

    write_window_png(window, args.output)
    median = statistics.median(times) if times else float("nan")
    print("%s: %dx%d, %s, %d labels, first frame %.0f ms, orbit frames median %.0f ms (%s)"
          % (args.output, width, height, args.mode, len(labels), first_ms, median,
             mapper.GetLastShaderFeatures()))


if __name__ == "__main__":
    main(sys.argv[1:])
