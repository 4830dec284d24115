#include "vtkScattererTemplateVolumeMapper.h"

#include "ScattererChangeKey.h"
#include "ScattererDecoratedVolumes.h"
#include "ScattererFramePlan.h"
#include "ScattererIlluminationParameters.h"
#include "ScattererMirroredWinding.h"
#include "ScattererProgramBudget.h"
#include "ScattererSceneMaterials.h"
#include "ScattererShaderCompileCheck.h"
#include "ScattererShaderInstaller.h"
#include "ScattererTemplateCache.h"
#include "ScattererTransportUpdate.h"
#include "ScattererUniformInstaller.h"
#include "ScattererWarnOnce.h"
#include "vtkScattererLightExchange.h"
#include "vtkScattererTransportVolume.h"

#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiVolume.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeInputHelper.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumeTexture.h"

#include <scatterer/Material.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkScattererTemplateVolumeMapper);

namespace
{
// Progress of a frame that rebuilds its illumination (ProgressEvent): the templates
// (CPU) up to kTemplatesDone, the transport volume's GPU stages up to kTransportDone,
// the image itself the rest. Frames that rebuild nothing report nothing.
constexpr double kTemplatesDone = 0.1;
constexpr double kTransportDone = 0.95;
constexpr const char* kProgressText = "Scatterer illumination";
}

// The stages' helpers (each keeps what it needs between frames) and what the frame
// reports back.
struct vtkScattererTemplateVolumeMapper::vtkInternals
{
  explicit vtkInternals(vtkScattererTemplateVolumeMapper* self)
    : Warn(self)
    , Volumes(self)
  {
  }

  std::vector<scatterer_scene::RequestedMaterial> Requested;
  std::string ExtraGLSL;
  int MaximumLightStride = scatterer::illumination::kMaximumLightReadStride;
  bool SurfaceDetail = true;
  scatterer_render::WarnOnce Warn;

  scatterer_render::FramePlanner Planner;
  scatterer_render::TemplateCache Templates;
  scatterer_render::TransportUpdate Transport;
  scatterer_render::UniformInstaller Uniforms;
  scatterer_render::ShaderCompileCheck CompileCheck;
  // Shader texts that failed to compile here: not tried again.
  scatterer_render::KeySet FailedShaders;
  scatterer_render::DecoratedVolumes Volumes;
  // A piece of a distributed volume: the light from the other pieces (or none).
  vtkSmartPointer<vtkScattererLightExchange> LightExchange;

  std::string LastFeatures = "stock: not rendered yet";
  int ActiveMaterials = 0;
  double LastTransportMs = 0.0;
  // This frame rebuilt something and reported progress: GPURender reports 1 at its end.
  bool ProgressReported = false;
  // The components of each input's scalars at the last frame (ReleaseOnNewComponents).
  std::vector<int> InputComponents;
};

vtkScattererTemplateVolumeMapper::vtkScattererTemplateVolumeMapper()
  : Internals(new vtkInternals(this))
{
}

vtkScattererTemplateVolumeMapper::~vtkScattererTemplateVolumeMapper() = default;

namespace
{
/// Says what is wrong with a material's arguments, naming the method the user called;
/// empty when they are usable. The index range is the physics' own rule
/// (scatterer::Material::validate), checked here so that a bad material is refused when
/// added, not at render time.
std::string MaterialArgumentsProblem(
  const char* method, double lo, double hi, double refractiveIndex, double r, double g, double b)
{
  std::ostringstream problem;
  const double values[] = { lo, hi, refractiveIndex, r, g, b };
  for (double v : values)
  {
    if (!std::isfinite(v))
    {
      problem << method << ": every argument must be finite; material ignored.";
      return problem.str();
    }
  }
  if (hi < lo || refractiveIndex < scatterer::kMinRefractiveIndex ||
    refractiveIndex > scatterer::kMaxRefractiveIndex)
  {
    problem << method << ": needs lo <= hi and a refractive index in ["
            << scatterer::kMinRefractiveIndex << ", " << scatterer::kMaxRefractiveIndex
            << "] (got [" << lo << ", " << hi << "], n = " << refractiveIndex
            << "); material ignored.";
  }
  return problem.str();
}

scatterer_scene::RequestedMaterial MakeMaterial(
  double lo, double hi, double refractiveIndex, double r, double g, double b)
{
  scatterer_scene::RequestedMaterial m;
  m.Lo = lo;
  m.Hi = hi;
  m.RefractiveIndex = refractiveIndex;
  m.Color[0] = std::min(std::max(r, 0.0), 1.0);
  m.Color[1] = std::min(std::max(g, 0.0), 1.0);
  m.Color[2] = std::min(std::max(b, 0.0), 1.0);
  return m;
}
}

void vtkScattererTemplateVolumeMapper::AddScalarRangeMaterial(
  double lo, double hi, double refractiveIndex, double r, double g, double b)
{
  const std::string problem =
    MaterialArgumentsProblem("AddScalarRangeMaterial", lo, hi, refractiveIndex, r, g, b);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return;
  }
  this->Internals->Requested.push_back(MakeMaterial(lo, hi, refractiveIndex, r, g, b));
  this->IlluminationTime.Modified();
}

void vtkScattererTemplateVolumeMapper::AddLabelMaterial(
  int label, double refractiveIndex, double r, double g, double b)
{
  // A label's material is the half-open range around its integer value.
  const double lo = label - 0.5;
  const double hi = label + 0.5;
  const std::string problem =
    MaterialArgumentsProblem("AddLabelMaterial", lo, hi, refractiveIndex, r, g, b);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return;
  }
  scatterer_scene::RequestedMaterial m = MakeMaterial(lo, hi, refractiveIndex, r, g, b);
  m.IsLabel = true;
  m.Label = label;
  this->Internals->Requested.push_back(m);
  this->IlluminationTime.Modified();
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
    vtkWarningMacro(
      "AddMaterialsFromLabelTransferFunctions: the volume property has no label "
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
    this->AddLabelMaterial(
      label, scatterer::defaultRefractiveIndex(index++), color[0], color[1], color[2]);
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
  return this->Internals->Templates.GetPacked().byteCount();
}

double vtkScattererTemplateVolumeMapper::GetLastTransportBuildMilliseconds() const
{
  return this->Internals->LastTransportMs;
}

vtkScattererTransportVolume* vtkScattererTemplateVolumeMapper::GetTransportVolume() const
{
  return this->Internals->Transport.GetVolume();
}

void vtkScattererTemplateVolumeMapper::SetLightExchange(vtkScattererLightExchange* exchange)
{
  if (this->Internals->LightExchange != exchange)
  {
    this->Internals->LightExchange = exchange;
    this->IlluminationTime.Modified();
    this->Modified();
  }
}

vtkScattererLightExchange* vtkScattererTemplateVolumeMapper::GetLightExchange() const
{
  return this->Internals->LightExchange;
}

bool vtkScattererTemplateVolumeMapper::GetLightExchangeUsed() const
{
  return this->Internals->Transport.UsesLightExchange();
}

void vtkScattererTemplateVolumeMapper::SetMaterialDerivationRange(double lo, double hi)
{
  if (!std::isfinite(lo) || !std::isfinite(hi))
  {
    vtkErrorMacro(
      "SetMaterialDerivationRange(" << lo << ", " << hi << "): the range must be finite; ignored.");
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
  const double radius =
    scatterer::illumination::templateRadiusFor(this->TemplateRadius, (sx + sy + sz) / 3.0);
  // Per sample: photons lie within one radius; the thin-part check marches on toward
  // the light to LongRangeMultiple x the photon's offset. Transport: the kernel reaches
  // one radius, the ambient occlusion two diffusion voxels and the diffusion one such
  // voxel per iteration (a diffusion voxel spans diffusionVoxelsFor(the still frames'
  // scale) volume voxels, also on frames built coarser while the user drags); and a
  // transport voxel is interpolated by its neighbours.
  const bool thin = this->ShadowsEnabled && this->ThinPartCheckEnabled;
  const bool transport = this->IlluminationMode == TRANSPORT;
  const int scale = this->WholeDimensions[0] > 0
    ? std::max(this->GetEffectiveTransportScale(this->WholeDimensions, spacing, false),
        this->GetEffectiveTransportScale(this->WholeDimensions, spacing, true))
    : std::max(this->TransportScale, this->InteractiveTransportScale);
  // The grid's terms count voxels, the same number along every axis or fewer along an axis
  // of long voxels (scatterer::illumination::transportStridesFor): measured along the
  // finest axis, the reach over the finest spacing is the ghost layers a piece needs. By
  // the largest spacing (until 2026-12-07) a CT's 1.5 mm slices over 0.96 mm pixels asked
  // for 58 layers instead of 37, and 0.5 x 0.5 x 5 mm voxels for 361: every rank held the
  // whole volume.
  const double voxel = std::min({ sx > 0.0 ? sx : VTK_DOUBLE_MAX, sy > 0.0 ? sy : VTK_DOUBLE_MAX,
    sz > 0.0 ? sz : VTK_DOUBLE_MAX });
  if (!(voxel < VTK_DOUBLE_MAX))
  {
    return 0.0; // no spacing to measure by (0, NaN): no reach
  }
  const int stillScale = this->WholeDimensions[0] > 0
    ? this->GetEffectiveTransportScale(this->WholeDimensions, spacing, false)
    : this->TransportScale;
  const double diffusionVoxel = scatterer::illumination::diffusionVoxelsFor(stillScale) * voxel;
  const int iterations = vtkScattererTransportVolume::Inputs().DiffusionIterations;
  const double transportReach = std::max({ radius, 2.0 * diffusionVoxel,
    this->MultipleScattering > 0.0 ? iterations * diffusionVoxel : 0.0 });
  const double photonReach =
    transport ? transportReach : (thin ? radius * this->LongRangeMultiple : radius);
  const double gridMargin = transport ? scale * voxel : 0.0;
  const double reach = photonReach + gridMargin;
  return std::isfinite(reach) ? reach : 0.0;
}

void vtkScattererTemplateVolumeMapper::SetWholeDimensions(int nx, int ny, int nz)
{
  const bool unset = nx == 0 && ny == 0 && nz == 0;
  if (!unset && (nx < 1 || ny < 1 || nz < 1))
  {
    vtkErrorMacro("SetWholeDimensions: needs three point counts of at least 1, or 0 0 0 for "
                  "\"the input is the whole volume\" (got "
      << nx << " " << ny << " " << nz << "); ignored.");
    return;
  }
  const int dims[3] = { nx, ny, nz };
  if (std::equal(dims, dims + 3, this->WholeDimensions))
  {
    return;
  }
  // No Modified(), as the settings (the class comment): the transport volume follows its key.
  std::copy(dims, dims + 3, this->WholeDimensions);
  this->IlluminationTime.Modified();
}

int vtkScattererTemplateVolumeMapper::GetEffectiveTransportScale(
  const int dims[3], const double spacing[3], bool interactive) const
{
  return this->GatherParameters().TransportScaleFor(dims, spacing, interactive);
}

void vtkScattererTemplateVolumeMapper::SetExtraShaderCodeForTesting(const std::string& glsl)
{
  this->Internals->ExtraGLSL = glsl;
}

void vtkScattererTemplateVolumeMapper::SetMaximumLightReadStrideForTesting(int stride)
{
  this->Internals->MaximumLightStride = std::max(1, stride);
}

void vtkScattererTemplateVolumeMapper::SetSurfaceDetailForTesting(bool surfaceDetail)
{
  this->Internals->SurfaceDetail = surfaceDetail;
}

void vtkScattererTemplateVolumeMapper::SetGatherAtCentroidForTesting(bool atCentroid)
{
  this->Internals->Transport.SetGatherAtCentroid(atCentroid);
  this->Modified();
}

void vtkScattererTemplateVolumeMapper::SetDiffuseOnTilesForTesting(bool onTiles)
{
  this->Internals->Transport.SetDiffuseOnTiles(onTiles);
  this->Modified();
}

void vtkScattererTemplateVolumeMapper::SetCoarseDimLightsForTesting(bool coarse)
{
  this->Internals->Transport.SetCoarseDimLights(coarse);
  this->Modified();
}

void vtkScattererTemplateVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->Transport.ReleaseGraphicsResources(window);
  this->Internals->Templates.ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
  // The released inputs keep blocks that point at their deleted textures, and
  // PreLoadData (UpdateTransport) would not reload them: the superclass decides that
  // inside its own GPURender. Dropped here, they are created and loaded afresh by the
  // next PreLoadData or GPURender, as on a first frame.
  this->AssembledInputs.clear();
}

scatterer_render::IlluminationParameters vtkScattererTemplateVolumeMapper::GatherParameters() const
{
  scatterer_render::IlluminationParameters p;
  p.Enabled = this->IlluminationEnabled;
  p.Shadows = this->ShadowsEnabled;
  p.ColorBleeding = this->ColorBleedingEnabled;
  p.ThinPartCheck = this->ThinPartCheckEnabled;
  p.BoundaryRefraction = this->BoundaryRefractionEnabled;
  p.TemplateBlending = this->TemplateBlendingEnabled;
  p.CroppedMatterCastsShadows = this->CroppedMatterCastsShadows;
  p.ShaderPathSelection = this->ShaderPathSelection;
  p.IlluminationMode = this->IlluminationMode;
  p.TransportScale = this->TransportScale;
  p.InteractiveTransportScale = this->InteractiveTransportScale;
  p.MaximumTransportVoxels = this->MaximumTransportVoxels;
  std::copy(this->WholeDimensions, this->WholeDimensions + 3, p.WholeDimensions);
  p.MultipleScattering = this->MultipleScattering;
  p.TemplateRadius = this->TemplateRadius;
  p.TemplatesPerMaterial = this->TemplatesPerMaterial;
  p.PhotonCap = this->PhotonCap;
  p.OcclusionStrength = this->OcclusionStrength;
  p.LongRangeMultiple = this->LongRangeMultiple;
  p.IlluminationInterval = this->IlluminationInterval;
  p.PhotonThreshold = this->PhotonThreshold;
  p.GeneratorThreshold = this->GeneratorThreshold;
  p.MaterialDerivationRange[0] = this->MaterialDerivationRange[0];
  p.MaterialDerivationRange[1] = this->MaterialDerivationRange[1];
  return p;
}

/*
 * GPURender: plan the frame, load the volume, refresh the templates and (transport mode)
 * the light transport volume, then render with the illumination GLSL; any stage that
 * cannot do its part says why and the volume renders as the stock mapper would.
 */
void vtkScattererTemplateVolumeMapper::GPURender(vtkRenderer* ren, vtkVolume* vol)
{
  this->ReleaseOnNewComponents(ren);
  vtkInternals& in = *this->Internals;
  const scatterer_render::IlluminationParameters parameters = this->GatherParameters();
  scatterer_render::FramePlan plan;
  std::string stock = this->PlanFrame(ren, vol, parameters, plan);
  if (stock.empty())
  {
    stock = this->LoadVolume(ren, vol, plan);
  }
  if (stock.empty())
  {
    stock = in.Templates.Update(
      plan.Materials.Materials, parameters,
      [this](double done) { this->ReportProgress(done * kTemplatesDone); }, in.Warn);
  }
  if (stock.empty() && plan.Features.Transport)
  {
    stock = this->UpdateTransport(ren, vol, parameters, plan);
  }
  if (stock.empty())
  {
    stock = this->RenderIlluminated(ren, vol, parameters, plan);
  }
  if (!stock.empty())
  {
    this->RenderStock(ren, vol, stock);
  }
  if (in.ProgressReported)
  {
    this->ReportProgress(1.0);
    in.ProgressReported = false;
  }
}

/*
 * VTK 9.1's ray caster makes its transfer-function tables, one per component, when its
 * volume property changes (vtkVolumeInputHelper::InitializeTransferFunction), not when
 * the scalars' components do: scalars that gained components under the same property
 * (a 1-component volume replaced by a 2-component one with SetInputData) crashed the
 * next frame in vtkVolumeInputHelper::UpdateTransferFunctions, which read a table never
 * made, the stock mapper as well. Released, the next frame starts as a first frame does.
 */
void vtkScattererTemplateVolumeMapper::ReleaseOnNewComponents(vtkRenderer* ren)
{
  std::vector<int> components;
  for (const int port : this->Ports)
  {
    int cellFlag = 0;
    vtkDataArray* scalars = vtkAbstractMapper::GetScalars(this->GetInput(port), this->ScalarMode,
      this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
    components.push_back(scalars ? scalars->GetNumberOfComponents() : 0);
  }
  std::vector<int>& last = this->Internals->InputComponents;
  if (!last.empty() && components != last && ren && ren->GetRenderWindow())
  {
    this->ReleaseGraphicsResources(ren->GetRenderWindow());
  }
  last = components;
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
  this->RenderRayCaster(ren, vol);
}

void vtkScattererTemplateVolumeMapper::RenderRayCaster(vtkRenderer* ren, vtkVolume* vol)
{
  const bool mirrors = scatterer_render::DirectionMirrors(vol, this->GetInput());
  const float requested = this->ImageSampleDistance;
  this->ImageSampleDistance = scatterer_render::ImageSampleDistanceFor(mirrors, requested);
  if (this->ImageSampleDistance != requested)
  {
    std::ostringstream what;
    what << "ImageSampleDistance " << requested
         << " is not applied to a volume whose direction matrix mirrors (determinant < 0): "
            "it renders at the full image resolution (docs/hard-cases.md).";
    this->Internals->Warn(what.str());
  }
  if (mirrors && scatterer_render::NearPlaneCutsVolume(ren, vol, this->GetInput()))
  {
    this->Internals->Warn(
      "A volume whose direction matrix mirrors (determinant < 0) is not drawn while the "
      "camera's near plane cuts through it: VTK 9.1's ray caster then clips its bounding box "
      "on the wrong side (the stock mapper draws nothing either). Store the voxels in the "
      "opposite order along one axis, with a direction matrix that does not mirror, to see it "
      "from inside (docs/hard-cases.md).");
  }
  {
    scatterer_render::ScopedMirroredWinding winding(mirrors);
    this->Superclass::GPURender(ren, vol);
  }
  this->ImageSampleDistance = requested;
}

void vtkScattererTemplateVolumeMapper::StillSampling(
  vtkVolume* vol, double& rayStep, double voxelEdges[3])
{
  rayStep = 0.0;
  std::fill(voxelEdges, voxelEdges + 3, 0.0);
  auto* image = vtkImageData::SafeDownCast(this->GetInput());
  if (!image || !vol)
  {
    return;
  }
  double spacing[3];
  int extent[6];
  image->GetSpacing(spacing);
  image->GetExtent(extent);
  // The voxel's edges in the world: the spacing scaled by the volume's matrix (an image's
  // direction matrix only turns them), as VTK 9.1 measures them for its step.
  vtkMatrix4x4* matrix = vol->GetMatrix();
  double smallest = VTK_DOUBLE_MAX;
  for (int a = 0; a < 3; ++a)
  {
    double squared = 0.0;
    for (int r = 0; r < 3; ++r)
    {
      squared += matrix->GetElement(r, a) * matrix->GetElement(r, a);
    }
    voxelEdges[a] = std::fabs(spacing[a]) * std::sqrt(squared);
    smallest = std::min(smallest, voxelEdges[a]);
  }
  // vtkOpenGLGPUVolumeRayCastMapper::vtkInternal::UpdateSamplingDistance (9.1), without
  // the reduction of frames rendered while the user drags.
  if (this->GetAutoAdjustSampleDistances())
  {
    rayStep = smallest;
  }
  else if (this->GetLockSampleDistanceToInputSpacing())
  {
    rayStep = this->SpacingAdjustedSampleDistance(spacing, extent);
  }
  else
  {
    rayStep = this->GetSampleDistance();
  }
}

std::string vtkScattererTemplateVolumeMapper::PlanFrame(vtkRenderer* ren, vtkVolume* vol,
  const scatterer_render::IlluminationParameters& parameters, scatterer_render::FramePlan& plan)
{
  vtkInternals& in = *this->Internals;
  scatterer_render::VolumeSource source;
  source.Input = this->GetInput();
  source.Mask = this->GetMaskInput();
  source.LabelMapMask = this->GetMaskType() == LabelMapMaskType;
  source.BlendMode = this->GetBlendMode();
  source.UseDepthPass = this->GetUseDepthPass() != 0;
  source.Clipped = this->GetClippingPlanes() && this->GetClippingPlanes()->GetNumberOfItems() > 0;
  source.Cropped = this->GetCropping() != 0;
  source.SampleDistance = this->GetSampleDistance();
  this->StillSampling(vol, source.StillRayStep, source.VoxelEdges);
  source.RayStepMayGrow =
    this->GetAutoAdjustSampleDistances() && ren->GetAllocatedRenderTime() < 1.0;
  source.ScalarMode = this->ScalarMode;
  source.ArrayAccessMode = this->ArrayAccessMode;
  source.ArrayId = this->ArrayId;
  source.ArrayName = this->ArrayName;
  // A vtkMultiVolume: each input in the ray caster's order (its ports, ascending).
  if (auto* multi = vtkMultiVolume::SafeDownCast(vol))
  {
    std::vector<int> ports(this->Ports);
    std::sort(ports.begin(), ports.end());
    for (int port : ports)
    {
      source.Parts.push_back(
        { vtkDataSet::SafeDownCast(this->GetInputDataObject(port, 0)), multi->GetVolume(port) });
    }
  }
  scatterer_render::PlanRequests requests;
  requests.Materials = &in.Requested;
  requests.ExtraGLSL = in.ExtraGLSL;
  requests.MaximumLightStride = in.MaximumLightStride;
  requests.SurfaceDetail = in.SurfaceDetail;
  requests.FailedShaders = &in.FailedShaders;
  const std::string stock = in.Planner.Plan(ren, vol, source, parameters, requests, in.Warn, plan);
  if (plan.MaterialsBuilt)
  {
    in.ActiveMaterials = static_cast<int>(plan.Materials.Materials.size());
  }
  return stock;
}

/*
 * The ray caster's own textures, loaded (on a first frame) before this frame makes any of
 * its own: the transport volume reads the scalar texture, and PreLoadData registers the
 * frame's window. A mapper shown in another window than last frame has VTK release the
 * last window's resources then; left to the ray caster's own GPURender, that came after
 * this frame's template texture was made for the new window, released it, and the
 * per-sample frame was drawn unlit (MapperBehaviour.OneVolumeShownInTwoWindowsIsLitInEach).
 */
std::string vtkScattererTemplateVolumeMapper::LoadVolume(
  vtkRenderer* ren, vtkVolume* vol, const scatterer_render::FramePlan& plan)
{
  if (!this->PreLoadData(ren, vol) || this->AssembledInputs.empty())
  {
    return "the volume could not be loaded into a texture";
  }
  // VTK 9.1: a partitioned texture loaded (PreLoadData) but not yet drawn throws when it
  // is loaded again (ClearBlocks reads the sorted block list only drawing fills), as the
  // ray caster does next on a first frame. Sorting the blocks now, as drawing does first,
  // makes that reload safe.
  vtkVolumeTexture* texture = this->AssembledInputs.begin()->second.Texture;
  const auto& parts = texture->GetPartitions();
  if (parts[0] * parts[1] * parts[2] > 1 && plan.Parts.empty())
  {
    texture->SortBlocksBackToFront(ren, vol->GetMatrix());
  }
  return "";
}

std::string vtkScattererTemplateVolumeMapper::UpdateTransport(vtkRenderer* ren, vtkVolume* vol,
  const scatterer_render::IlluminationParameters& parameters,
  const scatterer_render::FramePlan& plan)
{
  vtkInternals& in = *this->Internals;
  scatterer_render::TransportSource source;
  source.VolumeTexture = this->AssembledInputs.begin()->second.Texture;
  if (!plan.Parts.empty())
  {
    for (auto& input : this->AssembledInputs)
    {
      source.PartTextures.push_back(input.second.Texture);
    }
  }
  source.Mask = this->GetMaskInput();
  source.MaskBlend = this->GetMaskBlendFactor();
  source.ClippingPlanes = this->GetClippingPlanes();
  source.Cropping = this->GetCropping() != 0;
  source.CropFlags = this->GetCroppingRegionFlags();
  source.CroppingRegionPlanes = this->CroppingRegionPlanes;
  source.Exchange = in.LightExchange ? &in.LightExchange->GetResult() : nullptr;
  // Progress only when someone listens (ParaView's progress bar via the
  // representation): reporting makes the build wait for each GPU stage.
  if (this->HasObserver(vtkCommand::ProgressEvent))
  {
    source.Progress = [this](double done)
    { this->ReportProgress(kTemplatesDone + (kTransportDone - kTemplatesDone) * done); };
  }
  std::string error;
  const std::string stock =
    in.Transport.Update(ren, vol, plan, parameters, in.Templates, source, in.Warn, error);
  if (!error.empty())
  {
    in.Warn.Error(error); // a build that fails fails at every frame: said once
  }
  if (stock.empty())
  {
    in.LastTransportMs = in.Transport.GetVolume()->GetLastBuildMilliseconds();
  }
  return stock;
}

std::string vtkScattererTemplateVolumeMapper::RenderIlluminated(vtkRenderer* ren, vtkVolume* vol,
  const scatterer_render::IlluminationParameters& parameters,
  const scatterer_render::FramePlan& plan)
{
  vtkInternals& in = *this->Internals;
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  scatterer_render::FrameTextures textures;
  if (plan.Features.Transport)
  {
    textures.TransportLight = in.Transport.GetVolume()->GetLightTexture();
    in.Transport.DatasetToLightTexture(textures.DatasetToTransport);
  }
  else
  {
    in.LastTransportMs = 0.0;
    textures.Templates = in.Templates.GetTexture(renWin);
  }
  textures.PackedWidth = in.Templates.GetPacked().width;
  in.Uniforms.Install(vol, plan, parameters, textures);
  in.Volumes.Watch(vol);

  // Render, checking that the illumination program compiled.
  in.CompileCheck.Begin(renWin, this);
  in.Uniforms.BindTextures(vol);
  this->RenderRayCaster(ren, vol);
  in.Uniforms.UnbindTextures();
  const bool compiled = in.CompileCheck.End();
  // The program that drew is the last one bound, unless VTK drew its resampling quad
  // after it (ImageSampleDistance > 1): that frame's program is then not counted,
  // and is counted on the next full-resolution frame that uses it.
  scatterer_shader::NoteProgramUse(renWin, renWin->GetShaderCache()->GetLastShaderBound());
  if (!compiled)
  {
    // The errors held back are the ray caster's terse report of the failure (the
    // compiler's own message went to the output window): replaced by this one.
    in.FailedShaders.Insert(plan.ShaderKey());
    vtkErrorMacro("The scatterer-template illumination shader ("
      << plan.Features.Describe()
      << ") failed to compile on this OpenGL implementation (the compiler's message is above); "
         "this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return "the illumination shader failed to compile here";
  }
  for (const auto& e : in.CompileCheck.GetErrors())
  {
    vtkErrorMacro(<< e);
  }
  in.LastFeatures = plan.Features.Describe();
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
  os << indent << "LightExchange: " << this->Internals->LightExchange.GetPointer() << "\n";
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
  os << indent
     << "IlluminationMode: " << (this->IlluminationMode == TRANSPORT ? "Transport" : "PerSample")
     << "\n";
  os << indent << "TransportScale: " << this->TransportScale << "\n";
  os << indent << "InteractiveTransportScale: " << this->InteractiveTransportScale << "\n";
  os << indent << "MaximumTransportVoxels: " << this->MaximumTransportVoxels
     << (this->MaximumTransportVoxels > 0 ? "" : " (no limit)") << "\n";
  os << indent << "WholeDimensions: " << this->WholeDimensions[0] << " " << this->WholeDimensions[1]
     << " " << this->WholeDimensions[2]
     << (this->WholeDimensions[0] > 0 ? "" : " (the input is the whole volume)") << "\n";
  os << indent << "MultipleScattering: " << this->MultipleScattering << "\n";
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
