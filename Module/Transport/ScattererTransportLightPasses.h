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
 * with E_l its colour and intensity, a_l(p) VTK's attenuation and spot cone.
 */
void AddArrivingLight(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  const SweepPlan& plan, bool first);

/**
 * Gathers the arriving light of all lights (or the direct light, swept by @p plan)
 * through the materials' scatterer templates, and writes into pass.Textures.Light the
 * light each texel receives:
 *   R(p) = sum_j w_j c_j A(p + r_j) / sum_j w_j                     (single scattering)
 *   L(p) = R(p) + MultipleScattering phi(p) + ambient AO(p)
 * with phi the coarse @p fluence of SolveMultipleScattering (ScopedScatteredLight).
 * Linear in each light's T_l with weights that do not depend on the light, so one
 * gather serves every light.
 */
void GatherLight(const TransportPass& pass, const SweepPlan& plan, vtkTextureObject* fluence);
}

#endif
