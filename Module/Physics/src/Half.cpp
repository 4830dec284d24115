#include <scatterer/Half.h>

#include <cstring>

namespace scatterer {

std::uint16_t floatToHalf(float value)
{
  std::uint32_t x;
  std::memcpy(&x, &value, sizeof x);
  const auto sign = static_cast<std::uint16_t>((x >> 16u) & 0x8000u);
  const std::uint32_t absx = x & 0x7FFFFFFFu;

  if (absx >= 0x7F800000u) { // inf stays inf; NaN stays a (quiet) NaN
    return static_cast<std::uint16_t>(sign | 0x7C00u | (absx > 0x7F800000u ? 0x0200u : 0u));
  }
  if (absx >= 0x477FF000u) { // >= 65520 rounds past the largest half (65504)
    return static_cast<std::uint16_t>(sign | 0x7C00u);
  }
  const std::uint32_t exponent = absx >> 23u;
  if (exponent < 113u) {   // below 2^-14: a subnormal half, or zero
    if (exponent < 102u) { // below 2^-25: rounds to zero
      return sign;
    }
    const std::uint32_t mantissa = (absx & 0x7FFFFFu) | 0x800000u;
    const std::uint32_t shift = 126u - exponent; // value / 2^-24 = mantissa >> shift
    std::uint32_t h = mantissa >> shift;
    const std::uint32_t rest = mantissa & ((1u << shift) - 1u);
    const std::uint32_t half = 1u << (shift - 1u);
    if (rest > half || (rest == half && (h & 1u))) {
      ++h; // may carry into the smallest normal: still the right encoding
    }
    return static_cast<std::uint16_t>(sign | h);
  }
  std::uint32_t h = ((exponent - 112u) << 10u) | ((absx & 0x7FFFFFu) >> 13u);
  const std::uint32_t rest = absx & 0x1FFFu;
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) {
    ++h; // a carry into the exponent is correct rounding
  }
  return static_cast<std::uint16_t>(sign | h);
}

float halfToFloat(std::uint16_t bits)
{
  const std::uint32_t sign = static_cast<std::uint32_t>(bits & 0x8000u) << 16u;
  const std::uint32_t exponent = (bits >> 10u) & 0x1Fu;
  std::uint32_t mantissa = bits & 0x3FFu;
  std::uint32_t x;
  if (exponent == 0x1Fu) {
    x = sign | 0x7F800000u | (mantissa << 13u);
  } else if (exponent != 0u) {
    x = sign | ((exponent + 112u) << 23u) | (mantissa << 13u);
  } else if (mantissa == 0u) {
    x = sign;
  } else { // subnormal half: normalise
    std::uint32_t e = 113u;
    while ((mantissa & 0x400u) == 0u) {
      mantissa <<= 1u;
      --e;
    }
    x = sign | (e << 23u) | ((mantissa & 0x3FFu) << 13u);
  }
  float value;
  std::memcpy(&value, &x, sizeof value);
  return value;
}

} // namespace scatterer
