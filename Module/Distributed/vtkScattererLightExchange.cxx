#include "vtkScattererLightExchange.h"

#include "ScattererChangeKey.h"
#include "ScattererSceneLights.h"
#include "ScattererTransportUpdate.h"
#include "ScattererWarnOnce.h"
#include "vtkScattererTemplateVolumeMapper.h"

#include "vtkAbstractMapper.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <scatterer/LightSpace.h>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkScattererLightExchange);
vtkCxxSetObjectMacro(vtkScattererLightExchange, Controller, vtkMultiProcessController);

namespace ls = scatterer::lightspace;

namespace
{
// The largest map side: 1024^2 x 4 bytes per light and rank.
constexpr int kMaxMapSize = 1024;
// Steps along a line, in map texels (one voxel for still frames).
constexpr double kStep = 1.0;
// Per rank in the header AllGather: holds a piece, owned box (6), lights, floats.
constexpr int kHeader = 9;

// Structured index -> world, for one image in its volume: world = A i + b.
struct IndexFrame
{
  glm::dmat3 A{ 1.0 };
  glm::dvec3 b{ 0.0 };
  bool Valid = false;
};

IndexFrame FrameOf(vtkImageData* image, vtkVolume* volume)
{
  IndexFrame f;
  double indexToPhysical[16];
  image->ComputeIndexToPhysicalMatrix(image->GetOrigin(), image->GetSpacing(),
    image->GetDirectionMatrix()->GetData(), indexToPhysical);
  vtkNew<vtkMatrix4x4> indexToWorld;
  vtkMatrix4x4::Multiply4x4(
    volume->GetMatrix()->GetData(), indexToPhysical, indexToWorld->GetData());
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      f.A[c][r] = indexToWorld->GetElement(r, c); // glm: column-major
    }
    f.b[r] = indexToWorld->GetElement(r, 3);
  }
  f.Valid = std::abs(glm::determinant(f.A)) > 0.0;
  return f;
}

// The light-space map of one light, the same on every rank (it depends on the light,
// the whole volume and the settings only).
ls::Map MapOf(const vtkScattererTransportVolume::Light& light, const IndexFrame& frame,
  const ls::Box& whole, double texel)
{
  const glm::dmat3 toIndex = glm::inverse(frame.A);
  if (light.Positional)
  {
    const glm::dvec3 p(light.Position[0], light.Position[1], light.Position[2]);
    const glm::dvec3 extent = whole.hi - whole.lo;
    const double longest = std::max({ extent.x, extent.y, extent.z });
    const int size = std::min(kMaxMapSize, std::max(64, static_cast<int>(2.0 * longest / texel)));
    return ls::positionalMap(toIndex * (p - frame.b), size);
  }
  const glm::dvec3 toward(light.Toward[0], light.Toward[1], light.Toward[2]);
  return ls::directionalMap(toIndex * toward, whole, texel, kMaxMapSize);
}

// Scalars normalised over [lo, lo + span], as the transport's passes read them.
template <typename T>
void Normalise(const T* scalars, vtkIdType n, double lo, double span, float* out)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    out[i] = static_cast<float>((static_cast<double>(scalars[i]) - lo) / span);
  }
}

// Cell values (cells `cells` per axis, x fastest) averaged onto the points of an image of
// `dims` points: each point takes the mean of the up to 8 cells around it. The extinction
// grid holds values at points; a map one voxel fine then blurs a shadow's edge by half a
// voxel more than point data's.
std::vector<float> CellsOntoPoints(const std::vector<float>& cell, const int dims[3])
{
  int cells[3];
  for (int a = 0; a < 3; ++a)
  {
    cells[a] = std::max(dims[a] - 1, 1);
  }
  std::vector<float> point(static_cast<size_t>(dims[0]) * dims[1] * dims[2]);
  size_t p = 0;
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i, ++p)
      {
        double sum = 0.0;
        int count = 0;
        for (int ck = std::max(k - 1, 0); ck <= std::min(k, cells[2] - 1); ++ck)
        {
          for (int cj = std::max(j - 1, 0); cj <= std::min(j, cells[1] - 1); ++cj)
          {
            for (int ci = std::max(i - 1, 0); ci <= std::min(i, cells[0] - 1); ++ci)
            {
              sum += cell[static_cast<size_t>(ci) +
                cells[0] * (cj + static_cast<size_t>(cells[1]) * ck)];
              ++count;
            }
          }
        }
        point[p] = static_cast<float>(sum / count);
      }
    }
  }
  return point;
}

ls::Box BoxOf(const int extent[6])
{
  ls::Box b;
  b.lo = glm::dvec3(extent[0], extent[2], extent[4]);
  b.hi = glm::dvec3(extent[1], extent[3], extent[5]);
  return b;
}
}

struct vtkScattererLightExchange::vtkInternals
{
  explicit vtkInternals(vtkObject* owner)
    : Warn(owner)
  {
  }
  scatterer_render::WarnOnce Warn;
  scatterer_render::ChangeKey Inputs; // of the last exchange
  scatterer_render::ChangeKey Sigma;  // of the extinction grid
  ls::ExtinctionGrid Grid;

  /** The extinction grid of @p piece: its scalars normalised over their range (cell
   * scalars averaged onto the points), and sigma_t x OcclusionStrength per world unit
   * tabulated over them (@p occlusion 0: no shadows). False if the piece has no
   * single-component scalars the mapper would render. @p key: what the grid was made
   * from. */
  bool UpdateGrid(vtkImageData* piece, vtkVolume* volume, vtkScattererTemplateVolumeMapper* mapper,
    float occlusion, std::string& key);
};

bool vtkScattererLightExchange::vtkInternals::UpdateGrid(vtkImageData* piece, vtkVolume* volume,
  vtkScattererTemplateVolumeMapper* mapper, float occlusion, std::string& key)
{
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(piece, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  vtkVolumeProperty* property = volume->GetProperty();
  vtkPiecewiseFunction* opacity = property ? property->GetScalarOpacity(0) : nullptr;
  if (!scalars || cellFlag == 2 || scalars->GetNumberOfComponents() != 1 || !opacity ||
    (cellFlag == 1 && scalars->GetNumberOfTuples() != piece->GetNumberOfCells()))
  {
    return false;
  }
  const double unit = property->GetScalarOpacityUnitDistance(0) > 0.0
    ? property->GetScalarOpacityUnitDistance(0)
    : 1.0;
  scatterer_render::KeyWriter k;
  k << piece->GetMTime() << '|' << scalars->GetMTime() << '|' << cellFlag << '|'
    << opacity->GetMTime() << '|' << unit << '|' << occlusion;
  key = k.Key();
  if (!this->Sigma.Differs(key))
  {
    return true;
  }
  // Scalars normalised over their range, and sigma_t tabulated over it: the grid
  // interpolates the scalar and then looks sigma_t up, as the transport's passes do.
  double range[2];
  scalars->GetRange(range, 0);
  const double span = range[1] > range[0] ? range[1] - range[0] : 1.0;
  ls::ExtinctionGrid& grid = this->Grid;
  // The transport's own medium table (its fourth channel is sigma_t).
  std::vector<float> medium(4 * static_cast<size_t>(scatterer_render::kMediumTableSize));
  scatterer_render::TabulateMedium(
    medium.data(), nullptr, opacity, range[0], range[0] + span, unit);
  grid.table.resize(scatterer_render::kMediumTableSize);
  for (size_t i = 0; i < grid.table.size(); ++i)
  {
    grid.table[i] = occlusion * medium[4 * i + 3];
  }
  int extent[6], dims[3];
  piece->GetExtent(extent);
  piece->GetDimensions(dims);
  grid.origin = glm::ivec3(extent[0], extent[2], extent[4]);
  grid.dims = glm::ivec3(dims[0], dims[1], dims[2]);
  const vtkIdType n = scalars->GetNumberOfTuples();
  std::vector<float> normalised(static_cast<size_t>(n));
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(Normalise(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)), n, range[0],
      span, normalised.data()));
    default:
      for (vtkIdType i = 0; i < n; ++i)
      {
        normalised[static_cast<size_t>(i)] =
          static_cast<float>((scalars->GetComponent(i, 0) - range[0]) / span);
      }
  }
  grid.values = cellFlag == 1 ? CellsOntoPoints(normalised, dims) : std::move(normalised);
  grid.prepare();
  this->Sigma.Record(key);
  return true;
}

vtkScattererLightExchange::vtkScattererLightExchange()
  : Internals(new vtkInternals(this))
{
}

vtkScattererLightExchange::~vtkScattererLightExchange()
{
  this->SetController(nullptr);
}

void vtkScattererLightExchange::Exchange(vtkRenderer* renderer, vtkVolume* volume,
  vtkScattererTemplateVolumeMapper* mapper, vtkImageData* piece, const int owned[6],
  const int whole[6])
{
  vtkMultiProcessController* controller = this->Controller;
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  // Everything that decides whether to take part is the same on every rank (the
  // settings and the scene), so every rank returns here, or none does.
  if (ranks < 2 || !this->Enabled || !renderer || !volume || !mapper ||
    !mapper->GetIlluminationEnabled() ||
    mapper->GetIlluminationMode() != vtkScattererTemplateVolumeMapper::TRANSPORT)
  {
    this->Current = Result();
    this->Internals->Inputs.Clear();
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  // The lights of this frame, as the mapper will collect them (headlights and camera
  // lights follow the camera, which is set by now).
  renderer->UpdateLightsGeometryToFollowCamera();
  const scatterer_scene::LightSet set =
    scatterer_scene::CollectLights(renderer, volume->GetProperty());
  std::vector<vtkScattererTransportVolume::Light> lights(static_cast<size_t>(set.Count()));
  for (int l = 0; l < set.Count(); ++l)
  {
    for (int c = 0; c < 3; ++c)
    {
      lights[l].Toward[c] = set.Direction[3 * l + c];
      lights[l].Position[c] = set.Position[3 * l + c];
    }
    lights[l].Positional = set.Positional[l] != 0;
  }
  const float occlusion =
    mapper->GetShadowsEnabled() ? static_cast<float>(mapper->GetOcclusionStrength()) : 0.0f;
  std::string gridKey;
  const bool hasPiece = piece && piece->GetNumberOfPoints() > 0 &&
    this->Internals->UpdateGrid(piece, volume, mapper, occlusion, gridKey);
  if (piece && piece->GetNumberOfPoints() > 0 && !hasPiece)
  {
    this->Internals->Warn("The light exchange takes the volume's scalars as one component of "
                          "point or cell data: this piece's matter casts no shadow on the "
                          "other pieces beyond their ghost layers.");
  }
  const IndexFrame frame = hasPiece ? FrameOf(piece, volume) : IndexFrame();
  // Still frames: lines one voxel apart, since a coarser map blurs the edges of the
  // shadows it carries (a 2-voxel map doubled the error of the long-shadow test's
  // composite). Interactive frames: about as coarse as the transport volume is then, its
  // scale taken for cubic voxels: every rank must size the maps alike, and a rank
  // without a piece has no spacing to go by.
  const int wholeDims[3] = { whole[1] - whole[0] + 1, whole[3] - whole[2] + 1,
    whole[5] - whole[4] + 1 };
  const double cubic[3] = { 1.0, 1.0, 1.0 };
  const double texel = this->Interactive
    ? std::max(1, mapper->GetEffectiveTransportScale(wholeDims, cubic, true))
    : 1.0;

  // 1. Did anything change on any rank?
  scatterer_render::KeyWriter key;
  key << hasPiece << '|' << gridKey << '|' << texel;
  for (int a = 0; a < 6; ++a)
  {
    key << ',' << owned[a] << ',' << whole[a];
  }
  // A directional light's map is its direction's alone (MapOf): VTK's headlight and
  // ParaView's light kit move their positions with the camera, and zooming or panning
  // must not exchange again (each exchange also rebuilds every piece's light).
  for (const auto& l : lights)
  {
    key << '|' << l.Positional;
    if (l.Positional)
    {
      key << ',' << l.Position[0] << ',' << l.Position[1] << ',' << l.Position[2];
    }
    else
    {
      key << ',' << l.Toward[0] << ',' << l.Toward[1] << ',' << l.Toward[2];
    }
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      key << ',' << frame.A[c][r];
    }
    key << ',' << frame.b[r];
  }
  const int changed = this->Internals->Inputs.Differs(key.Key()) ? 1 : 0;
  std::vector<int> changes(static_cast<size_t>(ranks), 0);
  controller->AllGather(&changed, changes.data(), 1);
  if (std::find(changes.begin(), changes.end(), 1) == changes.end())
  {
    return; // the maps stand; LastExchange* still describe the exchange that made them
  }
  this->Internals->Inputs.Record(key.Key());

  // 2. The maps of this piece: the same lines on every rank.
  const ls::Box wholeBox = BoxOf(whole);
  std::vector<ls::Map> maps;
  size_t floats = 0;
  // Ranks without a piece do not know the frame; the ranks that do agree on it (one
  // image), and a rank without a piece sends zeros of the size the header says.
  if (hasPiece && frame.Valid)
  {
    for (const auto& l : lights)
    {
      maps.push_back(MapOf(l, frame, wholeBox, texel));
      floats += static_cast<size_t>(maps.back().size) * maps.back().size;
    }
  }
  const ls::Box ownedBox = hasPiece ? BoxOf(owned) : ls::Box();
  double header[kHeader] = { hasPiece && frame.Valid ? 1.0 : 0.0, ownedBox.lo.x, ownedBox.lo.y,
    ownedBox.lo.z, ownedBox.hi.x, ownedBox.hi.y, ownedBox.hi.z, static_cast<double>(lights.size()),
    static_cast<double>(floats) };
  std::vector<double> headers(static_cast<size_t>(kHeader) * ranks);
  controller->AllGather(header, headers.data(), kHeader);
  // Every rank sees every header, so all decide alike: the ranks with a piece must
  // agree on the lights and the map sizes.
  double agreed = -1.0;
  bool consistent = true;
  std::vector<ls::Box> boxes(static_cast<size_t>(ranks));
  for (int r = 0; r < ranks; ++r)
  {
    const double* h = headers.data() + static_cast<size_t>(kHeader) * r;
    if (h[0] == 0.0)
    {
      continue;
    }
    boxes[r].lo = glm::dvec3(h[1], h[2], h[3]);
    boxes[r].hi = glm::dvec3(h[4], h[5], h[6]);
    consistent =
      consistent && h[7] == static_cast<double>(lights.size()) && (agreed < 0.0 || h[8] == agreed);
    agreed = h[8];
  }
  if (!consistent || agreed <= 0.0)
  {
    if (!consistent)
    {
      vtkWarningMacro(<< "The ranks disagree on the lights or the volume's extent; each piece "
                         "is lit by its own voxels and ghost layers only.");
    }
    this->Current = Result();
    return;
  }
  // 3. This piece's depths per light, and the window of lines it crosses: all it sends.
  const size_t lightCount = lights.size();
  std::vector<int> windows(4 * lightCount, 0); // per light: x0, y0, width, height
  std::vector<float> sent;
  if (header[0] != 0.0)
  {
    const glm::dmat3 indexToWorld = frame.A;
    for (size_t l = 0; l < lightCount; ++l)
    {
      const std::vector<float> d =
        ls::opticalDepth(maps[l], this->Internals->Grid, ownedBox, indexToWorld, texel * kStep);
      const ls::DepthWindow w = ls::nonZeroWindow(d, maps[l].size);
      const std::vector<float> packed = ls::packWindow(w);
      sent.insert(sent.end(), packed.begin(), packed.end());
      if (!w.empty())
      {
        windows[4 * l] = w.x0;
        windows[4 * l + 1] = w.y0;
        windows[4 * l + 2] = w.width;
        windows[4 * l + 3] = w.height;
      }
    }
  }
  // 4. Everybody's windows, then their depths, and the sum of those in front of this
  // piece. Each rank receives the windows of the others: about P^(1/3) map areas in a
  // 3D split of P pieces, instead of (P - 1) whole maps.
  std::vector<int> allWindows(windows.size() * ranks);
  controller->AllGather(windows.data(), allWindows.data(), static_cast<vtkIdType>(windows.size()));
  std::vector<vtkIdType> lengths(static_cast<size_t>(ranks), 0), offsets(lengths);
  vtkIdType received = 0;
  for (int r = 0; r < ranks; ++r)
  {
    for (size_t l = 0; l < lightCount; ++l)
    {
      const int* w = allWindows.data() + 4 * (lightCount * r + l);
      lengths[r] += static_cast<vtkIdType>(w[2]) * w[3];
    }
    offsets[r] = received;
    received += lengths[r];
  }
  std::vector<float> all(static_cast<size_t>(std::max<vtkIdType>(received, 1)));
  controller->AllGatherV(
    sent.data(), all.data(), static_cast<vtkIdType>(sent.size()), lengths.data(), offsets.data());
  const int self = controller->GetLocalProcessId();
  this->LastExchangeBytes =
    static_cast<double>(received - lengths[static_cast<size_t>(self)]) * sizeof(float);
  Result result;
  result.Active = header[0] != 0.0;
  if (result.Active)
  {
    int reachExtent[6];
    piece->GetExtent(reachExtent);
    const ls::Box reach = BoxOf(reachExtent);
    std::vector<vtkIdType> at(offsets); // where each rank's next window starts
    for (size_t l = 0; l < lightCount; ++l)
    {
      const ls::Map& map = maps[l];
      std::vector<ls::DepthWindow> depths(static_cast<size_t>(ranks));
      for (int r = 0; r < ranks; ++r)
      {
        const int* w = allWindows.data() + 4 * (lightCount * r + l);
        if (!boxes[r].empty() && w[2] > 0 && w[3] > 0)
        {
          depths[r] = ls::DepthWindow{ all.data() + at[r], w[0], w[1], w[2], w[3], w[2] };
        }
        at[r] += static_cast<vtkIdType>(w[2]) * w[3];
      }
      auto entering = std::make_shared<vtkScattererTransportVolume::EnteringDepth>();
      entering->Positional = map.positional;
      entering->Size = map.size;
      entering->Side = static_cast<float>(map.texel * map.size);
      for (int c = 0; c < 3; ++c)
      {
        entering->Light[c] = static_cast<float>(map.light[c]);
        entering->U[c] = static_cast<float>(map.u[c]);
        entering->V[c] = static_cast<float>(map.v[c]);
      }
      entering->Lo[0] = static_cast<float>(map.lo.x);
      entering->Lo[1] = static_cast<float>(map.lo.y);
      entering->Depth = ls::enteringDepth(
        map, boxes, self, reach, depths, this->Internals->Grid, frame.A, texel * kStep);
      lights[l].Entering = entering;
    }
    result.Lights = lights;
  }
  this->Current = result;
  ++this->ExchangeCount;
  this->LastExchangeMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void vtkScattererLightExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "Enabled: " << (this->Enabled ? "On" : "Off") << "\n";
  os << indent << "Interactive: " << (this->Interactive ? "On" : "Off") << "\n";
  os << indent << "Active: " << (this->Current.Active ? "yes" : "no") << "\n";
  os << indent << "ExchangeCount: " << this->ExchangeCount << "\n";
  os << indent << "LastExchangeMilliseconds: " << this->LastExchangeMilliseconds << "\n";
  os << indent << "LastExchangeBytes: " << this->LastExchangeBytes << "\n";
}
