#!/usr/bin/python3
"""Mean brightness of the CT head scene under stock VTK and under the illumination.

    PYTHONPATH=build/lib/python3.11/dist-packages \\
      bash scripts/xvfb.sh /usr/bin/python3 Benchmarks/brightness/measure_brightness.py

Renders the ct-head scene (Examples/python/render_ct_head.py: transfer functions, camera,
one directional scene light with white ambient, diffuse and specular colours) at 256x256
and prints, per setting, the mean luminance (Rec. 709, 0-255) of the pixels that stock
composite rendering draws (luminance > 8), its ratio to stock composite and to stock
Phong, the share of clipped pixels (>= 250), and on the lit faces alone (the quarter of
those pixels that stock Phong draws brightest: surfaces that face the light, unoccluded)
its mean over stock Phong's there. docs/brightness.md shows the numbers.
"""
import importlib.util
import os

import numpy as np

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import (
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper

from scatterertemplate import vtkScattererTemplateVolumeMapper, vtkScattererVolumeReader

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location(
    "render_ct_head", os.path.join(HERE, "..", "..", "Examples", "python", "render_ct_head.py"))
scene = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scene)


def main():
    reader = vtkScattererVolumeReader()
    reader.SetFileName(os.path.join(scene.data_directory(), "ct-head.mhd"))
    reader.Update()
    image = reader.GetOutput()

    window = vtkRenderWindow()
    window.SetSize(256, 256)
    window.SetMultiSamples(0)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    light = scene.apply_ct_head_view(renderer)
    volume = vtkVolume()
    renderer.AddVolume(volume)

    def luminance(mapper, shade=False, intensity=1.0, ambient=0.1, multiple_scattering=None):
        prop = scene.ct_head_property()
        prop.SetShade(shade)
        prop.SetAmbient(ambient)
        light.SetIntensity(intensity)
        if multiple_scattering is not None:
            mapper.SetMultipleScattering(multiple_scattering)
        mapper.SetInputData(image)
        mapper.AutoAdjustSampleDistancesOff()
        mapper.LockSampleDistanceToInputSpacingOff()
        mapper.SetSampleDistance(0.5)
        mapper.UseJitteringOff()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.Update()
        rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)[:, :3]
        return 0.2126 * rgb[:, 0] + 0.7152 * rgb[:, 1] + 0.0722 * rgb[:, 2]

    stock = luminance(vtkOpenGLGPUVolumeRayCastMapper())
    phong = luminance(vtkOpenGLGPUVolumeRayCastMapper(), shade=True)
    drawn = stock > 8.0
    lit_faces = drawn & (phong >= np.quantile(phong[drawn], 0.75))
    print("setting,mean_luminance,ratio_to_stock,ratio_to_phong,clipped_percent,"
          "lit_faces_ratio_to_phong")

    def report(name, lum):
        mean = lum[drawn].mean()
        print("%s,%.1f,%.2f,%.2f,%.1f,%.2f" % (name, mean, mean / stock[drawn].mean(),
              mean / phong[drawn].mean(), 100.0 * (lum[drawn] >= 250.0).mean(),
              lum[lit_faces].mean() / phong[lit_faces].mean()))

    report("stock composite", stock)
    report("stock Phong (Shade on)", phong)
    illuminated = vtkScattererTemplateVolumeMapper
    report("transport (default)", luminance(illuminated()))
    report("transport light intensity 0.5", luminance(illuminated(), intensity=0.5))
    report("transport light intensity 1.5", luminance(illuminated(), intensity=1.5))
    report("transport light intensity 2.0", luminance(illuminated(), intensity=2.0))
    report("transport ambient 0.3", luminance(illuminated(), ambient=0.3))
    report("transport MultipleScattering 0", luminance(illuminated(), multiple_scattering=0.0))
    report("transport MultipleScattering 2", luminance(illuminated(), multiple_scattering=2.0))
    report("transport Shade on", luminance(illuminated(), shade=True))


if __name__ == "__main__":
    main()
