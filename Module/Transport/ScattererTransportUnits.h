// The length unit the transport volume measures in.
//
// Why: the passes store extinctions (per length) and the diffusion's terms at half
// precision (RGBA16F, R16F: largest 65504, smallest normal 6.1e-5). In world units, a
// volume stored in metres (micro-CT, spacing 1e-5, ParaView's unit distance following
// it) has extinctions of 1e5 per metre, past half precision's range, and one in
// micrometres 1e-5, below its normal range; either lost its multiple scattering
// silently. Measured in a power of two near the voxel size, the same matter stores the
// same numbers whatever the data's unit. A power of two scales exactly, so volumes with
// voxels of about one unit (the usual millimetres) keep unit 1 and their bits.
#ifndef ScattererTransportUnits_h
#define ScattererTransportUnits_h

#include "vtkScattererTransportVolume.h"

namespace scatterer_gpu
{
/** The transport's length unit for @p in: the power of two nearest (in log) the
 * geometric mean of a voxel's world edge lengths; 1 where that is not finite. */
double TransportLengthUnit(const vtkScattererTransportVolume::Inputs& in);

/**
 * @p in with every world length in units of @p unit: the placement, clipping planes,
 * positional lights (and their attenuation, 1 / (a0 + a1 d + a2 d^2)), the kernels'
 * photon offsets, and the medium's extinction (per length). Optical depths, light and
 * colours are unchanged.
 */
void ToTransportUnits(vtkScattererTransportVolume::Inputs& in, double unit);
}

#endif
