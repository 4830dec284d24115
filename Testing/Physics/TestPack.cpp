// GPU packing layout and size; half-float conversion.
#include <scatterer/Half.h>
#include <scatterer/Pack.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

using namespace scatterer;

namespace {

std::vector<std::vector<Template>> smallSet()
{
  GeneratorSettings s;
  s.templatesPerMaterial = 3;
  std::vector<Material> materials(2);
  materials[0].opacity = 0.9; // few photons
  materials[1].opacity = 0.5;
  return generateAllTemplates(materials, s);
}

} // namespace

TEST(Pack, OneTemplatePerRowPhotonPerTexelZerosAfter)
{
  const auto set = smallSet();
  const PackedTemplates p = packTemplates(set, 64);
  ASSERT_EQ(p.height, 6);
  ASSERT_EQ(p.rgba.size(), static_cast<std::size_t>(p.width * p.height * 4));
  EXPECT_EQ(p.materialFirstRow, (std::vector<int>{ 0, 3 }));
  EXPECT_EQ(p.materialRowCount, (std::vector<int>{ 3, 3 }));
  int widest = 0;
  for (std::size_t m = 0; m < set.size(); ++m) {
    for (std::size_t t = 0; t < set[m].size(); ++t) {
      const std::size_t row = m * 3 + t;
      const auto& photons = set[m][t].photons;
      const int count = static_cast<int>(std::min<std::size_t>(photons.size(), 64));
      widest = std::max(widest, count);
      EXPECT_EQ(p.photonCount[row], count);
      for (int j = 0; j < p.width; ++j) {
        const float* texel = &p.rgba[(row * p.width + j) * 4];
        if (j < count) {
          const Photon& ph = photons[static_cast<std::size_t>(j)];
          EXPECT_EQ(texel[0], ph.position.x);
          EXPECT_EQ(texel[1], ph.position.y);
          EXPECT_EQ(texel[2], ph.position.z);
          EXPECT_EQ(texel[3], ph.intensity);
          EXPECT_GT(texel[3], 0.0f);
        } else {
          for (int c = 0; c < 4; ++c) {
            EXPECT_EQ(texel[c], 0.0f) << row << " " << j;
          }
        }
      }
    }
  }
  EXPECT_EQ(p.width, widest);
  EXPECT_EQ(p.byteCount(), static_cast<std::size_t>(p.width) * 6 * 16);
  EXPECT_TRUE(p.rgbaHalf.empty());
}

TEST(Pack, CapKeepsBrightestAndReportsTheRest)
{
  const auto set = smallSet();
  const PackedTemplates p = packTemplates(set, 5);
  EXPECT_EQ(p.width, 5);
  for (std::size_t row = 0; row < 6; ++row) {
    const Template& t = set[row / 3][row % 3];
    EXPECT_EQ(p.photonCount[row], std::min<int>(5, static_cast<int>(t.photons.size())));
    double rest = 0.0;
    for (std::size_t j = 5; j < t.photons.size(); ++j) {
      rest += t.photons[j].intensity;
    }
    EXPECT_DOUBLE_EQ(p.truncatedIntensity[row], rest);
  }
}

TEST(Pack, FourMaterialsEightTemplatesFitSixteenKilobytesAsHalf)
{
  const auto set = generateAllTemplates(exampleTissueMaterials(), GeneratorSettings{});
  const PackedTemplates full = packTemplates(set, 64, TexelFormat::RGBA32F);
  const PackedTemplates half = packTemplates(set, 64, TexelFormat::RGBA16F);
  EXPECT_EQ(full.height, 32);
  EXPECT_LE(full.width, 64);
  EXPECT_EQ(full.byteCount(), static_cast<std::size_t>(full.width) * 32 * 16);
  EXPECT_LE(half.byteCount(), 16u * 1024u); // the target; RGBA32F needs twice this
  RecordProperty("rgba32f_bytes", static_cast<int>(full.byteCount()));
  RecordProperty("rgba16f_bytes", static_cast<int>(half.byteCount()));
  // Half texels are the rounded float texels, and the bits agree with the floats.
  ASSERT_EQ(half.rgbaHalf.size(), half.rgba.size());
  for (std::size_t i = 0; i < half.rgba.size(); ++i) {
    ASSERT_EQ(halfToFloat(half.rgbaHalf[i]), half.rgba[i]);
    ASSERT_NEAR(half.rgba[i], full.rgba[i], 1e-3f * std::max(1.0f, std::fabs(full.rgba[i])));
  }
  for (std::size_t row = 0; row < 32; ++row) {
    const int n = half.photonCount[row];
    if (n < half.width) {
      EXPECT_EQ(half.rgba[(row * half.width + n) * 4 + 3], 0.0f); // the row's stop marker
    }
  }
}

TEST(Pack, RejectsBadCapsAndHandlesEmptyInput)
{
  EXPECT_THROW(packTemplates({}, 0), std::invalid_argument);
  EXPECT_THROW(packTemplates({}, kMaxPackWidth + 1), std::invalid_argument);
  const PackedTemplates empty = packTemplates({}, 64);
  EXPECT_EQ(empty.width, 0);
  EXPECT_EQ(empty.height, 0);
  EXPECT_EQ(empty.byteCount(), 0u);
}

TEST(Half, EveryFiniteHalfRoundTrips)
{
  for (std::uint32_t bits = 0; bits < 0x10000u; ++bits) {
    const auto h = static_cast<std::uint16_t>(bits);
    const float f = halfToFloat(h);
    if (std::isnan(f)) {
      EXPECT_TRUE(std::isnan(halfToFloat(floatToHalf(f))));
      continue;
    }
    ASSERT_EQ(floatToHalf(f), h) << std::hex << bits;
  }
}

TEST(Half, RoundsToNearestEven)
{
  EXPECT_EQ(floatToHalf(1.0f), 0x3C00u);
  EXPECT_EQ(floatToHalf(1.0f + std::ldexp(1.0f, -11)), 0x3C00u);     // tie -> even
  EXPECT_EQ(floatToHalf(1.0f + 3 * std::ldexp(1.0f, -11)), 0x3C02u); // tie -> even (up)
  EXPECT_EQ(floatToHalf(65504.0f), 0x7BFFu);
  EXPECT_EQ(floatToHalf(65520.0f), 0x7C00u);              // rounds past the largest half
  EXPECT_EQ(floatToHalf(std::ldexp(1.0f, -25)), 0x0000u); // tie with 0 -> 0
  EXPECT_EQ(floatToHalf(std::ldexp(1.5f, -25)), 0x0001u); // smallest subnormal
  EXPECT_EQ(floatToHalf(-std::ldexp(1.0f, -24)), 0x8001u);
  EXPECT_EQ(floatToHalf(std::numeric_limits<float>::infinity()), 0x7C00u);
  EXPECT_TRUE(std::isnan(halfToFloat(floatToHalf(std::nanf("")))));
}
