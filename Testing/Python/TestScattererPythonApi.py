"""The wrapped API from Python: import, setter round-trips (including the custom
clamp/switch macros of the mapper), clamping warnings, NaN errors and array arguments."""
import math
import os
import re
import sys

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand

import scatterertemplate
from scatterertemplate import (
    vtkScattererMaterial,
    vtkScattererTemplateSource,
    vtkScattererTemplateVersion,
    vtkScattererTemplateVolumeMapper,
    vtkScattererVolumeReader,
)

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


class Messages:
    """Collects the WarningEvent / ErrorEvent texts of one VTK object."""

    def __init__(self, obj):
        self.warnings, self.errors = [], []
        obj.AddObserver(vtkCommand.WarningEvent, self.on_warning)
        obj.AddObserver(vtkCommand.ErrorEvent, self.on_error)

    @calldata_type(VTK_STRING)
    def on_warning(self, _obj, _event, text):
        self.warnings.append(text)

    @calldata_type(VTK_STRING)
    def on_error(self, _obj, _event, text):
        self.errors.append(text)

    def clear(self):
        self.warnings.clear()
        self.errors.clear()


# --- the package -------------------------------------------------------------------------
for name in scatterertemplate.__all__:
    check(hasattr(scatterertemplate, name), "scatterertemplate." + name + " missing")
m = vtkScattererTemplateVolumeMapper()
# One version number: what CMake configured, the C++ getter and __version__ agree.
expected_version = os.environ.get("SCATTERER_EXPECTED_VERSION", "")
check(bool(re.fullmatch(r"\d+\.\d+\.\d+", expected_version)), "the test knows the version")
check(scatterertemplate.__version__ == expected_version,
      "__version__ %r is the configured %r" % (scatterertemplate.__version__, expected_version))
check(vtkScattererTemplateVersion.GetVersion() == expected_version, "GetVersion()")
check("%d.%d.%d" % (vtkScattererTemplateVersion.GetMajorVersion(),
                    vtkScattererTemplateVersion.GetMinorVersion(),
                    vtkScattererTemplateVersion.GetPatchVersion()) == expected_version,
      "major.minor.patch")
check(m.GetClassName() == "vtkScattererTemplateVolumeMapper", "class name")
check(m.IsA("vtkOpenGLGPUVolumeRayCastMapper"), "the mapper is a vtkOpenGLGPUVolumeRayCastMapper")

# --- mapper: defaults and round-trips of every setter made by the custom macros --------------
defaults = {
    "IlluminationEnabled": True, "ShadowsEnabled": True, "ColorBleedingEnabled": True,
    "ThinPartCheckEnabled": True, "BoundaryRefractionEnabled": True,
    "TemplateBlendingEnabled": False, "IlluminationMode": 0, "TransportScale": 2,
    "InteractiveTransportScale": 4, "MaximumTransportVoxels": 1048576, "MultipleScattering": 1.0,
    "ShaderPathSelection": 0, "TemplateRadius": 0.0,
    "TemplatesPerMaterial": 8, "PhotonCap": 24, "OcclusionStrength": 1.0,
    "IlluminationInterval": 4, "LongRangeMultiple": 3.0, "PhotonThreshold": 0.002,
    "GeneratorThreshold": 0.01,
}
values = {
    "IlluminationEnabled": False, "ShadowsEnabled": False, "ColorBleedingEnabled": False,
    "ThinPartCheckEnabled": False, "BoundaryRefractionEnabled": False,
    "TemplateBlendingEnabled": True, "IlluminationMode": 1, "TransportScale": 4,
    "InteractiveTransportScale": 8, "MaximumTransportVoxels": 0, "MultipleScattering": 0.5,
    "ShaderPathSelection": 1, "TemplateRadius": 12.5,
    "TemplatesPerMaterial": 3, "PhotonCap": 100, "OcclusionStrength": 0.5,
    "IlluminationInterval": 2, "LongRangeMultiple": 5.0, "PhotonThreshold": 0.1,
    "GeneratorThreshold": 0.05,
}
for name, default in defaults.items():
    check(getattr(m, "Get" + name)() == default, "default of %s" % name)
    before = m.GetIlluminationMTime()
    getattr(m, "Set" + name)(values[name])
    check(getattr(m, "Get" + name)() == values[name], "round-trip of Set%s" % name)
    check(m.GetIlluminationMTime() > before, "Set%s bumps GetIlluminationMTime()" % name)
for name in ("ShadowsEnabled", "ColorBleedingEnabled", "ThinPartCheckEnabled",
             "BoundaryRefractionEnabled", "TemplateBlendingEnabled", "IlluminationEnabled"):
    getattr(m, name + "On")()
    check(getattr(m, "Get" + name)() is True, name + "On()")
    getattr(m, name + "Off")()
    check(getattr(m, "Get" + name)() is False, name + "Off()")
# A pair of numbers, not an opaque pointer (the getter's size hint).
check(tuple(m.GetMaterialDerivationRange()) == (1.0, 0.0), "unset derivation range")
m.SetMaterialDerivationRange(2.0, 5.0)
check(tuple(m.GetMaterialDerivationRange()) == (2.0, 5.0), "derivation range round-trip")
m.ClearMaterialDerivationRange()
# Three numbers too (they were an opaque pointer in Python).
m.SetWholeDimensions(4, 5, 6)
check(tuple(m.GetWholeDimensions()) == (4, 5, 6), "whole dimensions round-trip")
m.SetWholeDimensions(0, 0, 0)
# The mapper's light transport volume, a class of the package (it was reachable only
# through scatterertemplate.ScattererTemplate).
check(isinstance(m.GetTransportVolume(), scatterertemplate.vtkScattererTransportVolume),
      "GetTransportVolume() is a scatterertemplate.vtkScattererTransportVolume")
m.SetIlluminationModeToTransport()
check(m.GetIlluminationMode() == m.TRANSPORT, "SetIlluminationModeToTransport")
m.SetIlluminationModeToPerSample()
check(m.GetIlluminationMode() == vtkScattererTemplateVolumeMapper.PER_SAMPLE, "PerSample")
m.SetShaderPathSelectionToAsRequested()
check(m.GetShaderPathSelection() == m.AS_REQUESTED, "AsRequested")
check(m.GetOcclusionStrengthMinValue() == 0.0 and m.GetOcclusionStrengthMaxValue() == 100.0,
      "OcclusionStrength range")
check(m.GetTransportScaleMinValue() == 1 and m.GetTransportScaleMaxValue() == 8, "TransportScale range")

# --- clamping warns, NaN is an error and keeps the value ----------------------------------
msgs = Messages(m)
m.SetOcclusionStrength(0.5)
msgs.clear()
m.SetOcclusionStrength(250.0)
check(m.GetOcclusionStrength() == 100.0, "OcclusionStrength clamped to 100")
check(len(msgs.warnings) == 1 and "SetOcclusionStrength" in msgs.warnings[0],
      "one warning naming SetOcclusionStrength: %r" % msgs.warnings)
msgs.clear()
m.SetOcclusionStrength(float("nan"))
check(m.GetOcclusionStrength() == 100.0, "NaN keeps the old value")
check(len(msgs.errors) == 1 and "NaN" in msgs.errors[0], "one NaN error: %r" % msgs.errors)
msgs.clear()
m.SetTransportScale(0)
check(m.GetTransportScale() == 1 and len(msgs.warnings) == 1, "TransportScale clamped to 1 with a warning")
msgs.clear()
m.SetPhotonCap(24)
check(not msgs.warnings and not msgs.errors, "an in-range value is silent")

# --- materials on the mapper ---------------------------------------------------------------
m.RemoveAllMaterials()
m.AddScalarRangeMaterial(100.0, 300.0, 1.4, 0.9, 0.6, 0.5)
m.AddLabelMaterial(2, 1.5, 1.0, 1.0, 0.9)
check(m.GetNumberOfRequestedMaterials() == 2, "two requested materials")
m.RemoveAllMaterials()
check(m.GetNumberOfRequestedMaterials() == 0, "RemoveAllMaterials")
check(m.GetLastShaderFeatures() == "" or isinstance(m.GetLastShaderFeatures(), str),
      "GetLastShaderFeatures is a str before rendering")

# --- vtkScattererMaterial -------------------------------------------------------------------
mat = vtkScattererMaterial()
mm = Messages(mat)
check(mat.GetOpacity() == 0.5 and mat.GetRefractiveIndex() == 1.4, "material defaults")
mat.SetName("bone")
check(mat.GetName() == "bone", "SetName round-trip")
mat.SetOpacity(0.8)
mat.SetRefractiveIndex(1.6)
check(mat.GetOpacity() == 0.8 and mat.GetRefractiveIndex() == 1.6, "material round-trip")
mat.SetDiffuseColor(1.0, 0.5, 0.25)
check(mat.GetDiffuseColor() == (1.0, 0.5, 0.25), "SetDiffuseColor(r, g, b)")
mat.SetDiffuseColor([0.1, 0.2, 0.3])
check(mat.GetDiffuseColor() == (0.1, 0.2, 0.3), "SetDiffuseColor(list of 3)")
mat.SetScalarRange([200.0, 3000.0])
check(mat.GetScalarRange() == (200.0, 3000.0), "SetScalarRange(list of 2)")
check(mat.GetSelectorType() == vtkScattererMaterial.SCALAR_RANGE, "scalar-range selector")
mat.SetLabel(3)
check(mat.GetLabel() == 3 and mat.GetSelectorTypeAsString() is not None, "SetLabel")
check(mat.GetSelectorType() == vtkScattererMaterial.LABEL, "label selector")
mm.clear()
mat.SetOpacity(float("nan"))
check(mat.GetOpacity() == 0.8 and len(mm.errors) == 1, "material NaN opacity rejected")
mat.SetOpacity(2.0)
check(mat.GetOpacity() == 1.0, "material opacity clamped to 1")
# Arrays are passed with their size checked: a short or long list raises, it is never read past.
for bad in ([0.1, 0.2], [0.1, 0.2, 0.3, 0.4]):
    try:
        mat.SetDiffuseColor(bad)
    except TypeError:
        pass
    else:
        check(False, "SetDiffuseColor(%r) must raise TypeError" % (bad,))
check(mat.GetDiffuseColor() == (0.1, 0.2, 0.3), "a rejected list leaves the colour")
try:
    mat.SetScalarRange([1.0])
except TypeError:
    pass
else:
    check(False, "SetScalarRange([1.0]) must raise TypeError")

# --- the reader reports a missing file ------------------------------------------------------
reader = vtkScattererVolumeReader()
rm = Messages(reader)
reader.SetFileName("/nonexistent/volume.mhd")
reader.Update()
check(reader.GetErrorMessage() != "", "reader error message for a missing file")

# --- template source setters ----------------------------------------------------------------
src = vtkScattererTemplateSource()
src.SetTemplatesPerMaterial(2)
src.SetTemplateRadius(5.0)
check(src.GetTemplatesPerMaterial() == 2 and src.GetTemplateRadius() == 5.0, "source round-trip")

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("TestScattererPythonApi: OK")
