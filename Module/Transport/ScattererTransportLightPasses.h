// The passes of the lights: per light the transmittance sweep (pass 1,
// scatterer_transport_sweep.glsl) and the light it brings to each texel (pass 2a,
// scatterer_transport_arrive.glsl), added up, but for one directional light (the
// direct light) swept last and read from its transmittance; then once for all lights
// the template in-scattering gather (pass 2b, scatterer_transport_gather.glsl).
// Passes that read the arriving light (scatterer_transport_arriving.glsl) bind it with
// ScopedArrivingLight.
#ifndef ScattererTransportLightPasses_h
#define ScattererTransportLightPasses_h

#include "ScattererTransportPrograms.h"  // for ScopedSampler
#include "vtkScattererTransportVolume.h" // for Light

#include <memory> // for std::unique_ptr
#include <string>

class vtkShaderProgram;

namespace scatterer_gpu
{
struct SweepPlan;
struct TransportPass;

/** The direct light of @p in: its last directional light, or -1 when it has none. */
int DirectLight(const vtkScattererTransportVolume::Inputs& in);

/** Whether some light of @p in is not the direct light (it passes through pass 2a). */
bool HasArrivingLights(const vtkScattererTransportVolume::Inputs& in);

/**
 * Binds what scatterer_transport_arriving.glsl reads in @p program for this object's
 * lifetime: the lights of pass 2a, and the direct light (swept last, by @p plan).
 */
class ScopedArrivingLight
{
public:
  ScopedArrivingLight(vtkShaderProgram* program, const TransportPass& pass, const SweepPlan& plan);

private:
  std::unique_ptr<ScopedSampler> Arriving; ///< none without lights of pass 2a
  ScopedSampler Transmittance;
};

/**
 * Sweeps the transmittance T of @p light into pass.Textures.Transmittance (in sweep
 * order), slice by slice along the light's dominant axis:
 *   T(p) = T(q) exp(-integral_q^p sigma_t ds)        (Beer-Lambert)
 * with q one slice closer to the light. Sets @p swept to the sweep's plan. False with
 * @p why set if the textures cannot be allocated.
 */
bool SweepTransmittance(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  SweepPlan& swept, std::string& why);

/**
 * Adds the light that @p light (swept by @p plan; not the direct light) brings to each
 * texel, unscattered, to pass.Textures.Arriving, or replaces what it holds (@p first):
 *   A(p) += E_l a_l(p) T_l(p)
 * with E_l its colour and intensity, a_l(p) VTK's attenuation and spot cone.
 */
void AddArrivingLight(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  const SweepPlan& plan, bool first);

/**
 * Gathers the arriving light of all lights (the direct one swept last, by @p plan)
 * through the materials' scatterer templates into pass.Textures.Light:
 *   R(p) = sum_j w_j c_j A(p + r_j) / sum_j w_j                     (single scattering)
 * Linear in each light's T_l with weights that do not depend on the light, so one
 * gather serves every light.
 */
void GatherLight(const TransportPass& pass, const SweepPlan& plan);
}

#endif
