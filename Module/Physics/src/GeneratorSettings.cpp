#include <scatterer/GeneratorSettings.h>

#include "Describe.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace scatterer {

namespace {

void requireInt(const char* what, int value, int lo, int hi)
{
  if (value < lo || value > hi) {
    throw std::invalid_argument(std::string("GeneratorSettings: ") + what + " must be in [" +
                                std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                                std::to_string(value));
  }
}

// (lo, hi]: zero is as invalid as a negative value for these lengths and thresholds.
void requireOpenClosed(const char* what, double value, double lo, double hi)
{
  if (!(std::isfinite(value) && value > lo && value <= hi)) {
    throw std::invalid_argument(std::string("GeneratorSettings: ") + what +
                                " must be a finite number in (" + detail::describe(lo) + ", " +
                                detail::describe(hi) + "], got " + detail::describe(value));
  }
}

} // namespace

void GeneratorSettings::validate() const
{
  requireInt("initialLights", initialLights, 1, kMaxInitialLights);
  requireOpenClosed("threshold", threshold, 0.0, 1.0);
  requireInt("templatesPerMaterial", templatesPerMaterial, 1, kMaxTemplatesPerMaterial);
  requireOpenClosed("stepLength", stepLength, 0.0, 1.0);
  if (!(std::isfinite(latticeCell) && latticeCell >= kMinLatticeCell && latticeCell <= 1.0)) {
    throw std::invalid_argument(std::string("GeneratorSettings: latticeCell must be a finite "
                                            "number in [") +
                                detail::describe(kMinLatticeCell) + ", 1], got " +
                                detail::describe(latticeCell));
  }
  requireInt("maxPhotonsPerTemplate", maxPhotonsPerTemplate, 1, kMaxPhotonsCap);
  requireInt("maxEventsPerTemplate", maxEventsPerTemplate, 1, kMaxEventsCap);
}

} // namespace scatterer
