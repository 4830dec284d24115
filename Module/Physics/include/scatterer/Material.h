// A material of the scatterer-template model (paper section 3.1) and its mean free path.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace scatterer {

// How a material is found in a volume: a scalar range (density classes such as
// skin / muscle / bone in HU, inclusive on both ends) or one label id of a label map.
struct Selector {
  enum class Kind { ScalarRange, Label };

  Kind kind = Kind::ScalarRange;
  double lo = 0.0; // ScalarRange: lo <= s <= hi
  double hi = 1.0;
  int label = 0; // Label: s == label

  static Selector range(double lo, double hi);
  static Selector labelId(int id);

  bool matches(double scalar) const;
};

struct Material {
  std::string name;             // for messages and files only; at most 255 bytes, no NUL
  double opacity = 0.5;         // the paper's 1 - T(d), in [0, 1]: extinction per template radius
  double refractiveIndex = 1.4; // n > 0; 1.4 is typical of soft tissue
  glm::vec3 diffuse{ 1.0f, 1.0f, 1.0f }; // RGB in [0, 1]
  Selector selector;

  // Throws std::invalid_argument naming the parameter for NaN, infinite, negative or
  // out-of-range values (ranges are listed in docs/model.md).
  void validate() const;
};

// Valid refractive indices: wide enough for the hard inputs (1e-3, 1e3) the tests use,
// narrow enough that Snell's law stays accurate in double precision.
constexpr double kMinRefractiveIndex = 1e-4;
constexpr double kMaxRefractiveIndex = 1e4;

// The refractive index a derived material gets when the user gives none: the k-th class
// (0-based) in order of increasing density is taken to be optically denser, from water's
// 1.33 upward in steps of 0.12 (soft tissue about 1.4, bone about 1.55). A heuristic for
// the Snell speed ratios at material boundaries (paper section 3.4), not measured optics.
inline double defaultRefractiveIndex(int densityRank)
{
  return 1.33 + 0.12 * static_cast<double>(densityRank);
}

// Mean free path lambda in template radii (paper Eq. 2).
//
//   lambda = 1 / (sqrt(2) * n_s * sigma)      [kinetic theory, Maxwell-Boltzmann]
//
// n_s * sigma (scatterer density times effective cross-section) is the extinction
// coefficient, which Eq. 1 (dI/dx = -(1 - T) I) names 1 - T = opacity when x is measured
// in template radii. So lambda = 1 / (sqrt(2) * opacity) [template radii]; the sqrt(2)
// accounts for the relative motion of the colliding particles. Opacity 0 gives +inf
// (nothing in the way). Throws std::invalid_argument for an invalid material.
double meanFreePath(const Material& material);

// Four illustrative tissue classes (fat, skin, muscle, bone; HU ranges) used by the
// benchmark, the tests and examples. Not calibrated optical data.
std::vector<Material> exampleTissueMaterials();

} // namespace scatterer
