#include <scatterer/Material.h>

#include "Describe.h"

#include <cmath>
#include <stdexcept>

namespace scatterer {

namespace {

// "Material 'bone': opacity must be ..." (or "Material: ..." when unnamed).
std::string prefix(const Material& m)
{
  return m.name.empty() ? std::string("Material: ") : "Material '" + m.name + "': ";
}

void requireRange(const Material& m, const char* what, double value, double lo, double hi)
{
  if (!(std::isfinite(value) && value >= lo && value <= hi)) {
    throw std::invalid_argument(prefix(m) + what + " must be a finite number in [" +
                                detail::describe(lo) + ", " + detail::describe(hi) + "], got " +
                                detail::describe(value));
  }
}

} // namespace

Selector Selector::range(double lo, double hi)
{
  Selector s;
  s.kind = Kind::ScalarRange;
  s.lo = lo;
  s.hi = hi;
  return s;
}

Selector Selector::labelId(int id)
{
  Selector s;
  s.kind = Kind::Label;
  s.label = id;
  return s;
}

bool Selector::matches(double scalar) const
{
  if (kind == Kind::Label) {
    return scalar == static_cast<double>(label);
  }
  return scalar >= lo && scalar <= hi;
}

void Material::validate() const
{
  if (name.size() > 255) {
    throw std::invalid_argument(
      "Material: name must be at most 255 bytes, got " + std::to_string(name.size()));
  }
  // A NUL would silently cut the name short wherever it becomes a C string (VTK).
  if (const auto nul = name.find('\0'); nul != std::string::npos) {
    throw std::invalid_argument(
      "Material: name must not contain a NUL byte, found one at name byte " + std::to_string(nul));
  }
  requireRange(*this, "opacity", opacity, 0.0, 1.0);
  requireRange(*this, "refractiveIndex", refractiveIndex, kMinRefractiveIndex, kMaxRefractiveIndex);
  const char* channel[3] = { "diffuse.r", "diffuse.g", "diffuse.b" };
  for (int c = 0; c < 3; ++c) {
    requireRange(*this, channel[c], static_cast<double>(diffuse[c]), 0.0, 1.0);
  }
  if (selector.kind == Selector::Kind::Label) {
    if (selector.label < 0) {
      throw std::invalid_argument(
        prefix(*this) + "selector label must be >= 0, got " + std::to_string(selector.label));
    }
  } else if (selector.kind == Selector::Kind::ScalarRange) {
    if (!std::isfinite(selector.lo) || !std::isfinite(selector.hi)) {
      throw std::invalid_argument(prefix(*this) + "selector range must be finite, got [" +
                                  detail::describe(selector.lo) + ", " +
                                  detail::describe(selector.hi) + "]");
    }
    if (selector.lo > selector.hi) {
      throw std::invalid_argument(prefix(*this) + "selector range needs lo <= hi, got [" +
                                  detail::describe(selector.lo) + ", " +
                                  detail::describe(selector.hi) + "]");
    }
  } else {
    throw std::invalid_argument(prefix(*this) + "selector kind is not ScalarRange or Label");
  }
}

double meanFreePath(const Material& material)
{
  material.validate();
  if (material.opacity == 0.0) {
    return HUGE_VAL; // transparent: no scatterers, an infinite free path
  }
  // lambda = 1 / (sqrt(2) * n_s * sigma) with n_s * sigma = opacity per template radius.
  return 1.0 / (std::sqrt(2.0) * material.opacity);
}

std::vector<Material> exampleTissueMaterials()
{
  // Opacities follow the paper's ordering (bone most opaque, fat least); indices are
  // typical values for tissue (about 1.37 - 1.55). HU ranges are inclusive and disjoint.
  std::vector<Material> m(4);
  m[0].name = "fat";
  m[0].opacity = 0.2;
  m[0].refractiveIndex = 1.46;
  m[0].diffuse = { 0.95f, 0.85f, 0.55f };
  m[0].selector = Selector::range(-200.0, -50.0);

  m[1].name = "skin";
  m[1].opacity = 0.3;
  m[1].refractiveIndex = 1.42;
  m[1].diffuse = { 0.90f, 0.70f, 0.60f };
  m[1].selector = Selector::range(-49.0, 39.0);

  m[2].name = "muscle";
  m[2].opacity = 0.5;
  m[2].refractiveIndex = 1.37;
  m[2].diffuse = { 0.70f, 0.20f, 0.20f };
  m[2].selector = Selector::range(40.0, 200.0);

  m[3].name = "bone";
  m[3].opacity = 0.9;
  m[3].refractiveIndex = 1.55;
  m[3].diffuse = { 0.95f, 0.95f, 0.90f };
  m[3].selector = Selector::range(201.0, 3000.0);
  return m;
}

} // namespace scatterer
