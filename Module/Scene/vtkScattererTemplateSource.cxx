#include "vtkScattererTemplateSource.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkScattererMaterial.h"

#include "ScattererMaterialConversion.h"
#include "ScattererTemplatePoints.h"

#include <scatterer/Template.h>
#include <scatterer/TemplateIO.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

// The clamp ranges in the header are the core's limits.
static_assert(
  scatterer::kMaxTemplatesPerMaterial == 1024, "update vtkSetClampMacro(TemplatesPerMaterial)");
static_assert(scatterer::kMaxInitialLights == 1024, "update vtkSetClampMacro(InitialLights)");
static_assert(
  scatterer::kMaxPhotonsCap == (1 << 20), "update vtkSetClampMacro(MaxPhotonsPerTemplate)");
static_assert(
  scatterer::kMaxEventsCap == (1 << 24), "update vtkSetClampMacro(MaxEventsPerTemplate)");

vtkStandardNewMacro(vtkScattererTemplateSource);

namespace
{
constexpr double kMinThreshold = 1e-9;
constexpr double kMinStep = 1e-4;
static_assert(kMinStep >= scatterer::kMinLatticeCell, "LatticeCell clamp below the core's minimum");
}

class vtkScattererTemplateSource::vtkInternals
{
public:
  // The templates and the exact materials/settings they were made (or loaded) with.
  bool Valid = false;
  bool Aborted = false; // the last UpdateTemplates stopped on AbortExecute
  scatterer::TemplateSet Set;
};

vtkScattererTemplateSource::vtkScattererTemplateSource()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
  const scatterer::GeneratorSettings defaults;
  this->TemplatesPerMaterial = defaults.templatesPerMaterial;
  this->InitialLights = defaults.initialLights;
  this->Threshold = defaults.threshold;
  this->Seed = defaults.seed;
  this->StepLength = defaults.stepLength;
  this->LatticeCell = defaults.latticeCell;
  this->MaxPhotonsPerTemplate = defaults.maxPhotonsPerTemplate;
  this->MaxEventsPerTemplate = defaults.maxEventsPerTemplate;
}

vtkScattererTemplateSource::~vtkScattererTemplateSource() = default;

// ---------------------------------------------------------------------------
// Materials

void vtkScattererTemplateSource::AddMaterial(vtkScattererMaterial* material)
{
  if (!material)
  {
    vtkErrorMacro(<< "AddMaterial: the material is null; nothing was added.");
    return;
  }
  this->Materials.emplace_back(material);
  this->Modified();
}

void vtkScattererTemplateSource::RemoveAllMaterials()
{
  if (!this->Materials.empty())
  {
    this->Materials.clear();
    this->Modified();
  }
}

int vtkScattererTemplateSource::GetNumberOfMaterials() const
{
  return static_cast<int>(this->Materials.size());
}

vtkScattererMaterial* vtkScattererTemplateSource::GetMaterial(int index) const
{
  if (index < 0 || index >= this->GetNumberOfMaterials())
  {
    return nullptr;
  }
  return this->Materials[static_cast<std::size_t>(index)];
}

vtkMTimeType vtkScattererTemplateSource::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  for (const auto& material : this->Materials)
  {
    mtime = std::max(mtime, material->GetMTime());
  }
  return mtime;
}

// ---------------------------------------------------------------------------
// Settings with NaN checks

namespace
{
// The rule the three fractional settings share: NaN is refused with an error naming the
// setter and the range (the old value stays), anything else is clamped to [lo, 1].
// Returns whether the member changed.
bool SetClampedFraction(vtkObject* self, double value, double lo, double& member,
  const char* setter, const char* what, const char* unit)
{
  if (std::isnan(value))
  {
    vtkErrorWithObjectMacro(self, << setter << ": the " << what << " must be a number in [" << lo
                                  << ", 1]" << unit << ", got NaN; keeping " << member << ".");
    return false;
  }
  value = std::min(std::max(value, lo), 1.0);
  if (member == value)
  {
    return false;
  }
  member = value;
  return true;
}
}

void vtkScattererTemplateSource::SetThreshold(double threshold)
{
  if (SetClampedFraction(
        this, threshold, kMinThreshold, this->Threshold, "SetThreshold", "threshold", ""))
  {
    this->Modified();
  }
}

void vtkScattererTemplateSource::SetStepLength(double step)
{
  if (SetClampedFraction(
        this, step, kMinStep, this->StepLength, "SetStepLength", "step length", " template radii"))
  {
    this->Modified();
  }
}

void vtkScattererTemplateSource::SetLatticeCell(double cell)
{
  if (SetClampedFraction(this, cell, kMinStep, this->LatticeCell, "SetLatticeCell", "lattice cell",
        " template radii"))
  {
    this->Modified();
  }
}

void vtkScattererTemplateSource::SetTemplateRadius(double radius)
{
  if (!(std::isfinite(radius) && radius > 0.0))
  {
    vtkErrorMacro(<< "SetTemplateRadius: the template radius must be a finite number > 0, got "
                  << radius << "; keeping " << this->TemplateRadius << ".");
    return;
  }
  if (this->TemplateRadius != radius)
  {
    this->TemplateRadius = radius;
    this->Modified();
  }
}

// ---------------------------------------------------------------------------
// Generation

namespace
{
scatterer::GeneratorSettings CurrentSettings(vtkScattererTemplateSource* self)
{
  scatterer::GeneratorSettings s;
  s.initialLights = self->GetInitialLights();
  s.threshold = self->GetThreshold();
  s.templatesPerMaterial = self->GetTemplatesPerMaterial();
  s.seed = self->GetSeed();
  s.stepLength = self->GetStepLength();
  s.latticeCell = self->GetLatticeCell();
  s.maxPhotonsPerTemplate = self->GetMaxPhotonsPerTemplate();
  s.maxEventsPerTemplate = self->GetMaxEventsPerTemplate();
  return s;
}
}

bool vtkScattererTemplateSource::UpdateTemplates()
{
  vtkInternals& internals = *this->Internals;
  internals.Aborted = false;
  const scatterer::GeneratorSettings settings = CurrentSettings(this);
  std::vector<scatterer::Material> materials;
  materials.reserve(this->Materials.size());
  for (const auto& material : this->Materials)
  {
    materials.push_back(scatterer_vtk::ToPhysics(material));
  }

  // Up to date (generated or loaded with exactly these inputs)?
  if (internals.Valid && scatterer_vtk::SameSettings(internals.Set.settings, settings) &&
    internals.Set.materials.size() == materials.size() &&
    std::equal(materials.begin(), materials.end(), internals.Set.materials.begin(),
      [](const scatterer::Material& a, const scatterer::MaterialTemplates& b)
      { return scatterer_vtk::SamePhysics(a, b.material); }))
  {
    return true;
  }

  internals.Valid = false;
  internals.Set = scatterer::TemplateSet();
  scatterer::TemplateSet set;
  set.settings = settings;
  try
  {
    settings.validate();
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "Cannot generate templates: invalid generator settings: " << e.what());
    return false;
  }
  // Validate every material before generating any, so a bad last material fails fast.
  for (std::size_t m = 0; m < materials.size(); ++m)
  {
    try
    {
      materials[m].validate();
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro(<< "Cannot generate templates: material " << m << " is invalid: " << e.what());
      return false;
    }
  }

  // Template by template (the same streams as scatterer::generateAllTemplates), so
  // progress can be reported after each one.
  const double total = static_cast<double>(materials.size()) * settings.templatesPerMaterial;
  double done = 0.0;
  this->UpdateProgress(0.0);
  try
  {
    set.materials.resize(materials.size());
    for (std::size_t m = 0; m < materials.size(); ++m)
    {
      scatterer::GeneratorSettings materialSettings = settings;
      materialSettings.seed = scatterer::materialSeed(settings.seed, static_cast<int>(m));
      scatterer::MaterialTemplates& entry = set.materials[m];
      entry.material = materials[m];
      entry.templates.reserve(static_cast<std::size_t>(settings.templatesPerMaterial));
      for (int t = 0; t < settings.templatesPerMaterial; ++t)
      {
        entry.templates.push_back(scatterer::generateTemplate(materials[m], materialSettings, t));
        done += 1.0;
        this->UpdateProgress(done / total);
        if (this->GetAbortExecute())
        {
          internals.Aborted = true;
          return false;
        }
      }
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "Cannot generate templates: " << e.what());
    return false;
  }
  if (total == 0.0)
  {
    this->UpdateProgress(1.0); // no materials: done at once
  }
  internals.Set = std::move(set);
  internals.Valid = true;
  return true;
}

int vtkScattererTemplateSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  if (!this->UpdateTemplates())
  {
    // An abort is not an error: the output is just empty.
    return this->Internals->Aborted ? 1 : 0;
  }
  const scatterer::TemplateSet& set = this->Internals->Set;

  scatterer_vtk::TemplatePhotonsToPolyData(set, this->TemplateRadius, output);
  return 1;
}

// ---------------------------------------------------------------------------
// Files

bool vtkScattererTemplateSource::SaveTemplates(const char* path)
{
  if (!path || !*path)
  {
    vtkErrorMacro(<< "SaveTemplates: no file name was given.");
    return false;
  }
  if (!this->UpdateTemplates())
  {
    if (this->Internals->Aborted)
    {
      vtkErrorMacro(<< "SaveTemplates: '" << path
                    << "' was not written: generation was aborted (AbortExecute).");
    }
    else
    {
      vtkErrorMacro(<< "SaveTemplates: '" << path
                    << "' was not written: the templates could not be generated (see the "
                       "previous error).");
    }
    return false;
  }
  try
  {
    scatterer::saveTemplates(path, this->Internals->Set);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "SaveTemplates: " << e.what());
    return false;
  }
  return true;
}

bool vtkScattererTemplateSource::LoadTemplates(const char* path)
{
  if (!path || !*path)
  {
    vtkErrorMacro(<< "LoadTemplates: no file name was given.");
    return false;
  }
  scatterer::TemplateSet set;
  try
  {
    set = scatterer::loadTemplates(path);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "LoadTemplates: " << e.what());
    return false;
  }

  // The file's settings, as they are (the core validated them; no clamping here,
  // so that the loaded templates stay current).
  this->InitialLights = set.settings.initialLights;
  this->Threshold = set.settings.threshold;
  this->TemplatesPerMaterial = set.settings.templatesPerMaterial;
  this->Seed = set.settings.seed;
  this->StepLength = set.settings.stepLength;
  this->LatticeCell = set.settings.latticeCell;
  this->MaxPhotonsPerTemplate = set.settings.maxPhotonsPerTemplate;
  this->MaxEventsPerTemplate = set.settings.maxEventsPerTemplate;

  this->Materials.clear();
  for (const scatterer::MaterialTemplates& entry : set.materials)
  {
    vtkNew<vtkScattererMaterial> material;
    scatterer_vtk::FromPhysics(entry.material, material);
    this->Materials.emplace_back(material.GetPointer());
  }
  this->Internals->Set = std::move(set);
  this->Internals->Valid = true;
  this->Modified();
  return true;
}

// ---------------------------------------------------------------------------
// Inspection

int vtkScattererTemplateSource::GetNumberOfTemplates() const
{
  if (!this->Internals->Valid)
  {
    return 0;
  }
  std::size_t n = 0;
  for (const auto& entry : this->Internals->Set.materials)
  {
    n += entry.templates.size();
  }
  return static_cast<int>(n);
}

vtkIdType vtkScattererTemplateSource::GetNumberOfPhotons() const
{
  if (!this->Internals->Valid)
  {
    return 0;
  }
  return scatterer_vtk::CountPhotons(this->Internals->Set);
}

double vtkScattererTemplateSource::GetMaxLedgerResidual() const
{
  if (!this->Internals->Valid)
  {
    return 0.0;
  }
  double worst = 0.0;
  for (const auto& entry : this->Internals->Set.materials)
  {
    for (const auto& t : entry.templates)
    {
      worst = std::max(worst, std::abs(t.ledger.residual()));
    }
  }
  return worst;
}

int vtkScattererTemplateSource::GetNumberOfCappedTemplates() const
{
  if (!this->Internals->Valid)
  {
    return 0;
  }
  int n = 0;
  for (const auto& entry : this->Internals->Set.materials)
  {
    for (const auto& t : entry.templates)
    {
      n += t.capped ? 1 : 0;
    }
  }
  return n;
}

void vtkScattererTemplateSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TemplatesPerMaterial: " << this->TemplatesPerMaterial << "\n";
  os << indent << "InitialLights: " << this->InitialLights << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  const auto flags = os.flags();
  os << indent << "Seed: 0x" << std::hex << this->Seed << "\n";
  os.flags(flags);
  os << indent << "StepLength: " << this->StepLength << "\n";
  os << indent << "LatticeCell: " << this->LatticeCell << "\n";
  os << indent << "MaxPhotonsPerTemplate: " << this->MaxPhotonsPerTemplate << "\n";
  os << indent << "MaxEventsPerTemplate: " << this->MaxEventsPerTemplate << "\n";
  os << indent << "TemplateRadius: " << this->TemplateRadius << "\n";
  os << indent << "NumberOfTemplates: " << this->GetNumberOfTemplates() << "\n";
  os << indent << "NumberOfPhotons: " << this->GetNumberOfPhotons() << "\n";
  os << indent << "MaxLedgerResidual: " << this->GetMaxLedgerResidual() << "\n";
  os << indent << "NumberOfCappedTemplates: " << this->GetNumberOfCappedTemplates() << "\n";
  os << indent << "Materials: " << this->Materials.size() << "\n";
  for (std::size_t m = 0; m < this->Materials.size(); ++m)
  {
    os << indent << "Material " << m << ":\n";
    this->Materials[m]->PrintSelf(os, indent.GetNextIndent());
  }
}
