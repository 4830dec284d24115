// Deterministic random numbers for the reference renderer: PCG32 (PCG-XSH-RR 64/32,
// O'Neill 2014) seeded through SplitMix64. No std:: distributions (their output is
// implementation-defined); the float conversion is exact, so a seed gives the same
// image with every standard library and any thread count.
#pragma once

#include <cstdint>

namespace scatterer_reference {

class Pcg32 {
public:
  Pcg32(std::uint64_t seed, std::uint64_t stream)
  {
    // SplitMix64 mixing of (seed, stream) so that neighbouring pixels get unrelated streams.
    std::uint64_t z = seed ^ (stream * 0xD1B54A32D192ED03ull);
    const std::uint64_t a = mix(z);
    const std::uint64_t b = mix(z);
    inc_ = (b << 1u) | 1u;
    state_ = 0;
    next();
    state_ += a;
    next();
  }

  std::uint32_t next()
  {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1): the top 24 bits, exactly representable as float.
  float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }

private:
  static std::uint64_t mix(std::uint64_t& s)
  {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t state_ = 0;
  std::uint64_t inc_ = 1;
};

} // namespace scatterer_reference
