// The passes run once per build after the lights' gather: the light scattered once is
// spread by a diffusion solve on a coarser grid (multiple scattering) and added, with
// VTK's ambient term times its occlusion, to the light each fine texel receives. The
// coarse medium and the occlusion come from the medium passes
// (ScattererTransportMediumPasses), which run when the medium changes.
#ifndef ScattererTransportDiffusionPasses_h
#define ScattererTransportDiffusionPasses_h

#include "vtkScattererTransportVolume.h" // for Inputs

#include <string>

namespace scatterer_gpu
{
struct SweepPlan;
struct TransportPass;

/** Jacobi iterations the build runs for @p inputs (0: no multiple scattering). */
int DiffusionIterations(const vtkScattererTransportVolume::Inputs& inputs);

/**
 * Adds the multiply scattered light and the occluded ambient light to
 * pass.Textures.Light:
 * - pass 3a (scatterer_transport_source.glsl): the source S = sigma_s A (A the light
 *   arriving unscattered, or the direct light, swept by @p plan) on the coarse grid,
 *   the mean over a block of fine texels;
 * - pass 3b (scatterer_transport_diffuse.glsl), DiffusionIterations() Jacobi iterations of
 *     -div(D grad phi) + sigma_a phi = S,   D = 1 / (3 sigma_t),  sigma_a = sigma_t (1 - albedo)
 * - pass 4 (scatterer_transport_combine.glsl): L += MultipleScattering phi + ambient AO
 *   (the occlusion of pass 0b).
 * False with @p why set if the coarse textures cannot be allocated.
 */
bool AddScatteredAndAmbientLight(
  const TransportPass& pass, const SweepPlan& plan, std::string& why);
}

#endif
