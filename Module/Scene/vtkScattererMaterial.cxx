#include "vtkScattererMaterial.h"

#include "vtkObjectFactory.h"

#include "ScattererMaterialConversion.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkScattererMaterial);

namespace
{
double Clamp(double value, double lo, double hi)
{
  return std::min(std::max(value, lo), hi);
}
}

vtkScattererMaterial::vtkScattererMaterial()
{
  const scatterer::Material defaults;
  this->Name = defaults.name;
  this->Opacity = defaults.opacity;
  this->RefractiveIndex = defaults.refractiveIndex;
  for (int c = 0; c < 3; ++c)
  {
    this->DiffuseColor[c] = static_cast<double>(defaults.diffuse[c]);
  }
  this->SelectorType =
    defaults.selector.kind == scatterer::Selector::Kind::Label ? LABEL : SCALAR_RANGE;
  this->ScalarRange[0] = defaults.selector.lo;
  this->ScalarRange[1] = defaults.selector.hi;
  this->Label = defaults.selector.label;
}

vtkScattererMaterial::~vtkScattererMaterial() = default;

void vtkScattererMaterial::SetOpacity(double opacity)
{
  if (std::isnan(opacity))
  {
    vtkErrorMacro(<< "SetOpacity: the opacity (1 - T) must be a number in [0, 1], got NaN; "
                     "keeping "
                  << this->Opacity << ".");
    return;
  }
  opacity = Clamp(opacity, 0.0, 1.0);
  if (this->Opacity != opacity)
  {
    this->Opacity = opacity;
    this->Modified();
  }
}

double vtkScattererMaterial::GetRefractiveIndexMinValue() const
{
  return scatterer::kMinRefractiveIndex;
}

double vtkScattererMaterial::GetRefractiveIndexMaxValue() const
{
  return scatterer::kMaxRefractiveIndex;
}

void vtkScattererMaterial::SetRefractiveIndex(double n)
{
  if (std::isnan(n))
  {
    vtkErrorMacro(<< "SetRefractiveIndex: the refractive index must be a number in ["
                  << scatterer::kMinRefractiveIndex << ", " << scatterer::kMaxRefractiveIndex
                  << "], got NaN; keeping " << this->RefractiveIndex << ".");
    return;
  }
  n = Clamp(n, scatterer::kMinRefractiveIndex, scatterer::kMaxRefractiveIndex);
  if (this->RefractiveIndex != n)
  {
    this->RefractiveIndex = n;
    this->Modified();
  }
}

void vtkScattererMaterial::SetDiffuseColor(double r, double g, double b)
{
  if (std::isnan(r) || std::isnan(g) || std::isnan(b))
  {
    vtkErrorMacro(<< "SetDiffuseColor: each component must be a number in [0, 1], got (" << r
                  << ", " << g << ", " << b << "); keeping the colour (" << this->DiffuseColor[0]
                  << ", " << this->DiffuseColor[1] << ", " << this->DiffuseColor[2] << ").");
    return;
  }
  const double rgb[3] = { Clamp(r, 0.0, 1.0), Clamp(g, 0.0, 1.0), Clamp(b, 0.0, 1.0) };
  if (!std::equal(rgb, rgb + 3, this->DiffuseColor))
  {
    std::copy(rgb, rgb + 3, this->DiffuseColor);
    this->Modified();
  }
}

void vtkScattererMaterial::SetScalarRange(double lo, double hi)
{
  if (std::isnan(lo) || std::isnan(hi))
  {
    vtkErrorMacro(<< "SetScalarRange: the bounds must be numbers, got [" << lo << ", " << hi
                  << "]; keeping the selector as it was.");
    return;
  }
  if (this->SelectorType != SCALAR_RANGE || this->ScalarRange[0] != lo ||
    this->ScalarRange[1] != hi)
  {
    this->SelectorType = SCALAR_RANGE;
    this->ScalarRange[0] = lo;
    this->ScalarRange[1] = hi;
    this->Modified();
  }
}

void vtkScattererMaterial::SetLabel(int label)
{
  if (this->SelectorType != LABEL || this->Label != label)
  {
    this->SelectorType = LABEL;
    this->Label = label;
    this->Modified();
  }
}

const char* vtkScattererMaterial::GetSelectorTypeAsString() const
{
  return this->SelectorType == LABEL ? "Label" : "ScalarRange";
}

void vtkScattererMaterial::DeepCopy(vtkScattererMaterial* other)
{
  if (!other)
  {
    vtkErrorMacro(<< "DeepCopy: the material to copy is null.");
    return;
  }
  if (other == this)
  {
    return;
  }
  this->SetName(other->GetName());
  this->SetOpacity(other->Opacity);
  this->SetRefractiveIndex(other->RefractiveIndex);
  this->SetDiffuseColor(other->DiffuseColor);
  // Both selector fields, the active one last so that it sets SelectorType.
  if (other->SelectorType == LABEL)
  {
    this->SetScalarRange(other->ScalarRange);
    this->SetLabel(other->Label);
  }
  else
  {
    this->SetLabel(other->Label);
    this->SetScalarRange(other->ScalarRange);
  }
}

void vtkScattererMaterial::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << this->Name << "\n";
  os << indent << "Opacity: " << this->Opacity << "\n";
  os << indent << "RefractiveIndex: " << this->RefractiveIndex << "\n";
  os << indent << "DiffuseColor: (" << this->DiffuseColor[0] << ", " << this->DiffuseColor[1]
     << ", " << this->DiffuseColor[2] << ")\n";
  os << indent << "SelectorType: " << this->GetSelectorTypeAsString() << "\n";
  os << indent << "ScalarRange: [" << this->ScalarRange[0] << ", " << this->ScalarRange[1] << "]\n";
  os << indent << "Label: " << this->Label << "\n";
}

// ---------------------------------------------------------------------------
// Conversions to and from the physics core (ScattererMaterialConversion.h).

namespace scatterer_vtk
{
scatterer::Material ToPhysics(vtkScattererMaterial* material)
{
  scatterer::Material physics;
  physics.name = material->GetName() ? material->GetName() : "";
  physics.opacity = material->GetOpacity();
  physics.refractiveIndex = material->GetRefractiveIndex();
  const double* rgb = material->GetDiffuseColor();
  physics.diffuse = { static_cast<float>(rgb[0]), static_cast<float>(rgb[1]),
    static_cast<float>(rgb[2]) };
  const double* range = material->GetScalarRange();
  physics.selector.kind = material->GetSelectorType() == vtkScattererMaterial::LABEL
    ? scatterer::Selector::Kind::Label
    : scatterer::Selector::Kind::ScalarRange;
  physics.selector.lo = range[0];
  physics.selector.hi = range[1];
  physics.selector.label = material->GetLabel();
  return physics;
}

void FromPhysics(const scatterer::Material& physics, vtkScattererMaterial* material)
{
  material->SetName(physics.name.c_str());
  material->SetOpacity(physics.opacity);
  material->SetRefractiveIndex(physics.refractiveIndex);
  material->SetDiffuseColor(static_cast<double>(physics.diffuse.r),
    static_cast<double>(physics.diffuse.g), static_cast<double>(physics.diffuse.b));
  // Only the active selector field is meaningful (and validated by the core).
  if (physics.selector.kind == scatterer::Selector::Kind::Label)
  {
    material->SetLabel(physics.selector.label);
  }
  else
  {
    material->SetScalarRange(physics.selector.lo, physics.selector.hi);
  }
}

bool SamePhysics(const scatterer::Material& a, const scatterer::Material& b)
{
  if (a.name != b.name || a.opacity != b.opacity || a.refractiveIndex != b.refractiveIndex ||
    a.diffuse != b.diffuse || a.selector.kind != b.selector.kind)
  {
    return false;
  }
  if (a.selector.kind == scatterer::Selector::Kind::Label)
  {
    return a.selector.label == b.selector.label;
  }
  return a.selector.lo == b.selector.lo && a.selector.hi == b.selector.hi;
}

bool SameSettings(const scatterer::GeneratorSettings& a, const scatterer::GeneratorSettings& b)
{
  return a.initialLights == b.initialLights && a.threshold == b.threshold &&
    a.templatesPerMaterial == b.templatesPerMaterial && a.seed == b.seed &&
    a.stepLength == b.stepLength && a.latticeCell == b.latticeCell &&
    a.maxPhotonsPerTemplate == b.maxPhotonsPerTemplate &&
    a.maxEventsPerTemplate == b.maxEventsPerTemplate;
}
}
