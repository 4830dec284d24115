// Snell's law helpers (paper section 3.4, Eq. 6). Refractive indices must be finite and
// > 0; otherwise the functions throw std::invalid_argument.
#pragma once

#include <glm/vec3.hpp>

#include <optional>

namespace scatterer {

// v2 / v1 = n1 / n2 (Eq. 6: v2 = v1 n1 / n2). A photon crossing from a material with n1
// into one with n2 covers this fraction of the distance in the same time.
double speedRatio(double n1, double n2);

// Critical angle in radians, asin(n2 / n1), for light going from n1 into n2; nullopt
// when n2 >= n1 (no total internal reflection is possible).
std::optional<double> criticalAngle(double n1, double n2);

// Cosine of the critical angle, sqrt(1 - (n2/n1)^2), without a call to asin/cos
// (the generator uses this form so its output does not depend on libm's asin).
std::optional<double> cosCriticalAngle(double n1, double n2);

// Refracts the unit direction `dir` at a surface with unit normal `normal` (either
// orientation) going from index n1 into n2. Returns the unit refracted direction, or
// nullopt on total internal reflection. n1 == n2 returns `dir` unchanged, bit for bit.
std::optional<glm::vec3> refract(
  const glm::vec3& dir, const glm::vec3& normal, double n1, double n2);
std::optional<glm::dvec3> refract(
  const glm::dvec3& dir, const glm::dvec3& normal, double n1, double n2);

// Mirror reflection of `dir` about the plane with unit normal `normal`.
glm::dvec3 reflect(const glm::dvec3& dir, const glm::dvec3& normal);

} // namespace scatterer
