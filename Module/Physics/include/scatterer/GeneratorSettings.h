// Parameters of template generation shared by all materials (paper section 3.2).
#pragma once

#include "scatterer/IlluminationSettings.h"

#include <cstdint>

namespace scatterer {

struct GeneratorSettings {
  int initialLights = 4; // L: the initial energy 1 is split over L lights (Table 2)
  // a packet below threshold * (1 / L) stops branching
  double threshold = illumination::GeneratorThreshold.Default;
  // templates per material, each from its own random stream
  int templatesPerMaterial = illumination::TemplatesPerMaterial.Default;
  std::uint64_t seed = 0x5CA77E2E5EEDull;

  double stepLength = 0.05;  // dx of Eq. 2: distance between scattering events, template radii
  double latticeCell = 0.02; // edge of the merge lattice, template radii

  // Hard caps: whatever the threshold (1e-9 included), one template never has more
  // photons or processes more packets than this; Template::capped reports a hit.
  // 65536 packets take a few milliseconds, so a template is bounded in time too.
  int maxPhotonsPerTemplate = 4096;
  int maxEventsPerTemplate = 65536;

  // Throws std::invalid_argument naming the parameter when a value is NaN, infinite or
  // outside its documented range (see docs/model.md).
  void validate() const;
};

// Limits that validate() enforces on the settings themselves, so no setting can make
// generation unbounded.
constexpr int kMaxInitialLights = 1024;
constexpr int kMaxTemplatesPerMaterial = 1024;
constexpr int kMaxPhotonsCap = 1 << 20;
constexpr int kMaxEventsCap = 1 << 24;
constexpr double kMinLatticeCell = 1e-4;

} // namespace scatterer
