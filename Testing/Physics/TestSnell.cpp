// Snell helper: exact identity for n1 == n2, Snell's law, total internal reflection.
#include <scatterer/Random.h>
#include <scatterer/Snell.h>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

using namespace scatterer;

namespace {

glm::dvec3 randomUnit(Pcg32& rng)
{
  for (;;) {
    const glm::dvec3 v(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
    const double l = glm::length(v);
    if (l > 0.1 && l <= 1.0) {
      return v / l;
    }
  }
}

double sinBetween(const glm::dvec3& a, const glm::dvec3& n)
{
  return glm::length(glm::cross(a, n));
}

} // namespace

TEST(Snell, SpeedRatioIsN1OverN2)
{
  EXPECT_DOUBLE_EQ(speedRatio(1.0, 1.5), 1.0 / 1.5);
  EXPECT_DOUBLE_EQ(speedRatio(1.33, 1.33), 1.0);
  EXPECT_THROW(speedRatio(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(speedRatio(1.0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(speedRatio(-1.0, 1.0), std::invalid_argument);
}

TEST(Snell, CriticalAngleOnlyFromDenseToLight)
{
  ASSERT_TRUE(criticalAngle(1.5, 1.0).has_value());
  EXPECT_DOUBLE_EQ(*criticalAngle(1.5, 1.0), std::asin(1.0 / 1.5));
  EXPECT_NEAR(*cosCriticalAngle(1.5, 1.0), std::cos(std::asin(1.0 / 1.5)), 1e-15);
  EXPECT_FALSE(criticalAngle(1.0, 1.5).has_value());
  EXPECT_FALSE(criticalAngle(1.2, 1.2).has_value());
  EXPECT_FALSE(cosCriticalAngle(1.0, 1.5).has_value());
}

TEST(Snell, EqualIndicesLeaveDirectionBitIdentical)
{
  Pcg32 rng = Pcg32::forStream(1, 2);
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 d = randomUnit(rng);
    const glm::dvec3 n = randomUnit(rng);
    for (double index : { 1e-3, 1.0, 1.4, 1e3 }) {
      const auto t = refract(d, n, index, index);
      ASSERT_TRUE(t.has_value());
      EXPECT_EQ(std::memcmp(&*t, &d, sizeof d), 0);
      const glm::vec3 df(d), nf(n);
      const auto tf = refract(df, nf, index, index);
      ASSERT_TRUE(tf.has_value());
      EXPECT_EQ(std::memcmp(&*tf, &df, sizeof df), 0);
    }
  }
}

TEST(Snell, RefractionObeysSnellsLaw)
{
  Pcg32 rng = Pcg32::forStream(3, 4);
  int refracted = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 d = randomUnit(rng);
    const glm::dvec3 n = randomUnit(rng);
    const double n1 = 0.5 + 2.0 * rng.uniform();
    const double n2 = 0.5 + 2.0 * rng.uniform();
    const auto t = refract(d, n, n1, n2);
    const double sinI = sinBetween(d, n);
    if (!t) {
      EXPECT_GT(n1 * sinI, n2 * (1.0 - 1e-12)); // only past the critical angle
      continue;
    }
    ++refracted;
    EXPECT_NEAR(glm::length(*t), 1.0, 1e-12);
    EXPECT_NEAR(n1 * sinI, n2 * sinBetween(*t, n), 1e-12);   // Snell
    EXPECT_NEAR(glm::dot(glm::cross(d, n), *t), 0.0, 1e-12); // plane of incidence
    EXPECT_GE(glm::dot(d, n) * glm::dot(*t, n), -1e-15);     // crosses the surface
    const auto flipped = refract(d, -n, n1, n2);             // orientation-free
    ASSERT_TRUE(flipped.has_value());
    EXPECT_NEAR(glm::length(*flipped - *t), 0.0, 1e-14);
  }
  EXPECT_GT(refracted, 1000);
}

TEST(Snell, TotalInternalReflectionPastCriticalAngle)
{
  const double n1 = 1.5, n2 = 1.0;
  const double critical = *criticalAngle(n1, n2);
  const glm::dvec3 normal(0.0, 0.0, 1.0);
  for (double delta : { 1e-6, 0.01, 0.3 }) {
    const double past = critical + delta;
    const glm::dvec3 d(std::sin(past), 0.0, -std::cos(past));
    EXPECT_FALSE(refract(d, normal, n1, n2).has_value()) << delta;
    const double before = critical - delta;
    const glm::dvec3 e(std::sin(before), 0.0, -std::cos(before));
    EXPECT_TRUE(refract(e, normal, n1, n2).has_value()) << delta;
  }
  // Normal incidence passes straight through.
  const auto straight = refract(glm::dvec3(0, 0, -1), normal, n1, n2);
  ASSERT_TRUE(straight.has_value());
  EXPECT_NEAR(glm::length(*straight - glm::dvec3(0, 0, -1)), 0.0, 1e-15);
}

TEST(Snell, ExtremeIndicesStayFinite)
{
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, 0.1, -1.0));
  const glm::dvec3 n(0.0, 0.0, 1.0);
  const auto t = refract(d, n, 1e-3, 1.0); // into a far denser medium: bends to the normal
  ASSERT_TRUE(t.has_value());
  EXPECT_TRUE(std::isfinite(t->x) && std::isfinite(t->y) && std::isfinite(t->z));
  EXPECT_NEAR(glm::length(*t), 1.0, 1e-12);
  EXPECT_FALSE(refract(d, n, 1e3, 1.0).has_value()); // far past a tiny critical angle
}

TEST(Snell, ReflectMirrors)
{
  const glm::dvec3 r = reflect(glm::dvec3(1, -1, 0), glm::dvec3(0, 1, 0));
  EXPECT_EQ(r, glm::dvec3(1, 1, 0));
}
