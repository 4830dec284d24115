// Deterministic random numbers for template generation.
//
// std:: distributions are implementation-defined, so the same seed gives different
// templates with libstdc++, libc++ and MSVC. Everything here is specified down to the
// bit: SplitMix64 derives seeds, PCG32 draws numbers, and the float conversions below
// are exact (no rounding), so a seed means the same stream on every platform.
#pragma once

#include <cstdint>

namespace scatterer {

// SplitMix64 (Steele, Lea & Flood 2014; constants from Vigna's reference code).
// Used only to turn (seed, stream) pairs into well-mixed PCG32 states: nearby seeds
// such as 0, 1, 2 must not give correlated templates.
class SplitMix64 {
public:
  explicit SplitMix64(std::uint64_t state) : state_(state) {}
  std::uint64_t next()
  {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

private:
  std::uint64_t state_;
};

// PCG32 = PCG-XSH-RR 64/32 (O'Neill 2014), identical to pcg32_srandom_r/pcg32_random_r
// of the pcg-c-basic reference, so its published test vectors apply.
class Pcg32 {
public:
  Pcg32(std::uint64_t initState, std::uint64_t initSeq)
  {
    inc_ = (initSeq << 1u) | 1u;
    next();
    state_ += initState;
    next();
  }

  // The generator for one (seed, stream) pair, e.g. (settings seed, template index).
  // The stream is multiplied by an odd constant (a bijection) before mixing, so distinct
  // streams of one seed always get distinct SplitMix64 inputs.
  static Pcg32 forStream(std::uint64_t seed, std::uint64_t stream)
  {
    SplitMix64 mix(seed ^ (stream * 0xD1B54A32D192ED03ull));
    const std::uint64_t initState = mix.next();
    const std::uint64_t initSeq = mix.next();
    return Pcg32(initState, initSeq);
  }

  std::uint32_t next()
  {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform double in [0, 1) with 53 random bits (27 + 26 from two draws, in this
  // order). Both steps are exact in IEEE double, so no platform rounding enters.
  double uniform()
  {
    const std::uint64_t hi = next() >> 5u; // 27 bits
    const std::uint64_t lo = next() >> 6u; // 26 bits
    return (static_cast<double>(hi) * 67108864.0 + static_cast<double>(lo)) *
           (1.0 / 9007199254740992.0);
  }

  // Uniform float in [0, 1) with 24 random bits (exact).
  float uniformFloat() { return static_cast<float>(next() >> 8u) * (1.0f / 16777216.0f); }

private:
  std::uint64_t state_ = 0;
  std::uint64_t inc_ = 1;
};

} // namespace scatterer
