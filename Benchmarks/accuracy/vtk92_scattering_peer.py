#!/usr/bin/env python3
"""VTK's own volumetric scattering (VTK >= 9.2) as a peer in the accuracy benchmark.

Run by scatterer-bench-accuracy (--peer-python) with ParaView 5.11's VTK 9.2 Python
modules first on PYTHONPATH (see run_accuracy_benchmark.sh and shared/vtk91-notes.md:
python3-paraview is unpacked into a private folder, never installed). Reads the scene the
benchmark exported (volume .vti + scene JSON: transfer functions, camera, lights, sample
distance), renders it with vtkOpenGLGPUVolumeRayCastMapper, Shade on,
GlobalIlluminationReach 0.1 / 0.5 / 1.0 and VolumetricScatteringBlending 1.0 (the
peer_configs of shared/scenes/ct-head.json), a warm-up frame then N timed frames, and
writes one PNG per reach and a CSV (scene,config,frames,median_ms,png).
"""
import argparse
import json
import statistics
import sys
import time

from vtkmodules.vtkCommonCore import vtkVersion
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (object factory)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--volume", required=True)
    ap.add_argument("--scene", required=True)
    ap.add_argument("--name", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--frames", type=int, default=3)
    ap.add_argument("--reaches", default="0.1,0.5,1.0")
    a = ap.parse_args()
    s = json.load(open(a.scene))
    if not hasattr(vtkOpenGLGPUVolumeRayCastMapper, "SetGlobalIlluminationReach"):
        sys.exit("this VTK (%s) has no volumetric scattering" % vtkVersion.GetVTKVersion())
    reader = vtkXMLImageDataReader()
    reader.SetFileName(a.volume)
    reader.Update()
    image = reader.GetOutput()

    window = vtkRenderWindow()
    window.SetSize(s["width"], s["height"])
    window.SetMultiSamples(0)
    window.SetDesiredUpdateRate(0.0001)  # still render: scattering is off on interactive frames
    rows = []
    for reach in [float(r) for r in a.reaches.split(",")]:
        opacity = vtkPiecewiseFunction()
        for x, y in s["opacity"]:
            opacity.AddPoint(x, y)
        color = vtkColorTransferFunction()
        for x, r, g, b in s["color"]:
            color.AddRGBPoint(x, r, g, b)
        prop = vtkVolumeProperty()
        prop.SetScalarOpacity(opacity)
        prop.SetColor(color)
        prop.SetInterpolationTypeToLinear()
        prop.SetScalarOpacityUnitDistance(s["unit_distance"])
        prop.SetAmbient(s["ambient"])
        prop.SetDiffuse(s["diffuse"])
        prop.SetSpecular(s["specular"])
        prop.SetSpecularPower(s["specular_power"])
        prop.ShadeOn()
        prop.SetScatteringAnisotropy(0.0)
        mapper = vtkOpenGLGPUVolumeRayCastMapper()
        mapper.SetInputData(image)
        mapper.SetBlendModeToComposite()
        mapper.AutoAdjustSampleDistancesOff()
        mapper.LockSampleDistanceToInputSpacingOff()
        mapper.SetSampleDistance(s["sample_distance"])
        mapper.SetImageSampleDistance(1.0)
        mapper.UseJitteringOff()
        mapper.SetGlobalIlluminationReach(reach)
        mapper.SetVolumetricScatteringBlending(1.0)
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        ren = vtkRenderer()
        ren.SetBackground(0, 0, 0)
        ren.AddVolume(volume)
        cam = ren.GetActiveCamera()
        c = s["camera"]
        cam.SetPosition(*c["position"])
        cam.SetFocalPoint(*c["focal_point"])
        cam.SetViewUp(*c["view_up"])
        cam.SetViewAngle(c["view_angle"])
        cam.SetClippingRange(*c["clipping_range"])
        ren.AutomaticLightCreationOff()
        ren.RemoveAllLights()
        for l in s["lights"]:
            light = vtkLight()
            light.SetLightTypeToSceneLight()
            light.SetPositional(l["positional"])
            light.SetPosition(*l["position"])
            light.SetFocalPoint(*l["focal_point"])
            light.SetConeAngle(l.get("cone_angle", 30.0))
            light.SetIntensity(l["intensity"])
            light.SetDiffuseColor(*l["diffuse_color"])
            light.SetAmbientColor(1, 1, 1)
            light.SetSpecularColor(1, 1, 1)
            ren.AddLight(light)
        ren.SetTwoSidedLighting(True)
        rens = window.GetRenderers()
        rens.RemoveAllItems()
        window.AddRenderer(ren)
        t0 = time.perf_counter()
        window.Render()
        warm = time.perf_counter() - t0
        frames = 1 if warm > 8.0 else a.frames
        ms = []
        for _ in range(frames):
            t0 = time.perf_counter()
            window.Render()
            window.WaitForCompletion()
            ms.append(1000.0 * (time.perf_counter() - t0))
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.ReadFrontBufferOff()
        grab.SetInputBufferTypeToRGB()
        grab.Update()
        name = "vtk92_scattering_reach%.1f" % reach
        png = "%s/%s-%s.png" % (a.out, a.name, name)
        w = vtkPNGWriter()
        w.SetInputConnection(grab.GetOutputPort())
        w.SetFileName(png)
        w.Write()
        rows.append((a.name, name, frames, statistics.median(ms), png))
        print("%-12s %-32s %9.1f ms (VTK %s)" % (a.name, name, statistics.median(ms),
                                                 vtkVersion.GetVTKVersion()), flush=True)
    with open("%s/peer-%s.csv" % (a.out, a.name), "w") as f:
        f.write("scene,config,frames,median_ms,png\n")
        for r in rows:
            f.write("%s,%s,%d,%.3f,%s\n" % r)


if __name__ == "__main__":
    main()
