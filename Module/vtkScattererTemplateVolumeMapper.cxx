#include "vtkScattererTemplateVolumeMapper.h"

#include "ScattererOcclusionField.h"
#include "ScattererSceneLights.h"
#include "ScattererSceneMaterials.h"
#include "ScattererShaderComposer.h"
#include "ScattererShaderInstaller.h"

#include "vtkCallbackCommand.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiVolume.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRectilinearGrid.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUniforms.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"

#include <scatterer/Illumination.h>
#include <scatterer/Pack.h>
#include <scatterer/Template.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkScattererTemplateVolumeMapper);

namespace
{
const char* BlendModeName(int mode)
{
  switch (mode)
  {
    case vtkVolumeMapper::COMPOSITE_BLEND:
      return "composite";
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      return "maximum intensity";
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
      return "minimum intensity";
    case vtkVolumeMapper::AVERAGE_INTENSITY_BLEND:
      return "average intensity";
    case vtkVolumeMapper::ADDITIVE_BLEND:
      return "additive";
    case vtkVolumeMapper::ISOSURFACE_BLEND:
      return "isosurface";
    case vtkVolumeMapper::SLICE_BLEND:
      return "slice";
    default:
      return "unknown";
  }
}

// The generator's photons stay well inside the unit sphere (packets fall
// below the threshold long before they escape). Scale all templates by one
// factor so the farthest photon of any material lies at radius 1: the template
// radius is then the reach of the occlusion test, and the relative spread of
// dense and clear materials is kept.
void NormalizeExtent(std::vector<std::vector<scatterer::Template>>& templates)
{
  float reach = 0.0f;
  for (const auto& material : templates)
  {
    for (const auto& t : material)
    {
      for (const auto& p : t.photons)
      {
        reach = std::max(reach, std::sqrt(p.position.x * p.position.x +
                                  p.position.y * p.position.y + p.position.z * p.position.z));
      }
    }
  }
  if (reach > 0.0f)
  {
    for (auto& material : templates)
    {
      for (auto& t : material)
      {
        for (auto& p : t.photons)
        {
          p.position /= reach;
        }
      }
    }
  }
}

// Everything one frame of illumination needs, decided before rendering.
struct FramePlan
{
  scatterer_shader::Features Features;
  scatterer_scene::LightSet Lights;
  scatterer_scene::MaterialSet Materials;
  double Radius = 1.0;
  float ToTex[3][3] = {}; // columns: texture offset of one template radius along world x, y, z
};
}

struct vtkScattererTemplateVolumeMapper::vtkInternals
{
  std::vector<scatterer_scene::RequestedMaterial> Requested;
  std::string LastFeatures = "stock: not rendered yet";
  int ActiveMaterials = 0;
  std::set<std::string> Warned;
  std::string ExtraGLSL;

  // Templates: regenerated when their key changes, uploaded per context.
  std::string TemplateKey;
  scatterer::PackedTemplates Packed;
  std::vector<std::vector<scatterer::Template>> Templates;
  vtkSmartPointer<vtkTextureObject> Texture;
  std::string UploadedKey;

  // Cached mode: the occlusion field (rebuilt when data, transfer function or
  // materials change) and the illumination grid (also when lights or settings
  // change), uploaded as 3D textures.
  std::string FieldKey;
  scatterer::OcclusionField Field;
  std::string GridKey;
  vtkSmartPointer<vtkTextureObject> LightCache;
  vtkSmartPointer<vtkTextureObject> BleedCache;
  double LastCacheMs = 0.0;
  float Unlit[3] = { 1, 1, 1 };
  // Volume texture coordinates -> cache texture coordinates (the cache lattice is
  // anchored to extent index 0, so pieces of a split volume share it).
  float CacheTexScale[3] = { 1, 1, 1 };
  float CacheTexOffset[3] = { 0, 0, 0 };

  bool UpdateCache(vtkScattererTemplateVolumeMapper* self, vtkRenderer* ren, vtkVolume* vol,
    vtkImageData* image, vtkDataArray* scalars, int cellFlag, const double range[2],
    const FramePlan& plan, float unlit[3]);

  // Shader texts that failed to compile here: not tried again.
  std::set<std::string> FailedShaders;

  // Volumes carrying our replacements, watched so that a volume handed to
  // another mapper is cleaned at once.
  struct Decorated
  {
    vtkWeakPointer<vtkVolume> Volume;
    unsigned long Tag = 0;
  };
  std::vector<Decorated> Volumes;
  vtkNew<vtkCallbackCommand> VolumeWatcher;
};

vtkScattererTemplateVolumeMapper::vtkScattererTemplateVolumeMapper()
  : Internals(new vtkInternals)
{
  this->Internals->VolumeWatcher->SetClientData(this);
  this->Internals->VolumeWatcher->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    auto* self = static_cast<vtkScattererTemplateVolumeMapper*>(client);
    auto* volume = static_cast<vtkVolume*>(caller);
    if (volume->GetMapper() != self)
    {
      scatterer_shader::RemoveIllumination(volume);
      auto& list = self->Internals->Volumes;
      for (auto it = list.begin(); it != list.end(); ++it)
      {
        if (it->Volume == volume)
        {
          volume->RemoveObserver(it->Tag);
          list.erase(it);
          break;
        }
      }
    }
  });
}

vtkScattererTemplateVolumeMapper::~vtkScattererTemplateVolumeMapper()
{
  for (auto& d : this->Internals->Volumes)
  {
    if (d.Volume)
    {
      d.Volume->RemoveObserver(d.Tag);
      scatterer_shader::RemoveIllumination(d.Volume);
    }
  }
}

void vtkScattererTemplateVolumeMapper::AddScalarRangeMaterial(
  double lo, double hi, double refractiveIndex, double r, double g, double b)
{
  const double values[] = { lo, hi, refractiveIndex, r, g, b };
  for (double v : values)
  {
    if (!std::isfinite(v))
    {
      vtkErrorMacro("AddScalarRangeMaterial: every argument must be finite; material ignored.");
      return;
    }
  }
  if (hi < lo || refractiveIndex <= 0.0)
  {
    vtkErrorMacro("AddScalarRangeMaterial: needs lo <= hi and a refractive index > 0 (got ["
      << lo << ", " << hi << "], n = " << refractiveIndex << "); material ignored.");
    return;
  }
  scatterer_scene::RequestedMaterial m;
  m.Lo = lo;
  m.Hi = hi;
  m.RefractiveIndex = refractiveIndex;
  m.Color[0] = std::min(std::max(r, 0.0), 1.0);
  m.Color[1] = std::min(std::max(g, 0.0), 1.0);
  m.Color[2] = std::min(std::max(b, 0.0), 1.0);
  this->Internals->Requested.push_back(m);
  this->IlluminationTime.Modified();
}

void vtkScattererTemplateVolumeMapper::AddLabelMaterial(
  int label, double refractiveIndex, double r, double g, double b)
{
  this->AddScalarRangeMaterial(label - 0.5, label + 0.5, refractiveIndex, r, g, b);
  if (!this->Internals->Requested.empty() && this->Internals->Requested.back().Lo == label - 0.5)
  {
    this->Internals->Requested.back().IsLabel = true;
    this->Internals->Requested.back().Label = label;
  }
}

void vtkScattererTemplateVolumeMapper::AddMaterialsFromLabelTransferFunctions(
  vtkVolumeProperty* property)
{
  if (!property)
  {
    vtkErrorMacro("AddMaterialsFromLabelTransferFunctions: no volume property given.");
    return;
  }
  const std::set<int> labels = property->GetLabelMapLabels();
  if (labels.empty())
  {
    vtkWarningMacro("AddMaterialsFromLabelTransferFunctions: the volume property has no label "
                    "transfer functions (SetLabelColor / SetLabelScalarOpacity); no material added.");
    return;
  }
  int index = 0;
  for (int label : labels)
  {
    double color[3] = { 1.0, 1.0, 1.0 };
    if (vtkColorTransferFunction* ctf = property->GetLabelColor(label))
    {
      double range[2];
      ctf->GetRange(range);
      ctf->GetColor(0.5 * (range[0] + range[1]), color);
    }
    this->AddLabelMaterial(label, 1.33 + 0.12 * index++, color[0], color[1], color[2]);
  }
}

void vtkScattererTemplateVolumeMapper::RemoveAllMaterials()
{
  if (!this->Internals->Requested.empty())
  {
    this->Internals->Requested.clear();
    this->IlluminationTime.Modified();
  }
}

int vtkScattererTemplateVolumeMapper::GetNumberOfRequestedMaterials() const
{
  return static_cast<int>(this->Internals->Requested.size());
}

const std::string& vtkScattererTemplateVolumeMapper::GetLastShaderFeatures() const
{
  return this->Internals->LastFeatures;
}

int vtkScattererTemplateVolumeMapper::GetNumberOfActiveMaterials() const
{
  return this->Internals->ActiveMaterials;
}

size_t vtkScattererTemplateVolumeMapper::GetTemplateTextureBytes() const
{
  return this->Internals->Packed.byteCount();
}

double vtkScattererTemplateVolumeMapper::GetLastCacheUpdateMilliseconds() const
{
  return this->Internals->LastCacheMs;
}

void vtkScattererTemplateVolumeMapper::SetMaterialDerivationRange(double lo, double hi)
{
  if (!std::isfinite(lo) || !std::isfinite(hi))
  {
    vtkErrorMacro("SetMaterialDerivationRange(" << lo << ", " << hi
                                               << "): the range must be finite; ignored.");
    return;
  }
  // No Modified(): the materials are re-derived every frame and the templates and
  // cache follow their keys (a mapper Modified() would rebuild VTK's shader).
  this->MaterialDerivationRange[0] = lo;
  this->MaterialDerivationRange[1] = hi;
}

double vtkScattererTemplateVolumeMapper::GetIlluminationReach(const double spacing[3]) const
{
  if (!this->IlluminationEnabled)
  {
    return 0.0;
  }
  const double sx = std::abs(spacing[0]), sy = std::abs(spacing[1]), sz = std::abs(spacing[2]);
  const double radius = this->TemplateRadius > 0.0 ? this->TemplateRadius : 10.0 * (sx + sy + sz) / 3.0;
  // Photons lie within one radius; the thin-part check marches on toward the light
  // to LongRangeMultiple x the photon's offset (Physics/.../Illumination.h).
  const bool thin = this->ShadowsEnabled && this->ThinPartCheckEnabled;
  const double photonReach = thin ? radius * this->LongRangeMultiple : radius;
  // A cache voxel averages CacheScale voxels and is interpolated by its neighbours.
  const double cacheMargin =
    this->IlluminationMode == CACHED ? this->CacheScale * std::max({ sx, sy, sz }) : 0.0;
  const double reach = photonReach + cacheMargin;
  return std::isfinite(reach) ? reach : 0.0;
}

void vtkScattererTemplateVolumeMapper::SetExtraShaderCodeForTesting(const std::string& glsl)
{
  this->Internals->ExtraGLSL = glsl;
}

void vtkScattererTemplateVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& in = *this->Internals;
  for (auto* texture : { &in.Texture, &in.LightCache, &in.BleedCache })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      *texture = nullptr;
    }
  }
  in.UploadedKey.clear();
  in.GridKey.clear();
  this->Superclass::ReleaseGraphicsResources(window);
}

namespace
{
// Why illumination cannot apply to this volume, or "" if it can.
std::string Unsupported(vtkOpenGLGPUVolumeRayCastMapper* mapper, vtkVolume* vol)
{
  if (mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    return std::string("the ") + BlendModeName(mapper->GetBlendMode()) +
      " blend mode (illumination needs composite blending)";
  }
  if (vtkMultiVolume::SafeDownCast(vol))
  {
    return "a vtkMultiVolume (several inputs)";
  }
  if (vtkRectilinearGrid::SafeDownCast(mapper->GetInput()))
  {
    return "a rectilinear-grid input";
  }
  if (mapper->GetMaskInput())
  {
    return "a mask input";
  }
  if (mapper->GetUseDepthPass())
  {
    return "the depth pass (UseDepthPass)";
  }
  vtkVolumeProperty* property = vol->GetProperty();
  if (property->GetTransferFunctionMode() != vtkVolumeProperty::TF_1D)
  {
    return "2D transfer functions";
  }
  return "";
}
}

void vtkScattererTemplateVolumeMapper::GPURender(vtkRenderer* ren, vtkVolume* vol)
{
  vtkInternals& in = *this->Internals;
  if (!this->IlluminationEnabled)
  {
    in.LastFeatures = "stock: illumination off";
    scatterer_shader::RemoveIllumination(vol);
    this->Superclass::GPURender(ren, vol);
    return;
  }

  auto warnOnce = [&](const std::string& what) {
    if (in.Warned.insert(what).second)
    {
      vtkWarningMacro(<< what);
    }
  };
  auto renderStock = [&](const std::string& reason) {
    in.LastFeatures = "stock: " + reason;
    scatterer_shader::RemoveIllumination(vol);
    this->Superclass::GPURender(ren, vol);
  };

  const std::string unsupported = Unsupported(this, vol);
  if (!unsupported.empty())
  {
    warnOnce("Scatterer-template illumination does not apply to " + unsupported +
      "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    renderStock(unsupported);
    return;
  }
  vtkImageData* image = vtkImageData::SafeDownCast(this->GetInput());
  int cellFlag = 0;
  vtkDataArray* scalars = image ? vtkAbstractMapper::GetScalars(image, this->ScalarMode,
                                    this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag)
                                : nullptr;
  if (!scalars)
  {
    renderStock("no scalars");
    return;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    warnOnce("Scatterer-template illumination needs single-component scalars (intensities or "
             "a label map); these have " +
      std::to_string(scalars->GetNumberOfComponents()) +
      " components, so this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    renderStock("multi-component scalars");
    return;
  }

  FramePlan plan;
  vtkVolumeProperty* property = vol->GetProperty();
  plan.Lights = scatterer_scene::CollectLights(ren, property);
  if (plan.Lights.Count() == 0)
  {
    renderStock("no light is switched on");
    return;
  }
  if (plan.Lights.Skipped > 0)
  {
    warnOnce("Scatterer-template illumination uses the first 6 lights (VTK's limit); " +
      std::to_string(plan.Lights.Skipped) + " more are ignored.");
  }

  // Template radius and the world -> texture mapping of photon offsets.
  double spacing[3];
  int dims[3];
  image->GetSpacing(spacing);
  image->GetDimensions(dims);
  vtkMatrix4x4* volumeMatrix = vol->GetMatrix();
  double columnLength[3];
  for (int c = 0; c < 3; ++c)
  {
    columnLength[c] = std::sqrt(volumeMatrix->GetElement(0, c) * volumeMatrix->GetElement(0, c) +
      volumeMatrix->GetElement(1, c) * volumeMatrix->GetElement(1, c) +
      volumeMatrix->GetElement(2, c) * volumeMatrix->GetElement(2, c));
  }
  const double meanSpacing = (std::abs(spacing[0]) * columnLength[0] +
                               std::abs(spacing[1]) * columnLength[1] +
                               std::abs(spacing[2]) * columnLength[2]) / 3.0;
  plan.Radius = this->TemplateRadius > 0.0 ? this->TemplateRadius : 10.0 * meanSpacing;
  if (!(plan.Radius > 0.0) || !std::isfinite(plan.Radius))
  {
    warnOnce("Scatterer-template illumination needs a positive, finite voxel spacing or "
             "TemplateRadius; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    renderStock("degenerate spacing");
    return;
  }
  {
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(volumeMatrix, inverse);
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int row = 0; row < 3; ++row)
      {
        // data offset of one template radius along world `axis`, then texels -> [0,1]
        const double data = inverse->GetElement(row, axis) * plan.Radius;
        const int texels = std::max(1, cellFlag ? dims[row] - 1 : dims[row]);
        const double tex = data / (spacing[row] * texels);
        plan.ToTex[axis][row] = std::isfinite(tex) ? static_cast<float>(tex) : 0.0f;
      }
    }
  }

  double range[2];
  scalars->GetFiniteRange(range, 0);
  // Materials are derived over the derivation range when one is set (a piece of a
  // split volume: the whole volume's range); the occlusion field's opacity table
  // spans it too, so every piece classifies a scalar exactly as the whole does.
  const bool derivationSet = this->MaterialDerivationRange[0] <= this->MaterialDerivationRange[1];
  double derivation[2] = { range[0], range[1] };
  double fieldRange[2] = { range[0], range[1] };
  if (derivationSet)
  {
    derivation[0] = this->MaterialDerivationRange[0];
    derivation[1] = this->MaterialDerivationRange[1];
    fieldRange[0] = std::min(range[0], derivation[0]);
    fieldRange[1] = std::max(range[1], derivation[1]);
  }
  plan.Materials = scatterer_scene::BuildMaterials(in.Requested, property, range, derivation);
  in.ActiveMaterials = static_cast<int>(plan.Materials.Materials.size());
  if (plan.Materials.Materials.empty())
  {
    renderStock("no material: the opacity transfer function is below 1e-4 everywhere");
    return;
  }
  if (plan.Materials.Dropped > 0)
  {
    warnOnce("Scatterer-template illumination handles 8 materials; " +
      std::to_string(plan.Materials.Dropped) + " more stay unlit.");
  }

  // Which code paths this scene needs.
  const bool automatic = this->ShaderPathSelection == AUTOMATIC;
  const auto& mats = plan.Materials.Materials;
  bool colorsDiffer = false, indicesDiffer = false;
  for (const auto& m : mats)
  {
    colorsDiffer = colorsDiffer || m.Physics.diffuse != mats[0].Physics.diffuse;
    indicesDiffer = indicesDiffer || m.Physics.refractiveIndex != mats[0].Physics.refractiveIndex ||
      m.Physics.opacity != mats[0].Physics.opacity;
  }
  scatterer_shader::Features& f = plan.Features;
  f.Lights = plan.Lights.Count();
  f.Materials = static_cast<int>(mats.size());
  f.Shadow = this->ShadowsEnabled;
  f.Thin = f.Shadow && this->ThinPartCheckEnabled && (!automatic || this->LongRangeMultiple > 1.0);
  f.Bleed = this->ColorBleedingEnabled && (!automatic || (f.Materials > 1 && colorsDiffer));
  f.Boundary = this->BoundaryRefractionEnabled && f.Materials > 1 && (!automatic || indicesDiffer);
  f.Positional = plan.Lights.AnyPositional;
  f.Blend2 = this->TemplateBlendingEnabled;
  f.Phong = property->GetShade() != 0;
  f.Cached = this->IlluminationMode == CACHED;
  {
    scatterer::IlluminationSettings probe;
    probe.ambient = glm::vec3(plan.Lights.Ambient[0], plan.Lights.Ambient[1], plan.Lights.Ambient[2]);
    for (int l = 0; l < plan.Lights.Count(); ++l)
    {
      scatterer::GridLight g;
      g.color = glm::vec3(plan.Lights.Color[3 * l], plan.Lights.Color[3 * l + 1], plan.Lights.Color[3 * l + 2]);
      probe.lights.push_back(g);
    }
    f.CacheInOne = scatterer::singleChromaticity(probe);
  }
  if (automatic && !f.Shadow && !f.Bleed && !f.Boundary)
  {
    renderStock("no illumination effect is switched on");
    return;
  }

  const std::string declarations =
    scatterer_shader::IlluminationDeclarations(f) + in.ExtraGLSL;
  const std::string shading = scatterer_shader::ShadingInitialization(f) +
    scatterer_shader::ShadingImplementation(f);
  if (in.FailedShaders.count(declarations + shading))
  {
    renderStock("the illumination shader failed to compile here");
    return;
  }

  // Templates: regenerate when materials or generator settings change.
  {
    std::ostringstream key;
    key.precision(17);
    key << this->TemplatesPerMaterial << '|' << this->GeneratorThreshold << '|' << this->PhotonCap;
    for (const auto& m : mats)
    {
      key << '|' << m.Physics.opacity << ',' << m.Physics.refractiveIndex;
    }
    if (key.str() != in.TemplateKey)
    {
      std::vector<scatterer::Material> physics;
      for (const auto& m : mats)
      {
        physics.push_back(m.Physics);
      }
      scatterer::GeneratorSettings settings;
      settings.templatesPerMaterial = this->TemplatesPerMaterial;
      settings.threshold = this->GeneratorThreshold;
      try
      {
        in.Templates = scatterer::generateAllTemplates(physics, settings);
        NormalizeExtent(in.Templates);
        in.Packed = scatterer::packTemplates(in.Templates, this->PhotonCap);
      }
      catch (const std::exception& e)
      {
        warnOnce(std::string("Scatterer templates could not be generated (") + e.what() +
          "); this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
        renderStock("template generation failed");
        return;
      }
      in.TemplateKey = key.str();
    }
  }
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  std::vector<scatterer_shader::Sampler> samplers;
  std::vector<vtkTextureObject*> bound;
  float unlit[3] = { 1, 1, 1 };
  in.LastCacheMs = 0.0;
  if (f.Cached)
  {
    if (!in.UpdateCache(this, ren, vol, image, scalars, cellFlag, fieldRange, plan, unlit))
    {
      renderStock("the illumination cache could not be computed");
      return;
    }
    samplers.push_back({ "st_lightCache", "sampler3D" });
    bound.push_back(in.LightCache);
    if (f.Bleed && !f.CacheInOne)
    {
      samplers.push_back({ "st_bleedCache", "sampler3D" });
      bound.push_back(in.BleedCache);
    }
  }
  else
  {
    if (!in.Texture || in.Texture->GetContext() != renWin || in.UploadedKey != in.TemplateKey)
    {
      if (!in.Texture || in.Texture->GetContext() != renWin)
      {
        in.Texture = vtkSmartPointer<vtkTextureObject>::New();
        in.Texture->SetContext(renWin);
      }
      in.Texture->SetMinificationFilter(vtkTextureObject::Nearest);
      in.Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      in.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
      in.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
      in.Texture->Create2DFromRaw(in.Packed.width, in.Packed.height, 4, VTK_FLOAT,
        const_cast<float*>(in.Packed.rgba.data()));
      in.UploadedKey = in.TemplateKey;
    }
    samplers.push_back({ "st_templates", "sampler2D" });
    bound.push_back(in.Texture);
  }

  // Shader text and uniforms.
  scatterer_shader::InstallIllumination(vol, declarations,
    scatterer_shader::ShadingInitialization(f), scatterer_shader::ShadingImplementation(f),
    samplers);
  scatterer_shader::UniformValues u;
  u.TemplatesPerMaterial = this->TemplatesPerMaterial;
  u.PhotonCount = std::min(this->PhotonCap, in.Packed.width);
  u.PhotonThreshold = static_cast<float>(this->PhotonThreshold);
  u.OcclusionScale = static_cast<float>(this->OcclusionStrength * plan.Radius);
  u.LongRange = static_cast<float>(this->LongRangeMultiple);
  u.Interval = this->IlluminationInterval;
  int extent[6];
  image->GetExtent(extent);
  for (int c = 0; c < 3; ++c)
  {
    u.Unlit[c] = unlit[c];
    u.CacheTexScale[c] = in.CacheTexScale[c];
    u.CacheTexOffset[c] = in.CacheTexOffset[c];
    u.IndexOrigin[c] = static_cast<float>(extent[2 * c]);
  }
  for (int a = 0; a < 3; ++a)
  {
    for (int c = 0; c < 3; ++c)
    {
      u.ToTex[a][c] = plan.ToTex[a][c];
    }
  }
  u.Lights = &plan.Lights;
  for (const auto& m : mats)
  {
    u.MaterialRanges.push_back(m.Range[0]);
    u.MaterialRanges.push_back(m.Range[1]);
    for (int c = 0; c < 3; ++c)
    {
      u.MaterialColors.push_back(m.Physics.diffuse[c]);
    }
  }
  u.SpeedRatios = scatterer_scene::SpeedRatios(plan.Materials);
  u.OpacityRatios = scatterer_scene::OpacityRatios(plan.Materials);
  scatterer_shader::SetIlluminationUniforms(vol, u, samplers);

  bool watched = false;
  for (const auto& d : in.Volumes)
  {
    watched = watched || d.Volume == vol;
  }
  if (!watched)
  {
    in.Volumes.push_back({ vol, vol->AddObserver(vtkCommand::ModifiedEvent, in.VolumeWatcher) });
  }

  // Render, catching a shader that fails to compile.
  std::vector<std::string> errors;
  vtkNew<vtkCallbackCommand> catcher;
  catcher->SetClientData(&errors);
  catcher->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
    static_cast<std::vector<std::string>*>(client)->push_back(
      call ? static_cast<const char*>(call) : "");
  });
  const unsigned long tag = this->AddObserver(vtkCommand::ErrorEvent, catcher);
  vtkUniforms* fragmentUniforms = vol->GetShaderProperty()->GetFragmentCustomUniforms();
  for (size_t t = 0; t < bound.size(); ++t)
  {
    bound[t]->Activate();
    fragmentUniforms->SetUniformi(samplers[t].Name.c_str(), bound[t]->GetTextureUnit());
  }
  this->Superclass::GPURender(ren, vol);
  for (auto* texture : bound)
  {
    texture->Deactivate();
  }
  this->RemoveObserver(tag);

  bool compileFailed = false;
  for (const auto& e : errors)
  {
    if (e.find("Shader failed to compile") != std::string::npos)
    {
      compileFailed = true;
    }
    else
    {
      vtkErrorMacro(<< e);
    }
  }
  if (compileFailed)
  {
    in.FailedShaders.insert(declarations + shading);
    vtkErrorMacro("The scatterer-template illumination shader (" << f.Describe()
      << ") failed to compile on this OpenGL implementation (the compiler's message is above); "
         "this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    renderStock("the illumination shader failed to compile here");
    return;
  }
  in.LastFeatures = f.Describe();
}

bool vtkScattererTemplateVolumeMapper::vtkInternals::UpdateCache(
  vtkScattererTemplateVolumeMapper* self, vtkRenderer* ren, vtkVolume* vol, vtkImageData* image,
  vtkDataArray* scalars, int cellFlag, const double range[2], const FramePlan& plan, float unlit[3])
{
  const auto start = std::chrono::steady_clock::now();
  int dims[3];
  image->GetDimensions(dims);
  if (cellFlag)
  {
    for (int& d : dims)
    {
      d = std::max(1, d - 1);
    }
  }
  vtkVolumeProperty* property = vol->GetProperty();
  const auto& mats = plan.Materials.Materials;

  // The occlusion field: data, transfer function and materials.
  std::ostringstream fieldKey;
  fieldKey.precision(17);
  fieldKey << scalars << '|' << scalars->GetMTime() << '|' << image->GetMTime() << '|'
           << property->GetScalarOpacity(0)->GetMTime() << '|'
           << property->GetScalarOpacityUnitDistance(0) << '|' << range[0] << ',' << range[1];
  for (const auto& m : mats)
  {
    fieldKey << '|' << m.Physics.selector.lo << ',' << m.Physics.selector.hi << ','
             << m.Physics.selector.label;
  }
  if (fieldKey.str() != this->FieldKey)
  {
    this->Field = scatterer_scene::BuildOcclusionField(scalars, dims, range, property, plan.Materials);
    if (!this->Requested.empty())
    {
      const auto unassigned = scatterer_scene::CountUnassigned(scalars, this->Field);
      if (unassigned.Count > 0)
      {
        std::ostringstream what;
        what << unassigned.Count << " visible voxels (e.g. scalar value " << unassigned.Example
             << ") belong to none of the requested materials: they are drawn and occlude, but "
                "are lit as their nearest material (add a material for them to fix this).";
        if (this->Warned.insert(what.str()).second)
        {
          vtkWarningWithObjectMacro(self, << what.str());
        }
      }
    }
    this->FieldKey = fieldKey.str();
    this->GridKey.clear();
  }

  // The illumination grid: also lights, geometry and quality settings.
  scatterer::IlluminationSettings s;
  const int scale = self->CacheScale;
  // Cache voxel G of the lattice covers extent indices [G * scale, (G + 1) * scale):
  // anchored to index 0 rather than to this image's first voxel, so that a piece of a
  // split volume (ParaView with MPI) places and hashes its cache voxels as the whole
  // volume does, and pieces with enough ghost layers match a single-process render.
  int extent[6];
  image->GetExtent(extent);
  auto floorDiv = [](int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
  for (int a = 0; a < 3; ++a)
  {
    const int origin = extent[2 * a];
    const int first = floorDiv(origin, scale);
    const int last = floorDiv(origin + dims[a] - 1, scale);
    s.cacheDims[a] = std::max(1, last - first + 1);
    s.cacheStep[a] = static_cast<float>(scale);
    s.cacheFirstCentre[a] = (first + 0.5f) * scale - 0.5f - origin;
    s.cacheIndexOrigin[a] = first;
    // texel centre (i + 0.5) / dims of the volume <-> cache voxel (x - first centre) / scale
    const float span = static_cast<float>(scale) * s.cacheDims[a];
    this->CacheTexScale[a] = static_cast<float>(dims[a]) / span;
    this->CacheTexOffset[a] = (0.5f * scale - 0.5f - s.cacheFirstCentre[a]) / span;
  }
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  vtkMatrix4x4* matrix = vol->GetMatrix();
  double originWorld[4] = { origin[0], origin[1], origin[2], 1.0 };
  if (cellFlag)
  {
    for (int a = 0; a < 3; ++a)
    {
      originWorld[a] += 0.5 * spacing[a];
    }
  }
  matrix->MultiplyPoint(originWorld, originWorld);
  s.worldOrigin = glm::vec3(originWorld[0], originWorld[1], originWorld[2]);
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      s.indexToWorld[c][r] = static_cast<float>(matrix->GetElement(r, c) * spacing[c]);
    }
  }
  s.radius = static_cast<float>(plan.Radius);
  s.occlusionStrength = static_cast<float>(self->OcclusionStrength);
  s.longRange = static_cast<float>(self->LongRangeMultiple);
  s.photonThreshold = static_cast<float>(self->PhotonThreshold);
  s.photonCap = self->PhotonCap;
  s.templatesPerEstimate = plan.Features.Blend2 ? self->TemplatesPerMaterial : self->CacheTemplatesPerVoxel;
  s.shadow = plan.Features.Shadow;
  s.thin = plan.Features.Shadow && plan.Features.Thin;
  s.bleed = plan.Features.Bleed;
  s.boundary = plan.Features.Boundary && mats.size() > 1;
  s.packInOne = plan.Features.CacheInOne;
  for (const auto& m : mats)
  {
    s.materialColors.push_back(m.Physics.diffuse);
  }
  s.speedRatios = scatterer_scene::SpeedRatios(plan.Materials);
  s.opacityRatios = scatterer_scene::OpacityRatios(plan.Materials);
  const auto& lights = plan.Lights;
  s.ambient = glm::vec3(lights.Ambient[0], lights.Ambient[1], lights.Ambient[2]);
  for (int l = 0; l < lights.Count(); ++l)
  {
    scatterer::GridLight g;
    g.toLight = glm::vec3(lights.Direction[3 * l], lights.Direction[3 * l + 1], lights.Direction[3 * l + 2]);
    g.position = glm::vec3(lights.Position[3 * l], lights.Position[3 * l + 1], lights.Position[3 * l + 2]);
    g.positional = lights.Positional[l] != 0;
    g.color = glm::vec3(lights.Color[3 * l], lights.Color[3 * l + 1], lights.Color[3 * l + 2]);
    s.lights.push_back(g);
  }
  std::ostringstream gridKey;
  gridKey.precision(9);
  gridKey << this->FieldKey << '#' << this->TemplateKey << '#' << scale << '|' << extent[0] << ','
          << extent[2] << ',' << extent[4] << '|' << s.radius << '|'
          << s.occlusionStrength << '|' << s.longRange << '|' << s.photonThreshold << '|'
          << s.photonCap << '|' << s.templatesPerEstimate << s.shadow << s.thin << s.bleed
          << s.boundary << s.packInOne << '|' << s.ambient.x << ',' << s.ambient.y << ',' << s.ambient.z;
  for (int i = 0; i < 16; ++i)
  {
    gridKey << ',' << matrix->GetElement(i / 4, i % 4);
  }
  for (const auto& g : s.lights)
  {
    gridKey << '|' << g.toLight.x << ',' << g.toLight.y << ',' << g.toLight.z << ','
            << g.position.x << ',' << g.position.y << ',' << g.position.z << ',' << g.positional
            << ',' << g.color.x << ',' << g.color.y << ',' << g.color.z;
  }
  for (const auto& c : s.materialColors)
  {
    gridKey << '|' << c.x << ',' << c.y << ',' << c.z;
  }
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  const bool twoTextures = s.bleed && !s.packInOne;
  const bool contextChanged = !this->LightCache || this->LightCache->GetContext() != renWin ||
    (twoTextures && (!this->BleedCache || this->BleedCache->GetContext() != renWin));
  if (gridKey.str() != this->GridKey || contextChanged)
  {
    scatterer::IlluminationGrid grid;
    try
    {
      grid = scatterer::computeIllumination(this->Field, this->Templates, s);
    }
    catch (const std::exception& e)
    {
      vtkErrorWithObjectMacro(self, "The illumination cache could not be computed: " << e.what());
      return false;
    }
    auto upload = [&](vtkSmartPointer<vtkTextureObject>& texture, std::vector<std::uint8_t>& data) {
      if (!texture || texture->GetContext() != renWin)
      {
        texture = vtkSmartPointer<vtkTextureObject>::New();
        texture->SetContext(renWin);
      }
      texture->SetMinificationFilter(vtkTextureObject::Linear);
      texture->SetMagnificationFilter(vtkTextureObject::Linear);
      texture->SetWrapS(vtkTextureObject::ClampToEdge);
      texture->SetWrapT(vtkTextureObject::ClampToEdge);
      texture->SetWrapR(vtkTextureObject::ClampToEdge);
      return texture->Create3DFromRaw(
        grid.dims[0], grid.dims[1], grid.dims[2], 4, VTK_UNSIGNED_CHAR, data.data());
    };
    if (!upload(this->LightCache, grid.light) ||
      (twoTextures && !upload(this->BleedCache, grid.bleed)))
    {
      vtkErrorWithObjectMacro(self, "The illumination cache (" << grid.dims[0] << "x"
        << grid.dims[1] << "x" << grid.dims[2] << " RGBA8) could not be uploaded as a 3D texture.");
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      this->Unlit[c] = grid.unlit[c];
    }
    this->GridKey = gridKey.str();
    this->LastCacheMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  for (int c = 0; c < 3; ++c)
  {
    unlit[c] = this->Unlit[c];
  }
  return true;
}

void vtkScattererTemplateVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto onOff = [](bool b) { return b ? "On" : "Off"; };
  os << indent << "IlluminationEnabled: " << onOff(this->IlluminationEnabled) << "\n";
  os << indent << "ShadowsEnabled: " << onOff(this->ShadowsEnabled) << "\n";
  os << indent << "ColorBleedingEnabled: " << onOff(this->ColorBleedingEnabled) << "\n";
  os << indent << "ThinPartCheckEnabled: " << onOff(this->ThinPartCheckEnabled) << "\n";
  os << indent << "BoundaryRefractionEnabled: " << onOff(this->BoundaryRefractionEnabled) << "\n";
  os << indent << "TemplateBlendingEnabled: " << onOff(this->TemplateBlendingEnabled) << "\n";
  os << indent << "ShaderPathSelection: "
     << (this->ShaderPathSelection == AUTOMATIC ? "Automatic" : "AsRequested") << "\n";
  os << indent << "MaterialDerivationRange: ";
  if (this->MaterialDerivationRange[0] <= this->MaterialDerivationRange[1])
  {
    os << this->MaterialDerivationRange[0] << ", " << this->MaterialDerivationRange[1] << "\n";
  }
  else
  {
    os << "(the data range)\n";
  }
  os << indent << "TemplateRadius: " << this->TemplateRadius
     << (this->TemplateRadius > 0 ? "" : " (automatic: 10 x mean spacing)") << "\n";
  os << indent << "TemplatesPerMaterial: " << this->TemplatesPerMaterial << "\n";
  os << indent << "PhotonCap: " << this->PhotonCap << "\n";
  os << indent << "OcclusionStrength: " << this->OcclusionStrength << "\n";
  os << indent << "LongRangeMultiple: " << this->LongRangeMultiple << "\n";
  os << indent << "IlluminationInterval: " << this->IlluminationInterval << "\n";
  os << indent << "PhotonThreshold: " << this->PhotonThreshold << "\n";
  os << indent << "GeneratorThreshold: " << this->GeneratorThreshold << "\n";
  os << indent << "RequestedMaterials: " << this->Internals->Requested.size() << "\n";
  os << indent << "LastShaderFeatures: " << this->Internals->LastFeatures << "\n";
}
