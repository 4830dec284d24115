// IEEE 754 binary16 conversion, written out so packed textures are identical on every
// platform (no F16C / compiler-specific rounding).
#pragma once

#include <cstdint>

namespace scatterer {

// Round to nearest, ties to even; overflow gives +-inf, NaN stays NaN.
std::uint16_t floatToHalf(float value);
// Exact.
float halfToFloat(std::uint16_t bits);

} // namespace scatterer
