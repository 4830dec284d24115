#include <scatterer/Snell.h>

#include "Describe.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace scatterer {

namespace {

void requireIndex(const char* what, double n)
{
  if (!(std::isfinite(n) && n > 0.0)) {
    throw std::invalid_argument(std::string("Snell: refractive index ") + what +
                                " must be finite and > 0, got " + detail::describe(n));
  }
}

} // namespace

double speedRatio(double n1, double n2)
{
  requireIndex("n1", n1);
  requireIndex("n2", n2);
  return n1 / n2;
}

std::optional<double> criticalAngle(double n1, double n2)
{
  requireIndex("n1", n1);
  requireIndex("n2", n2);
  if (n2 >= n1) {
    return std::nullopt;
  }
  return std::asin(n2 / n1);
}

std::optional<double> cosCriticalAngle(double n1, double n2)
{
  requireIndex("n1", n1);
  requireIndex("n2", n2);
  if (n2 >= n1) {
    return std::nullopt;
  }
  const double r = n2 / n1;
  // (1 - r)(1 + r) keeps precision when r is close to 1, where 1 - r*r cancels.
  return std::sqrt((1.0 - r) * (1.0 + r));
}

std::optional<glm::dvec3> refract(
  const glm::dvec3& dir, const glm::dvec3& normal, double n1, double n2)
{
  requireIndex("n1", n1);
  requireIndex("n2", n2);
  if (n1 == n2) {
    return dir; // no interface: exactly the same direction, not a recomputed one
  }
  glm::dvec3 n = normal;
  double cosI = -glm::dot(dir, n);
  if (cosI < 0.0) { // accept either normal orientation
    n = -n;
    cosI = -cosI;
  }
  cosI = std::fmin(cosI, 1.0);
  const double eta = n1 / n2;
  const double sin2T = eta * eta * ((1.0 - cosI) * (1.0 + cosI));
  if (sin2T > 1.0) {
    return std::nullopt; // total internal reflection
  }
  const double cosT = std::sqrt(1.0 - sin2T);
  return glm::normalize(eta * dir + (eta * cosI - cosT) * n);
}

std::optional<glm::vec3> refract(
  const glm::vec3& dir, const glm::vec3& normal, double n1, double n2)
{
  requireIndex("n1", n1);
  requireIndex("n2", n2);
  if (n1 == n2) {
    return dir;
  }
  const auto t = refract(glm::dvec3(dir), glm::dvec3(normal), n1, n2);
  if (!t) {
    return std::nullopt;
  }
  return glm::vec3(*t);
}

glm::dvec3 reflect(const glm::dvec3& dir, const glm::dvec3& normal)
{
  return dir - 2.0 * glm::dot(dir, normal) * normal;
}

} // namespace scatterer
