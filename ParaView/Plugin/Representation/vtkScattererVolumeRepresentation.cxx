#include "vtkScattererVolumeRepresentation.h"

#include "ScattererChangeKey.h"
#include "vtkAbstractMapper.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkMultiProcessController.h"
#include "vtkPVRenderView.h"
#include "vtkPVView.h"
#include "vtkRenderer.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkScalarsToColors.h"
#include "vtkScattererLightExchange.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererTransportVolume.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <iterator>

vtkStandardNewMacro(vtkScattererVolumeRepresentation);

namespace
{
// Enough for any reach on any volume a piece can hold; keeps the int conversion sane.
constexpr int kMaxGhostLevels = 4096;
// vtkSmartVolumeMapper's default InteractiveUpdateRate: ParaView's render view asks for
// 5 frames per second while the user drags and 0.002 for still frames.
constexpr double kInteractiveUpdateRate = 1.0;
// How far, in voxels, the cropping plane between two pieces moves off their shared point
// layer (UpdateMapperParameters): far above the rounding of texture coordinates along a
// ray, far below anything a picture shows.
constexpr double kBorderShift = 0.01;

// The cropping plane to give VTK 9.1's ray caster so that it crops point data at `x`
// along an axis of `n` points, the first at `x0`, `s` apart. The ray caster takes the
// planes to texture coordinates by the dataset's texture matrix, which spans the points
// (t = (x - x0) / ((n - 1) s)), but compares them with the samples' coordinates, which
// span the texels, half a voxel more on each side ((x - x0 + s / 2) / (n s)): a plane
// given at c crops at c + (c - x0) / (n - 1) - s / 2. Inverted here.
double PointDataCroppingPlane(double x, double x0, double s, int n)
{
  return n > 1 ? x0 + (n - 1.0) / n * (x - x0 + 0.5 * s) : x;
}
}

vtkScattererVolumeRepresentation::vtkScattererVolumeRepresentation()
  : VectorInputKey(new scatterer_render::ChangeKey)
{
  auto mapper = vtkSmartPointer<vtkScattererTemplateVolumeMapper>::New();
  // As ParaView's own image volume mapper renders still frames (vtkMultiBlockVolume-
  // Mapper -> vtkSmartVolumeMapper -> GPU mapper): jittered ray starts and the fixed
  // sample distance, so "Scatterer Volume" with illumination off looks as "Volume".
  mapper->UseJitteringOn();
  mapper->AutoAdjustSampleDistancesOff();
  // ParaView's progress handler observes the representation (the proxy's object), not
  // the mapper that does the long work in the first frame.
  mapper->AddObserver(
    vtkCommand::ProgressEvent, this, &vtkScattererVolumeRepresentation::ForwardMapperProgress);
  this->LightExchange->SetController(vtkMultiProcessController::GetGlobalController());
  mapper->SetLightExchange(this->LightExchange);
  this->VolumeMapper = mapper;
}

bool vtkScattererVolumeRepresentation::AddToView(vtkView* view)
{
  auto* renderView = vtkPVRenderView::SafeDownCast(view);
  if (renderView && !this->ObservedRenderer)
  {
    // After ParaView's own StartEvent observers (priority 0), which synchronise the
    // camera across ranks: the exchange needs this frame's lights.
    this->ObservedRenderer = renderView->GetRenderer();
    this->ExchangeObserver = this->ObservedRenderer->AddObserver(
      vtkCommand::StartEvent, this, &vtkScattererVolumeRepresentation::ExchangeLight, -1.0f);
  }
  return this->Superclass::AddToView(view);
}

bool vtkScattererVolumeRepresentation::RemoveFromView(vtkView* view)
{
  auto* renderView = vtkPVRenderView::SafeDownCast(view);
  if (renderView && this->ObservedRenderer == renderView->GetRenderer())
  {
    this->ObservedRenderer->RemoveObserver(this->ExchangeObserver);
    this->ObservedRenderer = nullptr;
  }
  return this->Superclass::RemoveFromView(view);
}

void vtkScattererVolumeRepresentation::ExchangeLight(vtkObject*, unsigned long, void*)
{
  // Collective: the conditions are the same on every rank (the number of pieces, the
  // visibility, the settings, the view's rendering mode); a rank without a piece takes
  // part with none. Only when every rank renders this frame: without remote rendering
  // (a rank could not open its window) or distributed rendering, the others would wait
  // for it forever.
  auto* renderView = vtkPVRenderView::SafeDownCast(this->GetView());
  if (this->Pieces <= 1 || !this->GetVisibility() || !renderView ||
    !renderView->GetRemoteRenderingAvailable() ||
    !renderView->GetUseDistributedRenderingForRender())
  {
    return;
  }
  // What the mapper renders (the cache, or its array's component or magnitude).
  vtkImageData* piece = this->RendersOwnedPartOnly
    ? vtkImageData::SafeDownCast(this->VolumeMapper->GetInputDataObject(0, 0))
    : nullptr;
  // While the user drags, coarser maps, as the transport volume is then coarser too.
  vtkRenderWindow* window = renderView->GetRenderWindow();
  this->LightExchange->SetInteractive(
    window && window->GetDesiredUpdateRate() >= kInteractiveUpdateRate);
  this->LightExchange->Exchange(this->ObservedRenderer, this->Actor, this->GetScattererMapper(),
    piece, this->OwnedExtent, this->WholeExtent);
  this->LightExchangeInfo[0] = this->LightExchange->GetExchangeCount();
  this->LightExchangeInfo[1] = this->LightExchange->GetLastExchangeMilliseconds();
  this->LightExchangeInfo[2] = this->LightExchange->GetLastExchangeBytes();
}

void vtkScattererVolumeRepresentation::SetLightExchangeEnabled(int exchange)
{
  this->LightExchange->SetEnabled(exchange != 0);
  this->Modified();
}

void vtkScattererVolumeRepresentation::SetGhostLayers(int layers)
{
  layers = std::min(std::max(layers, -1), kMaxGhostLevels);
  if (layers != this->GhostLayers)
  {
    this->GhostLayers = layers;
    // Split data's pieces ask upstream again (RequestUpdateExtent) where the layers they
    // ask for change; otherwise re-executing would upload and redraw them for nothing.
    this->SettingChanged();
  }
}

int vtkScattererVolumeRepresentation::GhostLevelsFor(double reach) const
{
  if (this->GhostLayers >= 0)
  {
    return this->GhostLayers;
  }
  if (!(this->FinestSpacing > 0.0) || !(reach > 0.0))
  {
    return 0;
  }
  // One layer more than the reach: trilinear interpolation at the last owned voxel.
  const double levels = std::ceil(reach / this->FinestSpacing) + 1.0;
  return static_cast<int>(std::min(levels, static_cast<double>(kMaxGhostLevels)));
}

void vtkScattererVolumeRepresentation::SettingChanged()
{
  const bool otherGhosts = this->Pieces > 1 &&
    this->GhostLevelsFor(this->GetScattererMapper()->GetIlluminationReach(this->Spacing)) !=
      this->RequestedGhostLevels;
  if (otherGhosts)
  {
    this->MarkModified();
  }
  else
  {
    this->Modified();
  }
}

double* vtkScattererVolumeRepresentation::GetLightExchangeInfo()
{
  this->LightExchangeInfo[3] = this->GetScattererMapper()->GetLightExchangeUsed() ? 1.0 : 0.0;
  return this->LightExchangeInfo;
}

void vtkScattererVolumeRepresentation::ForwardMapperProgress(
  vtkObject* caller, unsigned long, void* callData)
{
  // Only the illumination's reports carry a text: the 0 and 1 of the mapper's own
  // pipeline runs (every few frames) would make the progress bar flicker.
  auto* mapper = vtkAlgorithm::SafeDownCast(caller);
  if (!mapper || !mapper->GetProgressText())
  {
    return;
  }
  // SetProgressText does not modify the algorithm (a render must not re-execute it).
  this->SetProgressText(mapper->GetProgressText());
  this->UpdateProgress(*static_cast<double*>(callData));
  this->SetProgressText(nullptr);
}

vtkScattererVolumeRepresentation::~vtkScattererVolumeRepresentation() = default;

vtkScattererTemplateVolumeMapper* vtkScattererVolumeRepresentation::GetScattererMapper()
{
  return vtkScattererTemplateVolumeMapper::SafeDownCast(this->VolumeMapper);
}

// Each setter changes the mapper only; the transport volume and shader notice the
// change themselves, and ParaView renders the view again as for any property of a
// representation. MarkModified (which makes ParaView hand the mapper the data again,
// uploaded again, the light's medium redrawn: 1.5-1.9 s on the CT head for a switch the
// transport does not read) only where the pieces must ask for other ghost layers.
#define vtkScattererForward(name, type)                                                            \
  void vtkScattererVolumeRepresentation::Set##name(type value)                                     \
  {                                                                                                \
    this->GetScattererMapper()->Set##name(value);                                                  \
    this->SettingChanged();                                                                        \
  }
vtkScattererForward(IlluminationEnabled, bool);
vtkScattererForward(ShadowsEnabled, bool);
vtkScattererForward(ColorBleedingEnabled, bool);
vtkScattererForward(ThinPartCheckEnabled, bool);
vtkScattererForward(BoundaryRefractionEnabled, bool);
vtkScattererForward(TemplateBlendingEnabled, bool);
vtkScattererForward(IlluminationMode, int);
vtkScattererForward(TransportScale, int);
vtkScattererForward(InteractiveTransportScale, int);
vtkScattererForward(MaximumTransportVoxels, int);
vtkScattererForward(MultipleScattering, double);
vtkScattererForward(TemplateRadius, double);
vtkScattererForward(TemplatesPerMaterial, int);
vtkScattererForward(PhotonCap, int);
vtkScattererForward(OcclusionStrength, double);
vtkScattererForward(LongRangeMultiple, double);
vtkScattererForward(PhotonThreshold, double);
#undef vtkScattererForward

double* vtkScattererVolumeRepresentation::GetIlluminationBuildInfo()
{
  const vtkScattererTransportVolume* transport = this->GetScattererMapper()->GetTransportVolume();
  if (transport)
  {
    const vtkScattererTransportVolume::StageMilliseconds stages =
      transport->GetLastBuildStageMilliseconds();
    const double info[] = { static_cast<double>(transport->GetBuildCount()),
      static_cast<double>(transport->GetMediumBuildCount()), transport->GetLastBuildMilliseconds(),
      stages.Medium, stages.Sweeps, stages.Arriving, stages.Gather, stages.Diffusion };
    static_assert(sizeof(info) == sizeof(this->IlluminationBuildInfo), "one value each");
    std::copy(std::begin(info), std::end(info), this->IlluminationBuildInfo);
  }
  return this->IlluminationBuildInfo;
}

const char* vtkScattererVolumeRepresentation::GetShaderFeatures()
{
  return this->GetScattererMapper()->GetLastShaderFeatures().c_str();
}

void vtkScattererVolumeRepresentation::SetCropping(int cropping)
{
  this->UserCropping = cropping;
  this->Superclass::SetCropping(cropping);
}

int vtkScattererVolumeRepresentation::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  this->RequestedGhostLevels = 0;
  this->Pieces = 1;
  for (int i = 0; i < inputVector[0]->GetNumberOfInformationObjects(); ++i)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(i);
    using SDDP = vtkStreamingDemandDrivenPipeline;
    const int pieces = inInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES())
      ? inInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES())
      : 1;
    this->Pieces = std::max(this->Pieces, pieces);
    if (inInfo->Has(SDDP::WHOLE_EXTENT()))
    {
      inInfo->Get(SDDP::WHOLE_EXTENT(), this->WholeExtent);
    }
    // Every piece builds its transport volume at the scale of the whole volume
    // (MaximumTransportVoxels), so that the pieces' light matches.
    const int* w = this->WholeExtent;
    if (pieces > 1 && w[1] >= w[0] && w[3] >= w[2] && w[5] >= w[4])
    {
      this->GetScattererMapper()->SetWholeDimensions(
        w[1] - w[0] + 1, w[3] - w[2] + 1, w[5] - w[4] + 1);
    }
    else
    {
      this->GetScattererMapper()->SetWholeDimensions(0, 0, 0);
    }
    if (pieces <= 1 || !inInfo->Has(vtkDataObject::SPACING()))
    {
      continue;
    }
    const double* spacing = inInfo->Get(vtkDataObject::SPACING());
    std::copy(spacing, spacing + 3, this->Spacing);
    this->FinestSpacing =
      std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) });
    const int ghosts =
      this->GhostLevelsFor(this->GetScattererMapper()->GetIlluminationReach(spacing));
    if (ghosts == 0 && this->GhostLayers < 0)
    {
      continue;
    }
    const int upstream = inInfo->Has(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS())
      ? inInfo->Get(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS())
      : 0;
    inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), std::max(upstream, ghosts));
    this->RequestedGhostLevels = std::max(this->RequestedGhostLevels, ghosts);
  }
  return 1;
}

int vtkScattererVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The superclass caches the input without its ghost cells (its Cache and
  // DataBounds then describe the piece this rank owns).
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  this->RendersOwnedPartOnly = false;
  vtkImageData* input = inputVector[0]->GetNumberOfInformationObjects() == 1
    ? vtkImageData::GetData(inputVector[0], 0)
    : nullptr;
  auto* owned = vtkImageData::SafeDownCast(this->Cache);
  if (!input || !owned)
  {
    return 1;
  }
  if (!input->HasAnyGhostCells())
  {
    // A piece of split data without ghost layers (ScattererGhostLayers 0, or a source that
    // gives none) owns all it holds, and still takes part in the light exchange, which
    // needs the part it owns: without it each piece was lit through its own voxels only.
    if (this->Pieces > 1)
    {
      owned->GetBounds(this->OwnedBounds);
      owned->GetExtent(this->OwnedExtent);
      this->RendersOwnedPartOnly = true;
    }
    return 1;
  }
  // Keep the ghost layers for the illumination; render only the owned bounds.
  owned->GetBounds(this->OwnedBounds);
  owned->GetExtent(this->OwnedExtent);
  vtkSmartPointer<vtkImageData> ghosted = vtkSmartPointer<vtkImageData>::New();
  ghosted->ShallowCopy(input);
  // A source keeps the ghost layers of an earlier, larger request (GhostLayers lowered
  // after a render): only those asked for now are kept, the memory of the rest let go.
  int keep[6];
  const int* has = input->GetExtent();
  for (int i = 0; i < 6; ++i)
  {
    const int wanted = this->OwnedExtent[i] + (i % 2 ? 1 : -1) * this->RequestedGhostLevels;
    keep[i] = i % 2 ? std::min(has[i], wanted) : std::max(has[i], wanted);
  }
  if (!std::equal(keep, keep + 6, has))
  {
    ghosted->Crop(keep);
  }
  // The ghost flags are for the superclass's crop above; the ray caster must see
  // every voxel as data (the cropping planes below do the hiding).
  ghosted->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  ghosted->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  if (this->UseSeparateOpacityArray)
  {
    this->AppendOpacityComponent(ghosted);
  }
  this->VolumeMapper->SetInputData(ghosted);
  this->Cache = ghosted;
  this->DataSize = ghosted->GetActualMemorySize();
  this->RendersOwnedPartOnly = true;
  return 1;
}

/*
 * ParaView colours a multi-component array whose components are mapped independently
 * (MapScalars on, MultiComponentsMapping off) by one component or by its magnitude, as
 * its lookup table's vector mode says; its Volume hands that to vtkSmartVolumeMapper
 * (vtkImageVolumeRepresentation::UpdateMapperParameters), which this representation's
 * mapper is not: the raw components rendered as independent ones, whatever component
 * the user chose. The mapper gets the image with that array as the chosen component, or
 * the magnitude, alone, under its own name; remade only when the data or the choice
 * changes.
 */
namespace
{
// Whether @p a and @p b hold the same arrays on the same extent: the view's delivered
// copy of the cache (several ranks) rather than another time step's data.
bool SameData(vtkImageData* a, vtkImageData* b)
{
  const int* ea = a->GetExtent();
  const int* eb = b->GetExtent();
  if (!std::equal(ea, ea + 6, eb))
  {
    return false;
  }
  const auto same = [](vtkDataSetAttributes* x, vtkDataSetAttributes* y)
  {
    if (x->GetNumberOfArrays() != y->GetNumberOfArrays())
    {
      return false;
    }
    for (int i = 0; i < x->GetNumberOfArrays(); ++i)
    {
      if (x->GetAbstractArray(i) != y->GetAbstractArray(i))
      {
        return false;
      }
    }
    return true;
  };
  return same(a->GetPointData(), b->GetPointData()) && same(a->GetCellData(), b->GetCellData());
}
}

vtkImageData* vtkScattererVolumeRepresentation::DeliveredPiece()
{
  vtkDataObject* connected = this->VolumeMapper->GetInputDataObject(0, 0);
  if (connected && connected == this->VectorInput)
  {
    return this->VectorSource;
  }
  auto* cache = vtkImageData::SafeDownCast(this->Cache);
  auto* image = vtkImageData::SafeDownCast(connected);
  // The view's copy of the cache is the cache: the mapper keeps the one object (another
  // object, the same data, would be uploaded and its light built again).
  if (!image || (cache && SameData(image, cache)))
  {
    return cache;
  }
  return image;
}

void vtkScattererVolumeRepresentation::UpdateMapperInput()
{
  vtkImageData* image = this->DeliveredPiece();
  vtkVolumeMapper* mapper = this->VolumeMapper;
  vtkColorTransferFunction* colors =
    this->Property ? this->Property->GetRGBTransferFunction(0) : nullptr;
  int cellFlag = 0;
  vtkDataArray* array = image && colors && this->Property->GetIndependentComponents()
    ? vtkAbstractMapper::GetScalars(image, mapper->GetScalarMode(), mapper->GetArrayAccessMode(),
        mapper->GetArrayId(), mapper->GetArrayName(), cellFlag)
    : nullptr;
  const int components = array ? array->GetNumberOfComponents() : 0;
  if (components < 2 || !array->GetName())
  {
    this->VectorInput = nullptr;
    this->VectorSource = nullptr;
    this->VectorInputKey->Clear();
    if (image && mapper->GetInputDataObject(0, 0) != image)
    {
      mapper->SetInputDataObject(image);
    }
    return;
  }
  const bool magnitude = colors->GetVectorMode() == vtkScalarsToColors::MAGNITUDE;
  const int component = std::min(std::max(colors->GetVectorComponent(), 0), components - 1);
  scatterer_render::KeyWriter writer;
  writer << static_cast<const void*>(image) << '|' << image->GetMTime() << '|' << array->GetMTime()
         << '|' << array->GetName() << '|' << cellFlag << '|' << (magnitude ? -1 : component);
  const std::string key = writer.Key();
  if (this->VectorInputKey->Differs(key))
  {
    vtkSmartPointer<vtkDataArray> one;
    one.TakeReference(magnitude ? vtkDataArray::CreateDataArray(VTK_FLOAT) : array->NewInstance());
    one->SetName(array->GetName());
    one->SetNumberOfComponents(1);
    one->SetNumberOfTuples(array->GetNumberOfTuples());
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
    {
      if (magnitude)
      {
        double squared = 0.0;
        for (int c = 0; c < components; ++c)
        {
          const double v = array->GetComponent(t, c);
          squared += v * v;
        }
        one->SetTuple1(t, std::sqrt(squared));
      }
      else
      {
        one->SetTuple1(t, array->GetComponent(t, component));
      }
    }
    this->VectorInput = vtkSmartPointer<vtkImageData>::New();
    this->VectorInput->ShallowCopy(image);
    vtkDataSetAttributes* attributes = cellFlag
      ? static_cast<vtkDataSetAttributes*>(this->VectorInput->GetCellData())
      : static_cast<vtkDataSetAttributes*>(this->VectorInput->GetPointData());
    attributes->RemoveArray(array->GetName());
    attributes->AddArray(one);
    this->VectorSource = image;
    this->VectorInputKey->Record(key);
  }
  if (mapper->GetInputDataObject(0, 0) != this->VectorInput)
  {
    mapper->SetInputDataObject(this->VectorInput);
  }
}

void vtkScattererVolumeRepresentation::UpdateMapperParameters()
{
  // The superclass sets the user's cropping planes when cropping is on.
  this->VolumeMapper->SetCropping(this->UserCropping);
  this->Superclass::UpdateMapperParameters();
  this->UpdateMapperInput();
  // Coarser sampling while dragging, as "Volume" does (see the class comment). Called
  // for every render (REQUEST_RENDER), after the view set the window's update rate.
  auto* view = vtkPVView::SafeDownCast(this->GetView());
  vtkRenderWindow* window = view ? view->GetRenderWindow() : nullptr;
  this->GetScattererMapper()->SetAutoAdjustSampleDistances(
    window && window->GetDesiredUpdateRate() >= kInteractiveUpdateRate ? 1 : 0);
  // Materials come from the opacity transfer function over its own range, which
  // ParaView keeps the same on every rank (the whole data range unless the user
  // chose another): every piece then derives the materials the whole volume would,
  // where each piece's own data range would not.
  vtkPiecewiseFunction* opacity = this->Property ? this->Property->GetScalarOpacity() : nullptr;
  if (opacity && opacity->GetSize() > 0)
  {
    double range[2];
    opacity->GetRange(range);
    this->GetScattererMapper()->SetMaterialDerivationRange(range[0], range[1]);
  }
  else
  {
    this->GetScattererMapper()->ClearMaterialDerivationRange();
  }
  // Cropping to the owned part hides the ghost layers, which must still carry light
  // (they lie between the light and the owned voxels). With the user's cropping too,
  // the cropped-away matter then casts shadows as well (docs/paraview.md).
  this->GetScattererMapper()->SetCroppedMatterCastsShadows(this->RendersOwnedPartOnly);
  if (!this->RendersOwnedPartOnly)
  {
    return;
  }
  double planes[6];
  std::copy(this->OwnedBounds, this->OwnedBounds + 6, planes);
  // Neighbouring pieces share the plane between them (the point layer both hold), and
  // must crop exactly there, each from its own texture. As given, VTK 9.1 cropped point
  // data off the plane by an amount that grows with the distance from the piece's first
  // point (PointDataCroppingPlane), different in the two pieces: rays within a quarter of
  // a voxel of the plane were composited by both, a bright line one pixel wide where a
  // view along an axis met the border (the long-shadow scene, 4 ranks: 41 levels of 255
  // against 33). The planes are corrected for that, and both pieces move the plane by the
  // same hundredth of a voxel, so that a ray that runs in it lies well inside one piece
  // whatever the rounding. (The volume's outer faces keep their planes.)
  vtkImageData* piece = this->DeliveredPiece();
  if (!piece)
  {
    return;
  }
  const double* spacing = piece->GetSpacing();
  const double* pieceBounds = piece->GetBounds();
  int dims[3];
  piece->GetDimensions(dims);
  const int mode = this->VolumeMapper->GetScalarMode();
  const bool pointData =
    mode != VTK_SCALAR_MODE_USE_CELL_DATA && mode != VTK_SCALAR_MODE_USE_CELL_FIELD_DATA;
  for (int i = 0; i < 6; ++i)
  {
    const int axis = i / 2;
    const bool interior = i % 2 == 0 ? this->OwnedExtent[i] > this->WholeExtent[i]
                                     : this->OwnedExtent[i] < this->WholeExtent[i];
    if (interior)
    {
      const double x = this->OwnedBounds[i] + kBorderShift * spacing[axis];
      planes[i] =
        pointData ? PointDataCroppingPlane(x, pieceBounds[2 * axis], spacing[axis], dims[axis]) : x;
    }
  }
  if (this->UserCropping)
  {
    const double* user = this->VolumeMapper->GetCroppingRegionPlanes();
    for (int axis = 0; axis < 3; ++axis)
    {
      planes[2 * axis] = std::max(planes[2 * axis], user[2 * axis]);
      planes[2 * axis + 1] =
        std::max(planes[2 * axis], std::min(planes[2 * axis + 1], user[2 * axis + 1]));
    }
  }
  this->VolumeMapper->SetCropping(1);
  this->VolumeMapper->SetCroppingRegionFlagsToSubVolume();
  this->VolumeMapper->SetCroppingRegionPlanes(planes);
}

void vtkScattererVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GhostLayers: " << this->GhostLayers
     << (this->GhostLayers < 0 ? " (automatic: the illumination reach)" : "") << "\n";
  os << indent << "RequestedGhostLevels: " << this->RequestedGhostLevels << "\n";
  os << indent << "UserCropping: " << this->UserCropping << "\n";
  os << indent << "RendersOwnedPartOnly: " << this->RendersOwnedPartOnly << "\n";
  if (this->RendersOwnedPartOnly)
  {
    os << indent << "OwnedBounds: (" << this->OwnedBounds[0] << ", " << this->OwnedBounds[1] << ", "
       << this->OwnedBounds[2] << ", " << this->OwnedBounds[3] << ", " << this->OwnedBounds[4]
       << ", " << this->OwnedBounds[5] << ")\n";
  }
  os << indent << "Pieces: " << this->Pieces << "\n";
  os << indent << "LightExchange:\n";
  this->LightExchange->PrintSelf(os, indent.GetNextIndent());
  os << indent << "ScattererMapper:\n";
  this->VolumeMapper->PrintSelf(os, indent.GetNextIndent());
}
