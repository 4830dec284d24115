#include "ScattererTransportUpdate.h"

#include "ScattererColourFunction.h"
#include "ScattererFramePlan.h"
#include "ScattererIlluminationParameters.h"
#include "ScattererTemplateCache.h"
#include "ScattererTransfer2D.h"
#include "ScattererTransportGrid.h"
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
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumeTexture.h"

#include <scatterer/Material.h>
#include <scatterer/Transport.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace scatterer_render
{
// One row of the medium over the table coordinate: albedo from @p color (white when
// none), extinction from @p opacity per @p unit distance.
void TabulateMedium(float* row, vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity,
  double lo, double hi, double unit, int entries)
{
  for (int i = 0; i < entries; ++i)
  {
    const double value = lo + (hi - lo) * i / (entries - 1.0);
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

// Where a volume texture lies: texture coordinate -> structured index -> physical
// (origin, spacing, direction). Texel centre (i + 0.5) / N holds data point i (cell
// data: the centre of cell i), so distances are the data's own.
void TextureToDataset(vtkImageData* image, int cellFlag, vtkTextureObject* texture,
  vtkMatrix4x4* texToDataset, vtkMatrix4x4* texToIndexOut)
{
  vtkNew<vtkMatrix4x4> texToIndex, indexToDataset;
  int extent[6];
  image->GetExtent(extent);
  const unsigned int texels[3] = { texture->GetWidth(), texture->GetHeight(), texture->GetDepth() };
  for (int a = 0; a < 3; ++a)
  {
    texToIndex->SetElement(a, a, texels[a]);
    texToIndex->SetElement(a, 3, extent[2 * a] - 0.5 + (cellFlag ? 0.5 : 0.0));
  }
  image->ComputeIndexToPhysicalMatrix(image->GetOrigin(), image->GetSpacing(),
    image->GetDirectionMatrix()->GetData(), indexToDataset->GetData());
  vtkMatrix4x4::Multiply4x4(indexToDataset, texToIndex, texToDataset);
  if (texToIndexOut)
  {
    texToIndexOut->DeepCopy(texToIndex);
  }
}

// What UpdateTables makes (the inputs the transport volume's tables are uploaded from).
struct TableContents
{
  std::vector<float> Medium, MaterialTable, MaterialColors, Kernels, SpeedRatios, OpacityRatios;
  int MediumRows, MaterialRows, KernelWidth;

  explicit TableContents(const TransportInputs& t)
    : Medium(t.Medium)
    , MaterialTable(t.MaterialTable)
    , MaterialColors(t.MaterialColors)
    , Kernels(t.Kernels)
    , SpeedRatios(t.SpeedRatios)
    , OpacityRatios(t.OpacityRatios)
    , MediumRows(t.MediumRows)
    , MaterialRows(t.MaterialRows)
    , KernelWidth(t.KernelWidth)
  {
  }
  bool operator==(const TableContents& o) const
  {
    return this->Medium == o.Medium && this->MaterialTable == o.MaterialTable &&
      this->MaterialColors == o.MaterialColors && this->Kernels == o.Kernels &&
      this->SpeedRatios == o.SpeedRatios && this->OpacityRatios == o.OpacityRatios &&
      this->MediumRows == o.MediumRows && this->MaterialRows == o.MaterialRows &&
      this->KernelWidth == o.KernelWidth;
  }
};

// The medium over (scalar, gradient magnitude) with a gradient opacity: 1024 entries over
// the scalar, as VTK 9.1's own table, and 512 rows over [0, a quarter of the range], half
// VTK's 1024 (an 8 MiB table while a gradient opacity is on). With 64 rows a row spanned
// 16 gradient units of a CT's range: matter a steep step of the function hid below 8
// still cast its full shadow.
constexpr int kGradientOpacityColumns = 1024;
constexpr int kGradientOpacityRows = 512;

// A vtkMultiVolume's box: at most this many texels along an axis (before the
// transport's own downsampling).
constexpr int kMaxBoxTexels = 1024;

// One medium row: set @p f's functions over component @p c's range.
void TabulateRow(float* row, vtkVolumeProperty* property, int f, const float range[2],
  int entries = kMediumTableSize)
{
  TabulateMedium(row, scatterer_scene::RayCasterColour(property, f), property->GetScalarOpacity(f),
    range[0], range[1], UnitDistance(property, f), entries);
}
}

TransportUpdate::TransportUpdate() = default;
TransportUpdate::~TransportUpdate() = default;

std::string TransportUpdate::Update(vtkRenderer* ren, vtkVolume* vol, const FramePlan& plan,
  const IlluminationParameters& parameters, const TemplateCache& templates,
  const TransportSource& source, WarnOnce& warn, std::string& error)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkScattererTransportVolume::Inputs& t = this->Inputs;
  const std::string stock = plan.Parts.empty() ? this->UpdateVolume(ren, vol, plan, source, warn)
                                               : this->UpdateParts(plan, source, warn);
  if (!stock.empty())
  {
    return stock;
  }
  this->UpdateClipping(source, parameters, !plan.Parts.empty());

  // The tables change with the transfer functions, the ranges, the materials, the
  // templates and the kernel settings only: rebuilt then, not every frame, and the
  // transport volume is told by TablesVersion.
  // A function touched without a change of value (Modified(), a point set to the value it
  // has, an editor or preset setting the same points again) makes the same tables: the
  // transport volume, told by TablesVersion, keeps what it built (a rebuild of the CT
  // head's medium and light, 0.7 s on llvmpipe, for nothing).
  const std::string key = this->TablesKey(vol, plan, parameters, templates);
  if (this->Tables.Differs(key))
  {
    const TableContents before(t);
    this->UpdateTables(vol, plan, parameters, templates);
    this->Tables.Record(key);
    if (!(TableContents(t) == before))
    {
      ++t.TablesVersion;
    }
  }
  // Occlusion off: nothing along a light path absorbs (OcclusionScale in world units).
  t.OcclusionScale =
    plan.Features.Shadow ? OcclusionScale(parameters.OcclusionStrength, 1.0) : 0.0f;
  this->UpdateLights(plan, source, warn);
  t.Bleed = plan.Features.Bleed;
  t.Boundary = plan.Features.Boundary;
  t.MultipleScattering = static_cast<float>(parameters.MultipleScattering);

  // Interactive frames (the renderer's time budget under a second: 1 / the window's
  // DesiredUpdateRate, as VTK's interactor sets it while the user drags; not the
  // volume's share of it, which other props in view shrink) build the volume coarser, but
  // only when it must be rebuilt at all: while the user orbits under a scene light,
  // the still frames' volume stays valid, and a coarse one would cost a build now and
  // another when the user lets go.
  // A volume larger than MaximumTransportVoxels allows is built coarser.
  int gridDims[3];
  t.GetGridSourceDims(gridDims);
  double voxelLengths[3];
  scatterer_gpu::VoxelLengths(gridDims, t.TexToWorld, voxelLengths);
  t.Downsample = parameters.TransportScaleFor(gridDims, voxelLengths, false);
  t.StillDownsample = t.Downsample; // the diffusion's grid, also on interactive frames
  const bool interactive = ren->GetAllocatedRenderTime() < 1.0;
  if (interactive && !this->Transport->IsCurrent(renWin, t))
  {
    t.Downsample = parameters.TransportScaleFor(gridDims, voxelLengths, true);
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

std::string TransportUpdate::UpdateVolume(vtkRenderer* ren, vtkVolume* vol, const FramePlan& plan,
  const TransportSource& source, WarnOnce& warn)
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
  vtkTextureObject* texture = block->TextureObject;
  if (texture->GetWidth() < 1 || texture->GetHeight() < 1 || texture->GetDepth() < 1)
  {
    // VTK could not upload the volume (it says "Invalid texture dimensions"): an axis
    // longer than the GPU's 3D textures. Said once, not as a degenerate placement at
    // every frame.
    warn("Scatterer-template illumination cannot light this volume: VTK did not upload it "
         "to the GPU (at most " +
      std::to_string(vtkTextureObject::GetMaximumTextureSize3D(renWin)) +
      " texels along an axis of a 3D texture here); this volume renders as "
      "vtkOpenGLGPUVolumeRayCastMapper would.");
    return "the volume texture holds no voxels";
  }
  vtkScattererTransportVolume::Inputs& t = this->Inputs;
  this->ReadTexture = volumeTexture;
  this->PartTextures.clear();
  t.Parts.clear();
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
  t.VolumeFilter = t.Volume->GetMagnificationFilter();
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
  this->UpdateGeometry(vol, plan);
  return "";
}

// A vtkMultiVolume. The grid lies on a box around all inputs, on the first input's voxel
// lattice (within a budget of the inputs' texels together); each input is read through
// its own texture -> world placement (texture = VTK's texel-centred coordinates, as for
// one volume).
std::string TransportUpdate::UpdateParts(
  const FramePlan& plan, const TransportSource& source, WarnOnce& warn)
{
  vtkScattererTransportVolume::Inputs& t = this->Inputs;
  if (source.PartTextures.size() != plan.Parts.size())
  {
    return "the vtkMultiVolume's inputs are not loaded";
  }
  this->ReadTexture = source.PartTextures.front();
  this->PartTextures = source.PartTextures;
  t.Parts.assign(plan.Parts.size(), {});
  t.Mask = nullptr;
  t.MaskUploadTime = 0;
  t.LabelMask = false;
  t.ComponentMode = TransportInputs::MultiInput;
  t.Components = 1;
  t.MaterialComponent = 0;
  double texelCount = 0.0;
  std::vector<vtkSmartPointer<vtkMatrix4x4>> texToWorld;
  for (size_t k = 0; k < plan.Parts.size(); ++k)
  {
    vtkVolumeTexture* texture = source.PartTextures[k];
    const auto& parts = texture->GetPartitions();
    vtkVolumeTexture::VolumeBlock* block = texture->GetCurrentBlock();
    if (!block || !block->TextureObject)
    {
      return "a vtkMultiVolume input that is not loaded";
    }
    if (parts[0] * parts[1] * parts[2] != 1)
    {
      warn("Scatterer-template illumination does not apply to a partitioned "
           "vtkMultiVolume input; this volume renders as vtkOpenGLGPUVolumeRayCastMapper "
           "would.");
      return "a partitioned vtkMultiVolume input";
    }
    const FramePlan::Part& part = plan.Parts[k];
    auto& out = t.Parts[k];
    out.Volume = block->TextureObject;
    out.ScalarScale = texture->HandleLargeDataTypes ? 1.0f : texture->Scale[0];
    out.ScalarBias = texture->HandleLargeDataTypes ? 0.0f : texture->Bias[0];
    out.UploadTime = texture->UploadTime.GetMTime();
    out.Filter = out.Volume->GetMagnificationFilter();
    vtkNew<vtkMatrix4x4> texToDataset;
    TextureToDataset(part.Image, part.CellFlag, out.Volume, texToDataset, nullptr);
    texToWorld.push_back(vtkSmartPointer<vtkMatrix4x4>::New());
    vtkMatrix4x4::Multiply4x4(part.Volume->GetMatrix(), texToDataset, texToWorld.back());
    texelCount += static_cast<double>(out.Volume->GetWidth()) * out.Volume->GetHeight() *
      out.Volume->GetDepth();
  }
  for (const auto& toWorld : texToWorld)
  {
    const double determinant = toWorld->Determinant();
    if (!(std::abs(determinant) > 0.0) || !std::isfinite(determinant))
    {
      warn("Scatterer-template illumination does not apply to a vtkMultiVolume input of "
           "zero spacing or scale; this volume renders as vtkOpenGLGPUVolumeRayCastMapper "
           "would.");
      return "a vtkMultiVolume input with zero spacing or scale";
    }
  }
  // The box is laid along the first input's texture axes (a CT and its segmentations
  // share them, and the light then follows their voxels with no staircase), stretched
  // over every input's data points in those coordinates.
  vtkNew<vtkMatrix4x4> worldToFirst;
  vtkMatrix4x4::Invert(texToWorld.front(), worldToFirst);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (size_t k = 0; k < texToWorld.size(); ++k)
  {
    // The corners of the input's data points (texel centres; the first input's own
    // extent then gives the grid it gets alone).
    const unsigned int texels[3] = { t.Parts[k].Volume->GetWidth(), t.Parts[k].Volume->GetHeight(),
      t.Parts[k].Volume->GetDepth() };
    for (int corner = 0; corner < 8; ++corner)
    {
      double p[4] = { 0.0, 0.0, 0.0, 1.0 };
      for (int a = 0; a < 3; ++a)
      {
        const double n = std::max(1u, texels[a]);
        p[a] = (corner >> a & 1) ? 1.0 - 0.5 / n : 0.5 / n;
      }
      texToWorld[k]->MultiplyPoint(p, p);
      worldToFirst->MultiplyPoint(p, p);
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], p[a] / p[3]);
        hi[a] = std::max(hi[a], p[a] / p[3]);
      }
    }
  }
  // The box's texels lie on the first input's voxel lattice, every `stride`-th one: where
  // the inputs share that lattice (a volume and its segmentations), each is lit as it
  // would be alone. The stride is the smallest that keeps the box within twice the texels
  // the inputs have together (room for the space between them; a small input far from a
  // large one does not multiply the cost).
  const unsigned int firstTexels[3] = { t.Parts.front().Volume->GetWidth(),
    t.Parts.front().Volume->GetHeight(), t.Parts.front().Volume->GetDepth() };
  double first[3], last[3];
  for (int a = 0; a < 3; ++a)
  {
    first[a] = std::floor(lo[a] * firstTexels[a] - 0.5 + 1e-6);
    last[a] = std::ceil(hi[a] * firstTexels[a] - 0.5 - 1e-6);
  }
  int stride = 1;
  const auto count = [&](int a, int m)
  { return static_cast<int>(std::ceil((last[a] - m * std::floor(first[a] / m)) / m)) + 1; };
  while ((static_cast<double>(count(0, stride)) * count(1, stride) * count(2, stride) >
             2.0 * std::max(texelCount, 8.0) ||
           std::max({ count(0, stride), count(1, stride), count(2, stride) }) > kMaxBoxTexels) &&
    stride < kMaxBoxTexels)
  {
    ++stride;
  }
  // Box texel j (centre (j + 0.5) / n) is the first input's texel i0 + j * stride.
  vtkNew<vtkMatrix4x4> boxToFirst, boxToWorld;
  for (int a = 0; a < 3; ++a)
  {
    const double i0 = stride * std::floor(first[a] / stride);
    const int n = count(a, stride);
    t.BoxTexels[a] = n;
    t.IndexOrigin[a] = static_cast<int>(i0) / stride; // the grid keeps to this lattice too
    boxToFirst->SetElement(a, a, static_cast<double>(n) * stride / firstTexels[a]);
    boxToFirst->SetElement(a, 3, (i0 - 0.5 * stride + 0.5) / firstTexels[a]);
  }
  vtkMatrix4x4::Multiply4x4(texToWorld.front(), boxToFirst, boxToWorld);
  for (size_t k = 0; k < plan.Parts.size(); ++k)
  {
    vtkNew<vtkMatrix4x4> worldToTex, boxToTex;
    vtkMatrix4x4::Invert(texToWorld[k], worldToTex);
    vtkMatrix4x4::Multiply4x4(worldToTex, boxToWorld, boxToTex);
    for (int i = 0; i < 16; ++i)
    {
      t.Parts[k].BoxToTexture[i] = boxToTex->GetElement(i / 4, i % 4);
    }
  }
  // The grid's "volume texture" is the box; part 0's texture stands in where a pass
  // binds the volume (nothing reads it).
  t.Volume = t.Parts.front().Volume;
  t.VolumeUploadTime = 0;
  t.VolumeFilter = 0;
  for (int c = 0; c < 4; ++c)
  {
    t.ScalarScale[c] = 1.0f;
    t.ScalarBias[c] = 0.0f;
  }
  this->VolumeTextureToDataset->DeepCopy(boxToWorld);
  for (int i = 0; i < 16; ++i)
  {
    t.TexToWorld[i] = boxToWorld->GetElement(i / 4, i % 4);
    t.TexToDataset[i] = t.TexToWorld[i];
    t.TexToIndex[i] = (i % 5 == 0) ? 1.0 : 0.0;
  }
  // VTK 9.1 crops a vtkMultiVolume in coordinates of its own: with planes that keep the
  // plate of a plate-and-ball scene in the world and in the multi-volume's data
  // coordinates, it drew nothing (the stock mapper too). The light does not follow it.
  if (source.Cropping)
  {
    warn("Scatterer-template illumination does not crop the light of a vtkMultiVolume "
         "(VTK 9.1 crops its picture in coordinates the light cannot follow): cropped "
         "matter still casts shadows.");
  }
  return "";
}

std::string TransportUpdate::TablesKey(vtkVolume* vol, const FramePlan& plan,
  const IlluminationParameters& parameters, const TemplateCache& templates) const
{
  const vtkScattererTransportVolume::Inputs& t = this->Inputs;
  KeyWriter key;
  key << t.ComponentMode << '|' << t.MaterialComponent;
  // The functions and ranges of each medium row's source: the volume's property (one set
  // per independent component), or each input's of a vtkMultiVolume.
  const auto addFunctions = [&key](vtkVolumeProperty* property, int f)
  {
    key << '|' << property->GetScalarOpacity(f)->GetMTime() << ','
        << scatterer_scene::RayCasterColour(property, f)->GetMTime() << ','
        << UnitDistance(property, f);
  };
  vtkVolumeProperty* property = vol->GetProperty();
  if (plan.Parts.empty())
  {
    for (int f = 0; f < FunctionCount(t); ++f)
    {
      addFunctions(property, f);
    }
    for (int c = 0; c < t.Components; ++c)
    {
      key << '|' << this->ReadTexture->ScalarRange[c][0] << ','
          << this->ReadTexture->ScalarRange[c][1];
    }
  }
  for (size_t k = 0; k < plan.Parts.size(); ++k)
  {
    addFunctions(plan.Parts[k].Volume->GetProperty(), 0);
    key << '|' << this->PartTextures[k]->ScalarRange[0][0] << ','
        << this->PartTextures[k]->ScalarRange[0][1];
  }
  if (plan.Transfer2D)
  {
    vtkImageData* table = property->GetTransferFunction2D();
    key << "|2d:" << table << ',' << table->GetMTime() << ',' << plan.SampleDistance;
  }
  if (plan.GradientOpacity)
  {
    key << "|gradient opacity:" << property->GetGradientOpacity(0)->GetMTime() << ','
        << plan.SampleDistance;
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
  return key.Key();
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
      t.ComponentMode = plan.Transfer2D || plan.GradientOpacity ? TransportInputs::Transfer2D
                                                                : TransportInputs::OneScalar;
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

void TransportUpdate::UpdateGeometry(vtkVolume* vol, const FramePlan& plan)
{
  vtkScattererTransportVolume::Inputs& t = this->Inputs;
  vtkNew<vtkMatrix4x4> texToIndex, texToDataset, texToWorld;
  TextureToDataset(plan.Image, plan.CellFlag, t.Volume, texToDataset, texToIndex);
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix(), texToDataset, texToWorld);
  int extent[6];
  plan.Image->GetExtent(extent);
  for (int a = 0; a < 3; ++a)
  {
    t.IndexOrigin[a] = extent[2 * a];
  }
  for (int i = 0; i < 16; ++i)
  {
    t.TexToWorld[i] = texToWorld->GetElement(i / 4, i % 4);
    t.TexToDataset[i] = texToDataset->GetElement(i / 4, i % 4);
    t.TexToIndex[i] = texToIndex->GetElement(i / 4, i % 4);
  }
}

void TransportUpdate::UpdateClipping(
  const TransportSource& source, const IlluminationParameters& parameters, bool multiVolume)
{
  vtkScattererTransportVolume::Inputs& t = this->Inputs;
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
  t.Cropping = source.Cropping && !parameters.CroppedMatterCastsShadows && !multiVolume;
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
  // before this frame rendered; they must be this frame's (a directional light's by its
  // direction alone, as the exchange keys it: a headlight moves with a pan).
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
      same = a.Positional
        ? std::abs(a.Position[c] - out[l].Position[c]) <= 1e-5f * (1.0f + std::abs(a.Position[c]))
        : std::abs(a.Toward[c] - out[l].Toward[c]) <= 1e-5f;
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
  const IlluminationParameters& parameters, const TemplateCache& templates)
{
  TransportInputs& t = this->Inputs;
  // The ScalarOpacityUnitDistance each material's extinction is per.
  std::vector<double> units(plan.Materials.Materials.size(), 1.0);
  if (!plan.Parts.empty())
  {
    this->UpdatePartTables(plan);
    for (const auto& part : plan.Parts)
    {
      std::fill_n(units.begin() + part.FirstMaterial, part.MaterialCount,
        UnitDistance(part.Volume->GetProperty(), 0));
    }
  }
  else
  {
    this->UpdateVolumeTables(vol, plan);
    std::fill(units.begin(), units.end(),
      UnitDistance(vol->GetProperty(), FunctionCount(t) > 1 ? t.MaterialComponent : 0));
  }
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
    const double sigma = scatterer::extinctionFromOpacity(material.OpacityPerUnit, units[m]);
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

void TransportUpdate::UpdatePartTables(const FramePlan& plan)
{
  // Row k of the medium and of the material table: input k's functions over its own
  // texture's range (as VTK's tables span it); its materials numbered after the
  // inputs' before it.
  TransportInputs& t = this->Inputs;
  const int rows = static_cast<int>(plan.Parts.size());
  t.MediumRows = rows;
  t.MaterialRows = rows;
  t.Medium.assign(static_cast<size_t>(4) * kMediumTableSize * rows, 0.0f);
  t.MaterialTable.assign(static_cast<size_t>(kMediumTableSize) * rows, -1.0f);
  for (int k = 0; k < rows; ++k)
  {
    const FramePlan::Part& part = plan.Parts[k];
    const float* range = this->PartTextures[k]->ScalarRange[0];
    TabulateRow(t.Medium.data() + static_cast<size_t>(4) * kMediumTableSize * k,
      part.Volume->GetProperty(), 0, range);
    scatterer_scene::MaterialSet own;
    own.Materials.assign(plan.Materials.Materials.begin() + part.FirstMaterial,
      plan.Materials.Materials.begin() + part.FirstMaterial + part.MaterialCount);
    const double tableRange[2] = { range[0], range[1] };
    const std::vector<float> table =
      scatterer_scene::MaterialTable(own, tableRange, kMediumTableSize);
    for (int i = 0; i < kMediumTableSize; ++i)
    {
      t.MaterialTable[static_cast<size_t>(kMediumTableSize) * k + i] =
        table[i] >= 0.0f ? table[i] + static_cast<float>(part.FirstMaterial) : -1.0f;
    }
  }
}

void TransportUpdate::UpdateVolumeTables(vtkVolume* vol, const FramePlan& plan)
{
  TransportInputs& t = this->Inputs;
  const float(*ranges)[2] = this->ReadTexture->ScalarRange;
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
    case TransportInputs::Transfer2D: // over (scalar, gradient magnitude)
      if (plan.Transfer2D)            // its own table
      {
        TabulateTransfer2D(
          property->GetTransferFunction2D(), plan.SampleDistance, t.Medium, t.MediumRows);
      }
      else // the 1D functions and the gradient opacity
      {
        std::vector<float> oneScalar(static_cast<size_t>(4) * kGradientOpacityColumns);
        TabulateRow(oneScalar.data(), property, 0, ranges[0], kGradientOpacityColumns);
        t.MediumRows = kGradientOpacityRows;
        TabulateGradientOpacity(oneScalar.data(), kGradientOpacityColumns,
          property->GetGradientOpacity(0), static_cast<double>(ranges[0][1]) - ranges[0][0],
          plan.SampleDistance, t.MediumRows, t.Medium);
      }
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
      TabulateMedium(row(label), property->GetLabelColor(label), labelOpacity, lo, hi, unit);
    }
  }
  const double tableRange[2] = { lo, hi };
  t.MaterialTable = scatterer_scene::MaterialTable(plan.Materials, tableRange, kMediumTableSize);
  t.MaterialRows = 1;
}

void TransportUpdate::ReleaseGraphicsResources(vtkWindow* window)
{
  this->WholeVolume->ReleaseGraphicsResources(window);
  this->WholeVolumeKey.Clear();
  this->Transport->ReleaseGraphicsResources(window);
  this->Mask.ReleaseGraphicsResources(window);
}
}
