#include "ScattererTransportGrid.h"

#include "vtkMatrix3x3.h"
#include "vtkNew.h"

#include <scatterer/IlluminationSettings.h>

#include <algorithm>
#include <cmath>

namespace scatterer_gpu
{
namespace
{
void Multiply3(const double m[9], const double v[3], double out[3])
{
  for (int r = 0; r < 3; ++r)
  {
    out[r] = m[3 * r] * v[0] + m[3 * r + 1] * v[1] + m[3 * r + 2] * v[2];
  }
}
}

int FloorDiv(int a, int b)
{
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

void VoxelLengths(const int dims[3], const double texToWorld[16], double lengths[3])
{
  for (int a = 0; a < 3; ++a)
  {
    lengths[a] = std::sqrt(texToWorld[a] * texToWorld[a] + texToWorld[4 + a] * texToWorld[4 + a] +
                   texToWorld[8 + a] * texToWorld[8 + a]) /
      std::max(dims[a], 1);
  }
}

bool TransportGrid::Place(
  const int volumeDims[3], const int indexOrigin[3], int downsample, const double texToWorld[16])
{
  // Every ds-th structured index from index 0 (ds the axis's stride); one more at each
  // end covers the texture's edges.
  this->Downsample = std::max(1, downsample);
  VoxelLengths(volumeDims, texToWorld, this->Spacing);
  scatterer::illumination::transportStridesFor(this->Downsample, this->Spacing, this->Strides);
  for (int a = 0; a < 3; ++a)
  {
    const int ds = this->Strides[a];
    const int n = std::max(1, volumeDims[a]);
    const int e0 = indexOrigin[a];
    const int first = FloorDiv(e0, ds), last = FloorDiv(e0 + n - 1 + ds - 1, ds);
    this->Dims[a] = n < 2 ? 1 : last - first + 1;
    this->FirstIndex[a] = first;
    const int m = this->Dims[a];
    // Texel j sits at index first * ds + j * ds, texture coordinate (index - e0 + 0.5) / n.
    this->GridToTex[a] = m > 1 ? static_cast<double>(ds) / n : 0.0;
    this->GridToTexOffset[a] = m > 1 ? (first * ds - e0 + 0.5) / n : 0.5;
    // Light texture coordinate = (j + 0.5) / M with j = (t - offset) / scale.
    if (m > 1)
    {
      this->TexScale[a] = static_cast<float>(1.0 / (this->GridToTex[a] * m));
      this->TexOffset[a] =
        static_cast<float>((0.5 - this->GridToTexOffset[a] / this->GridToTex[a]) / m);
    }
    else
    {
      this->TexScale[a] = 0.0f;
      this->TexOffset[a] = 0.5f;
    }
    // A flat axis still needs a direction scale: one voxel.
    const double scale = m > 1 ? this->GridToTex[a] : 1.0 / n;
    for (int r = 0; r < 3; ++r)
    {
      this->GridToWorld[3 * r + a] = texToWorld[4 * r + a] * scale;
    }
  }
  for (int r = 0; r < 3; ++r)
  {
    this->GridOriginWorld[r] = texToWorld[4 * r + 3];
    for (int a = 0; a < 3; ++a)
    {
      this->GridOriginWorld[r] += texToWorld[4 * r + a] * this->GridToTexOffset[a];
    }
  }
  vtkNew<vtkMatrix3x3> inverse;
  for (int i = 0; i < 9; ++i)
  {
    inverse->SetElement(i / 3, i % 3, this->GridToWorld[i]);
  }
  const double determinant = inverse->Determinant();
  if (determinant == 0.0 || !std::isfinite(determinant))
  {
    return false;
  }
  inverse->Invert();
  for (int i = 0; i < 9; ++i)
  {
    this->WorldToGrid[i] = inverse->GetElement(i / 3, i % 3);
  }
  return true;
}

double TransportGrid::TexelLength(int a) const
{
  const double* g = this->GridToWorld;
  return std::sqrt(g[a] * g[a] + g[3 + a] * g[3 + a] + g[6 + a] * g[6 + a]);
}

void TransportGrid::GetPositionsOn(const TransportGrid& to, float scale[3], float offset[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    const double ratio = static_cast<double>(this->Strides[a]) / to.Strides[a];
    const bool flat = to.Dims[a] < 2;
    scale[a] = flat ? 0.0f : static_cast<float>(ratio);
    offset[a] = flat ? 0.0f : static_cast<float>(this->FirstIndex[a] * ratio - to.FirstIndex[a]);
  }
}

void TransportGrid::GetDims(float dims[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = static_cast<float>(this->Dims[a]);
  }
}

CoarseGrid CoarseGrid::Over(const TransportGrid& grid, int downsample, int stillDownsample)
{
  // A coarse texel spans diffusionVoxelsFor(s) volume voxels (of the shortest axis, along
  // an axis of long voxels: diffusionBlocksFor), s a still frame's transport scale. A coarse
  // texel's medium is the mean of its fine texels' (pass 0b; its albedo over the block grown by
  // half a block, scatterer_transport_coarsen.glsl); one point sample of the transfer
  // function standing for a whole block (transport scale 3 or more) let the diffusion pile the
  // bone's colour up into yellow-green blotches on the CT head, hence at least 2 fine texels a
  // block at a still frame's scale. A frame rendered while the user drags is built at a coarser
  // scale than s, and its coarse texels stay as large as a still frame's: blocks of 8 voxels (scale
  // 4 on the CT head, 2 fine texels a block) outweighed the skull, a few voxels thick, by the soft
  // tissue and air around it, and tinted the bone pink and mottled while the user dragged (ivory
  // when they let go). Such a frame's fine texels are then blocks of their own, and pass 0b
  // takes their medium as the mean of 2^3 points (Subsamples) instead of one, about as far
  // apart as a still frame's fine texels. A still frame's pass 0b keeps its texels'
  // centres, so that a volume resampled more finely, built coarser under
  // MaximumTransportVoxels, is lit as the original (2^3 points there moved the
  // 511x511x215 CT head away from it). Pass 0a takes a texel's medium over the points of
  // its mean extinction on every frame (scatterer_transport_medium.glsl).
  const int fine = std::max(1, downsample);
  const int still = stillDownsample > 0 ? stillDownsample : fine;
  CoarseGrid coarse;
  coarse.Subsamples = fine >= 2 * still ? 2 : 1;
  scatterer::illumination::diffusionBlocksFor(still, grid.Strides, grid.Spacing, coarse.Block);
  for (int a = 0; a < 3; ++a)
  {
    const int first = grid.FirstIndex[a];
    const int coarseFirst = FloorDiv(first, coarse.Block[a]);
    coarse.ToGrid[a] = coarse.Block[a] * coarseFirst - first;
    coarse.Dims[a] = FloorDiv(first + grid.Dims[a] - 1, coarse.Block[a]) - coarseFirst + 1;
  }
  coarse.AtlasColumns = AtlasColumnsFor(coarse.Dims, kAtlasMaxSide);
  return coarse;
}

int AtlasColumnsFor(const int dims[3], int maxSide)
{
  const long long layers = std::max(1, dims[2]);
  int best = 1;
  long long bestEmpty = 0, bestSide = 0;
  for (int columns = 1; columns <= layers; ++columns)
  {
    const long long rows = (layers + columns - 1) / columns;
    const long long empty = columns * rows - layers;
    const long long side = std::max(columns * static_cast<long long>(dims[0]), rows * dims[1]);
    const bool fits = side <= maxSide, bestFits = bestSide <= maxSide;
    const bool better = columns == 1 || (fits && !bestFits) ||
      (fits == bestFits &&
        (fits ? (empty < bestEmpty || (empty == bestEmpty && side < bestSide)) : side < bestSide));
    if (better)
    {
      best = columns;
      bestEmpty = empty;
      bestSide = side;
    }
  }
  return best;
}

void CoarseGrid::GetAtlasSize(int size[2]) const
{
  const int layers = std::max(1, this->Dims[2]);
  size[0] = this->AtlasColumns * this->Dims[0];
  size[1] = ((layers + this->AtlasColumns - 1) / this->AtlasColumns) * this->Dims[1];
}

void CoarseGrid::GetDims(float dims[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = static_cast<float>(this->Dims[a]);
  }
}

void CoarseGrid::GetToGrid(float toGrid[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    toGrid[a] = static_cast<float>(this->ToGrid[a]);
  }
}

CoarseUniforms::CoarseUniforms(const TransportGrid& grid, const CoarseGrid& coarse)
{
  coarse.GetDims(this->Dims);
  coarse.GetToGrid(this->ToGrid);
  for (int a = 0; a < 3; ++a)
  {
    this->H[a] = static_cast<float>(coarse.Block[a] * grid.TexelLength(a));
  }
  this->AtlasColumns = coarse.AtlasColumns;
}

void SweepPlan::GetSweepDims(const TransportGrid& grid, int dims[3]) const
{
  dims[0] = grid.Dims[this->Row];
  dims[1] = grid.Dims[this->Column];
  dims[2] = grid.Dims[this->Axis];
}

SweepPlan PlanSweep(const TransportGrid& grid, const vtkScattererTransportVolume::Light& light)
{
  SweepPlan plan;
  double toward[3];
  double lightGrid[3] = { 0, 0, 0 };
  if (light.Positional)
  {
    double rel[3];
    for (int a = 0; a < 3; ++a)
    {
      rel[a] = light.Position[a] - grid.GridOriginWorld[a];
    }
    Multiply3(grid.WorldToGrid, rel, lightGrid);
    for (int a = 0; a < 3; ++a)
    {
      toward[a] = lightGrid[a] - 0.5 * (grid.Dims[a] - 1);
    }
  }
  else
  {
    const double w[3] = { light.Toward[0], light.Toward[1], light.Toward[2] };
    Multiply3(grid.WorldToGrid, w, toward);
  }
  plan.Axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    if (std::abs(toward[a]) > std::abs(toward[plan.Axis]))
    {
      plan.Axis = a;
    }
  }
  plan.Row = plan.Axis == 0 ? 1 : 0;
  plan.Column = plan.Axis == 2 ? 1 : 2;
  const int n = grid.Dims[plan.Axis];
  if (light.Positional)
  {
    // The radial variant: away from the light's own slice, on both sides.
    const double k = lightGrid[plan.Axis];
    const int below = static_cast<int>(std::floor(std::min(k, n - 1.0)));
    if (below >= 0)
    {
      plan.Runs.emplace_back(below, 0);
    }
    const int above = static_cast<int>(std::max(std::floor(k) + 1.0, 0.0));
    if (above <= n - 1)
    {
      plan.Runs.emplace_back(above, n - 1);
    }
  }
  else if (toward[plan.Axis] > 0.0)
  {
    plan.Runs.emplace_back(n - 1, 0);
  }
  else
  {
    plan.Runs.emplace_back(0, n - 1);
  }
  return plan;
}

ExtinctionSampling ExtinctionSampling::For(int downsample)
{
  ExtinctionSampling sampling;
  sampling.StepSamples = std::max(1, downsample);
  sampling.MeanPoints = sampling.StepSamples > 1 ? 2 : 0;
  return sampling;
}

LightStep StepTowardLight(
  const TransportGrid& grid, const SweepPlan& plan, const vtkScattererTransportVolume::Light& light)
{
  const double w[3] = { light.Toward[0], light.Toward[1], light.Toward[2] };
  double g[3];
  Multiply3(grid.WorldToGrid, w, g);
  const double ds[3] = { g[plan.Row], g[plan.Column], g[plan.Axis] };
  const double along = std::max(std::abs(ds[2]), std::hypot(ds[0], ds[1]) / 4.0);
  LightStep step;
  for (int i = 0; i < 2; ++i)
  {
    step.Sweep[i] = ds[i] / std::max(along, 1.0e-20);
  }
  step.Sweep[2] = ds[2] > 0.0 ? 1.0 : (ds[2] < 0.0 ? -1.0 : 0.0);
  step.Grid[plan.Row] = step.Sweep[0];
  step.Grid[plan.Column] = step.Sweep[1];
  step.Grid[plan.Axis] = step.Sweep[2];
  double world[3];
  Multiply3(grid.GridToWorld, step.Grid, world);
  step.Length = std::sqrt(world[0] * world[0] + world[1] * world[1] + world[2] * world[2]);
  return step;
}

LineRange LinesOf(const TransportGrid& grid, const SweepPlan& plan,
  const vtkScattererTransportVolume::Light& light, int fromStep, int toStep)
{
  const LightStep step = StepTowardLight(grid, plan, light);
  // The global indices of the steps' first and last slices (away from the light).
  const int first = plan.Runs.empty() ? 0 : plan.Runs.front().first;
  const int away = plan.Runs.empty() || plan.Runs.front().second >= first ? 1 : -1;
  const double z0 = grid.FirstIndex[plan.Axis] + first + away * fromStep;
  const double z1 = grid.FirstIndex[plan.Axis] + first + away * (toStep - 1);
  const int sliceDims[2] = { grid.Dims[plan.Row], grid.Dims[plan.Column] };
  LineRange range;
  for (int i = 0; i < 2; ++i)
  {
    const double a = step.Sweep[i] * step.Sweep[2]; // the sideways step per slice
    // round(z a) is monotonic in z: its extremes are at the first and last slices.
    const double r0 = std::floor(z0 * a + 0.5), r1 = std::floor(z1 * a + 0.5);
    const int lo = static_cast<int>(-std::max(r0, r1)) - 1;
    const int hi = sliceDims[i] - 1 - static_cast<int>(std::min(r0, r1)) + 1;
    range.Lo[i] = lo;
    range.Count[i] = hi - lo + 1;
  }
  return range;
}

std::vector<float> SweepOrderToGridOrder(
  const TransportGrid& grid, const SweepPlan& plan, const std::vector<float>& sweep)
{
  const int* dims = grid.Dims;
  const size_t w = static_cast<size_t>(dims[plan.Row]), h = static_cast<size_t>(dims[plan.Column]);
  std::vector<float> ordered(sweep.size());
  for (int z = 0; z < dims[2]; ++z)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        const int j[3] = { x, y, z };
        const size_t from = j[plan.Row] + w * (j[plan.Column] + h * j[plan.Axis]);
        ordered[x + static_cast<size_t>(dims[0]) * (y + static_cast<size_t>(dims[1]) * z)] =
          sweep[from];
      }
    }
  }
  return ordered;
}
}
