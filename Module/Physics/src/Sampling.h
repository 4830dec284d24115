// Internal: direction sampling from Pcg32 with only +, *, / and sqrt, which IEEE 754
// rounds identically everywhere (no sin/cos of a random angle, whose last bit depends on
// the libm).
#pragma once

#include <scatterer/Random.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace scatterer {
namespace detail {

// (cos phi, sin phi) for a uniform random phi, by rejection from the square. Gives up
// after 64 rejections (probability 0.22^64) so the loop is bounded whatever happens.
inline glm::dvec2 randomUnitCircle(Pcg32& rng)
{
  for (int attempt = 0; attempt < 64; ++attempt) {
    const double x = 2.0 * rng.uniform() - 1.0;
    const double y = 2.0 * rng.uniform() - 1.0;
    const double r2 = x * x + y * y;
    if (r2 <= 1.0 && r2 > 1e-6) {
      const double inv = 1.0 / std::sqrt(r2);
      return { x * inv, y * inv };
    }
  }
  return { 1.0, 0.0 };
}

// Orthonormal b1, b2 perpendicular to unit n (Duff et al. 2017, branch-free, no trig).
inline void orthonormalBasis(const glm::dvec3& n, glm::dvec3& b1, glm::dvec3& b2)
{
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  b1 = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  b2 = glm::dvec3(b, sign + n.y * n.y * a, -n.y);
}

// Unit direction at angle acos(cosTheta) from unit `axis`, uniform azimuth.
inline glm::dvec3 directionInCone(const glm::dvec3& axis, double cosTheta, Pcg32& rng)
{
  glm::dvec3 b1, b2;
  orthonormalBasis(axis, b1, b2);
  const double sinTheta = std::sqrt(std::fmax(0.0, (1.0 - cosTheta) * (1.0 + cosTheta)));
  const glm::dvec2 c = randomUnitCircle(rng);
  return cosTheta * axis + sinTheta * (c.x * b1 + c.y * b2);
}

// Uniform random rotation (Marsaglia 1972: a uniform point on the 3-sphere from two
// points in the unit disk).
inline glm::dquat randomRotation(Pcg32& rng)
{
  double x1 = 0.0, y1 = 0.0, s1 = 0.0;
  double x2 = 1.0, y2 = 0.0, s2 = 1.0;
  for (int attempt = 0; attempt < 64; ++attempt) {
    x1 = 2.0 * rng.uniform() - 1.0;
    y1 = 2.0 * rng.uniform() - 1.0;
    s1 = x1 * x1 + y1 * y1;
    if (s1 < 1.0) {
      break;
    }
  }
  for (int attempt = 0; attempt < 64; ++attempt) {
    x2 = 2.0 * rng.uniform() - 1.0;
    y2 = 2.0 * rng.uniform() - 1.0;
    s2 = x2 * x2 + y2 * y2;
    if (s2 < 1.0 && s2 > 0.0) {
      break;
    }
  }
  if (!(s1 < 1.0 && s2 < 1.0 && s2 > 0.0)) {
    return glm::dquat(1.0, 0.0, 0.0, 0.0); // unreachable in practice; keeps the loops bounded
  }
  const double k = std::sqrt((1.0 - s1) / s2);
  return glm::dquat(x1, y1, x2 * k, y2 * k); // (w, x, y, z), unit length by construction
}

} // namespace detail
} // namespace scatterer
