// The change key of the light transport volume: a fingerprint of everything one build
// of vtkScattererTransportVolume depends on, so that Update() rebuilds only when one
// of those inputs changed.
#ifndef ScattererTransportKey_h
#define ScattererTransportKey_h

#include "vtkScattererTransportVolume.h" // for Inputs

#include <cstdint> // for std::uint64_t

namespace scatterer_gpu
{
/**
 * The fingerprint of @p inputs: equal for inputs that build the same transport volume.
 * The tables (medium, materials, kernels) count by their TablesVersion, not their
 * content, so that the key is cheap enough for every frame.
 */
std::uint64_t TransportKey(const vtkScattererTransportVolume::Inputs& inputs);

/**
 * The fingerprint of what no light changes (the volume, its transfer functions and
 * placement, clipping, cropping, the materials, the grid): the passes that depend on
 * these alone (ScattererTransportMediumPasses) run again only when it changes.
 */
std::uint64_t MediumKey(const vtkScattererTransportVolume::Inputs& inputs);
}

#endif
