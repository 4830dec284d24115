// The textures the light transport volume renders into, and their allocation: each is
// allocated again only when the grid it covers changes size, and released together.
// The small tables the passes read are ScattererTransportTables.
#ifndef ScattererTransportTextures_h
#define ScattererTransportTextures_h

#include "ScattererTransportTiles.h" // for CoarseTiles
#include "vtkSmartPointer.h"

#include <cstddef> // for size_t
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace scatterer_gpu
{
/** A new texture in @p window's context: linear or nearest filtering, @p wrap
 * (vtkTextureObject::ClampToEdge, ...) along all three axes. Not allocated. */
vtkSmartPointer<vtkTextureObject> NewTransportTexture(
  vtkOpenGLRenderWindow* window, bool linear, int wrap);

/** The float texels of 3D @p texture, RED (1 component) or RGBA (4), x fastest. */
std::vector<float> DownloadTexture3D(vtkTextureObject* texture, int components);

/** The RGBA texels of a grid of @p dims that 2D @p atlas holds, its layers side by side in
 * @p columns columns (CoarseGrid::AtlasColumns), in grid order (x fastest). */
std::vector<float> DownloadAtlas(vtkTextureObject* atlas, const int dims[3], int columns);

/** The render targets of the transport passes. */
struct TransportTextures
{
  vtkSmartPointer<vtkTextureObject> Light; ///< RGBA16F, fine grid: the light received
  /// R11F_G11F_B10F, fine grid, what no light changes (pass 0a): the scattering
  /// coefficient as the multiple-scattering source takes it (the source averages it
  /// over a block of texels). With FineGather 5 bytes a texel, where one RGBA16F
  /// texture of both took 8.
  vtkSmartPointer<vtkTextureObject> FineScattering;
  /// R8, fine grid (pass 0a): the gather each texel takes (st_storedGather)
  vtkSmartPointer<vtkTextureObject> FineGather;
  /// R16F, fine grid (pass 0a): the extinction along light paths, the texel's mean (a
  /// step's far half in the sweeps, scatterer_transport_sweep_common.glsl); its border
  /// reads 0. A texture of its own: kept in Light's unused alpha instead, the sweeps'
  /// trilinear read of four half-float channels made a headlight rebuild 18 % and
  /// pvbatch's light-kit orbit 10-20 % slower on llvmpipe (docs/rendering.md). One
  /// texel, neither drawn nor read, where a sweep takes no texel's mean
  /// (ExtinctionSampling: a texel of one voxel).
  vtkSmartPointer<vtkTextureObject> FineExtinction;
  /// Per layer of FineGather, the gather variant it needs (a GatherVariant)
  std::vector<int> LayerGathers;
  /// RGBA16F, fine grid + 1 texel a side: light arriving unscattered (null when unused)
  vtkSmartPointer<vtkTextureObject> Arriving;
  vtkSmartPointer<vtkTextureObject> Transmittance; ///< R16F, sweep order
  /// RG16F, ping-pong of the slice sweep: per texel T and (a directional light's)
  /// st_farFactor at the line's point (scatterer_transport_sweep.glsl)
  vtkSmartPointer<vtkTextureObject> Slices[2];
  /// RG16F, sweep order: a directional light's lines swept in parallel, per texel T and
  /// st_farFactor at the line's point (scatterer_transport_lines.glsl), a ring of the
  /// slices their texels' draw has yet to read and the slice before them (st_lineSlot);
  /// its border reads 1
  vtkSmartPointer<vtkTextureObject> Lines;
  /// RG32F, 2D, per line: T where a draw of the lines leaves it, and that step (ping-pong)
  vtkSmartPointer<vtkTextureObject> LineEnds[2];
  /// RGBA16F, 2D, the coarse grid's atlas (CoarseGrid::AtlasColumns): diffusion ping-pong
  vtkSmartPointer<vtkTextureObject> Fluence[2];
  vtkSmartPointer<vtkTextureObject> CoarseMedium; ///< RGBA16F, coarse grid: albedo, sigma_t
  /// RGBA16F, 2D, the coarse grid's atlas: light scattered once
  vtkSmartPointer<vtkTextureObject> CoarseSource;
  vtkSmartPointer<vtkTextureObject> CoarseOcclusion; ///< R16F, coarse grid: ambient occlusion
  /// The coarse texels the diffusion draws: those of CoarseMedium that hold a medium
  CoarseTiles Tiles;

  /// Counts the allocations of FineScattering, FineGather, CoarseMedium and CoarseOcclusion: what
  /// the medium passes drew is gone when it changes.
  int MediumAllocations = 0;

  /** Light, FineScattering, FineGather and, where the sweeps take texels' means
   * (@p texelMeans), FineExtinction on the fine grid of @p dims; false with @p why set if
   * refused. */
  bool AllocateFine(
    vtkOpenGLRenderWindow* window, const int dims[3], bool texelMeans, std::string& why);

  /** Arriving for the fine grid of @p dims (one texel more a side), needed by builds
   * whose lights are more than one directional light; false with @p why set if refused. */
  bool AllocateArriving(vtkOpenGLRenderWindow* window, const int dims[3], std::string& why);

  /** Frees Arriving (a build of one directional light does without it). */
  void ReleaseArriving(vtkWindow* window);

  /** Transmittance of @p sweepDims (rows, columns, slices), and with @p slices the
   * slices of the sweep one slice per draw; false with @p why set if refused. A sweep
   * allocates only what it draws into: a light kit's lines swept in parallel need
   * neither. */
  bool AllocateSweep(
    vtkOpenGLRenderWindow* window, const int sweepDims[3], bool slices, std::string& why);

  /** Lines of @p ringDims (a sweep's rows and columns, and the slices of its ring) and
   * LineEnds of @p lineDims (the lines' draws); false with @p why set if refused. */
  bool AllocateLines(
    vtkOpenGLRenderWindow* window, const int ringDims[3], const int lineDims[2], std::string& why);

  /** The five coarse grids of @p dims, those the diffusion draws as atlases of @p atlas
   * texels; false with @p why set if refused. */
  bool AllocateCoarse(
    vtkOpenGLRenderWindow* window, const int dims[3], const int atlas[2], std::string& why);

  /** Bytes of GPU memory the textures held take. */
  size_t GetGPUBytes() const;

  void ReleaseGraphicsResources(vtkWindow* window);
};
}

#endif
