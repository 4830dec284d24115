// The reference path tracer against closed forms. Statistical tolerance: every Monte
// Carlo estimate must lie within 4 standard errors (estimated from the same samples) of
// the exact value, plus 1e-9; with a correct estimator one such check fails by chance
// with probability 6e-5. The furnace test without Russian roulette is exact (every path
// has weight 1 and leaves the medium), so there the tolerance is 1e-6.
#include "scatterer_reference/PathTracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace scatterer_reference;

namespace
{
constexpr double kPi = 3.14159265358979323846;

struct Stat
{
  double sum = 0, sum2 = 0;
  long n = 0;
  void add(double v)
  {
    sum += v;
    sum2 += v * v;
    ++n;
  }
  double mean() const { return sum / n; }
  double se() const { return std::sqrt(std::max(0.0, sum2 / n - mean() * mean()) / (n - 1)); }
};

#define EXPECT_WITHIN_4SE(stat, exact)                                                             \
  std::printf(                                                                                     \
    "  estimate %.6f +- %.6f (1 SE), exact %.6f\n", (stat).mean(), (stat).se(), double(exact));    \
  EXPECT_NEAR((stat).mean(), (exact), 4.0 * (stat).se() + 1e-9)                                    \
    << "mean " << (stat).mean() << " se " << (stat).se() << " exact " << (exact)

// A box [-h, h]^2 x [0, thickness] of constant scalar 0 and a one-entry table.
Scene slab(int nz, double thickness, double sigma, glm::vec3 albedo, double half = 500.0)
{
  Scene s;
  Volume& v = s.volume;
  v.dims = glm::ivec3(2, 2, nz);
  v.origin = glm::dvec3(-half, -half, 0.0);
  v.spacing = glm::dvec3(2 * half, 2 * half, thickness / (nz - 1));
  v.scalars.assign(static_cast<size_t>(4) * nz, 0.0f);
  v.table.sigmaT = { static_cast<float>(sigma) };
  v.table.albedo = { albedo };
  return s;
}

// Renders an 8x8 image straight down through the slab at 512 samples per pixel.
RenderResult renderThroughSlab(Scene s)
{
  s.camera.position = { 0, 0, 100 };
  s.camera.focalPoint = { 0, 0, 0 };
  s.camera.viewUp = { 0, 1, 0 };
  s.camera.viewAngleDeg = 1.0;
  s.camera.width = s.camera.height = 8;
  PathTracer tracer(s);
  RenderSettings rs;
  rs.samplesPerPixel = 512;
  rs.threads = 2;
  return tracer.render(rs);
}
}

TEST(ReferenceClosedForms, SigmaFromOpacityMatchesVtkOpacityCorrection)
{
  // alpha per u = 2 world units: through d = 5 units the opacity is 1 - (1 - alpha)^(d/u).
  const double alpha = 0.3, u = 2.0, d = 5.0;
  EXPECT_NEAR(
    1.0 - std::exp(-sigmaFromOpacity(alpha, u) * d), 1.0 - std::pow(1.0 - alpha, d / u), 1e-12);
  EXPECT_EQ(sigmaFromOpacity(0.0, 1.0), 0.0);
  EXPECT_TRUE(std::isfinite(sigmaFromOpacity(1.0, 1.0)));
}

TEST(ReferenceClosedForms, BeerLambertHomogeneousSlabIndependentOfVoxelCount)
{
  const double sigma = 0.7, d = 2.0, exact = std::exp(-sigma * d);
  for (int nz : { 2, 5, 64 })
  {
    PathTracer tracer(slab(nz, d, sigma, glm::vec3(0.0f)));
    Stat st;
    for (int i = 0; i < 100000; ++i)
      st.add(tracer.transmittance({ 0.3, -0.2, -1.0 }, { 0, 0, 1 }, 1e9, 7, i));
    EXPECT_WITHIN_4SE(st, exact) << " nz " << nz;
  }
}

TEST(ReferenceClosedForms, BeerLambertLinearRampThroughMacroCells)
{
  // sigma rises linearly from 0 to 2 s0 across the slab (trilinear scalars, a two-entry
  // table): optical depth s0 * d, whatever the grid and macro-cell sizes.
  const double s0 = 0.8, d = 3.0, exact = std::exp(-s0 * d);
  for (int nz : { 2, 7, 40 })
    for (int macro : { 1, 4 })
    {
      Scene s = slab(nz, d, 0.0, glm::vec3(0.0f));
      for (int k = 0; k < nz; ++k)
        for (int q = 0; q < 4; ++q)
          s.volume.scalars[static_cast<size_t>(k) * 4 + q] = float(k) / float(nz - 1);
      s.volume.table.scalarMin = 0.0;
      s.volume.table.scalarMax = 1.0;
      s.volume.table.sigmaT = { 0.0f, static_cast<float>(2 * s0) };
      s.volume.table.albedo = { glm::vec3(0.0f), glm::vec3(0.0f) };
      PathTracer tracer(s, macro);
      Stat st;
      // Oblique ray: path length d / cos.
      const glm::dvec3 dir = glm::normalize(glm::dvec3(0.6, 0.0, 0.8));
      for (int i = 0; i < 100000; ++i)
        st.add(tracer.transmittance({ 0.0, 0.0, -1.0 }, dir, 1e9, 11, i));
      EXPECT_WITHIN_4SE(st, std::exp(-s0 * d / 0.8)) << " nz " << nz << " macro " << macro;
      (void)exact;
    }
}

TEST(ReferenceClosedForms, AbsorptionSlabInFrontOfABackgroundLight)
{
  // Albedo 0, uniform background radiance 1: each pixel shows exp(-tau). Through the
  // camera, the renderer's image and its stated standard error.
  const double sigma = 0.5, d = 2.0;
  Scene s = slab(9, d, sigma, glm::vec3(0.0f), 50.0);
  s.environment = glm::dvec3(1.0);
  const RenderResult r = renderThroughSlab(s);
  double mean = 0.0;
  for (size_t p = 0; p < 64; ++p)
    mean += r.rgb[3 * p + 1] / 64.0;
  const double se = r.rmsStandardError / std::sqrt(64.0);
  EXPECT_NEAR(mean, std::exp(-sigma * d), 4.0 * se) << "se " << se;
  EXPECT_GT(r.rmsStandardError, 0.0);
  // The stated per-pixel standard error is that of a Bernoulli(exp(-tau)) mean.
  const double p = std::exp(-sigma * d);
  EXPECT_NEAR(
    r.rmsStandardError, std::sqrt(p * (1 - p) / 512.0), 0.15 * std::sqrt(p * (1 - p) / 512.0));
}

TEST(ReferenceClosedForms, EmissionAbsorptionSlab)
{
  // Albedo 0, emitted radiance Le, no background: looking straight through a
  // slab of optical depth tau shows Le (1 - exp(-tau)).
  const double sigma = 0.6, d = 2.0, Le = 2.0;
  Scene s = slab(9, d, sigma, glm::vec3(0.0f), 50.0);
  s.volume.table.emission = { glm::vec3(static_cast<float>(Le)) };
  const RenderResult r = renderThroughSlab(s);
  double mean = 0.0;
  for (size_t p = 0; p < 64; ++p)
    mean += r.rgb[3 * p] / 64.0;
  const double exact = Le * (1.0 - std::exp(-sigma * d));
  const double se = r.rmsStandardError / std::sqrt(64.0);
  EXPECT_GT(se, 0.0);
  EXPECT_NEAR(mean, exact, 4.0 * se) << "se " << se;
}

namespace
{
// Exact single scattering reflected by a homogeneous slab (Chandrasekhar; van de Hulst's
// first-order reflection): L = a E p mu0 / (mu + mu0) (1 - exp(-tau (1/mu + 1/mu0))).
double singleScatteringReflection(double a, double E, double p, double mu, double mu0, double tau)
{
  return a * E * p * mu0 / (mu + mu0) * (1.0 - std::exp(-tau * (1.0 / mu + 1.0 / mu0)));
}

double hg(double c, double g)
{
  const double den = 1 + g * g - 2 * g * c;
  return (1 - g * g) / (4 * kPi * den * std::sqrt(den));
}
}

TEST(ReferenceClosedForms, SingleScatteringFromAHomogeneousSlab)
{
  const double sigma = 1.3, d = 1.0, a = 0.8;
  const double theta0 = 60.0 * kPi / 180.0, theta = 30.0 * kPi / 180.0;
  const double mu0 = std::cos(theta0), mu = std::cos(theta);
  for (double g : { 0.0, 0.5 })
  {
    Scene s = slab(6, d, sigma, glm::vec3(float(a)));
    s.anisotropy = g;
    s.directionalLights.push_back(
      { glm::dvec3(std::sin(theta0), 0.0, mu0), glm::dvec3(1.0, 0.5, 0.25) });
    PathTracer tracer(s);
    RenderSettings rs;
    rs.maxScatteringOrder = 1;
    const glm::dvec3 dir(-std::sin(theta), 0.0, -mu); // looking down into the slab
    const glm::dvec3 origin = -5.0 * dir + glm::dvec3(0, 0, d);
    const double p = hg(glm::dot(dir, s.directionalLights[0].toLight), g);
    Stat st[3];
    Pcg32 rng(3, 0);
    for (int i = 0; i < 200000; ++i)
    {
      const glm::dvec3 L = tracer.radiance(origin, dir, rng, rs);
      for (int c = 0; c < 3; ++c)
        st[c].add(L[c]);
    }
    for (int c = 0; c < 3; ++c)
    {
      const double E = s.directionalLights[0].irradiance[c];
      EXPECT_WITHIN_4SE(st[c], singleScatteringReflection(a, E, p, mu, mu0, sigma * d))
        << " g " << g << " c " << c;
    }
  }
}

TEST(ReferenceClosedForms, FurnaceAlbedoOneShowsTheEnvironmentEverywhere)
{
  // A thick (tau = 6), non-uniform albedo-1 cube in a uniform white environment: every
  // path keeps weight 1 and leaves the cube, so every pixel is exactly 1 (no roulette).
  Scene s;
  Volume& v = s.volume;
  v.dims = glm::ivec3(6, 6, 6);
  v.spacing = glm::dvec3(1.0);
  for (int i = 0; i < 216; ++i)
    v.scalars.push_back(float(i % 7) / 6.0f);
  v.table.scalarMin = 0;
  v.table.scalarMax = 1;
  v.table.sigmaT = { 0.2f, 3.0f };
  v.table.albedo = { glm::vec3(1.0f), glm::vec3(1.0f) };
  s.environment = glm::dvec3(1.0);
  s.anisotropy = 0.3;
  s.camera.position = { 2.5, -20, 2.5 };
  s.camera.focalPoint = { 2.5, 2.5, 2.5 };
  s.camera.viewUp = { 0, 0, 1 };
  s.camera.viewAngleDeg = 20;
  s.camera.width = s.camera.height = 10;
  PathTracer tracer(s);
  RenderSettings rs;
  rs.samplesPerPixel = 32;
  rs.maxScatteringOrder = 1000000;
  rs.rouletteStart = 1000000;
  rs.threads = 2;
  const RenderResult r = tracer.render(rs);
  for (float c : r.rgb)
    ASSERT_NEAR(c, 1.0f, 1e-6f);
  EXPECT_NEAR(r.rmsStandardError, 0.0, 1e-6);

  // With Russian roulette the weights vary, but the mean is still 1 (unbiased).
  rs.rouletteStart = 2;
  rs.samplesPerPixel = 64;
  const RenderResult rr = tracer.render(rs);
  double mean = 0.0;
  for (size_t p = 0; p < 100; ++p)
    mean += rr.rgb[3 * p] / 100.0;
  EXPECT_NEAR(mean, 1.0, 4.0 * rr.rmsStandardError / 10.0 + 1e-9) << "se " << rr.rmsStandardError;
}

TEST(ReferenceClosedForms, DeterministicForASeedWhateverTheThreadCount)
{
  Scene s = slab(4, 2.0, 1.0, glm::vec3(0.7f, 0.5f, 0.3f), 2.0);
  s.pointLights.push_back({ glm::dvec3(0, 0, 5), glm::dvec3(10.0), true });
  s.camera.position = { 0, -8, 4 };
  s.camera.focalPoint = { 0, 0, 1 };
  s.camera.viewUp = { 0, 0, 1 };
  s.camera.width = s.camera.height = 12;
  PathTracer tracer(s);
  RenderSettings rs;
  rs.samplesPerPixel = 4;
  rs.threads = 1;
  const RenderResult a = tracer.render(rs);
  rs.threads = 3;
  int calls = 0;
  rs.progress = [&](double) { ++calls; };
  const RenderResult b = tracer.render(rs);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_GE(calls, 1);
  rs.seed = 2;
  EXPECT_NE(tracer.render(rs).rgb, a.rgb);
  EXPECT_GT(a.meanLuminance, 0.0);
}
