// The passes run once per build after the lights' sweeps: the light scattered once is
// spread by a diffusion solve on a coarser grid (multiple scattering), which the gather
// then adds, with VTK's ambient term times its occlusion, to the light each fine texel
// receives (ScopedScatteredLight). The coarse medium and the occlusion come from the
// medium passes (ScattererTransportMediumPasses), which run when the medium changes.
#ifndef ScattererTransportDiffusionPasses_h
#define ScattererTransportDiffusionPasses_h

#include "ScattererTransportPrograms.h"  // for ScopedSampler
#include "vtkScattererTransportVolume.h" // for Inputs

#include <string>

class vtkShaderProgram;
class vtkTextureObject;

namespace scatterer_gpu
{
struct SweepPlan;
struct TransportPass;

/** Jacobi iterations the build runs for @p inputs (0: no multiple scattering). */
int DiffusionIterations(const vtkScattererTransportVolume::Inputs& inputs);

/**
 * Solves for the multiply scattered light on the coarse grid:
 * - pass 3a (scatterer_transport_source.glsl): the source S = sigma_s A (A the light
 *   arriving unscattered, or the direct light, swept by @p plan) on the coarse grid,
 *   the mean over a block of fine texels;
 * - pass 3b (scatterer_transport_diffuse.glsl), DiffusionIterations() Jacobi iterations of
 *     -div(D grad phi) + sigma_a phi = S,   D = 1 / (3 sigma_t),  sigma_a = sigma_t (1 - albedo)
 * both drawn only on the tiles of the coarse grid that hold a medium (TransportTextures::Tiles,
 * ScattererTransportTiles.h), and sets @p fluence to the coarse texture that holds phi, for
 * ScopedScatteredLight.
 * False with @p why set if the coarse textures cannot be allocated.
 */
bool SolveMultipleScattering(
  const TransportPass& pass, const SweepPlan& plan, vtkTextureObject*& fluence, std::string& why);

/**
 * Pass 4, in the gather's draw (scatterer_transport_scattered.glsl): binds @p fluence (from
 * SolveMultipleScattering) and the ambient occlusion of pass 0b, and sets the uniforms
 * with which st_scatteredAndAmbient gives a fine texel
 *   MultipleScattering phi + ambient AO,
 * for this object's lifetime.
 */
class ScopedScatteredLight
{
public:
  ScopedScatteredLight(
    vtkShaderProgram* program, const TransportPass& pass, vtkTextureObject* fluence);

private:
  ScopedSampler Fluence;
  ScopedSampler Occlusion;
};
}

#endif
