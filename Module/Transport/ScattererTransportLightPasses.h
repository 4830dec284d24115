// The passes of the lights: per light the transmittance sweep (pass 1,
// scatterer_transport_sweep.glsl, or for a directional light scatterer_transport_lines.glsl)
// and the light it brings to each texel (pass 2a, scatterer_transport_arrive.glsl, or the
// lines' own mean draw), added up; a build of one directional light (the direct light)
// reads it from its transmittance instead. Then once for all lights the template
// in-scattering gather (pass 2b, scatterer_transport_gather.glsl).
// Passes that read the arriving light (scatterer_transport_arriving.glsl) bind it with
// ScopedArrivingLight.
#ifndef ScattererTransportLightPasses_h
#define ScattererTransportLightPasses_h

#include "ScattererTransportPrograms.h"  // for ScopedSampler
#include "vtkScattererTransportVolume.h" // for Light

#include <memory> // for std::unique_ptr
#include <string>
#include <vector> // for DimLightsOf

class vtkShaderProgram;
class vtkTextureObject;

namespace scatterer_gpu
{
struct SweepPlan;
struct TransportPass;

/**
 * The direct light of @p in, read by the passes from its transmittance: its light when
 * that is one directional light, -1 otherwise. With several lights all are summed in
 * the arriving light, so that the gather and the source read one texture per photon.
 */
int DirectLight(const vtkScattererTransportVolume::Inputs& in);

/** Whether some light of @p in is not the direct light (it is summed in the arriving
 * light). */
bool HasArrivingLights(const vtkScattererTransportVolume::Inputs& in);

/**
 * A light dimmer than this fraction of the brightest light of a build (the largest
 * channel of Light::Color, its irradiance) is a dim light: it is swept on a grid twice as
 * coarse as the fine one, and the light it brings is added to the fine grid's arriving
 * light (AddDimLights). Its shadows blur by a fine texel, and what it brings is a third
 * or less of what the brightest brings: ParaView's and vtkLightKit's light kit (key
 * light 0.75; fill and head light a third of it, the two back lights 1/3.5) keeps the
 * key light fine and sweeps the other four at an eighth of the texels
 * (docs/model.md, "Dim lights").
 */
constexpr float kDimLightFraction = 0.5f;

/** The dim lights' grid: this many times the fine grid's voxels per texel along each
 * axis (an eighth of its texels). 4 (a 64th) took the light kit's sweeps on the CT head
 * from 126 to 79 ms in the render benchmark, at RMSE 0.0156 against 0.0133 (2) and
 * 0.0129 (every light fine). */
constexpr int kDimLightCoarsening = 2;

/**
 * Which lights of @p in are dim (kDimLightFraction): none in a build of one light, at
 * Downsample 1 (a texel of one voxel: the finest setting, whose sweeps hold no texel
 * means for the coarser grid to read), or without Inputs::CoarseDimLights.
 */
std::vector<bool> DimLightsOf(const vtkScattererTransportVolume::Inputs& in);

/**
 * Adds the light the dim lights bring, in @p dim's arriving light (its grid twice as
 * coarse as @p pass's), to pass.Textures.Arriving, read trilinearly at each fine texel
 * (scatterer_transport_dim_lights.glsl). False with @p why set if its program is refused.
 */
bool AddDimLights(const TransportPass& pass, const TransportPass& dim, std::string& why);

/** Where a sweep's light goes. */
enum class SweepOutput
{
  Transmittance, ///< the transmittance texture: the direct light, tests
  ArrivingFirst, ///< the arriving light, replacing what it holds (the first light)
  ArrivingAdded  ///< the arriving light, added to what it holds
};

/**
 * Binds what scatterer_transport_arriving.glsl reads in @p program for this object's
 * lifetime: the arriving light, or the direct light (swept by @p plan).
 */
class ScopedArrivingLight
{
public:
  ScopedArrivingLight(vtkShaderProgram* program, const TransportPass& pass, const SweepPlan& plan);

private:
  std::unique_ptr<ScopedSampler> Arriving;      ///< none without an arriving light
  std::unique_ptr<ScopedSampler> Transmittance; ///< the direct light's; none without one
};

/**
 * Sweeps the transmittance T of @p light through the grid, slice by slice along the
 * light's dominant axis (or, for a directional light, its lines in parallel):
 *   T(p) = T(q) exp(-integral_q^p sigma_t ds)        (Beer-Lambert)
 * with q one slice closer to the light, into pass.Textures.Transmittance (in sweep
 * order). With @p output one of the arriving light's, a directional light swept in
 * parallel brings its light E_l T to pass.Textures.Arriving instead, and sets
 * @p summed (AddArrivingLight is then not needed). Sets @p swept to the sweep's plan.
 * False with @p why set if the textures cannot be allocated.
 */
bool SweepTransmittance(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  SweepOutput output, SweepPlan& swept, bool& summed, std::string& why);

/**
 * Adds the light that @p light (swept by @p plan; not the direct light) brings to each
 * texel, unscattered, to pass.Textures.Arriving, or replaces what it holds (@p first):
 *   A(p) += E_l a_l(p) T_l(p)
 * with E_l its colour and intensity, a_l(p) VTK's attenuation and spot cone. False with
 * @p why set if its program is refused.
 */
bool AddArrivingLight(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  const SweepPlan& plan, bool first, std::string& why);

/**
 * Gathers the arriving light of all lights (or the direct light, swept by @p plan)
 * through the materials' scatterer templates, and writes into pass.Textures.Light the
 * light each texel receives:
 *   R(p) = sum_j w_j c_j A(p + r_j) / sum_j w_j                     (single scattering)
 *   L(p) = R(p) + MultipleScattering phi(p) + ambient AO(p)
 * with phi the coarse @p fluence of SolveMultipleScattering (ScopedScatteredLight).
 * Linear in each light's T_l with weights that do not depend on the light, so one
 * gather serves every light. False with @p why set if a program is refused.
 */
bool GatherLight(
  const TransportPass& pass, const SweepPlan& plan, vtkTextureObject* fluence, std::string& why);
}

#endif
