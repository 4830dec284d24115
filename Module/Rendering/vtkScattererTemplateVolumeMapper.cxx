#include "vtkScattererTemplateVolumeMapper.h"

#include "ScattererMaskTexture.h"
#include "ScattererProgramBudget.h"
#include "ScattererSceneLights.h"
#include "ScattererSceneMaterials.h"
#include "ScattererShaderComposer.h"
#include "ScattererShaderInstaller.h"
#include "vtkScattererTransportVolume.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiVolume.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkVolumeInputHelper.h"
#include "vtkVolumeTexture.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
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

#include <scatterer/Material.h>
#include <scatterer/Pack.h>
#include <scatterer/Template.h>
#include <scatterer/Transport.h>

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

}

// Everything one frame of illumination needs, decided before rendering.
struct vtkScattererTemplateVolumeMapper::FramePlan
{
  scatterer_shader::Features Features;
  scatterer_scene::LightSet Lights;
  scatterer_scene::MaterialSet Materials;
  vtkImageData* Image = nullptr;
  vtkDataArray* Scalars = nullptr;
  int CellFlag = 0;
  double Radius = 1.0;    // template radius, world units
  float ToTex[3][3] = {}; // per-sample mode: texture offset of one radius along world x, y, z
  std::string Declarations, ShadingInit, Shading; // this frame's GLSL
};

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

  double LastTransportMs = 0.0;
  // This frame rebuilt something and reported progress: GPURender reports 1 at its end.
  bool ProgressReported = false;
  // Transport mode: the light transport volume (owns its textures and change key).
  vtkNew<vtkScattererTransportVolume> Transport;
  // Transport mode: the mask (binary or label map) as the transport volume reads it.
  scatterer_gpu::MaskTexture Mask;
  // A label-map mask: the opacity that materials are derived from (the largest any label
  // gives a scalar), and what it was tabulated from.
  vtkNew<vtkVolumeProperty> LabelUnion;
  std::string LabelUnionKey;
  // Transport mode: what the transport volume is built from (kept between frames: its
  // tables are rebuilt only when TablesKey changes).
  vtkScattererTransportVolume::Inputs TransportInputs;
  std::string TablesKey;
  // Transport mode: each material's un-normalised templates (photons in template
  // radii, as generated), for the in-scattering kernels.
  std::vector<std::vector<scatterer::Template>> RawTemplates;

  // The data, transfer function and materials last scanned for unassigned voxels.
  std::string UnassignedKey;

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
  // The index range is the physics' own rule (scatterer::Material::validate), checked
  // here so that a bad material is refused when added, not at render time.
  if (hi < lo || refractiveIndex < scatterer::kMinRefractiveIndex ||
    refractiveIndex > scatterer::kMaxRefractiveIndex)
  {
    vtkErrorMacro("AddScalarRangeMaterial: needs lo <= hi and a refractive index in ["
      << scatterer::kMinRefractiveIndex << ", " << scatterer::kMaxRefractiveIndex << "] (got ["
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

double vtkScattererTemplateVolumeMapper::GetLastTransportBuildMilliseconds() const
{
  return this->Internals->LastTransportMs;
}

vtkScattererTransportVolume* vtkScattererTemplateVolumeMapper::GetTransportVolume() const
{
  return this->Internals->Transport;
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
  // Per sample: photons lie within one radius; the thin-part check marches on toward
  // the light to LongRangeMultiple x the photon's offset. Transport: the kernel reaches
  // one radius, the ambient occlusion two diffusion voxels and the diffusion one such
  // voxel per iteration (a diffusion voxel spans max(4, scale) volume voxels); and a
  // transport voxel is interpolated by its neighbours.
  const bool thin = this->ShadowsEnabled && this->ThinPartCheckEnabled;
  const bool transport = this->IlluminationMode == TRANSPORT;
  const int scale = std::max(this->TransportScale, this->InteractiveTransportScale);
  const double voxel = std::max({ sx, sy, sz });
  const double diffusionVoxel = std::max(4, scale) * voxel;
  const int iterations = vtkScattererTransportVolume::Inputs().DiffusionIterations;
  const double transportReach = std::max({ radius, 2.0 * diffusionVoxel,
    this->MultipleScattering > 0.0 ? iterations * diffusionVoxel : 0.0 });
  const double photonReach =
    transport ? transportReach : (thin ? radius * this->LongRangeMultiple : radius);
  const double gridMargin = transport ? scale * voxel : 0.0;
  const double reach = photonReach + gridMargin;
  return std::isfinite(reach) ? reach : 0.0;
}

void vtkScattererTemplateVolumeMapper::SetExtraShaderCodeForTesting(const std::string& glsl)
{
  this->Internals->ExtraGLSL = glsl;
}

void vtkScattererTemplateVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& in = *this->Internals;
  in.Transport->ReleaseGraphicsResources(window);
  in.Mask.ReleaseGraphicsResources(window);
  for (auto* texture : { &in.Texture })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      *texture = nullptr;
    }
  }
  in.UploadedKey.clear();
  this->Superclass::ReleaseGraphicsResources(window);
  // The released inputs keep blocks that point at their deleted textures, and
  // PreLoadData (UpdateTransport) would not reload them: the superclass decides that
  // inside its own GPURender. Dropped here, they are created and loaded afresh by the
  // next PreLoadData or GPURender, as on a first frame.
  this->AssembledInputs.clear();
}

namespace
{
// Why illumination cannot apply to this volume, or "" if it can.
std::string Unsupported(vtkScattererTemplateVolumeMapper* mapper, vtkVolume* vol)
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
  if (mapper->GetMaskInput() &&
    mapper->GetIlluminationMode() != vtkScattererTemplateVolumeMapper::TRANSPORT)
  {
    // The per-sample photon test would still see masked-out matter as occluders.
    return "a mask input in per-sample mode (the transport mode honours binary masks)";
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

/*
 * GPURender: plan the frame, refresh the templates and (transport mode) the light
 * transport volume, then render with the illumination GLSL; any stage that
 * cannot do its part says why and the volume renders as the stock mapper would.
 */
void vtkScattererTemplateVolumeMapper::GPURender(vtkRenderer* ren, vtkVolume* vol)
{
  FramePlan plan;
  std::string stock = this->PlanFrame(ren, vol, plan);
  if (stock.empty())
  {
    stock = this->UpdateTemplates(plan);
  }
  if (stock.empty() && plan.Features.Transport)
  {
    stock = this->UpdateTransport(ren, vol, plan);
  }
  if (stock.empty())
  {
    stock = this->RenderIlluminated(ren, vol, plan);
  }
  if (!stock.empty())
  {
    this->RenderStock(ren, vol, stock);
  }
  if (this->Internals->ProgressReported)
  {
    this->ReportProgress(1.0);
    this->Internals->ProgressReported = false;
  }
}

namespace
{
// Progress of a frame that rebuilds its illumination (ProgressEvent): the templates
// (CPU) up to kTemplatesDone, the transport volume's GPU stages up to kTransportDone,
// the image itself the rest. Frames that rebuild nothing report nothing.
constexpr double kTemplatesDone = 0.1;
constexpr double kTransportDone = 0.95;
constexpr const char* kProgressText = "Scatterer illumination";
}

void vtkScattererTemplateVolumeMapper::ReportProgress(double fraction)
{
  this->Internals->ProgressReported = true;
  // The text tells these reports from the 0 and 1 that the mapper's own executive
  // reports whenever its pipeline runs (vtkScattererVolumeRepresentation forwards
  // only ours). SetProgressText does not modify the mapper.
  this->SetProgressText(kProgressText);
  this->UpdateProgress(fraction);
  this->SetProgressText(nullptr);
}

void vtkScattererTemplateVolumeMapper::RenderStock(
  vtkRenderer* ren, vtkVolume* vol, const std::string& reason)
{
  this->Internals->LastFeatures = "stock: " + reason;
  this->Internals->LastTransportMs = 0.0;
  scatterer_shader::RemoveIllumination(vol);
  this->Superclass::GPURender(ren, vol);
}

std::string vtkScattererTemplateVolumeMapper::PlanFrame(
  vtkRenderer* ren, vtkVolume* vol, FramePlan& plan)
{
  vtkInternals& in = *this->Internals;
  if (!this->IlluminationEnabled)
  {
    return "illumination off";
  }
  auto warnOnce = [&](const std::string& what) {
    if (in.Warned.insert(what).second)
    {
      vtkWarningMacro(<< what);
    }
  };
  const std::string unsupported = Unsupported(this, vol);
  if (!unsupported.empty())
  {
    warnOnce("Scatterer-template illumination does not apply to " + unsupported +
      "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return unsupported;
  }
  plan.Image = vtkImageData::SafeDownCast(this->GetInput());
  plan.Scalars = plan.Image ? vtkAbstractMapper::GetScalars(plan.Image, this->ScalarMode,
                                this->ArrayAccessMode, this->ArrayId, this->ArrayName, plan.CellFlag)
                            : nullptr;
  if (!plan.Scalars)
  {
    return "no scalars";
  }
  if (plan.Scalars->GetNumberOfComponents() != 1)
  {
    warnOnce("Scatterer-template illumination needs single-component scalars (intensities or "
             "a label map); these have " +
      std::to_string(plan.Scalars->GetNumberOfComponents()) +
      " components, so this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return "multi-component scalars";
  }
  vtkVolumeProperty* property = vol->GetProperty();
  plan.Lights = scatterer_scene::CollectLights(ren, property);
  if (plan.Lights.Count() == 0)
  {
    return "no light is switched on";
  }
  if (plan.Lights.Skipped > 0)
  {
    warnOnce("Scatterer-template illumination uses the first 6 lights (VTK's limit); " +
      std::to_string(plan.Lights.Skipped) + " more are ignored.");
  }

  // Template radius and the world -> texture mapping of photon offsets.
  vtkImageData* image = plan.Image;
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
    return "degenerate spacing";
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
        const int texels = std::max(1, plan.CellFlag ? dims[row] - 1 : dims[row]);
        const double tex = data / (spacing[row] * texels);
        plan.ToTex[axis][row] = std::isfinite(tex) ? static_cast<float>(tex) : 0.0f;
      }
    }
  }

  double range[2];
  plan.Scalars->GetFiniteRange(range, 0);
  // Materials are derived over the derivation range when one is set (a piece of a
  // split volume: the whole volume's range), so every piece derives the same ones.
  double derivation[2] = { range[0], range[1] };
  if (this->MaterialDerivationRange[0] <= this->MaterialDerivationRange[1])
  {
    derivation[0] = this->MaterialDerivationRange[0];
    derivation[1] = this->MaterialDerivationRange[1];
  }
  // With a label-map mask, what is visible is what any label's opacity function (or the
  // volume's own, label 0) makes visible: materials are derived from their maximum,
  // tabulated again only when a function or the range changes (not every frame).
  vtkVolumeProperty* materialProperty = property;
  if (this->GetMaskInput() && this->GetMaskType() == LabelMapMaskType)
  {
    const std::set<int> labels = property->GetLabelMapLabels();
    std::ostringstream key;
    key.precision(17);
    key << property->GetScalarOpacity(0)->GetMTime() << '|'
        << property->GetRGBTransferFunction(0)->GetMTime() << '|' << derivation[0] << ','
        << derivation[1];
    for (int label : labels)
    {
      vtkPiecewiseFunction* o = property->GetLabelScalarOpacity(label);
      key << '|' << label << ':' << (o ? o->GetMTime() : 0);
    }
    if (key.str() != in.LabelUnionKey)
    {
      vtkNew<vtkPiecewiseFunction> visible;
      const int samples = 256;
      for (int i = 0; i < samples; ++i)
      {
        const double x = derivation[0] + (derivation[1] - derivation[0]) * i / (samples - 1.0);
        double alpha = property->GetScalarOpacity(0)->GetValue(x);
        for (int label : labels)
        {
          if (vtkPiecewiseFunction* o = property->GetLabelScalarOpacity(label))
          {
            alpha = std::max(alpha, o->GetValue(x));
          }
        }
        visible->AddPoint(x, alpha);
      }
      in.LabelUnion->SetColor(property->GetRGBTransferFunction(0));
      in.LabelUnion->SetScalarOpacity(visible);
      in.LabelUnionKey = key.str();
    }
    in.LabelUnion->SetScalarOpacityUnitDistance(property->GetScalarOpacityUnitDistance());
    materialProperty = in.LabelUnion;
  }
  plan.Materials = scatterer_scene::BuildMaterials(in.Requested, materialProperty, range, derivation);
  in.ActiveMaterials = static_cast<int>(plan.Materials.Materials.size());
  if (plan.Materials.Materials.empty())
  {
    return "no material: the opacity transfer function is below 1e-4 everywhere";
  }
  if (plan.Materials.Dropped > 0)
  {
    warnOnce("Scatterer-template illumination handles 8 materials; " +
      std::to_string(plan.Materials.Dropped) + " more stay unlit.");
  }
  if (!in.Requested.empty())
  {
    // Visible voxels that no requested material selects: scanned once per change of
    // the data, the transfer function or the materials.
    std::ostringstream key;
    key.precision(17);
    key << plan.Scalars << '|' << plan.Scalars->GetMTime() << '|'
        << property->GetScalarOpacity(0)->GetMTime() << '|' << range[0] << ',' << range[1];
    for (const auto& m : plan.Materials.Materials)
    {
      key << '|' << m.Physics.selector.lo << ',' << m.Physics.selector.hi << ','
          << m.Physics.selector.label;
    }
    if (key.str() != in.UnassignedKey)
    {
      in.UnassignedKey = key.str();
      const auto unassigned =
        scatterer_scene::CountUnassigned(plan.Scalars, plan.Materials, property, range);
      if (unassigned.Count > 0)
      {
        std::ostringstream what;
        what << unassigned.Count << " visible voxels (e.g. scalar value " << unassigned.Example
             << ") belong to none of the requested materials: they are drawn and cast shadows, "
                "but receive light without in-scattering (add a material for them to fix this).";
        warnOnce(what.str());
      }
    }
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
  f.Transport = this->IlluminationMode == TRANSPORT;
  f.Shadow = this->ShadowsEnabled;
  // The thin-part check and template blending belong to the per-sample photon test.
  f.Thin = !f.Transport && f.Shadow && this->ThinPartCheckEnabled &&
    (!automatic || this->LongRangeMultiple > 1.0);
  f.Bleed = this->ColorBleedingEnabled && (!automatic || (f.Materials > 1 && colorsDiffer));
  f.Boundary = this->BoundaryRefractionEnabled && f.Materials > 1 && (!automatic || indicesDiffer);
  f.Positional = plan.Lights.AnyPositional;
  f.Blend2 = !f.Transport && this->TemplateBlendingEnabled;
  f.Phong = property->GetShade() != 0;
  f.LabelMask = this->GetMaskInput() && this->GetMaskType() == LabelMapMaskType;
  if (automatic && !f.Shadow && !f.Bleed && !f.Boundary)
  {
    return "no illumination effect is switched on";
  }
  plan.Declarations = scatterer_shader::IlluminationDeclarations(f) + in.ExtraGLSL;
  plan.ShadingInit = scatterer_shader::ShadingInitialization(f);
  plan.Shading = scatterer_shader::ShadingImplementation(f);
  if (in.FailedShaders.count(plan.Declarations + plan.ShadingInit + plan.Shading))
  {
    return "the illumination shader failed to compile here";
  }
  return "";
}

std::string vtkScattererTemplateVolumeMapper::UpdateTemplates(const FramePlan& plan)
{
  vtkInternals& in = *this->Internals;
  std::ostringstream key;
  key.precision(17);
  key << this->TemplatesPerMaterial << '|' << this->GeneratorThreshold << '|' << this->PhotonCap;
  for (const auto& m : plan.Materials.Materials)
  {
    key << '|' << m.Physics.opacity << ',' << m.Physics.refractiveIndex;
  }
  if (key.str() == in.TemplateKey)
  {
    return "";
  }
  std::vector<scatterer::Material> physics;
  for (const auto& m : plan.Materials.Materials)
  {
    physics.push_back(m.Physics);
  }
  scatterer::GeneratorSettings settings;
  settings.templatesPerMaterial = this->TemplatesPerMaterial;
  settings.threshold = this->GeneratorThreshold;
  this->ReportProgress(0.0);
  try
  {
    in.RawTemplates = scatterer::generateAllTemplates(physics, settings);
    in.Templates = in.RawTemplates;
    NormalizeExtent(in.Templates);
    in.Packed = scatterer::packTemplates(in.Templates, this->PhotonCap);
    this->ReportProgress(kTemplatesDone);
  }
  catch (const std::exception& e)
  {
    const std::string what = std::string("Scatterer templates could not be generated (") +
      e.what() + "); this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.";
    if (in.Warned.insert(what).second)
    {
      vtkWarningMacro(<< what);
    }
    return "template generation failed";
  }
  in.TemplateKey = key.str();
  return "";
}

std::string vtkScattererTemplateVolumeMapper::UpdateTransport(
  vtkRenderer* ren, vtkVolume* vol, const FramePlan& plan)
{
  vtkInternals& in = *this->Internals;
  auto warnOnce = [&](const std::string& what) {
    if (in.Warned.insert(what).second)
    {
      vtkWarningMacro(<< what);
    }
  };
  // The ray caster's own scalar texture: loaded now if this is the first frame.
  if (!this->PreLoadData(ren, vol) || this->AssembledInputs.empty())
  {
    return "the volume could not be loaded into a texture";
  }
  vtkVolumeTexture* volumeTexture = this->AssembledInputs.begin()->second.Texture;
  if (!volumeTexture || volumeTexture->GetPartitions()[0] * volumeTexture->GetPartitions()[1] *
        volumeTexture->GetPartitions()[2] != 1)
  {
    warnOnce("Scatterer-template illumination does not apply to a partitioned volume (one "
             "3D texture per block); this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return "a partitioned volume";
  }
  vtkVolumeTexture::VolumeBlock* block = volumeTexture->GetCurrentBlock();
  if (!block || !block->TextureObject)
  {
    return "the volume texture is not loaded";
  }

  vtkScattererTransportVolume::Inputs& t = in.TransportInputs;
  t.Volume = block->TextureObject;
  // Scale and bias as the ray caster applies them (64-bit types come pre-scaled).
  t.ScalarScale = volumeTexture->HandleLargeDataTypes ? 1.0f : volumeTexture->Scale[0];
  t.ScalarBias = volumeTexture->HandleLargeDataTypes ? 0.0f : volumeTexture->Bias[0];
  t.VolumeUploadTime = volumeTexture->UploadTime.GetMTime();
  // A binary mask: masked-out matter neither shows (the ray caster's mask) nor casts
  // shadow or scatters (the transport volume). A label-map mask: each label's medium
  // comes from its own transfer functions, in the picture and in the light.
  t.Mask = nullptr;
  t.MaskUploadTime = 0;
  t.LabelMask = plan.Features.LabelMask;
  t.MaskBlend = this->GetMaskBlendFactor();
  if (vtkImageData* mask = this->GetMaskInput())
  {
    const int volumeDims[3] = { static_cast<int>(block->TextureObject->GetWidth()),
      static_cast<int>(block->TextureObject->GetHeight()),
      static_cast<int>(block->TextureObject->GetDepth()) };
    std::string why;
    t.Mask = in.Mask.Update(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()), mask,
      volumeDims, why);
    if (!t.Mask)
    {
      warnOnce("Scatterer-template illumination cannot use this mask: " + why +
        "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
      return "an unusable mask";
    }
    t.MaskUploadTime = in.Mask.GetUploadTime();
  }
  // Texture coordinate -> structured index -> physical (origin, spacing, direction)
  // -> world (the volume's matrix). Texel centre (i + 0.5) / N holds data point i
  // (cell data: the centre of cell i), so distances are the data's own.
  vtkNew<vtkMatrix4x4> texToIndex, indexToDataset, texToDataset, texToWorld;
  int extent[6];
  plan.Image->GetExtent(extent);
  const unsigned int texels[3] = { block->TextureObject->GetWidth(),
    block->TextureObject->GetHeight(), block->TextureObject->GetDepth() };
  for (int a = 0; a < 3; ++a)
  {
    texToIndex->SetElement(a, a, texels[a]);
    texToIndex->SetElement(a, 3, extent[2 * a] - 0.5 + (plan.CellFlag ? 0.5 : 0.0));
    t.IndexOrigin[a] = extent[2 * a];
  }
  plan.Image->ComputeIndexToPhysicalMatrix(
    plan.Image->GetOrigin(), plan.Image->GetSpacing(), plan.Image->GetDirectionMatrix()->GetData(),
    indexToDataset->GetData());
  vtkMatrix4x4::Multiply4x4(indexToDataset, texToIndex, texToDataset);
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix(), texToDataset, texToWorld);
  for (int i = 0; i < 16; ++i)
  {
    t.TexToWorld[i] = texToWorld->GetElement(i / 4, i % 4);
    t.TexToDataset[i] = texToDataset->GetElement(i / 4, i % 4);
  }
  // The medium over the table coordinate (VTK's tables span the scalar range): albedo
  // from the colour transfer function, extinction from the opacity transfer function.
  vtkVolumeProperty* property = vol->GetProperty();
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const double unit = property->GetScalarOpacityUnitDistance(0) > 0.0
    ? property->GetScalarOpacityUnitDistance(0)
    : 1.0;
  const double lo = volumeTexture->ScalarRange[0][0], hi = volumeTexture->ScalarRange[0][1];
  // The tables (medium, materials, kernels) change with the transfer functions, the range,
  // the materials, the templates and the kernel settings only: rebuilt then, not every
  // frame, and the transport volume is told by TablesVersion.
  const auto& mats = plan.Materials.Materials;
  std::ostringstream tablesKey;
  tablesKey.precision(17);
  const bool gray = property->GetColorChannels(0) == 1;
  tablesKey << opacity->GetMTime() << '|'
            << (gray ? property->GetGrayTransferFunction(0)->GetMTime()
                     : property->GetRGBTransferFunction(0)->GetMTime())
            << '|' << gray << '|' << lo << ',' << hi << '|' << unit << '|' << in.TemplateKey
            << '|' << this->PhotonCap << '|' << plan.Radius;
  // A label-map mask adds one medium row per label: its transfer functions count too.
  const bool labelMask = plan.Features.LabelMask;
  tablesKey << '|' << labelMask;
  if (labelMask)
  {
    tablesKey << ',' << property->GetLabelColorMTime().GetMTime() << ','
              << property->GetLabelScalarOpacityMTime().GetMTime();
    for (int label : property->GetLabelMapLabels())
    {
      vtkColorTransferFunction* c = property->GetLabelColor(label);
      vtkPiecewiseFunction* o = property->GetLabelScalarOpacity(label);
      tablesKey << ',' << label << ':' << (c ? c->GetMTime() : 0) << ':' << (o ? o->GetMTime() : 0);
    }
  }
  for (const auto& m : mats)
  {
    tablesKey << '|' << m.Physics.selector.lo << ',' << m.Physics.selector.hi << ','
              << m.Physics.selector.label << ',' << static_cast<int>(m.Physics.selector.kind)
              << ',' << m.OpacityPerUnit << ',' << m.Physics.refractiveIndex << ','
              << m.Physics.diffuse.x << ','
              << m.Physics.diffuse.y << ',' << m.Physics.diffuse.z;
  }
  if (tablesKey.str() != in.TablesKey)
  {
    this->UpdateTransportTables(vol, plan, lo, hi, unit);
    in.TablesKey = tablesKey.str();
    ++t.TablesVersion;
  }
  t.ExtinctionScale = plan.Features.Shadow ? static_cast<float>(this->OcclusionStrength) : 0.0f;
  t.ClipPlanes.clear();
  if (vtkPlaneCollection* planes = this->GetClippingPlanes())
  {
    for (int p = 0; p < planes->GetNumberOfItems() && p < 6; ++p)
    {
      vtkPlane* plane = planes->GetItem(p);
      double n[3], o[3];
      plane->GetNormal(n);
      plane->GetOrigin(o);
      t.ClipPlanes.insert(t.ClipPlanes.end(), { static_cast<float>(n[0]),
        static_cast<float>(n[1]), static_cast<float>(n[2]),
        static_cast<float>(-(n[0] * o[0] + n[1] * o[1] + n[2] * o[2])) });
    }
  }
  t.Cropping = this->GetCropping() != 0 && !this->CroppedMatterCastsShadows;
  t.CropFlags = this->GetCroppingRegionFlags();
  for (int a = 0; a < 3; ++a)
  {
    t.CropMin[a] = static_cast<float>(this->CroppingRegionPlanes[2 * a]);
    t.CropMax[a] = static_cast<float>(this->CroppingRegionPlanes[2 * a + 1]);
  }
  const auto& lights = plan.Lights;
  t.Lights.clear();
  for (int l = 0; l < lights.Count(); ++l)
  {
    vtkScattererTransportVolume::Light light;
    for (int c = 0; c < 3; ++c)
    {
      light.Toward[c] = lights.Direction[3 * l + c];
      light.Position[c] = lights.Position[3 * l + c];
      light.Color[c] = lights.Color[3 * l + c];
      light.Ambient[c] = lights.AmbientColor[3 * l + c];
      light.FocalDirection[c] = lights.FocalDirection[3 * l + c];
      light.Attenuation[c] = lights.Attenuation[3 * l + c];
    }
    light.Positional = lights.Positional[l] != 0;
    light.ConeCos = lights.ConeCos[l];
    light.Exponent = lights.Exponent[l];
    t.Lights.push_back(light);
  }
  t.Bleed = plan.Features.Bleed;
  t.Boundary = plan.Features.Boundary;
  t.MultipleScattering = static_cast<float>(this->MultipleScattering);

  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  // Interactive frames (a time budget under a second) build the volume coarser, but
  // only when it must be rebuilt at all: while the user orbits under a scene light,
  // the still frames' volume stays valid, and a coarse one would cost a build now and
  // another when the user lets go.
  t.Downsample = this->TransportScale;
  const bool interactive = vol->GetAllocatedRenderTime() < 1.0;
  if (interactive && !in.Transport->IsCurrent(renWin, t))
  {
    t.Downsample = this->InteractiveTransportScale;
  }
  // Progress only when someone listens (ParaView's progress bar via the
  // representation): reporting makes the build wait for each GPU stage.
  if (this->HasObserver(vtkCommand::ProgressEvent) && !in.Transport->IsCurrent(renWin, t))
  {
    this->ReportProgress(kTemplatesDone);
    in.Transport->SetProgressCallback([this](double fraction) {
      this->ReportProgress(kTemplatesDone + (kTransportDone - kTemplatesDone) * fraction);
    });
  }
  else
  {
    in.Transport->SetProgressCallback(nullptr);
  }
  std::string why;
  if (!in.Transport->Update(renWin, t, why))
  {
    vtkErrorMacro("The light transport volume could not be built: " << why
      << "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return "the light transport volume could not be built";
  }
  in.LastTransportMs = in.Transport->GetLastBuildMilliseconds();
  return "";
}

void vtkScattererTemplateVolumeMapper::UpdateTransportTables(
  vtkVolume* vol, const FramePlan& plan, double lo, double hi, double unit)
{
  vtkInternals& in = *this->Internals;
  vtkScattererTransportVolume::Inputs& t = in.TransportInputs;
  vtkVolumeProperty* property = vol->GetProperty();
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const bool gray = property->GetColorChannels(0) == 1;
  const int tableSize = 4096;
  t.Medium.resize(4 * tableSize);
  for (int i = 0; i < tableSize; ++i)
  {
    const double value = lo + (hi - lo) * i / (tableSize - 1.0);
    double rgb[3] = { 1.0, 1.0, 1.0 };
    if (gray)
    {
      rgb[0] = rgb[1] = rgb[2] = property->GetGrayTransferFunction(0)->GetValue(value);
    }
    else
    {
      property->GetRGBTransferFunction(0)->GetColor(value, rgb);
    }
    for (int c = 0; c < 3; ++c)
    {
      t.Medium[4 * i + c] = static_cast<float>(std::min(std::max(rgb[c], 0.0), 1.0));
    }
    t.Medium[4 * i + 3] =
      static_cast<float>(scatterer::extinctionFromOpacity(opacity->GetValue(value), unit));
  }
  // A label-map mask: row L holds label L's colour and opacity functions (rows 1..255;
  // a label without functions is empty, as VTK's label table leaves it).
  t.MediumRows = 1;
  if (plan.Features.LabelMask)
  {
    t.MediumRows = 256;
    t.Medium.resize(static_cast<size_t>(4) * tableSize * t.MediumRows, 0.0f);
    for (int label : property->GetLabelMapLabels())
    {
      vtkColorTransferFunction* color = property->GetLabelColor(label);
      vtkPiecewiseFunction* labelOpacity = property->GetLabelScalarOpacity(label);
      if (label < 1 || label > 255 || !labelOpacity)
      {
        continue;
      }
      float* row = t.Medium.data() + static_cast<size_t>(4) * tableSize * label;
      for (int i = 0; i < tableSize; ++i)
      {
        const double value = lo + (hi - lo) * i / (tableSize - 1.0);
        double rgb[3] = { 1.0, 1.0, 1.0 };
        if (color)
        {
          color->GetColor(value, rgb);
        }
        for (int c = 0; c < 3; ++c)
        {
          row[4 * i + c] = static_cast<float>(std::min(std::max(rgb[c], 0.0), 1.0));
        }
        row[4 * i + 3] =
          static_cast<float>(scatterer::extinctionFromOpacity(labelOpacity->GetValue(value), unit));
      }
    }
  }
  const double tableRange[2] = { lo, hi };
  t.MaterialTable = scatterer_scene::MaterialTable(plan.Materials, tableRange, tableSize);
  // Materials and their kernels: the merged templates, in the material's mean free
  // paths (scatterer/Transport.h), at most one template radius.
  const auto& mats = plan.Materials.Materials;
  t.KernelWidth = std::max(1, this->PhotonCap);
  t.MaterialColors.clear();
  t.Kernels.clear();
  for (size_t m = 0; m < mats.size(); ++m)
  {
    const auto& material = mats[m];
    const glm::vec3 c = material.Physics.diffuse;
    t.MaterialColors.insert(t.MaterialColors.end(), { c.x, c.y, c.z });
    const double sigma = scatterer::extinctionFromOpacity(material.OpacityPerUnit, unit);
    std::vector<scatterer::KernelPhoton> kernel;
    if (m < in.RawTemplates.size())
    {
      kernel = scatterer::mergedKernel(in.RawTemplates[m], t.KernelWidth,
        scatterer::kernelRadius(material.Physics, sigma, 0.0, plan.Radius));
    }
    for (int k = 0; k < t.KernelWidth; ++k)
    {
      const bool has = k < static_cast<int>(kernel.size());
      t.Kernels.insert(t.Kernels.end(),
        { has ? kernel[k].offset.x : 0.0f, has ? kernel[k].offset.y : 0.0f,
          has ? kernel[k].offset.z : 0.0f, has ? kernel[k].weight : 0.0f });
    }
  }
  t.SpeedRatios = scatterer_scene::SpeedRatios(plan.Materials);
  t.OpacityRatios = scatterer_scene::OpacityRatios(plan.Materials);
}

std::string vtkScattererTemplateVolumeMapper::RenderIlluminated(
  vtkRenderer* ren, vtkVolume* vol, const FramePlan& plan)
{
  vtkInternals& in = *this->Internals;
  const scatterer_shader::Features& f = plan.Features;
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  std::vector<scatterer_shader::Sampler> samplers;
  std::vector<vtkTextureObject*> bound;
  scatterer_shader::UniformValues u;
  if (f.Transport)
  {
    samplers.push_back({ "st_transport", "sampler3D" });
    bound.push_back(in.Transport->GetLightTexture());
    in.Transport->GetTextureTransform(u.TransportScale, u.TransportOffset);
  }
  else
  {
    in.LastTransportMs = 0.0;
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
  scatterer_shader::InstallIllumination(
    vol, plan.Declarations, plan.ShadingInit, plan.Shading, samplers);
  u.TemplatesPerMaterial = this->TemplatesPerMaterial;
  u.PhotonCount = std::min(this->PhotonCap, in.Packed.width);
  u.PhotonThreshold = static_cast<float>(this->PhotonThreshold);
  u.OcclusionScale = static_cast<float>(this->OcclusionStrength * plan.Radius);
  u.LongRange = static_cast<float>(this->LongRangeMultiple);
  u.Interval = this->IlluminationInterval;
  int extent[6];
  plan.Image->GetExtent(extent);
  for (int c = 0; c < 3; ++c)
  {
    u.IndexOrigin[c] = static_cast<float>(extent[2 * c]);
    for (int a = 0; a < 3; ++a)
    {
      u.ToTex[c][a] = plan.ToTex[c][a];
    }
  }
  u.Lights = &plan.Lights;
  for (const auto& m : plan.Materials.Materials)
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
  // The program that drew is the last one bound, unless VTK drew its resampling quad
  // after it (ImageSampleDistance > 1): that frame's program is then not counted,
  // and is counted on the next full-resolution frame that uses it.
  scatterer_shader::NoteProgramUse(renWin, renWin->GetShaderCache()->GetLastShaderBound());

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
    in.FailedShaders.insert(plan.Declarations + plan.ShadingInit + plan.Shading);
    vtkErrorMacro("The scatterer-template illumination shader (" << f.Describe()
      << ") failed to compile on this OpenGL implementation (the compiler's message is above); "
         "this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return "the illumination shader failed to compile here";
  }
  in.LastFeatures = f.Describe();
  return "";
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
  os << indent << "CroppedMatterCastsShadows: " << onOff(this->CroppedMatterCastsShadows) << "\n";
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
