#include <scatterer/Transport.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace scatterer {

double extinctionFromOpacity(double alpha, double unitDistance)
{
  if (!(unitDistance > 0.0) || !std::isfinite(unitDistance)) {
    throw std::invalid_argument("extinctionFromOpacity: the unit distance must be positive and "
                                "finite");
  }
  const double a = std::isfinite(alpha) ? std::clamp(alpha, 0.0, 1.0 - 1e-6) : 0.0;
  return -std::log1p(-a) / unitDistance;
}

double kernelRadius(const Material& material, double sigmaT, double minRadius, double maxRadius)
{
  if (!(sigmaT > 0.0) || !std::isfinite(sigmaT)) {
    return maxRadius;
  }
  const double lambdaRadii = meanFreePath(material);
  const double radius =
    std::isfinite(lambdaRadii) && lambdaRadii > 0.0 ? (1.0 / sigmaT) / lambdaRadii : maxRadius;
  return std::clamp(radius, minRadius, maxRadius);
}

std::vector<KernelPhoton> mergedKernel(
  const std::vector<Template>& templates, int cap, double radius)
{
  if (cap < 1) {
    throw std::invalid_argument("mergedKernel: the photon cap must be at least 1");
  }
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("mergedKernel: the radius must be positive and finite");
  }
  std::vector<KernelPhoton> all;
  if (templates.empty()) {
    return all;
  }
  const float share = 1.0f / static_cast<float>(templates.size());
  for (const auto& t : templates) {
    for (const auto& p : t.photons) {
      all.push_back({ p.position * static_cast<float>(radius), p.intensity * share });
    }
  }
  // Ties keep template order (stable), so the kernel is deterministic.
  std::stable_sort(all.begin(), all.end(),
    [](const KernelPhoton& a, const KernelPhoton& b) { return a.weight > b.weight; });
  if (static_cast<int>(all.size()) > cap) {
    all.resize(static_cast<size_t>(cap));
  }
  double sum = 0.0;
  for (const auto& p : all) {
    sum += p.weight;
  }
  if (sum > 0.0) {
    for (auto& p : all) {
      p.weight = static_cast<float>(p.weight / sum);
    }
  }
  return all;
}

glm::vec3 kernelCentroid(const std::vector<KernelPhoton>& kernel)
{
  glm::dvec3 sum(0.0);
  double weights = 0.0;
  for (const auto& p : kernel) {
    sum += glm::dvec3(p.offset) * static_cast<double>(p.weight);
    weights += p.weight;
  }
  return weights > 0.0 ? glm::vec3(sum / weights) : glm::vec3(0.0f);
}

double kernelSpread(const std::vector<KernelPhoton>& kernel, const glm::mat3& worldToGrid)
{
  const glm::vec3 c = kernelCentroid(kernel);
  double spread = 0.0;
  for (const auto& p : kernel) {
    if (p.weight > 0.0f) {
      const glm::vec3 d = worldToGrid * (p.offset - c);
      if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) {
        return std::numeric_limits<double>::infinity(); // a degenerate grid: no bound
      }
      spread = std::max({ spread, static_cast<double>(std::abs(d.x)),
        static_cast<double>(std::abs(d.y)), static_cast<double>(std::abs(d.z)) });
    }
  }
  return spread;
}

bool readsAtCentroid(const std::vector<KernelPhoton>& kernel, const glm::mat3& worldToGrid)
{
  // A degenerate grid spreads infinitely: gathered photon by photon.
  return kernelSpread(kernel, worldToGrid) <= kCentroidReadSpread;
}

} // namespace scatterer
