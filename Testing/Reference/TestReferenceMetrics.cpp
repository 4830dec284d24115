// The error metrics on tiny synthetic images with known answers.
#include "scatterer_reference/Metrics.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace scatterer_reference;

namespace
{
std::vector<float> constant(int w, int h, float v)
{
  return std::vector<float>(static_cast<size_t>(w) * h * 3, v);
}
std::vector<float> ramp(int w, int h)
{
  std::vector<float> img(static_cast<size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        img[(static_cast<size_t>(y) * w + x) * 3 + c] =
          0.1f + 0.8f * float((x * 7 + y * 3) % 16) / 15.0f;
  return img;
}
}

TEST(ReferenceMetrics, IdenticalImages)
{
  const auto a = ramp(16, 16);
  const Metrics m = compare(a, a, 16, 16);
  EXPECT_NEAR(m.scale, 1.0, 1e-12);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr));
  EXPECT_NEAR(m.ssim, 1.0, 1e-12);
}

TEST(ReferenceMetrics, ConstantOffsetWithoutNormalisation)
{
  // RMSE of a constant 0.1 offset is 0.1; PSNR = 20 log10(0.6 / 0.1).
  const auto r = constant(16, 16, 0.6f), t = constant(16, 16, 0.5f);
  const Metrics m = compare(t, r, 16, 16, Normalisation::None);
  EXPECT_NEAR(m.rmse, 0.1, 1e-6);
  EXPECT_NEAR(m.psnr, 20.0 * std::log10(6.0), 1e-4);
  // SSIM of two constant images a, b (no variance): (2ab + C1) / (a^2 + b^2 + C1).
  const double C1 = 1e-4;
  EXPECT_NEAR(m.ssim, (2 * 0.5 * 0.6 + C1) / (0.25 + 0.36 + C1), 1e-6);
}

TEST(ReferenceMetrics, LeastSquaresExposureRemovesAGlobalScale)
{
  const auto r = ramp(16, 16);
  auto t = r;
  for (float& v : t)
    v *= 0.25f;
  const Metrics m = compare(t, r, 16, 16);
  EXPECT_NEAR(m.scale, 4.0, 1e-5);
  EXPECT_NEAR(m.rmse, 0.0, 1e-6);
  EXPECT_NEAR(m.ssim, 1.0, 1e-6);
  // Without the normalisation the scale is an error.
  EXPECT_GT(compare(t, r, 16, 16, Normalisation::None).rmse, 0.1);
}

TEST(ReferenceMetrics, SsimFallsWithStructureLoss)
{
  const auto r = ramp(32, 32);
  const auto flat = constant(32, 32, 0.5f);
  const double s = ssim(flat, r, 32, 32);
  EXPECT_LT(s, 0.2); // no correlation: the structure term is C2 / (var + C2)
  auto noisy = r;
  for (size_t i = 0; i < noisy.size(); ++i)
    noisy[i] += (i / 3) % 2 ? 0.05f : -0.05f;
  const double sn = ssim(noisy, r, 32, 32);
  EXPECT_LT(sn, 1.0);
  EXPECT_GT(sn, s);
}

TEST(ReferenceMetrics, ErrorMapIsPerPixelLuminanceDifference)
{
  auto r = constant(4, 4, 0.5f), t = r;
  t[3 * 5 + 0] = 1.5f; // red of pixel 5 up by 1: luminance up by 0.2126
  const auto e = errorMap(t, r, 4, 4);
  ASSERT_EQ(e.size(), 16u);
  for (int i = 0; i < 16; ++i)
    EXPECT_NEAR(e[i], i == 5 ? 0.2126f : 0.0f, 1e-6) << i;
}

TEST(ReferenceMetrics, MismatchedSizesThrow)
{
  EXPECT_THROW(compare(constant(4, 4, 1), constant(4, 5, 1), 4, 4), std::invalid_argument);
}
