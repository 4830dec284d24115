// What every light transport pass draws with, in one record: the passes
// (ScattererTransportLightPasses, ScattererTransportDiffusionPasses) take it whole.
#ifndef ScattererTransportPass_h
#define ScattererTransportPass_h

#include "vtkScattererTransportVolume.h" // for Inputs

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace scatterer_gpu
{
struct TransportGrid;
struct TransportPrograms;
struct TransportTables;
struct TransportTextures;
class TransportProgress;

/** The context, programs, inputs and textures of one build's passes. */
struct TransportPass
{
  vtkOpenGLRenderWindow* Window;
  vtkOpenGLFramebufferObject* Framebuffer; ///< bound (TransportPassState)
  TransportPrograms& Programs;             ///< the sweep's are compiled when first used
  const vtkScattererTransportVolume::Inputs& In;
  const TransportGrid& Grid;
  const TransportTables& Tables;
  TransportTextures& Textures; ///< the targets, allocated by the passes as they need
  TransportProgress& Progress;
  /// A directional light's lines swept in parallel where the implementation can
  /// (vtkScattererTransportVolume::SweepLinesInParallel)
  bool SweepLinesInParallel = true;
  /// The grid whose texels' mean extinction Textures.FineExtinction holds (pass 0a), which
  /// the sweeps read for a step's far half: Grid itself (null), or, on the dim lights'
  /// grid, the fine grid, whose textures hold the means (MeansTexture).
  const TransportGrid* MeansGrid = nullptr;
  vtkTextureObject* MeansTexture = nullptr; ///< null: Textures.FineExtinction
};
}

#endif
