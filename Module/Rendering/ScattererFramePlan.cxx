#include "ScattererFramePlan.h"

#include "ScattererColourFunction.h"
#include "ScattererIlluminationParameters.h"
#include "ScattererTransfer2D.h"
#include "ScattererWarnOnce.h"
#include "vtkScattererTransportVolume.h"

#include "vtkAbstractMapper.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiVolume.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRectilinearGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace scatterer_render
{
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

// Why illumination cannot apply to this volume, or "" if it can.
std::string Unsupported(
  const VolumeSource& source, const IlluminationParameters& parameters, vtkVolume* vol)
{
  if (source.BlendMode != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    return std::string("the ") + BlendModeName(source.BlendMode) +
      " blend mode (illumination needs composite blending)";
  }
  if (vtkMultiVolume::SafeDownCast(vol) && !parameters.Transport())
  {
    return "a vtkMultiVolume in per-sample mode (the transport mode lights it)";
  }
  if (vtkRectilinearGrid::SafeDownCast(source.Input))
  {
    return "a rectilinear-grid input";
  }
  // The per-sample photon test reads the voxels as they are: it would still see
  // masked-out, clipped or cropped matter as occluders (a roof cropped away halved the
  // light under it).
  if (source.Mask && !parameters.Transport())
  {
    return "a mask input in per-sample mode (the transport mode honours binary masks)";
  }
  if (source.Clipped && !parameters.Transport())
  {
    return "clipping planes in per-sample mode (the transport mode honours them)";
  }
  if (source.Cropped && !parameters.CroppedMatterCastsShadows && !parameters.Transport())
  {
    return "cropping in per-sample mode (the transport mode honours it; so does "
           "CroppedMatterCastsShadows on, where cropped matter is meant to cast shadows)";
  }
  if (source.UseDepthPass)
  {
    return "the depth pass (UseDepthPass)";
  }
  return "";
}

// What becomes of the materials beyond the limit: the transport volume still lights
// their matter (shadows, multiple scattering), without template in-scattering; the
// per-sample photon test leaves it unlit.
std::string DroppedMaterials(
  int dropped, const char* where, const IlluminationParameters& parameters)
{
  return "Scatterer-template illumination handles " +
    std::to_string(scatterer_scene::kMaxMaterials) + " materials" + where + "; " +
    std::to_string(dropped) +
    (parameters.Transport()
        ? " more are lit by the transport volume without scatterer templates of their own."
        : " more stay unlit.");
}

// Does VTK's ray caster multiply a step's opacity by a gradient opacity that is not 1
// somewhere (a 1D transfer function with a gradient opacity function set and not
// disabled)? VTK looks the function up as it stands (vtkPiecewiseFunction::GetTable): with
// nodes it is their linear interpolation, held at the ends when clamping (the default),
// 0 beyond them when not; so not 1 somewhere exactly when some node is not 1 or clamping
// is off. Above 1 it thickens the matter. One with no nodes VTK fills with a ramp from 0
// when it first draws it; until then it counts as hiding everything (the next frame takes
// the ramp).
bool ChangesOpacityByGradient(vtkVolumeProperty* property)
{
  if (property->GetTransferFunctionMode() != vtkVolumeProperty::TF_1D ||
    !property->HasGradientOpacity(0) || property->GetDisableGradientOpacity(0))
  {
    return false;
  }
  vtkPiecewiseFunction* function = property->GetGradientOpacity(0);
  if (function->GetSize() == 0 || !function->GetClamping())
  {
    return true;
  }
  for (int i = 0; i < function->GetSize(); ++i)
  {
    double node[4];
    function->GetNodeValue(i, node);
    if (!(node[1] == 1.0))
    {
      return true;
    }
  }
  return false;
}

// A vtkMultiVolume: each input as the ray caster composites it (one scalar through its
// volume's 1D transfer functions), or why it cannot be lit.
std::string PlanParts(const VolumeSource& source, FramePlan& plan)
{
  if (source.Parts.size() > static_cast<size_t>(vtkScattererTransportVolume::Inputs::kMaxParts))
  {
    return "a vtkMultiVolume of more than " +
      std::to_string(vtkScattererTransportVolume::Inputs::kMaxParts) + " inputs";
  }
  for (const auto& in : source.Parts)
  {
    FramePlan::Part part;
    part.Volume = in.Volume;
    part.Image = vtkImageData::SafeDownCast(in.Input);
    part.Scalars = part.Image
      ? vtkAbstractMapper::GetScalars(part.Image, source.ScalarMode, source.ArrayAccessMode,
          source.ArrayId, source.ArrayName, part.CellFlag)
      : nullptr;
    if (!part.Volume || !part.Volume->GetProperty() || !part.Scalars)
    {
      return "a vtkMultiVolume input without image scalars or a volume";
    }
    if (part.Scalars->GetNumberOfComponents() != 1)
    {
      return "multi-component scalars in a vtkMultiVolume";
    }
    if (part.Volume->GetProperty()->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D)
    {
      return "2D transfer functions in a vtkMultiVolume";
    }
    if (ChangesOpacityByGradient(part.Volume->GetProperty()))
    {
      return "gradient opacity in a vtkMultiVolume";
    }
    plan.Parts.push_back(part);
  }
  plan.Image = plan.Parts.front().Image;
  plan.Scalars = plan.Parts.front().Scalars;
  plan.CellFlag = plan.Parts.front().CellFlag;
  plan.Features.Components = scatterer_shader::Features::Scalars::One;
  return "";
}

// How the components make colour and opacity (VTK's rules), and which one selects the
// materials; or why this input cannot be lit.
std::string PlanComponents(vtkVolumeProperty* property, const VolumeSource& source,
  const IlluminationParameters& parameters, FramePlan& plan)
{
  using Scalars = scatterer_shader::Features::Scalars;
  const int n = plan.Scalars->GetNumberOfComponents();
  plan.Features.Components = Scalars::One;
  plan.MaterialComponent = 0;
  // The ray caster's step: with AutoAdjustSampleDistances (VTK's default) the smallest
  // voxel edge, not SampleDistance. A 2D transfer function's opacity is one step's.
  plan.SampleDistance = source.StillRayStep > 0.0 ? source.StillRayStep : source.SampleDistance;
  plan.Transfer2D = property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D;
  if (plan.Transfer2D)
  {
    if (n != 1)
    {
      return "2D transfer functions on multi-component scalars";
    }
    if (!parameters.Transport())
    {
      return "2D transfer functions in per-sample mode (the transport mode lights them)";
    }
    if (source.Mask && source.LabelMapMask)
    {
      return "a label-map mask with a 2D transfer function";
    }
    if (!(plan.SampleDistance > 0.0) || !std::isfinite(plan.SampleDistance))
    {
      return "a 2D transfer function with a sample distance that is not positive";
    }
    const std::string problem = Transfer2DProblem(property->GetTransferFunction2D());
    return problem.empty() ? "" : "this 2D transfer function (" + problem + ")";
  }
  plan.GradientOpacity = ChangesOpacityByGradient(property);
  if (plan.GradientOpacity)
  {
    if (!parameters.Transport())
    {
      return "gradient opacity in per-sample mode (the photon test would see the matter it "
             "hides as occluders; the transport mode lights it)";
    }
    if (n != 1)
    {
      return "gradient opacity on multi-component scalars";
    }
    if (source.Mask && source.LabelMapMask)
    {
      return "a label-map mask with gradient opacity";
    }
    if (!(plan.SampleDistance > 0.0) || !std::isfinite(plan.SampleDistance))
    {
      return "gradient opacity with a sample distance that is not positive";
    }
  }
  if (n == 1)
  {
    return "";
  }
  const std::string count = std::to_string(n) + " ";
  if (n > 4)
  {
    return count + "components (VTK's ray caster takes at most 4)";
  }
  if (!parameters.Transport())
  {
    return "multi-component scalars in per-sample mode (the transport mode lights them)";
  }
  if (source.Mask && source.LabelMapMask)
  {
    return "a label-map mask on multi-component scalars";
  }
  if (property->GetIndependentComponents())
  {
    // Materials are scalar ranges of one component: the first one the picture shows.
    plan.Features.Components = Scalars::Independent;
    for (int c = n - 1; c >= 0; --c)
    {
      double range[2];
      plan.Scalars->GetFiniteRange(range, c);
      if (property->GetComponentWeight(c) > 0.0 &&
        scatterer_scene::MaxOpacity(property->GetScalarOpacity(c), range[0], range[1]) > 0.0)
      {
        plan.MaterialComponent = c;
      }
    }
    return "";
  }
  if (n == 3)
  {
    return "3 dependent components (VTK's ray caster takes opacity from a 2nd or 4th)";
  }
  // Luminance + alpha, RGBA: the opacity function reads the last component; it is the
  // one that decides what is matter, so it selects the materials.
  plan.Features.Components = Scalars::Dependent;
  plan.MaterialComponent = n - 1;
  return "";
}
}

FramePlanner::FramePlanner() = default;
FramePlanner::~FramePlanner() = default;

std::string FramePlanner::Plan(vtkRenderer* ren, vtkVolume* vol, const VolumeSource& source,
  const IlluminationParameters& parameters, const PlanRequests& requests, WarnOnce& warn,
  FramePlan& plan)
{
  if (!parameters.Enabled)
  {
    return "illumination off";
  }
  const std::string unsupported = Unsupported(source, parameters, vol);
  if (!unsupported.empty())
  {
    warn("Scatterer-template illumination does not apply to " + unsupported +
      "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return unsupported;
  }
  std::string components;
  if (!source.Parts.empty())
  {
    components = PlanParts(source, plan);
  }
  else
  {
    plan.Image = vtkImageData::SafeDownCast(source.Input);
    plan.Scalars = plan.Image
      ? vtkAbstractMapper::GetScalars(plan.Image, source.ScalarMode, source.ArrayAccessMode,
          source.ArrayId, source.ArrayName, plan.CellFlag)
      : nullptr;
    if (!plan.Scalars)
    {
      return "no scalars";
    }
    components = PlanComponents(vol->GetProperty(), source, parameters, plan);
  }
  if (!components.empty())
  {
    warn("Scatterer-template illumination does not apply to " + components +
      "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return components;
  }
  plan.Lights = scatterer_scene::CollectLights(ren, vol->GetProperty());
  if (plan.Lights.NonFinite > 0)
  {
    warn("Scatterer-template illumination ignores " + std::to_string(plan.Lights.NonFinite) +
      " switched-on light(s) with a NaN or infinite intensity, colour, position, focal point, "
      "attenuation, cone angle or exponent (or volume property diffuse or ambient "
      "coefficient).");
  }
  if (plan.Lights.Undefined > 0)
  {
    warn("Scatterer-template illumination ignores " + std::to_string(plan.Lights.Undefined) +
      " switched-on light(s) whose direction is undefined (a directional light or spot whose "
      "position is its focal point) or whose attenuation is not positive at every distance "
      "(a positional light with a negative or all-zero attenuation value).");
  }
  if (plan.Lights.Count() == 0)
  {
    return "no light is switched on with an intensity above 0";
  }
  if (plan.Lights.Skipped > 0)
  {
    warn("Scatterer-template illumination uses the first 6 lights (VTK's limit); " +
      std::to_string(plan.Lights.Skipped) + " more are ignored.");
  }
  std::string stock = this->PlanGeometry(vol, parameters, warn, plan);
  if (stock.empty())
  {
    stock = this->PlanMaterials(vol, source, parameters, requests, warn, plan);
  }
  if (stock.empty())
  {
    stock = this->PlanFeatures(vol, source, parameters, requests, plan);
  }
  return stock;
}

// Template radius and the world -> texture mapping of photon offsets.
std::string FramePlanner::PlanGeometry(
  vtkVolume* vol, const IlluminationParameters& parameters, WarnOnce& warn, FramePlan& plan)
{
  vtkImageData* image = plan.Image;
  double spacing[3];
  int dims[3];
  image->GetSpacing(spacing);
  image->GetDimensions(dims);
  // A vtkMultiVolume: the template radius follows its first input's voxels.
  vtkMatrix4x4* volumeMatrix =
    plan.Parts.empty() ? vol->GetMatrix() : plan.Parts.front().Volume->GetMatrix();
  double columnLength[3];
  for (int c = 0; c < 3; ++c)
  {
    columnLength[c] = std::sqrt(volumeMatrix->GetElement(0, c) * volumeMatrix->GetElement(0, c) +
      volumeMatrix->GetElement(1, c) * volumeMatrix->GetElement(1, c) +
      volumeMatrix->GetElement(2, c) * volumeMatrix->GetElement(2, c));
  }
  const double meanSpacing =
    (std::abs(spacing[0]) * columnLength[0] + std::abs(spacing[1]) * columnLength[1] +
      std::abs(spacing[2]) * columnLength[2]) /
    3.0;
  plan.Radius = scatterer::illumination::templateRadiusFor(parameters.TemplateRadius, meanSpacing);
  if (!(plan.Radius > 0.0) || !std::isfinite(plan.Radius))
  {
    warn("Scatterer-template illumination needs a positive, finite voxel spacing or "
         "TemplateRadius; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return "degenerate spacing";
  }
  // World -> dataset (the volume's matrix), dataset -> index axes (the image's direction
  // matrix: without it a rotated or mirrored image tested its photons along the wrong
  // texture axes), then texels -> [0, 1].
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(volumeMatrix, inverse);
  vtkNew<vtkMatrix3x3> toIndexAxes;
  vtkMatrix3x3::Invert(image->GetDirectionMatrix(), toIndexAxes);
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int row = 0; row < 3; ++row)
    {
      // index-axis offset of one template radius along world `axis`
      double data = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        data += toIndexAxes->GetElement(row, c) * inverse->GetElement(c, axis) * plan.Radius;
      }
      const int texels = std::max(1, plan.CellFlag ? dims[row] - 1 : dims[row]);
      const double tex = data / (spacing[row] * texels);
      plan.ToTex[axis][row] = std::isfinite(tex) ? static_cast<float>(tex) : 0.0f;
    }
  }
  return "";
}

std::string FramePlanner::PlanMaterials(vtkVolume* vol, const VolumeSource& source,
  const IlluminationParameters& parameters, const PlanRequests& requests, WarnOnce& warn,
  FramePlan& plan)
{
  if (!plan.Parts.empty())
  {
    return this->PlanPartMaterials(parameters, requests, warn, plan);
  }
  vtkVolumeProperty* property = vol->GetProperty();
  double range[2];
  plan.Scalars->GetFiniteRange(range, plan.MaterialComponent);
  // Materials are derived over the derivation range when one is set (a piece of a
  // split volume: the whole volume's range), so every piece derives the same ones.
  double derivation[2] = { range[0], range[1] };
  if (parameters.MaterialDerivationRange[0] <= parameters.MaterialDerivationRange[1])
  {
    derivation[0] = parameters.MaterialDerivationRange[0];
    derivation[1] = parameters.MaterialDerivationRange[1];
  }
  const auto& requested = *requests.Materials;
  vtkVolumeProperty* materialProperty =
    this->MaterialProperty(property, source.Mask && source.LabelMapMask, derivation, plan);
  plan.Materials = scatterer_scene::BuildMaterials(requested, materialProperty, range, derivation);
  plan.MaterialsBuilt = true;
  plan.SpeedRatios = scatterer_scene::SpeedRatios(plan.Materials);
  plan.OpacityRatios = scatterer_scene::OpacityRatios(plan.Materials);
  if (plan.Materials.Materials.empty())
  {
    if (requested.empty() &&
      parameters.MaterialDerivationRange[0] <= parameters.MaterialDerivationRange[1])
    {
      // The volume may well show: the range the user set is where nothing does.
      std::ostringstream why;
      why << "no material: the opacity transfer function is below 1e-4 over the material "
             "derivation range ["
          << derivation[0] << ", " << derivation[1] << "] (SetMaterialDerivationRange)";
      warn("Scatterer-template illumination found " + why.str() +
        "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
      return why.str();
    }
    return "no material: the opacity transfer function is below 1e-4 everywhere";
  }
  if (plan.Materials.Dropped > 0)
  {
    warn(DroppedMaterials(plan.Materials.Dropped, "", parameters));
  }
  if (!requested.empty())
  {
    this->WarnUnassigned(materialProperty, range, warn, plan);
  }
  return "";
}

std::string FramePlanner::PlanPartMaterials(const IlluminationParameters& parameters,
  const PlanRequests& requests, WarnOnce& warn, FramePlan& plan)
{
  plan.Materials = scatterer_scene::MaterialSet();
  int dropped = 0;
  for (auto& part : plan.Parts)
  {
    double range[2];
    part.Scalars->GetFiniteRange(range, 0);
    double derivation[2] = { range[0], range[1] };
    if (parameters.MaterialDerivationRange[0] <= parameters.MaterialDerivationRange[1])
    {
      derivation[0] = parameters.MaterialDerivationRange[0];
      derivation[1] = parameters.MaterialDerivationRange[1];
    }
    const scatterer_scene::MaterialSet own = scatterer_scene::BuildMaterials(
      *requests.Materials, part.Volume->GetProperty(), range, derivation);
    auto& all = plan.Materials.Materials;
    part.FirstMaterial = static_cast<int>(all.size());
    const int room = scatterer_scene::kMaxMaterials - part.FirstMaterial;
    part.MaterialCount = std::min(room, static_cast<int>(own.Materials.size()));
    all.insert(all.end(), own.Materials.begin(), own.Materials.begin() + part.MaterialCount);
    dropped += own.Dropped + static_cast<int>(own.Materials.size()) - part.MaterialCount;
  }
  plan.Materials.Dropped = dropped;
  plan.MaterialsBuilt = true;
  plan.SpeedRatios = scatterer_scene::SpeedRatios(plan.Materials);
  plan.OpacityRatios = scatterer_scene::OpacityRatios(plan.Materials);
  if (plan.Materials.Materials.empty())
  {
    return "no material: the opacity transfer functions are below 1e-4 everywhere";
  }
  if (dropped > 0)
  {
    warn(DroppedMaterials(dropped, " over all inputs", parameters));
  }
  return "";
}

// With a label-map mask, what is visible is what any label's opacity function (or the
// volume's own, label 0) makes visible: materials are derived from their maximum,
// tabulated again only when a function or the range changes (not every frame).
vtkVolumeProperty* FramePlanner::MaterialProperty(
  vtkVolumeProperty* property, bool labelMapMask, const double derivation[2], const FramePlan& plan)
{
  const int c = plan.MaterialComponent;
  if (plan.Transfer2D)
  {
    vtkImageData* table = property->GetTransferFunction2D();
    const double unit = property->GetScalarOpacityUnitDistance() > 0.0
      ? property->GetScalarOpacityUnitDistance()
      : 1.0;
    KeyWriter key;
    key << table << '|' << table->GetMTime() << '|' << derivation[0] << ',' << derivation[1] << '|'
        << plan.SampleDistance << '|' << unit;
    if (this->Transfer2DKey.Differs(key.Key()))
    {
      vtkNew<vtkPiecewiseFunction> opacity;
      vtkNew<vtkColorTransferFunction> color;
      Transfer2DVisibility(
        table, derivation[0], derivation[1], plan.SampleDistance, unit, opacity, color);
      this->ComponentView->SetScalarOpacity(opacity);
      this->ComponentView->SetColor(color);
      this->ComponentView->SetScalarOpacityUnitDistance(unit);
      this->Transfer2DKey.Record(key.Key());
    }
    return this->ComponentView;
  }
  if (plan.Features.Components == scatterer_shader::Features::Scalars::Independent && c != 0)
  {
    vtkVolumeProperty* view = this->ComponentView;
    this->Transfer2DKey.Clear();
    view->SetScalarOpacity(property->GetScalarOpacity(c));
    view->SetColor(scatterer_scene::RayCasterColour(property, c));
    view->SetScalarOpacityUnitDistance(property->GetScalarOpacityUnitDistance(c));
    return view;
  }
  if (!labelMapMask)
  {
    return property;
  }
  const std::set<int> labels = property->GetLabelMapLabels();
  KeyWriter key;
  key << property->GetScalarOpacity(0)->GetMTime() << '|'
      << scatterer_scene::RayCasterColour(property, 0)->GetMTime() << '|' << derivation[0] << ','
      << derivation[1];
  for (int label : labels)
  {
    vtkPiecewiseFunction* o = property->GetLabelScalarOpacity(label);
    key << '|' << label << ':' << (o ? o->GetMTime() : 0);
  }
  if (this->LabelUnionKey.Differs(key.Key()))
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
    this->LabelUnion->SetColor(scatterer_scene::RayCasterColour(property, 0));
    this->LabelUnion->SetScalarOpacity(visible);
    this->LabelUnionKey.Record(key.Key());
  }
  this->LabelUnion->SetScalarOpacityUnitDistance(property->GetScalarOpacityUnitDistance());
  return this->LabelUnion;
}

// Visible voxels that no requested material selects: scanned once per change of the
// data, the transfer function or the materials.
void FramePlanner::WarnUnassigned(
  vtkVolumeProperty* property, const double range[2], WarnOnce& warn, const FramePlan& plan)
{
  KeyWriter materials;
  for (const auto& m : plan.Materials.Materials)
  {
    materials << '|' << m.Physics.selector.lo << ',' << m.Physics.selector.hi << ','
              << m.Physics.selector.label;
  }
  KeyWriter key;
  key << plan.Scalars << '|' << plan.Scalars->GetMTime() << '|' << plan.MaterialComponent << '|'
      << property->GetScalarOpacity(0)->GetMTime() << '|' << range[0] << ',' << range[1]
      << materials.Key();
  if (!this->UnassignedKey.Differs(key.Key()))
  {
    return;
  }
  this->UnassignedKey.Record(key.Key());
  const auto unassigned = scatterer_scene::CountUnassigned(
    plan.Scalars, plan.Materials, property, range, plan.MaterialComponent);
  if (unassigned.Count > 0)
  {
    std::ostringstream what;
    what << unassigned.Count << " visible voxels (e.g. scalar value " << unassigned.Example
         << ") belong to none of the requested materials: they are drawn and cast shadows, "
            "but receive light without in-scattering (add a material for them to fix this).";
    // Said once for these materials: the count changes with the data (a time series).
    warn(what.str(), "unassigned" + materials.Key());
  }
}

// Which code paths this scene needs, and their GLSL.
std::string FramePlanner::PlanFeatures(vtkVolume* vol, const VolumeSource& source,
  const IlluminationParameters& parameters, const PlanRequests& requests, FramePlan& plan)
{
  const bool automatic = parameters.Automatic();
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
  f.Transport = parameters.Transport();
  f.Shadow = parameters.Shadows;
  // The thin-part check and template blending belong to the per-sample photon test.
  f.Thin = !f.Transport && f.Shadow && parameters.ThinPartCheck &&
    (!automatic || parameters.LongRangeMultiple > 1.0);
  // Dependent components carry their colour per voxel, not per material: nothing to bleed.
  f.Bleed = parameters.ColorBleeding &&
    f.Components != scatterer_shader::Features::Scalars::Dependent &&
    (!automatic || (f.Materials > 1 && colorsDiffer));
  f.Boundary = parameters.BoundaryRefraction && f.Materials > 1 && (!automatic || indicesDiffer);
  f.Positional = plan.Lights.AnyPositional;
  f.Blend2 = !f.Transport && parameters.TemplateBlending;
  // A vtkMultiVolume's property is its first input's, whose Shade VTK 9.1 applies to all.
  f.Phong = vol->GetProperty()->GetShade() != 0;
  f.Parts = static_cast<int>(plan.Parts.size());
  f.LabelMask = source.Mask && source.LabelMapMask;
  // Ray samples per light read: the still frames' step against the still frames'
  // transport texel. On a frame whose step may be longer (VTK divides it by half its
  // reduction factor while the user drags with AutoAdjustSampleDistances on, up to 20
  // times, and sets it only when it draws), every sample reads the light: planned from the
  // still step, a read 2 or 4 samples ahead lay several texels deep in the matter, and a
  // lit ball turned red and ringed while the user dragged (steps 8 times the still one: mean
  // 2.2 levels from its still frame, up to 103, now 1.3 and 53; stock 0.2;
  // MapperBehaviour.FramesDraggedWithLongerStepsReadTheLightAtEverySample).
  f.LightStride = 1;
  if (f.Transport && f.Parts == 0 && !source.RayStepMayGrow)
  {
    auto* image = vtkImageData::SafeDownCast(source.Input);
    int dims[3] = { 1, 1, 1 };
    if (image)
    {
      image->GetDimensions(dims);
    }
    f.LightStride = std::min(requests.MaximumLightStride,
      il::lightReadStride(source.StillRayStep,
        il::transportTexelSize(
          parameters.TransportScaleFor(dims, source.VoxelEdges, false), source.VoxelEdges)));
  }
  // The light inside a dense texel (scatterer_illumination_dec.glsl, st_surfaceChange)
  // marches the volume toward the light with the ray's own transfer function: not where
  // matter the ray does not show would shadow (clipping planes, cropping that removes
  // matter, a mask), nor where that function is not the one the ray composites (VTK's
  // gradient shading takes its own light, a 2D transfer function, independent components).
  // Linear interpolation only: nearest interpolation's voxel faces are steps, and a sample
  // just past one takes its whole step's opacity wherever in the step the face lies, so
  // its attenuation followed the ray's phase (rings on a flat face at TransportScale 1:
  // 83 to 111 levels, 102 to 113 without; TransportVolume.DenseFaceAtScaleOneShowsNoRings).
  f.SurfaceDetail = requests.SurfaceDetail && f.Transport && f.Parts == 0 && !f.Phong &&
    vol->GetProperty()->GetInterpolationType() == VTK_LINEAR_INTERPOLATION && !source.Clipped &&
    !(source.Cropped && !parameters.CroppedMatterCastsShadows) && !source.Mask &&
    !plan.Transfer2D && f.Components != scatterer_shader::Features::Scalars::Independent;
  // Multiple scattering is an effect of its own: with shadows off the transport volume
  // still carries it (the light unattenuated, scattered as the medium scatters it).
  const bool multipleScattering = f.Transport && parameters.MultipleScattering > 0.0;
  if (automatic && !f.Shadow && !f.Bleed && !f.Boundary && !multipleScattering)
  {
    return "no illumination effect is switched on";
  }
  plan.Declarations = scatterer_shader::IlluminationDeclarations(f) + requests.ExtraGLSL;
  plan.ShadingInit = scatterer_shader::ShadingInitialization(f);
  plan.Shading = scatterer_shader::ShadingImplementation(f);
  plan.ShadingExit = scatterer_shader::ShadingExit(f);
  if (requests.FailedShaders->Contains(plan.ShaderKey()))
  {
    return "the illumination shader failed to compile here";
  }
  return "";
}
}
