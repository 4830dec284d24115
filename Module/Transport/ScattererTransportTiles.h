// The diffusion's coarse texels that hold a medium, covered by rectangles of whole tiles
// per layer, so that the diffusion's passes draw those and no others.
//
// Why: on the CT head about three quarters of the coarse grid hold no medium (air around
// the head and inside the skull). Those texels' fluence is 0 whatever the iteration, and their
// source is read by no one, but llvmpipe runs a fragment whether it returns early or is
// discarded (docs/rendering.md, "what a Jacobi iteration costs"); only not drawing it
// spares it. The texels left out keep the 0 they are cleared to, which is what the
// Jacobi pass writes where there is no medium, so the solve is the same, texel for texel.
#ifndef ScattererTransportTiles_h
#define ScattererTransportTiles_h

#include "vtkSmartPointer.h"

#include <cstddef> // for size_t
#include <functional>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkShaderProgram;
class vtkTextureObject;

namespace scatterer_gpu
{
/** Texels [X0, X1) x [Y0, Y1) of layer Z. */
struct TexelRect
{
  int X0, Y0, X1, Y1, Z;
};

/** Side of a tile, in coarse texels. llvmpipe rasterises blocks of 4x4 pixels; smaller
 * tiles leave out more texels but cost more rectangles. */
constexpr int kCoarseTile = 4;

/**
 * Rectangles covering every texel (x, y, z) of a grid of @p dims for which @p has holds
 * and no tile of @p tile x @p tile texels (per layer) without one: per layer and row of
 * tiles, each run of consecutive tiles holding such a texel is one rectangle, and a run
 * with the same columns as the one below it in the layer extends it.
 */
std::vector<TexelRect> CoverTexels(
  const int dims[3], int tile, const std::function<bool(int, int, int)>& has);

/** The rectangles of the coarse grid the diffusion draws, on the GPU. */
struct CoarseTiles
{
  /// Two triangles a rectangle, 3 floats a corner: (x, y) in coarse texels and the layer z
  /// (scatterer_transport_tiles_vs.glsl). Vertices, not instances of one quad: llvmpipe
  /// spends about 10 microseconds on each instance of a draw, 7 ms a pass for the CT
  /// head's 601 rectangles, where their fragments take under 1 ms.
  vtkSmartPointer<vtkOpenGLBufferObject> Corners;
  int Count = 0; ///< rectangles

  /** The rectangles around the texels of @p coarseMedium (RGBA: albedo, sigma_t) whose
   * sigma_t is not 0 (@p onTiles; else whole layers), uploaded. The fluence atlases
   * start at 0 where they leave out (scatterer_transport_fluence_start.glsl). */
  void Update(vtkTextureObject* coarseMedium, bool onTiles);

  /** Bytes the rectangles take on the GPU. */
  size_t GetGPUBytes() const;

  void ReleaseGraphicsResources();
};

/** Draws with @p program (in use; scatterer_transport_tiles_vs.glsl) over the rectangles
 * of @p tiles into @p target, the coarse grid's atlas (CoarseGrid::AtlasColumns; the
 * viewport its size), in one draw call. Detaches it after. */
void DrawTiles(vtkOpenGLFramebufferObject* framebuffer, vtkShaderProgram* program,
  vtkTextureObject* target, const CoarseTiles& tiles);
}

#endif
