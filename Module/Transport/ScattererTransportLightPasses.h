// The passes run once per light: the transmittance sweep (pass 1,
// scatterer_transport_sweep.glsl) and the template in-scattering gather (pass 2,
// scatterer_transport_gather.glsl) that adds the light's contribution to the light
// texture and to the source of multiple scattering.
#ifndef ScattererTransportLightPasses_h
#define ScattererTransportLightPasses_h

#include "vtkScattererTransportVolume.h" // for Light

#include <string>

namespace scatterer_gpu
{
struct SweepPlan;
struct TransportPass;

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
 * Gathers the transmittance of @p light (swept by @p plan) through the materials'
 * scatterer templates into pass.Textures.Light and Source:
 *   R_l(p) = E_l a_l(p) sum_j w_j c_j T_l(p + r_j) / sum_j w_j     (single scattering)
 *   S(p) = sigma_t(p) albedo(p) E_l a_l(p) T_l(p)                   (its source)
 * replacing what they hold (@p first) or adding to it.
 */
void GatherLight(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  const SweepPlan& plan, bool first);
}

#endif
