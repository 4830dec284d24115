"""vtkScattererTemplateSource from Python: the output arrays (read with numpy when it is
installed, else through the VTK arrays), determinism, save/load and errors."""
import os
import sys
import tempfile

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand

from scatterertemplate import vtkScattererMaterial, vtkScattererTemplateSource

try:
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:  # python3-numpy is optional
    vtk_to_numpy = None

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def values(array):
    if vtk_to_numpy is not None:
        return list(vtk_to_numpy(array))
    return [array.GetValue(i) for i in range(array.GetNumberOfTuples())]


def make_source():
    skin = vtkScattererMaterial()
    skin.SetName("skin")
    skin.SetOpacity(0.3)
    skin.SetRefractiveIndex(1.4)
    skin.SetScalarRange(-450.0, -50.0)
    bone = vtkScattererMaterial()
    bone.SetName("bone")
    bone.SetOpacity(0.8)
    bone.SetRefractiveIndex(1.6)
    bone.SetDiffuseColor(1.0, 1.0, 0.9)
    bone.SetScalarRange(300.0, 3000.0)
    src = vtkScattererTemplateSource()
    src.AddMaterial(skin)
    src.AddMaterial(bone)
    src.SetTemplatesPerMaterial(3)
    return src


src = make_source()
src.SetTemplateRadius(2.0)
src.Update()
out = src.GetOutput()
n = out.GetNumberOfPoints()
check(n > 0, "the source outputs photons")
check(n == src.GetNumberOfPhotons(), "points == GetNumberOfPhotons()")
check(src.GetNumberOfTemplates() == 6, "2 materials x 3 templates")
check(out.GetNumberOfVerts() == n, "one vertex cell per photon")
pd = out.GetPointData()
intensity = pd.GetArray("Intensity")
template_id = pd.GetArray("TemplateId")
material_id = pd.GetArray("MaterialId")
check(intensity is not None and template_id is not None and material_id is not None,
      "Intensity, TemplateId and MaterialId arrays")
check(pd.GetScalars().GetName() == "Intensity", "Intensity is the active scalars")
inten, tids, mids = values(intensity), values(template_id), values(material_id)
check(all(0.0 < v <= 1.0 for v in inten), "intensities in (0, 1]")
check(set(int(t) for t in tids) == {0, 1, 2}, "template ids 0..2")
check(set(int(mm) for mm in mids) == {0, 1}, "material ids 0..1")
for i in range(n):  # |p| <= radius
    x, y, z = out.GetPoint(i)
    if (x * x + y * y + z * z) ** 0.5 > 2.0 + 1e-9:
        check(False, "photon %d outside the template radius" % i)
        break
names = out.GetFieldData().GetAbstractArray("MaterialName")
check(names is not None and names.GetValue(0) == "skin" and names.GetValue(1) == "bone",
      "field data MaterialName")
check(abs(src.GetMaxLedgerResidual()) < 1e-9, "energy ledger balanced")

# Deterministic: a second source gives the same points.
again = make_source()
again.SetTemplateRadius(2.0)
again.Update()
check(again.GetOutput().GetNumberOfPoints() == n, "deterministic photon count")
check(values(again.GetOutput().GetPointData().GetArray("Intensity")) == inten,
      "deterministic intensities")

# Save and load.
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, "templates.bin")
    check(src.SaveTemplates(path), "SaveTemplates")
    loaded = vtkScattererTemplateSource()
    check(loaded.LoadTemplates(path), "LoadTemplates")
    loaded.SetTemplateRadius(2.0)
    loaded.Update()
    check(loaded.GetNumberOfMaterials() == 2 and loaded.GetMaterial(1).GetName() == "bone",
          "loaded materials")
    check(loaded.GetOutput().GetNumberOfPoints() == n, "loaded photons")
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(_obj, _event, text):
        errors.append(text)

    loaded.AddObserver(vtkCommand.ErrorEvent, on_error)
    check(not loaded.LoadTemplates(os.path.join(tmp, "missing.bin")), "missing file fails")
    check(len(errors) >= 1, "missing file reports an error")

# An invalid material (lo > hi) is an error and an empty output.
bad = vtkScattererMaterial()
bad.SetScalarRange(10.0, 1.0)
bsrc = vtkScattererTemplateSource()
bsrc.AddMaterial(bad)
errors = []


@calldata_type(VTK_STRING)
def on_bad(_obj, _event, text):
    errors.append(text)


bsrc.AddObserver(vtkCommand.ErrorEvent, on_bad)
bsrc.Update()
check(bsrc.GetOutput().GetNumberOfPoints() == 0 and errors, "invalid material: error, empty output")

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("TestScattererPythonTemplateSource: OK (%d photons)" % n)
