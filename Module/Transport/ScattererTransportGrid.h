// Where the light transport grid lies and how a light is swept through it: the CPU
// geometry of vtkScattererTransportVolume, no OpenGL.
//
// The grid is every Downsample-th structured index of the volume, anchored to index 0
// (not to the image's first voxel), so that a piece of a split volume (ParaView with
// MPI) puts its transport voxels where the whole volume does. Its placement in the
// world is the ray caster's own (the volume texture's texture -> world matrix).
#ifndef ScattererTransportGrid_h
#define ScattererTransportGrid_h

#include "vtkScattererTransportVolume.h" // for Light

#include <array>   // for CoarseGrid::BlockSize
#include <utility> // for std::pair
#include <vector>  // for SweepPlan::Runs

namespace scatterer_gpu
{
/** a / b rounded toward minus infinity (b > 0): grids anchored to index 0 for pieces
 * whose extents start below or above it. */
int FloorDiv(int a, int b);

/** The world length of a voxel along each axis of a volume texture of @p dims texels
 * placed by @p texToWorld (row-major 4x4; column a spans the texture along axis a). */
void VoxelLengths(const int dims[3], const double texToWorld[16], double lengths[3]);

/** The fine transport grid: its size, and the maps between its texels, the volume
 * texture's coordinates and the world. */
struct TransportGrid
{
  int Dims[3] = { 0, 0, 0 };
  /// The transport scale it is placed at.
  int Downsample = 1;
  /// Volume voxels per grid texel along each axis (transportStridesFor).
  int Strides[3] = { 1, 1, 1 };
  /// The voxels' world lengths the strides follow.
  double Spacing[3] = { 1, 1, 1 };
  int FirstIndex[3] = { 0, 0, 0 }; ///< global index (in grid texels) of grid texel 0
  /// Grid texel j -> volume texture coordinate: j * GridToTex + GridToTexOffset.
  double GridToTex[3] = { 0, 0, 0 };
  double GridToTexOffset[3] = { 0.5, 0.5, 0.5 };
  /// Volume texture coordinate t -> light texture coordinate: t * TexScale + TexOffset.
  float TexScale[3] = { 1, 1, 1 };
  float TexOffset[3] = { 0, 0, 0 };
  double GridToWorld[9] = {};              ///< grid-index vector -> world vector (row-major 3x3)
  double WorldToGrid[9] = {};              ///< its inverse
  double GridOriginWorld[3] = { 0, 0, 0 }; ///< world position of grid texel 0

  /**
   * Places the grid on a volume texture of @p volumeDims texels whose first texel is
   * structured index @p indexOrigin, with @p texToWorld (row-major 4x4), at transport
   * scale @p downsample: one grid texel per transportStridesFor voxels along each axis,
   * for the voxels' lengths (VoxelLengths). Returns false when that placement is
   * degenerate (zero spacing, a singular matrix); the sizes are set all the same.
   */
  bool Place(
    const int volumeDims[3], const int indexOrigin[3], int downsample, const double texToWorld[16]);

  /** World length of one grid texel along grid axis @p a. */
  double TexelLength(int a) const;

  /** Dims as floats (the passes' uniforms). */
  void GetDims(float dims[3]) const;

  /**
   * Where this grid's positions lie on grid @p to (both placed on the same volume, at any
   * Downsample): position j here is j * scale + offset there. Texel j lies at global
   * index (F + j) d (d the axis's stride), which on @p to is (F + j) d / d_to - F_to. An
   * axis of one texel on @p to maps to its texel, 0.
   */
  void GetPositionsOn(const TransportGrid& to, float scale[3], float offset[3]) const;
};

/** The diffusion's coarse grid: blocks of Block[0] x Block[1] x Block[2] fine texels,
 * anchored like the fine grid (to multiples of Block in global fine indices) so that
 * pieces share it. */
struct CoarseGrid
{
  int Dims[3] = { 0, 0, 0 };
  int ToGrid[3] = { 0, 0, 0 }; ///< coarse texel c covers fine texels Block c + ToGrid + [0, Block)
  int Block[3] = { 2, 2, 2 };  ///< fine texels per coarse texel along each axis

  /** Block as floats (the passes' st_blockSize). */
  std::array<float, 3> BlockSize() const
  {
    return { static_cast<float>(this->Block[0]), static_cast<float>(this->Block[1]),
      static_cast<float>(this->Block[2]) };
  }
  /// Points per axis each fine texel's medium is the mean of in pass 0b: 2 on a
  /// frame built at twice a still frame's scale or more (while the user drags), so that
  /// its medium is sampled about as finely as a still frame's; 1 (the centre) otherwise.
  int Subsamples = 1;
  /// The source and Jacobi passes draw the grid as a 2D atlas of its layers: layer z is
  /// the tile (z % AtlasColumns, z / AtlasColumns) of Dims[0] x Dims[1] texels. llvmpipe
  /// shares a draw among its threads by 64x64 tiles of the framebuffer, all layers of a
  /// 3D target in one, so the CT head's coarse layers (65x65) ran on one thread; its atlas
  /// (4 columns of 7 layers, 260x455 texels) gives every thread tiles.
  int AtlasColumns = 1;

  /**
   * The coarse grid over @p grid for volume voxels per fine texel @p downsample, its
   * texels as large as a still frame's (@p stillDownsample voxels per fine texel; 0:
   * @p downsample): the frames rendered while the user drags, built coarser, keep the
   * still frames' multiple scattering.
   */
  static CoarseGrid Over(const TransportGrid& grid, int downsample, int stillDownsample);

  void GetDims(float dims[3]) const;
  void GetToGrid(float toGrid[3]) const;
  /** The atlas's width and height in texels. */
  void GetAtlasSize(int size[2]) const;
};

/** The longest side CoarseGrid::Over gives an atlas where it can: 2D textures of 8192
 * texels a side are allocated by the GPUs VTK runs on (OpenGL 4.1 asks 16384). */
constexpr int kAtlasMaxSide = 8192;

/** The columns of the atlas of a grid of @p dims (CoarseGrid::AtlasColumns): the fewest
 * empty tiles within @p maxSide texels a side, of those the most nearly square (of equal
 * sides, the fewer columns); the most nearly square if none fits. */
int AtlasColumnsFor(const int dims[3], int maxSide);

/** The coarse grid as the coarse passes' uniforms (st_coarseDims, st_coarseToGrid, st_h,
 * st_atlasColumns). */
struct CoarseUniforms
{
  float Dims[3];
  float ToGrid[3];
  float H[3];       ///< coarse texel size along each axis, world units
  int AtlasColumns; ///< st_atlasColumns

  CoarseUniforms(const TransportGrid& grid, const CoarseGrid& coarse);
};

/** How one light is swept: the grid axis the slices run along (the light's dominant
 * axis in grid units) and the other two in order. */
struct SweepPlan
{
  int Axis = 2;
  int Row = 0, Column = 1;
  /// Slices to sweep, each run starting with T = 1: (first, last) inclusive.
  std::vector<std::pair<int, int>> Runs;

  /** Texels of the transmittance texture, (rows, columns, slices). */
  void GetSweepDims(const TransportGrid& grid, int dims[3]) const;
};

/** The sweep of @p light through @p grid: along its dominant axis away from it (a
 * directional light), or away from its own slice on both sides (a positional light). */
SweepPlan PlanSweep(const TransportGrid& grid, const vtkScattererTransportVolume::Light& light);

/** One step of a directional light's sweep toward it: Sweep in sweep texels (rows,
 * columns, slices), its slice component +-1 and its sideways part at most 4 texels (a
 * light nearly in a slice's plane would shift sideways without bound); Grid the same
 * in grid texels; Length its length in the world. A positional light's step changes
 * from texel to texel, and its sweep takes it there (st_stepTowardLight in
 * scatterer_transport_sweep_common.glsl, the same rule); a directional light's is taken
 * here once, and the sweeps read it as uniforms (st_stepSweep, st_stepGrid,
 * st_stepLength), so that its lines, their mean and LinesOf share one value and no
 * fragment computes it again. */
struct LightStep
{
  double Sweep[3] = { 0, 0, 0 };
  double Grid[3] = { 0, 0, 0 };
  double Length = 0;
};
LightStep StepTowardLight(const TransportGrid& grid, const SweepPlan& plan,
  const vtkScattererTransportVolume::Light& light);

/** How a sweep samples the extinction over a step from a texel toward the light
 * (st_nearHalfDepth, st_farExtinction: scatterer_transport_sweep_common.glsl), for @p downsample
 * volume voxels per texel. StepSamples points evenly along the step, one a voxel (max(1,
 * downsample)); those in its near half, inside the texel, give that half's optical depth. The far
 * half, inside the texel the step reaches, takes that texel's mean extinction over MeanPoints^3
 * points spread evenly over it (pass 0a, TransportTextures::FineExtinction), 2^3 at every
 * scale: one point a voxel along each axis (4^3 at 511x511x215, scale 4) cost about a
 * second a medium change on llvmpipe, and the dragging frames (scale 4 on the CT head)
 * measured closer to the reference with 2^3. With one sample a step (a texel of one
 * voxel) that sample, on the texel's face, serves both halves: MeanPoints is 0, and no
 * texel's mean is computed or held (the texture is one texel, unread). */
struct ExtinctionSampling
{
  int StepSamples = 1;
  int MeanPoints = 0;
  bool UsesTexelMeans() const { return this->MeanPoints > 0; }
  static ExtinctionSampling For(int downsample);
};

/** The lines of directional @p light swept by @p plan through @p grid
 * (scatterer_transport_lines.glsl): line k holds texel k + round(z a) of slice z (sweep
 * rows and columns, z the global slice index, a the sideways step per slice). Lo is the
 * first k with a texel in the grid in the sweep's steps [@p fromStep, @p toStep) (step 0:
 * the slice nearest the light), Count how many, per sweep row and column; one more on
 * each side than the exact range, for rounding. */
struct LineRange
{
  int Lo[2] = { 0, 0 };
  int Count[2] = { 1, 1 };
};
LineRange LinesOf(const TransportGrid& grid, const SweepPlan& plan,
  const vtkScattererTransportVolume::Light& light, int fromStep, int toStep);

/** @p sweep (a transmittance texture read back in sweep order, @p plan's) in grid order
 * (x fastest). */
std::vector<float> SweepOrderToGridOrder(
  const TransportGrid& grid, const SweepPlan& plan, const std::vector<float>& sweep);
}

#endif
