// The passes that depend on the medium alone: the volume, its transfer functions and
// placement, clipping, cropping, the materials and the grid, none of the lights. They
// run when that changes (ScattererTransportKey's MediumKey), not when a light moves,
// and the passes of every build read what they leave.
#ifndef ScattererTransportMediumPasses_h
#define ScattererTransportMediumPasses_h

#include <string>

namespace scatterer_gpu
{
struct TransportPass;

/**
 * - pass 0a (scatterer_transport_medium.glsl), into pass.Textures.FineScattering and
 *   FineGather: each fine texel's scattering coefficient as the multiple-scattering
 *   source takes it, and which gather it takes (whether its photons land in another
 *   material);
 * - pass 0b (scatterer_transport_coarsen.glsl), into CoarseMedium and CoarseOcclusion:
 *   the medium on the diffusion's coarse grid, each texel the mean over a block of fine
 *   texels, and the ambient occlusion of its centre.
 * False with @p why set if the coarse textures cannot be allocated.
 */
bool BuildMediumTextures(const TransportPass& pass, std::string& why);
}

#endif
