// Deterministic random numbers for the reference renderer: the physics core's PCG32
// (PCG-XSH-RR 64/32, O'Neill 2014) seeded through SplitMix64 (scatterer/Random.h). No
// std:: distributions (their output is implementation-defined); the float conversion is
// exact, so a seed gives the same image with every standard library and any thread count.
#pragma once

#include <scatterer/Random.h>

#include <cstdint>

namespace scatterer_reference
{

// scatterer::Pcg32::forStream(seed, stream) (SplitMix64 mixing of (seed, stream), so that
// neighbouring pixels get unrelated streams), drawing floats.
class Pcg32
{
public:
  Pcg32(std::uint64_t seed, std::uint64_t stream)
    : rng_(scatterer::Pcg32::forStream(seed, stream))
  {
  }

  std::uint32_t next() { return rng_.next(); }

  // Uniform in [0, 1): the top 24 bits, exactly representable as float.
  float uniform() { return rng_.uniformFloat(); }

private:
  scatterer::Pcg32 rng_;
};

} // namespace scatterer_reference
