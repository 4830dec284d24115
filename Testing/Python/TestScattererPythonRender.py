"""A small render from Python (under Xvfb): a ball above a plate, template illumination on.
Checks that the image is not blank, that the illumination shader ran
(GetLastShaderFeatures), and that illumination changes the picture."""
import os
import sys

from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
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

from scatterertemplate import vtkScattererTemplateVolumeMapper

if not os.environ.get("DISPLAY"):
    print("TestScattererPythonRender: needs an X display (run under xvfb-run)")
    sys.exit(1)
out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out_dir, exist_ok=True)

N = 48
image = vtkImageData()
image.SetDimensions(N, N, N)
image.SetSpacing(1.0, 1.0, 1.0)
scalars = vtkUnsignedCharArray()
scalars.SetName("density")
scalars.SetNumberOfTuples(N * N * N)
c, r = (N - 1) / 2.0, N * 0.22
i = 0
for z in range(N):
    for y in range(N):
        for x in range(N):
            v = 0
            if (x - c) ** 2 + (y - c) ** 2 + (z - c - 6) ** 2 <= r * r:
                v = 200  # ball
            elif 6 <= z <= 10 and 4 <= x < N - 4 and 4 <= y < N - 4:
                v = 100  # plate
            scalars.SetValue(i, v)
            i += 1
image.GetPointData().SetScalars(scalars)

opacity = vtkPiecewiseFunction()
opacity.AddPoint(0, 0.0)
opacity.AddPoint(50, 0.0)
opacity.AddPoint(90, 0.6)
opacity.AddPoint(255, 0.9)
color = vtkColorTransferFunction()
color.AddRGBPoint(0, 0.0, 0.0, 0.0)
color.AddRGBPoint(100, 0.9, 0.9, 0.9)
color.AddRGBPoint(200, 1.0, 0.6, 0.4)
prop = vtkVolumeProperty()
prop.SetScalarOpacity(opacity)
prop.SetColor(color)
prop.SetInterpolationTypeToLinear()

mapper = vtkScattererTemplateVolumeMapper()
mapper.SetInputData(image)
mapper.SetBlendModeToComposite()
mapper.AutoAdjustSampleDistancesOff()
mapper.SetSampleDistance(0.5)
mapper.UseJitteringOff()
mapper.AddScalarRangeMaterial(80, 150, 1.4, 0.9, 0.9, 0.9)
mapper.AddScalarRangeMaterial(150, 255, 1.5, 1.0, 0.5, 0.3)
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)

renderer = vtkRenderer()
renderer.AddVolume(volume)
renderer.SetBackground(0, 0, 0)
renderer.AutomaticLightCreationOff()
light = vtkLight()
light.SetLightTypeToSceneLight()
light.PositionalOff()
light.SetPosition(c + 20, c - 10, N * 3)
light.SetFocalPoint(c, c, c)
renderer.AddLight(light)
window = vtkRenderWindow()
window.SetSize(160, 160)
window.SetMultiSamples(0)
window.AddRenderer(renderer)
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(c, c, c)
camera.SetPosition(c, c - 3 * N, c + 1.5 * N)
camera.SetViewUp(0, 0, 1)
renderer.ResetCamera()


def grab():
    window.Render()
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(window)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    img = w2i.GetOutput()
    arr = img.GetPointData().GetScalars()
    values = [arr.GetValue(k) for k in range(arr.GetNumberOfValues())]
    return img, values


failures = []
lit_image, lit = grab()
features = mapper.GetLastShaderFeatures()
print("features:", features)
writer = vtkPNGWriter()
writer.SetFileName(os.path.join(out_dir, "TestScattererPythonRender.png"))
writer.SetInputData(lit_image)
writer.Write()
nonzero = sum(1 for v in lit if v > 8)
print("non-black values: %d of %d" % (nonzero, len(lit)))
if nonzero < len(lit) // 50:
    failures.append("the image is blank")
if features.startswith("stock") or "shadow" not in features:
    failures.append("illumination not active: %r" % features)
if mapper.GetNumberOfActiveMaterials() != 2:
    failures.append("expected 2 active materials, got %d" % mapper.GetNumberOfActiveMaterials())

mapper.IlluminationEnabledOff()
_, stock = grab()
if not mapper.GetLastShaderFeatures().startswith("stock"):
    failures.append("IlluminationEnabledOff did not give the stock path: %r"
                    % mapper.GetLastShaderFeatures())
diff = sum(abs(a - b) for a, b in zip(lit, stock))
print("sum |lit - stock| = %d" % diff)
if diff == 0:
    failures.append("illumination did not change the image")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
