#!/usr/bin/python3
"""An unoccluded face toward a light: how bright the illumination shows it against stock Phong.

    PYTHONPATH=build/lib/python3.11/dist-packages \\
      bash scripts/xvfb.sh /usr/bin/python3 Benchmarks/brightness/measure_faces.py

A slab across a 64^3 volume (voxels 28-47 along z, dense: opacity 0.9 per unit; or
voxels 45-47, thin: 0.3 per unit; linear interpolation), grey of albedo 0.3, 0.8 or 1.0,
lit straight onto its top face by one directional scene light (intensity 1, VTK's
default diffuse 0.7, no specular), seen obliquely at 200x200. Prints one CSV row per
slab: the mean brightness (0-255) of the face's middle under stock Phong (`Shade` on),
and the illumination's over Phong's there with single scattering alone
(`MultipleScattering` 0) and with the defaults. docs/brightness.md shows the numbers.
"""
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkLight,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from scatterertemplate import vtkScattererTemplateVolumeMapper

N = 64
SIZE = 200


def slab(first, last):
    voxels = np.zeros((N, N, N), np.uint8)  # [k][j][i]
    voxels[first:last + 1, 4:N - 4, 4:N - 4] = 200
    image = vtkImageData()
    image.SetDimensions(N, N, N)
    image.GetPointData().SetScalars(numpy_to_vtk(voxels.ravel(), deep=1))
    return image


def main():
    window = vtkRenderWindow()
    window.SetSize(SIZE, SIZE)
    window.SetMultiSamples(0)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    renderer.AutomaticLightCreationOff()
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetFocalPoint(0, 0, 0)
    light.SetPosition(0, 0, 1)  # onto the top face, along its normal
    renderer.AddLight(light)
    volume = vtkVolume()
    renderer.AddVolume(volume)

    def face(mapper, image, grey, alpha, shade):
        colour = vtkColorTransferFunction()
        colour.AddRGBPoint(0, grey, grey, grey)
        colour.AddRGBPoint(255, grey, grey, grey)
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(0, 0.0)
        opacity.AddPoint(100, 0.0)
        opacity.AddPoint(200, alpha)
        opacity.AddPoint(255, alpha)
        prop = vtkVolumeProperty()
        prop.SetColor(colour)
        prop.SetScalarOpacity(opacity)
        prop.SetInterpolationTypeToLinear()
        prop.SetShade(shade)
        prop.SetSpecular(0.0)
        mapper.SetInputData(image)
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        camera = renderer.GetActiveCamera()
        c = 0.5 * (N - 1)
        camera.SetFocalPoint(c, c, c)
        camera.SetPosition(c + 30, c - 40, c + 150)
        camera.SetViewUp(0, 1, 0)
        renderer.ResetCamera()
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.Update()
        rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
        rgb = rgb.reshape(SIZE, SIZE, -1)[:, :, :3].astype(float)
        middle = slice(3 * SIZE // 8, 5 * SIZE // 8)
        return rgb[middle, middle].mean()

    print("slab,albedo,phong,single_scattering_over_phong,default_over_phong")
    for name, first, last, alpha in (("dense", 28, 47, 0.9), ("thin", 45, 47, 0.3)):
        image = slab(first, last)
        for grey in (0.3, 0.8, 1.0):
            phong = face(vtkOpenGLGPUVolumeRayCastMapper(), image, grey, alpha, True)
            single = vtkScattererTemplateVolumeMapper()
            single.SetMultipleScattering(0.0)
            single = face(single, image, grey, alpha, False)
            default = face(vtkScattererTemplateVolumeMapper(), image, grey, alpha, False)
            print("%s,%.1f,%.1f,%.2f,%.2f" % (name, grey, phong, single / phong, default / phong))


if __name__ == "__main__":
    main()
