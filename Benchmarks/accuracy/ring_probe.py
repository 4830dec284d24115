#!/usr/bin/python3
"""The crown's rings on a synthetic surface: how much a smooth, evenly lit surface ripples.

    PYTHONPATH=build/lib/python3.11/dist-packages LD_LIBRARY_PATH=build/lib \\
      bash scripts/xvfb.sh /usr/bin/python3 Benchmarks/accuracy/ring_probe.py

A thick "bone" slab (opacity 0.8 per mm, as the CT head's bone) under a smooth surface
(a logistic edge 0.7 voxel wide, as a CT's partial volume) that rises 0.1 voxel per voxel
along x, on a grid of 96 x 96 x 64 voxels of 1 x 1 x 1.5 mm (the CT head's slices), lit by
one directional light and seen from above in parallel projection, single scattering
(MultipleScattering 0, where the rings are starkest). Every column of the surface is lit
alike, so what the picture shows across x and y beyond a smooth trend is the transport
grid's: the surface climbs through the texel layers along x (one layer every 20 voxels
at TransportScale 2), which is what draws the CT head's crown in rings
(docs/accuracy.md, "Bands on the crown"), and an oblique light's sweep runs along y.

Prints one CSV row per light: the mean brightness (0-255) and the ripple, the standard
deviation of the brightness less its moving average over 20 voxels, in % of the mean,
across x (the texel layers) and along y. --output writes the pictures (light index
appended). A few seconds on llvmpipe.
"""
import argparse
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
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
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from scatterertemplate import vtkScattererTemplateVolumeMapper

SIZE, DEPTH, SPACING_Z = 96, 64, 1.5
PIXELS = 384  # 4 pixels a voxel
# Light directions (toward the light): grazing along y, the CT head benchmark's kind of
# obliquity, and straight above.
DEFAULT_LIGHTS = ["0,-0.8,0.6", "-0.5,0,0.86", "0,0,1"]


def tilted_slab():
    k, _, i = np.meshgrid(np.arange(DEPTH), np.arange(SIZE), np.arange(SIZE), indexing="ij")
    surface = 20.0 + 0.1 * i
    scalars = 200.0 / (1.0 + np.exp((k - surface) / 0.7))
    image = vtkImageData()
    image.SetDimensions(SIZE, SIZE, DEPTH)
    image.SetSpacing(1.0, 1.0, SPACING_Z)
    array = numpy_to_vtk(scalars.ravel().astype(np.float32), deep=True)
    array.SetName("bone")
    image.GetPointData().SetScalars(array)
    return image


def bone_property():
    opacity = vtkPiecewiseFunction()
    for x, y in [(0, 0.0), (50, 0.0), (150, 0.8), (255, 0.8)]:
        opacity.AddPoint(x, y)
    color = vtkColorTransferFunction()
    color.AddRGBPoint(0, 1.0, 1.0, 0.95)
    color.AddRGBPoint(255, 1.0, 1.0, 0.95)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetInterpolationTypeToLinear()
    prop.SetScalarOpacityUnitDistance(1.0)
    prop.SetAmbient(0.1)
    prop.SetDiffuse(0.9)
    return prop


def ripple(profile, window):
    """Standard deviation of `profile` less its moving average, in % of its mean."""
    kernel = np.ones(window) / window
    padded = np.pad(profile, window // 2, mode="edge")
    trend = np.convolve(padded, kernel, mode="valid")[: len(profile)]
    detail = (profile - trend)[window:-window]
    return 100.0 * detail.std() / profile.mean()


def render(image, toward, scale, multiple_scattering, output):
    mapper = vtkScattererTemplateVolumeMapper()
    mapper.SetInputData(image)
    mapper.SetTransportScale(scale)
    mapper.SetMultipleScattering(multiple_scattering)
    mapper.AutoAdjustSampleDistancesOff()
    mapper.SetSampleDistance(0.5)
    mapper.UseJitteringOff()
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(bone_property())
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.RemoveAllLights()
    centre = np.array([SIZE / 2.0, SIZE / 2.0, DEPTH * SPACING_Z / 2.0])
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetFocalPoint(*centre)
    light.SetPosition(*(centre + 100.0 * toward))
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + np.array([0.0, 0.0, 200.0])))
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetParallelScale(SIZE / 2.0)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(PIXELS, PIXELS)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    if output:
        writer = vtkPNGWriter()
        writer.SetFileName(output)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
    rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    return rgb.reshape(PIXELS, PIXELS, -1)[:, :, :3].astype(float).mean(axis=2)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--light", action="append",
                        help="direction toward a light, x,y,z (repeatable; default: %s)"
                        % " ".join(DEFAULT_LIGHTS))
    parser.add_argument("--transport-scale", type=int, default=2)
    parser.add_argument("--multiple-scattering", type=float, default=0.0)
    parser.add_argument("--output", help="PNG path prefix for the pictures")
    args = parser.parse_args(argv)
    image = tilted_slab()
    band = slice(PIXELS // 5, PIXELS - PIXELS // 5)  # clear of the slab's sides
    window = 20 * PIXELS // SIZE  # 20 voxels: one texel layer's climb at scale 2
    print("light,transport_scale,multiple_scattering,mean,ripple_across_layers_pct,"
          "ripple_along_y_pct")
    for n, text in enumerate(args.light or DEFAULT_LIGHTS):
        toward = np.array([float(v) for v in text.split(",")])
        if toward.shape != (3,) or not np.linalg.norm(toward) > 0.0:
            sys.exit("ring_probe.py: --light takes three numbers x,y,z, not all 0: %s" % text)
        toward /= np.linalg.norm(toward)
        output = "%s-%d.png" % (args.output, n) if args.output else None
        picture = render(image, toward, args.transport_scale, args.multiple_scattering, output)
        across = picture[band, :].mean(axis=0)[PIXELS // 20: -PIXELS // 20]
        along = picture[:, band].mean(axis=1)[PIXELS // 20: -PIXELS // 20]
        print('"%s",%d,%g,%.1f,%.2f,%.2f' % (text, args.transport_scale, args.multiple_scattering,
                                            picture[band, band].mean(), ripple(across, window),
                                            ripple(along, window)))


if __name__ == "__main__":
    main(sys.argv[1:])
