// The physics the light transport volume takes: VTK's extinction convention and
// the scatterer templates merged into an in-scattering kernel.
#include <scatterer/Template.h>
#include <scatterer/Transport.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

TEST(Transport, ExtinctionReproducesVtkOpacityCorrection)
{
  // d world units of constant alpha (per unit distance u) must let through
  // (1 - alpha)^(d / u): VTK's opacity correction.
  const double alpha = 0.3, u = 2.0, d = 5.0;
  const double sigma = scatterer::extinctionFromOpacity(alpha, u);
  EXPECT_NEAR(std::exp(-sigma * d), std::pow(1.0 - alpha, d / u), 1e-12);
  EXPECT_EQ(scatterer::extinctionFromOpacity(0.0, 1.0), 0.0);
  EXPECT_TRUE(std::isfinite(scatterer::extinctionFromOpacity(1.0, 1.0)));
  EXPECT_GT(scatterer::extinctionFromOpacity(1.0, 1.0), 10.0);
  EXPECT_EQ(scatterer::extinctionFromOpacity(std::nan(""), 1.0), 0.0);
  EXPECT_THROW(scatterer::extinctionFromOpacity(0.5, 0.0), std::invalid_argument);
  EXPECT_THROW(scatterer::extinctionFromOpacity(0.5, INFINITY), std::invalid_argument);
}

TEST(Transport, KernelRadiusPutsPhotonsInMeanFreePathsOfTheScene)
{
  scatterer::Material m;
  m.opacity = 0.5;
  const double lambdaRadii = scatterer::meanFreePath(m); // 1 / (sqrt 2 * 0.5)
  const double sigma = 0.25;                             // mean free path 4 world units
  const double radius = scatterer::kernelRadius(m, sigma, 0.0, 1e9);
  // One mean free path of the template (lambdaRadii radii) is one of the scene (1 / sigma).
  EXPECT_NEAR(radius * lambdaRadii, 1.0 / sigma, 1e-12);
  EXPECT_EQ(scatterer::kernelRadius(m, sigma, 0.0, 2.0), 2.0);
  EXPECT_EQ(scatterer::kernelRadius(m, sigma, 10.0, 20.0), 10.0);
  EXPECT_EQ(scatterer::kernelRadius(m, 0.0, 0.0, 3.0), 3.0);
}

TEST(Transport, MergedKernelIsTheMeanOfTheTemplates)
{
  scatterer::Template a, b;
  a.photons = { { glm::vec3(1, 0, 0), 0.6f }, { glm::vec3(0, 1, 0), 0.2f } };
  b.photons = { { glm::vec3(0, 0, 1), 0.4f } };
  const auto k = scatterer::mergedKernel({ a, b }, 8, 2.0);
  ASSERT_EQ(k.size(), 3u);
  // Template weight 1/2 each: 0.3, 0.2, 0.1 -> normalised 0.5, 0.333, 0.167, sorted.
  EXPECT_NEAR(k[0].weight, 0.5f, 1e-6);
  EXPECT_NEAR(k[1].weight, 1.0f / 3.0f, 1e-6);
  EXPECT_NEAR(k[2].weight, 1.0f / 6.0f, 1e-6);
  EXPECT_EQ(k[0].offset, glm::vec3(2, 0, 0)); // scaled by the radius
  EXPECT_EQ(k[1].offset, glm::vec3(0, 0, 2));
  const auto capped = scatterer::mergedKernel({ a, b }, 2, 1.0);
  ASSERT_EQ(capped.size(), 2u);
  EXPECT_NEAR(capped[0].weight + capped[1].weight, 1.0f, 1e-6);
  EXPECT_TRUE(scatterer::mergedKernel({}, 4, 1.0).empty());
  EXPECT_THROW(scatterer::mergedKernel({ a }, 0, 1.0), std::invalid_argument);
  EXPECT_THROW(scatterer::mergedKernel({ a }, 4, -1.0), std::invalid_argument);
}

TEST(Transport, GeneratedKernelIsDeterministicAndNormalised)
{
  scatterer::Material m;
  m.opacity = 0.4;
  scatterer::GeneratorSettings s;
  s.templatesPerMaterial = 4;
  const auto templates = scatterer::generateTemplates(m, s);
  const auto k1 = scatterer::mergedKernel(templates, 24, 3.0);
  const auto k2 = scatterer::mergedKernel(templates, 24, 3.0);
  ASSERT_EQ(k1.size(), 24u);
  double sum = 0.0;
  for (size_t i = 0; i < k1.size(); ++i) {
    EXPECT_EQ(k1[i].offset, k2[i].offset);
    EXPECT_LE(glm::length(k1[i].offset), 3.0f + 1e-5f);
    if (i > 0) {
      EXPECT_LE(k1[i].weight, k1[i - 1].weight);
    }
    sum += k1[i].weight;
  }
  EXPECT_NEAR(sum, 1.0, 1e-5);
}

TEST(Transport, KernelCentroidAndSpreadOnTheGrid)
{
  const std::vector<scatterer::KernelPhoton> kernel = { { glm::vec3(1, 0, 0), 0.75f },
    { glm::vec3(-1, 2, 0), 0.25f }, { glm::vec3(9, 9, 9), 0.0f } };
  const glm::vec3 c = scatterer::kernelCentroid(kernel);
  EXPECT_NEAR(c.x, 0.5f, 1e-6);
  EXPECT_NEAR(c.y, 0.5f, 1e-6);
  EXPECT_NEAR(c.z, 0.0f, 1e-6);
  // Texels 4 world units along x, 0.5 along y: photon 1 lies 1.5 from c along y, 3 texels;
  // the weightless photon does not count.
  const glm::mat3 worldToGrid(glm::vec3(0.25f, 0, 0), glm::vec3(0, 2.0f, 0), glm::vec3(0, 0, 1));
  EXPECT_NEAR(scatterer::kernelSpread(kernel, worldToGrid), 3.0, 1e-6);
  EXPECT_EQ(scatterer::kernelCentroid({}), glm::vec3(0.0f));
  EXPECT_EQ(scatterer::kernelSpread({}, worldToGrid), 0.0);
  EXPECT_EQ(scatterer::kernelCentroid({ { glm::vec3(1, 1, 1), 0.0f } }), glm::vec3(0.0f));
}

TEST(Transport, KernelIsReadAtItsCentroidOnlyWhileItSpreadsLittle)
{
  const float s = static_cast<float>(scatterer::kCentroidReadSpread);
  const glm::mat3 unit(1.0f);
  const auto pair = [](float half) {
    return std::vector<scatterer::KernelPhoton>{ { glm::vec3(half, 0, 0), 0.5f },
      { glm::vec3(-half, 0, 0), 0.5f } };
  };
  EXPECT_TRUE(scatterer::readsAtCentroid(pair(0.99f * s), unit));
  EXPECT_FALSE(scatterer::readsAtCentroid(pair(1.01f * s), unit));
  // On a grid twice as coarse the same kernel spreads half as many texels.
  EXPECT_TRUE(scatterer::readsAtCentroid(pair(1.5f * s), unit * 0.5f));
  // A degenerate grid (non-finite map): photon by photon.
  const glm::mat3 broken(glm::vec3(NAN, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
  EXPECT_FALSE(scatterer::readsAtCentroid(pair(0.01f * s), broken));
}

// The bound kCentroidReadSpread rests on: for a field trilinear between texel centres, a
// kernel whose photons lie within s texels of its centroid c along each axis averages to
// within 3 s G of the field at c, G the largest difference between neighbouring texels.
TEST(Transport, CentroidReadIsWithinItsBoundOfThePhotonsMean)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), side(-1.0f, 1.0f);
  const int n = 4;
  std::vector<float> texels(n * n * n);
  const auto at = [&](int i, int j, int k) { return texels[i + n * (j + n * k)]; };
  const auto field = [&](glm::vec3 p) {
    const glm::ivec3 i0 = glm::clamp(glm::ivec3(glm::floor(p)), glm::ivec3(0), glm::ivec3(n - 2));
    const glm::vec3 f = p - glm::vec3(i0);
    float v = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::ivec3 d(corner & 1, (corner >> 1) & 1, corner >> 2);
      const glm::vec3 w = glm::mix(glm::vec3(1.0f) - f, f, glm::vec3(d));
      v += w.x * w.y * w.z * at(i0.x + d.x, i0.y + d.y, i0.z + d.z);
    }
    return v;
  };
  double worst = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    for (auto& t : texels) {
      t = unit(random) < 0.5f ? 0.0f : unit(random); // shadow edges: jumps of up to 1
    }
    float G = 0.0f;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i + 1 < n; ++i)
          G = std::max({ G, std::abs(at(i + 1, j, k) - at(i, j, k)),
            std::abs(at(j, i + 1, k) - at(j, i, k)), std::abs(at(j, k, i + 1) - at(j, k, i)) });
    // 24 photons within s of their centroid about a texel centre (a kink of the field).
    const float s = static_cast<float>(scatterer::kCentroidReadSpread);
    std::vector<scatterer::KernelPhoton> kernel;
    for (int j = 0; j < 24; ++j) {
      kernel.push_back(
        { 0.5f * s * glm::vec3(side(random), side(random), side(random)), 0.1f + unit(random) });
    }
    ASSERT_TRUE(scatterer::readsAtCentroid(kernel, glm::mat3(1.0f)));
    const glm::vec3 p(1.0f, 2.0f, 1.0f), c = scatterer::kernelCentroid(kernel);
    double mean = 0.0, weights = 0.0;
    for (const auto& photon : kernel) {
      mean += photon.weight * field(p + photon.offset);
      weights += photon.weight;
    }
    const double error = std::abs(mean / weights - field(p + c));
    const double bound = 3.0 * scatterer::kernelSpread(kernel, glm::mat3(1.0f)) * G;
    EXPECT_LE(error, bound + 1e-6) << "trial " << trial;
    worst = std::max(worst, bound > 0.0 ? error / bound : 0.0);
  }
  std::printf("centroid read: worst error %.3f of the bound 3 s G\n", worst);
  EXPECT_GT(worst, 0.0) << "the kernels straddle no kink: the test checks nothing";
}
