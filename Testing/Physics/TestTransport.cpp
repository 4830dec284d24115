// The physics the light transport volume takes: VTK's extinction convention and
// the scatterer templates merged into an in-scattering kernel.
#include <scatterer/Template.h>
#include <scatterer/Transport.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

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
