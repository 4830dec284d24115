// The RNG must match its published reference streams: that is what makes templates
// bit-identical across platforms.
#include <scatterer/Random.h>

#include <gtest/gtest.h>

#include <set>

using scatterer::Pcg32;
using scatterer::SplitMix64;

TEST(Random, Pcg32MatchesReferenceStream)
{
  // pcg32-demo (pcg-c-basic) with pcg32_srandom_r(&rng, 42u, 54u).
  Pcg32 rng(42u, 54u);
  const std::uint32_t expected[6] = { 0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u,
    0xbfa4784bu, 0xcbed606eu };
  for (std::uint32_t e : expected) {
    EXPECT_EQ(rng.next(), e);
  }
}

TEST(Random, SplitMix64MatchesReferenceStream)
{
  // Vigna's splitmix64.c seeded with 0.
  SplitMix64 mix(0);
  EXPECT_EQ(mix.next(), 0xE220A8397B1DCDAFull);
  EXPECT_EQ(mix.next(), 0x6E789E6AA1B965F4ull);
  EXPECT_EQ(mix.next(), 0x06C45D188009454Full);
}

TEST(Random, UniformIsInUnitIntervalAndCentred)
{
  Pcg32 rng = Pcg32::forStream(7, 0);
  double sum = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    const float f = rng.uniformFloat();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    ASSERT_GE(f, 0.0f);
    ASSERT_LT(f, 1.0f);
    sum += u;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.005);
}

TEST(Random, StreamsOfOneSeedDiffer)
{
  std::set<std::uint32_t> first;
  for (std::uint64_t stream = 0; stream < 64; ++stream) {
    first.insert(Pcg32::forStream(123, stream).next());
  }
  EXPECT_EQ(first.size(), 64u);
}
