#!/usr/bin/python3
"""Opaque surfaces and a fly-through: two defects of docs/hard-cases.md, measured.

    PYTHONPATH=build/lib/python3.11/dist-packages LD_LIBRARY_PATH=build/lib \\
      bash scripts/xvfb.sh /usr/bin/python3 Benchmarks/accuracy/surface_probe.py

Each scene is drawn by the mapper's defaults and by stock Phong
(vtkOpenGLGPUVolumeRayCastMapper, Shade on) at 200 x 200 pixels; one CSV row per scene.

- torus: a smooth torus (64^3, the scalar ramping over a few voxels, a step of the opacity
  at 100) coloured (0.85, 0.6, 0.4), at an opacity of 1, 0.95 and 0.8 per voxel, under the
  renderer's headlight and under a directional light from +z. Every pixel of it under the
  headlight sees an unoccluded surface, so its picture should be smooth. Columns: the mean
  luminance (0-255) over the torus, the mapper's and Phong's, and the mapper's high-pass
  energy (mean |second difference| of the luminance) as a multiple of Phong's.
- tube: a straight tube (96^3, inner radius 14 voxels, wall 3 voxels at opacity 0.8), the
  camera and a positional light on its axis looking along it, the light at the camera or
  10 voxels ahead. Every point of the inner wall sees the light along a line through air,
  and the picture is the same all around its centre. Columns: the wall's mean luminance
  in rings of the picture 20-40, 40-60, 60-80 and 80-100 px from its centre, the mapper's
  and Phong's, and how much each varies around the circles of 40, 60 and 80 px (standard
  deviation over mean): dark rays along the grid's axes and diagonals.

--output DIR writes each scene's pair of pictures (Phong | mapper). About 10 seconds on
llvmpipe.
"""
import argparse
import os

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
import vtkmodules.vtkRenderingCore as core
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper

from scatterertemplate import vtkScattererTemplateVolumeMapper

PIXELS = 200


def image_of(scalars):
    """A vtkImageData of 1-unit voxels holding scalars[k, j, i] at voxel (i, j, k)."""
    image = vtkImageData()
    image.SetDimensions(scalars.shape[2], scalars.shape[1], scalars.shape[0])
    array = numpy_to_vtk(np.ascontiguousarray(scalars).ravel(), deep=True)
    array.SetName("scalars")
    image.GetPointData().SetScalars(array)
    return image


def torus(n=64):
    k, j, i = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    c = (n - 1) / 2
    ring = np.sqrt((i - c) ** 2 + (j - c) ** 2) - 0.3 * n
    d = np.sqrt(ring ** 2 + (k - c) ** 2)
    return image_of(np.clip(200 - (d - 0.1 * n) * 60, 0, 200).astype(np.uint8))


def tube(n=96):
    k, j, _ = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    c = (n - 1) / 2
    r = np.sqrt((j - c) ** 2 + (k - c) ** 2)
    return image_of(np.clip(200 * (1 - np.abs(r - 15.5) / 3.0), 0, 255).astype(np.uint8))


def volume_property(opacity, colour, shade):
    o = vtkPiecewiseFunction()
    for x, y in [(0, 0), (99, 0), (101, opacity), (255, opacity)]:
        o.AddPoint(x, y)
    c = core.vtkColorTransferFunction()
    for x in (0, 255):
        c.AddRGBPoint(x, *colour)
    p = core.vtkVolumeProperty()
    p.SetScalarOpacity(o)
    p.SetColor(c)
    p.SetInterpolationTypeToLinear()
    p.SetScalarOpacityUnitDistance(1.0)
    p.SetShade(1 if shade else 0)
    return p


def render(window, image, prop, phong, setup):
    """The picture (rows top down, RGB) of image drawn by the mapper or by stock Phong;
    setup(renderer) places the camera and the lights."""
    mapper = vtkOpenGLGPUVolumeRayCastMapper() if phong else vtkScattererTemplateVolumeMapper()
    mapper.SetInputData(image)
    volume = core.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = core.vtkRenderer()
    renderer.AddVolume(volume)
    setup(renderer)
    window.AddRenderer(renderer)
    window.Render()
    grab = core.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    picture = rgb.reshape(PIXELS, PIXELS, -1)[::-1, :, :3].copy()
    mapper.ReleaseGraphicsResources(window)
    window.RemoveRenderer(renderer)
    return picture


def luminance(picture):
    p = picture.astype(np.float64)
    return 0.2126 * p[..., 0] + 0.7152 * p[..., 1] + 0.0722 * p[..., 2]


def eroded(mask, steps):
    m = mask.copy()
    for _ in range(steps):
        e = m.copy()
        e[1:, :] &= m[:-1, :]
        e[:-1, :] &= m[1:, :]
        e[:, 1:] &= m[:, :-1]
        e[:, :-1] &= m[:, 1:]
        m = e
    return m


def high_pass(lum, mask):
    """Mean |second difference| along rows and columns inside mask."""
    dx = np.abs(lum[:, 2:] - 2 * lum[:, 1:-1] + lum[:, :-2])
    dy = np.abs(lum[2:, :] - 2 * lum[1:-1, :] + lum[:-2, :])
    mx = mask[:, 1:-1] & mask[:, 2:] & mask[:, :-2]
    my = mask[1:-1, :] & mask[2:, :] & mask[:-2, :]
    return float(np.concatenate([dx[mx], dy[my]]).mean())


def torus_setup(light):
    def setup(renderer):
        n = 64
        c = (n - 1) / 2
        view = np.array([1.0, -1.2, 0.8])
        view /= np.linalg.norm(view)
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(c, c, c)
        camera.SetPosition(*(c + view * (n - 1) * 3))
        camera.SetViewUp(0, 0, 1)
        renderer.ResetCamera()
        camera.Dolly(1.6)
        renderer.ResetCameraClippingRange()
        if light == "+z":
            renderer.AutomaticLightCreationOff()
            l = core.vtkLight()
            l.SetLightTypeToSceneLight()
            l.PositionalOff()
            l.SetPosition(c, c, c + (n - 1) * 3)
            l.SetFocalPoint(c, c, c)
            renderer.AddLight(l)

    return setup


def tube_setup(light_x):
    def setup(renderer):
        n = 96
        c = (n - 1) / 2
        renderer.AutomaticLightCreationOff()
        l = core.vtkLight()
        l.SetLightTypeToSceneLight()
        l.PositionalOn()
        l.SetPosition(light_x, c + 0.3, c + 0.2)
        l.SetFocalPoint(n, c, c)
        l.SetConeAngle(180)
        l.SetAttenuationValues(1, 0, 0)
        renderer.AddLight(l)
        camera = renderer.GetActiveCamera()
        camera.SetPosition(10, c, c)
        camera.SetFocalPoint(n, c, c)
        camera.SetViewUp(0, 0, 1)
        camera.SetViewAngle(70)
        camera.SetClippingRange(0.5, 200)

    return setup


def write_pair(directory, name, phong, mapper):
    pair = np.concatenate([phong, np.full((PIXELS, 3, 3), 80, np.uint8), mapper], axis=1)
    image = vtkImageData()
    image.SetDimensions(pair.shape[1], pair.shape[0], 1)
    array = numpy_to_vtk(np.ascontiguousarray(pair[::-1]).reshape(-1, 3), deep=True)
    image.GetPointData().SetScalars(array)
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(os.path.join(directory, name + ".png"))
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", help="a folder for the pictures")
    args = parser.parse_args()
    if args.output:
        os.makedirs(args.output, exist_ok=True)
    window = core.vtkRenderWindow()
    window.SetSize(PIXELS, PIXELS)
    window.SetMultiSamples(0)
    window.SetDesiredUpdateRate(0.0001)

    print("scene,light,opacity,mean,phong_mean,high_pass_over_phong")
    image = torus()
    for light in ("headlight", "+z"):
        for opacity in (1.0, 0.95, 0.8):
            pictures = [
                render(window, image, volume_property(opacity, (0.85, 0.6, 0.4), phong), phong,
                    torus_setup(light))
                for phong in (True, False)
            ]
            phong_lum, lum = (luminance(p) for p in pictures)
            mask = eroded(pictures[0].max(axis=2) > 3, 3)
            print("torus,%s,%.2f,%.1f,%.1f,%.2f" % (light, opacity, lum[mask].mean(),
                phong_lum[mask].mean(), high_pass(lum, mask) / high_pass(phong_lum, mask)),
                flush=True)
            if args.output:
                write_pair(args.output, "torus-%s-%.2f" % (light.replace("+", ""), opacity),
                    *pictures)

    print("scene,light,ring_20_40,ring_40_60,ring_60_80,ring_80_100,"
          "phong_rings,around_40,around_60,around_80,phong_around")
    image = tube()
    rows, columns = np.mgrid[0:PIXELS, 0:PIXELS]
    radius = np.hypot(rows - PIXELS // 2, columns - PIXELS // 2)
    angles = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    for name, light_x in (("at the camera", 12.0), ("10 voxels ahead", 22.0)):
        pictures = [
            render(window, image, volume_property(0.8, (0.9, 0.6, 0.5), phong), phong,
                tube_setup(light_x))
            for phong in (True, False)
        ]
        measures = []
        for picture in pictures:
            lum = luminance(picture)
            rings = [lum[(radius >= a) & (radius < a + 20)].mean() for a in (20, 40, 60, 80)]
            around = []
            for r in (40, 60, 80):
                v = lum[(PIXELS // 2 + r * np.sin(angles)).astype(int),
                        (PIXELS // 2 + r * np.cos(angles)).astype(int)]
                around.append(v.std() / v.mean())
            measures.append((rings, around))
        (phong_rings, phong_around), (rings, around) = measures
        print("tube,%s,%s,%s,%s,%s" % (name, ",".join("%.0f" % v for v in rings),
            "/".join("%.0f" % v for v in phong_rings), ",".join("%.3f" % v for v in around),
            "/".join("%.3f" % v for v in phong_around)), flush=True)
        if args.output:
            write_pair(args.output, "tube-" + name.split()[0], *pictures)


if __name__ == "__main__":
    main()
