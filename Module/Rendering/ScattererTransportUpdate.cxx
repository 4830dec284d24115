#include "ScattererTransportUpdate.h"

#include "ScattererFramePlan.h"
#include "ScattererIlluminationParameters.h"
#include "ScattererTemplateCache.h"
#include "ScattererTransfer2D.h"
#include "ScattererWarnOnce.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumeTexture.h"

#include <scatterer/Material.h>
#include <scatterer/Transport.h>

#include <algorithm>
#include <cmath>

namespace scatterer_render
{
// One row of the medium over the table coordinate: albedo from @p color (white when
// none), extinction from @p opacity per @p unit distance.
void TabulateMedium(float* row, vtkColorTransferFunction* color, vtkPiecewiseFunction* gray,
  vtkPiecewiseFunction* opacity, double lo, double hi, double unit)
{
  for (int i = 0; i < kMediumTableSize; ++i)
  {
    const double value = lo + (hi - lo) * i / (kMediumTableSize - 1.0);
    double rgb[3] = { 1.0, 1.0, 1.0 };
    if (gray)
    {
      rgb[0] = rgb[1] = rgb[2] = gray->GetValue(value);
    }
    else if (color)
    {
      color->GetColor(value, rgb);
    }
    for (int c = 0; c < 3; ++c)
    {
      row[4 * i + c] = static_cast<float>(std::min(std::max(rgb[c], 0.0), 1.0));
    }
    row[4 * i + 3] =
      static_cast<float>(scatterer::extinctionFromOpacity(opacity->GetValue(value), unit));
  }
}

namespace
{
using TransportInputs = vtkScattererTransportVolume::Inputs;

// The ScalarOpacityUnitDistance of transfer-function set @p f (1 where unset).
double UnitDistance(vtkVolumeProperty* property, int f)
{
  const double unit = property->GetScalarOpacityUnitDistance(f);
  return unit > 0.0 ? unit : 1.0;
}

// How many of the property's transfer-function sets the medium reads: one per
// independent component, else the first.
int FunctionCount(const TransportInputs& t)
{
  return t.ComponentMode == TransportInputs::Independent ? t.Components : 1;
}

// One medium row: set @p f's functions over component @p c's range.
void TabulateRow(float* row, vtkVolumeProperty* property, int f, const float range[2])
{
  const bool gray = property->GetColorChannels(f) == 1;
  TabulateMedium(row, gray ? nullptr : property->GetRGBTransferFunction(f),
    gray ? property->GetGrayTransferFunction(f) : nullptr, property->GetScalarOpacity(f), range[0],
    range[1], UnitDistance(property, f));
}
}

TransportUpdate::TransportUpdate() = default;
TransportUpdate::~TransportUpdate() = default;

std::string TransportUpdate::Update(vtkRenderer* ren, vtkVolume* vol, const FramePlan& plan,
  const IlluminationParameters& parameters, const TemplateCache& templates,
  const TransportSource& source, WarnOnce& warn, std::string& error)
{
  std::string whyNot;
  vtkVolumeTexture* volumeTexture =
    this->WholeVolumeTexture(ren, vol, plan, source.VolumeTexture, whyNot);
  if (!volumeTexture)
  {
    warn("Scatterer-template illumination cannot light this partitioned volume: " + whyNot +
      "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    return "a partitioned volume that does not fit one texture";
  }
  vtkVolumeTexture::VolumeBlock* block = volumeTexture->GetCurrentBlock();
  if (!block || !block->TextureObject)
  {
    return "the volume texture is not loaded";
  }
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkScattererTransportVolume::Inputs& t = this->Inputs;
  t.Volume = block->TextureObject;
  vtkNew<vtkMatrix4x4> pointToCell;
  vtkMatrix4x4::Invert(volumeTexture->CellToPointMatrix, pointToCell);
  vtkMatrix4x4::Multiply4x4(block->TextureToDataset, pointToCell, this->VolumeTextureToDataset);
  this->UpdateComponents(vol, plan);
  // Scale and bias as the ray caster applies them: none for 64-bit types (they come
  // pre-scaled) and none for RGBA, whose colour is the texel itself (VTK 9.1's
  // SetVolumeShaderParameters).
  const bool raw = volumeTexture->HandleLargeDataTypes ||
    t.ComponentMode == vtkScattererTransportVolume::Inputs::RGBA;
  for (int c = 0; c < 4; ++c)
  {
    t.ScalarScale[c] = raw ? 1.0f : volumeTexture->Scale[c];
    t.ScalarBias[c] = raw ? 0.0f : volumeTexture->Bias[c];
  }
  t.VolumeUploadTime = volumeTexture->UploadTime.GetMTime();
  // A binary mask: masked-out matter neither shows (the ray caster's mask) nor casts
  // shadow or scatters (the transport volume). A label-map mask: each label's medium
  // comes from its own transfer functions, in the picture and in the light.
  t.Mask = nullptr;
  t.MaskUploadTime = 0;
  t.LabelMask = plan.Features.LabelMask;
  t.MaskBlend = source.MaskBlend;
  if (source.Mask)
  {
    const int volumeDims[3] = { static_cast<int>(block->TextureObject->GetWidth()),
      static_cast<int>(block->TextureObject->GetHeight()),
      static_cast<int>(block->TextureObject->GetDepth()) };
    std::string why;
    t.Mask = this->Mask.Update(renWin, source.Mask, volumeDims, why);
    if (!t.Mask)
    {
      warn("Scatterer-template illumination cannot use this mask: " + why +
        "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
      return "an unusable mask";
    }
    t.MaskUploadTime = this->Mask.GetUploadTime();
  }
  this->UpdateGeometry(vol, plan, source, parameters);

  // The tables change with the transfer functions, the ranges, the materials, the
  // templates and the kernel settings only: rebuilt then, not every frame, and the
  // transport volume is told by TablesVersion.
  vtkVolumeProperty* property = vol->GetProperty();
  KeyWriter key;
  key << t.ComponentMode << '|' << t.MaterialComponent;
  for (int f = 0; f < FunctionCount(t); ++f)
  {
    const bool gray = property->GetColorChannels(f) == 1;
    key << '|' << property->GetScalarOpacity(f)->GetMTime() << ','
        << (gray ? property->GetGrayTransferFunction(f)->GetMTime()
                 : property->GetRGBTransferFunction(f)->GetMTime())
        << ',' << gray << ',' << UnitDistance(property, f);
  }
  for (int c = 0; c < t.Components; ++c)
  {
    key << '|' << volumeTexture->ScalarRange[c][0] << ',' << volumeTexture->ScalarRange[c][1];
  }
  if (plan.Transfer2D)
  {
    vtkImageData* table = property->GetTransferFunction2D();
    key << "|2d:" << table << ',' << table->GetMTime() << ',' << plan.SampleDistance;
  }
  key << '|' << templates.GetGenerationKey() << '|' << parameters.PhotonCap << '|' << plan.Radius;
  // A label-map mask adds one medium row per label: its transfer functions count too.
  key << '|' << plan.Features.LabelMask;
  if (plan.Features.LabelMask)
  {
    key << ',' << property->GetLabelColorMTime().GetMTime() << ','
        << property->GetLabelScalarOpacityMTime().GetMTime();
    for (int label : property->GetLabelMapLabels())
    {
      vtkColorTransferFunction* c = property->GetLabelColor(label);
      vtkPiecewiseFunction* o = property->GetLabelScalarOpacity(label);
      key << ',' << label << ':' << (c ? c->GetMTime() : 0) << ':' << (o ? o->GetMTime() : 0);
    }
  }
  for (const auto& m : plan.Materials.Materials)
  {
    key << '|' << m.Physics.selector.lo << ',' << m.Physics.selector.hi << ','
        << m.Physics.selector.label << ',' << static_cast<int>(m.Physics.selector.kind) << ','
        << m.OpacityPerUnit << ',' << m.Physics.refractiveIndex << ',' << m.Physics.diffuse.x << ','
        << m.Physics.diffuse.y << ',' << m.Physics.diffuse.z;
  }
  if (this->Tables.Differs(key.Key()))
  {
    this->UpdateTables(vol, plan, parameters, templates, volumeTexture->ScalarRange);
    this->Tables.Record(key.Key());
    ++t.TablesVersion;
  }
  // Occlusion off: nothing along a light path absorbs (OcclusionScale in world units).
  t.OcclusionScale =
    plan.Features.Shadow ? OcclusionScale(parameters.OcclusionStrength, 1.0) : 0.0f;
  this->UpdateLights(plan, source, warn);
  t.Bleed = plan.Features.Bleed;
  t.Boundary = plan.Features.Boundary;
  t.MultipleScattering = static_cast<float>(parameters.MultipleScattering);

  // Interactive frames (a time budget under a second) build the volume coarser, but
  // only when it must be rebuilt at all: while the user orbits under a scene light,
  // the still frames' volume stays valid, and a coarse one would cost a build now and
  // another when the user lets go.
  t.Downsample = parameters.TransportScale;
  const bool interactive = vol->GetAllocatedRenderTime() < 1.0;
  if (interactive && !this->Transport->IsCurrent(renWin, t))
  {
    t.Downsample = parameters.InteractiveTransportScale;
  }
  if (source.Progress && !this->Transport->IsCurrent(renWin, t))
  {
    source.Progress(0.0);
    this->Transport->SetProgressCallback(source.Progress);
  }
  else
  {
    this->Transport->SetProgressCallback(nullptr);
  }
  std::string why;
  if (!this->Transport->Update(renWin, t, why))
  {
    error = "The light transport volume could not be built: " + why +
      "; this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.";
    return "the light transport volume could not be built";
  }
  return "";
}

vtkVolumeTexture* TransportUpdate::WholeVolumeTexture(vtkRenderer* ren, vtkVolume* vol,
  const FramePlan& plan, vtkVolumeTexture* rayCaster, std::string& why)
{
  if (!rayCaster)
  {
    why = "the volume is not loaded";
    return nullptr;
  }
  const auto& parts = rayCaster->GetPartitions();
  if (parts[0] * parts[1] * parts[2] == 1)
  {
    this->WholeVolume->ReleaseGraphicsResources(ren->GetRenderWindow());
    this->WholeVolumeKey.Clear();
    return rayCaster;
  }
  const int interpolation = vol->GetProperty()->GetInterpolationType();
  KeyWriter key;
  key << plan.Image << '|' << plan.Image->GetMTime() << '|' << plan.Scalars << '|'
      << plan.Scalars->GetMTime() << '|' << plan.CellFlag << '|' << ren->GetRenderWindow();
  if (this->WholeVolumeKey.Differs(key.Key()))
  {
    this->WholeVolumeKey.Clear();
    if (!this->WholeVolume->LoadVolume(ren, plan.Image, plan.Scalars, plan.CellFlag, interpolation))
    {
      why = "the whole volume does not fit one 3D texture here (the transport reads it "
            "whole)";
      return nullptr;
    }
    this->WholeVolumeKey.Record(key.Key());
  }
  // Linear or nearest, as the property asks now.
  this->WholeVolume->UpdateVolume(vol->GetProperty());
  return this->WholeVolume;
}

void TransportUpdate::DatasetToLightTexture(double rowMajor[16]) const
{
  // texture -> light texture: t * scale + offset, after dataset -> texture.
  float scale[3], offset[3];
  this->Transport->GetTextureTransform(scale, offset);
  vtkNew<vtkMatrix4x4> datasetToTexture, toLight, product;
  vtkMatrix4x4::Invert(this->VolumeTextureToDataset, datasetToTexture);
  for (int a = 0; a < 3; ++a)
  {
    toLight->SetElement(a, a, scale[a]);
    toLight->SetElement(a, 3, offset[a]);
  }
  vtkMatrix4x4::Multiply4x4(toLight, datasetToTexture, product);
  for (int i = 0; i < 16; ++i)
  {
    rowMajor[i] = product->GetElement(i / 4, i % 4);
  }
}

void TransportUpdate::UpdateComponents(vtkVolume* vol, const FramePlan& plan)
{
  using Scalars = scatterer_shader::Features::Scalars;
  TransportInputs& t = this->Inputs;
  t.Components = plan.Scalars->GetNumberOfComponents();
  t.MaterialComponent = plan.MaterialComponent;
  switch (plan.Features.Components)
  {
    case Scalars::Independent:
      t.ComponentMode = TransportInputs::Independent;
      break;
    case Scalars::Dependent:
      t.ComponentMode = t.Components == 2 ? TransportInputs::LuminanceAlpha : TransportInputs::RGBA;
      break;
    default:
      t.ComponentMode = plan.Transfer2D ? TransportInputs::Transfer2D : TransportInputs::OneScalar;
  }
  // A 2D transfer function's gradient, as VTK's computeGradient takes it.
  double spacing[3];
  plan.Image->GetSpacing(spacing);
  const double mean = (std::abs(spacing[0]) + std::abs(spacing[1]) + std::abs(spacing[2])) / 3.0;
  for (int a = 0; a < 3; ++a)
  {
    const unsigned int texels[3] = { t.Volume->GetWidth(), t.Volume->GetHeight(),
      t.Volume->GetDepth() };
    t.VoxelStep[a] = 1.0f / static_cast<float>(std::max(1u, texels[a]));
    t.GradientAspect[a] = mean > 0.0 ? static_cast<float>(std::abs(spacing[a]) * 2.0 / mean) : 1.0f;
  }
  for (int c = 0; c < 4; ++c)
  {
    t.ComponentWeights[c] = static_cast<float>(vol->GetProperty()->GetComponentWeight(c));
  }
}

void TransportUpdate::UpdateGeometry(vtkVolume* vol, const FramePlan& plan,
  const TransportSource& source, const IlluminationParameters& parameters)
{
  vtkScattererTransportVolume::Inputs& t = this->Inputs;
  vtkTextureObject* texture = t.Volume;
  // Texture coordinate -> structured index -> physical (origin, spacing, direction)
  // -> world (the volume's matrix). Texel centre (i + 0.5) / N holds data point i
  // (cell data: the centre of cell i), so distances are the data's own.
  vtkNew<vtkMatrix4x4> texToIndex, indexToDataset, texToDataset, texToWorld;
  int extent[6];
  plan.Image->GetExtent(extent);
  const unsigned int texels[3] = { texture->GetWidth(), texture->GetHeight(), texture->GetDepth() };
  for (int a = 0; a < 3; ++a)
  {
    texToIndex->SetElement(a, a, texels[a]);
    texToIndex->SetElement(a, 3, extent[2 * a] - 0.5 + (plan.CellFlag ? 0.5 : 0.0));
    t.IndexOrigin[a] = extent[2 * a];
  }
  plan.Image->ComputeIndexToPhysicalMatrix(plan.Image->GetOrigin(), plan.Image->GetSpacing(),
    plan.Image->GetDirectionMatrix()->GetData(), indexToDataset->GetData());
  vtkMatrix4x4::Multiply4x4(indexToDataset, texToIndex, texToDataset);
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix(), texToDataset, texToWorld);
  for (int i = 0; i < 16; ++i)
  {
    t.TexToWorld[i] = texToWorld->GetElement(i / 4, i % 4);
    t.TexToDataset[i] = texToDataset->GetElement(i / 4, i % 4);
    t.TexToIndex[i] = texToIndex->GetElement(i / 4, i % 4);
  }
  t.ClipPlanes.clear();
  if (vtkPlaneCollection* planes = source.ClippingPlanes)
  {
    for (int p = 0; p < planes->GetNumberOfItems() && p < 6; ++p)
    {
      vtkPlane* plane = planes->GetItem(p);
      double n[3], o[3];
      plane->GetNormal(n);
      plane->GetOrigin(o);
      t.ClipPlanes.insert(t.ClipPlanes.end(),
        { static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]),
          static_cast<float>(-(n[0] * o[0] + n[1] * o[1] + n[2] * o[2])) });
    }
  }
  t.Cropping = source.Cropping && !parameters.CroppedMatterCastsShadows;
  t.CropFlags = source.CropFlags;
  for (int a = 0; a < 3; ++a)
  {
    t.CropMin[a] = static_cast<float>(source.CroppingRegionPlanes[2 * a]);
    t.CropMax[a] = static_cast<float>(source.CroppingRegionPlanes[2 * a + 1]);
  }
}

void TransportUpdate::UpdateLights(
  const FramePlan& plan, const TransportSource& source, WarnOnce& warn)
{
  const auto& lights = plan.Lights;
  auto& out = this->Inputs.Lights;
  out.clear();
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
    out.push_back(light);
  }
  // A piece of a distributed volume: the maps are for the lights the exchange saw
  // before this frame rendered; they must be this frame's.
  const vtkScattererLightExchange::Result* exchange = source.Exchange;
  if (!exchange || !exchange->Active)
  {
    return;
  }
  bool same = exchange->Lights.size() == out.size();
  for (size_t l = 0; same && l < out.size(); ++l)
  {
    const vtkScattererTransportVolume::Light& a = exchange->Lights[l];
    same = a.Positional == out[l].Positional;
    for (int c = 0; same && c < 3; ++c)
    {
      same = std::abs(a.Toward[c] - out[l].Toward[c]) <= 1e-5f &&
        std::abs(a.Position[c] - out[l].Position[c]) <= 1e-5f * (1.0f + std::abs(a.Position[c]));
    }
  }
  if (!same)
  {
    warn("The light exchange between the pieces was made for other lights than this "
         "frame's; this piece is lit through its own voxels and ghost layers only.");
    return;
  }
  for (size_t l = 0; l < out.size(); ++l)
  {
    out[l].Entering = exchange->Lights[l].Entering;
  }
}

void TransportUpdate::UpdateTables(vtkVolume* vol, const FramePlan& plan,
  const IlluminationParameters& parameters, const TemplateCache& templates,
  const float ranges[4][2])
{
  TransportInputs& t = this->Inputs;
  vtkVolumeProperty* property = vol->GetProperty();
  // The medium over the table coordinate (VTK's tables span each component's range):
  // albedo from the colour transfer function, extinction from the opacity transfer
  // function, one row per rule (Inputs::ComponentRule).
  const auto row = [&t](int r)
  { return t.Medium.data() + static_cast<size_t>(4) * kMediumTableSize * r; };
  t.MediumRows = t.ComponentMode == TransportInputs::Independent ? t.Components
    : t.ComponentMode == TransportInputs::LuminanceAlpha         ? 2
    : plan.Features.LabelMask                                    ? 256
                                                                 : 1;
  t.Medium.assign(static_cast<size_t>(4) * kMediumTableSize * t.MediumRows, 0.0f);
  switch (t.ComponentMode)
  {
    case TransportInputs::Transfer2D: // its own table, over (scalar, gradient magnitude)
      TabulateTransfer2D(
        property->GetTransferFunction2D(), plan.SampleDistance, t.Medium, t.MediumRows);
      break;
    case TransportInputs::Independent:
      for (int c = 0; c < t.Components; ++c)
      {
        TabulateRow(row(c), property, c, ranges[c]);
      }
      break;
    case TransportInputs::LuminanceAlpha: // colour over the luminance, opacity over the alpha
      TabulateRow(row(0), property, 0, ranges[0]);
      TabulateRow(row(1), property, 0, ranges[1]);
      break;
    case TransportInputs::RGBA: // opacity over the alpha (the colour is the data's)
      TabulateRow(row(0), property, 0, ranges[3]);
      break;
    default:
      TabulateRow(row(0), property, 0, ranges[0]);
  }
  const double lo = ranges[t.MaterialComponent][0], hi = ranges[t.MaterialComponent][1];
  const double unit = UnitDistance(property, FunctionCount(t) > 1 ? t.MaterialComponent : 0);
  // A label-map mask: row L holds label L's colour and opacity functions (rows 1..255;
  // a label without functions is empty, as VTK's label table leaves it).
  if (plan.Features.LabelMask)
  {
    for (int label : property->GetLabelMapLabels())
    {
      vtkPiecewiseFunction* labelOpacity = property->GetLabelScalarOpacity(label);
      if (label < 1 || label > 255 || !labelOpacity)
      {
        continue;
      }
      TabulateMedium(
        row(label), property->GetLabelColor(label), nullptr, labelOpacity, lo, hi, unit);
    }
  }
  const double tableRange[2] = { lo, hi };
  t.MaterialTable = scatterer_scene::MaterialTable(plan.Materials, tableRange, kMediumTableSize);
  // Materials and their kernels: the merged templates, in the material's mean free
  // paths (scatterer/Transport.h), at most one template radius.
  const auto& mats = plan.Materials.Materials;
  const auto& raw = templates.GetRawTemplates();
  t.KernelWidth = std::max(1, parameters.PhotonCap);
  t.MaterialColors.clear();
  t.Kernels.clear();
  for (size_t m = 0; m < mats.size(); ++m)
  {
    const auto& material = mats[m];
    const glm::vec3 c = material.Physics.diffuse;
    t.MaterialColors.insert(t.MaterialColors.end(), { c.x, c.y, c.z });
    const double sigma = scatterer::extinctionFromOpacity(material.OpacityPerUnit, unit);
    std::vector<scatterer::KernelPhoton> kernel;
    if (m < raw.size())
    {
      kernel = scatterer::mergedKernel(
        raw[m], t.KernelWidth, scatterer::kernelRadius(material.Physics, sigma, 0.0, plan.Radius));
    }
    for (int k = 0; k < t.KernelWidth; ++k)
    {
      const bool has = k < static_cast<int>(kernel.size());
      t.Kernels.insert(t.Kernels.end(),
        { has ? kernel[k].offset.x : 0.0f, has ? kernel[k].offset.y : 0.0f,
          has ? kernel[k].offset.z : 0.0f, has ? kernel[k].weight : 0.0f });
    }
  }
  t.SpeedRatios = plan.SpeedRatios;
  t.OpacityRatios = plan.OpacityRatios;
}

void TransportUpdate::ReleaseGraphicsResources(vtkWindow* window)
{
  this->WholeVolume->ReleaseGraphicsResources(window);
  this->WholeVolumeKey.Clear();
  this->Transport->ReleaseGraphicsResources(window);
  this->Mask.ReleaseGraphicsResources(window);
}
}
