// Scatterer templates: photons produced by the paper's Eq. 1-5 for one material.
#pragma once

#include <scatterer/GeneratorSettings.h>
#include <scatterer/Material.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace scatterer {

struct Photon {
  glm::vec3 position; // template radii, relative to the template centre; |position| <= 1
  float intensity;    // absorbed energy (initial energy of a template = 1); always > 0
};

// Where the initial energy went. Every packet's energy ends in exactly one field, so
// stored + lostInTransit + escaped + droppedBelowThreshold + droppedAtCap == initial
// up to double rounding (see docs/model.md, "Energy").
struct EnergyLedger {
  double initial = 0.0;
  double stored = 0.0;                // sum of photon intensities (Eq. 3)
  double lostInTransit = 0.0;         // e^(-dx/lambda) and cos(theta) losses of Eq. 2
  double escaped = 0.0;               // reached the template sphere's surface
  double droppedBelowThreshold = 0.0; // scattered part of packets that stopped branching
  double droppedAtCap = 0.0;          // in flight when a hard cap stopped generation

  double accounted() const
  {
    return stored + lostInTransit + escaped + droppedBelowThreshold + droppedAtCap;
  }
  double residual() const { return initial - accounted(); }
};

struct Template {
  std::vector<Photon> photons; // sorted by descending intensity, ties by lattice cell (x, y, z)
  EnergyLedger ledger;
  bool capped = false;      // a hard cap of GeneratorSettings stopped generation early
  std::uint64_t events = 0; // packets processed (each one lands or escapes)
};

// One template. templateIndex (>= 0) selects the random stream: the same
// (material, settings, templateIndex) gives a bit-identical template on every run.
// Throws std::invalid_argument for invalid inputs.
Template generateTemplate(
  const Material& material, const GeneratorSettings& settings, int templateIndex);

// settings.templatesPerMaterial templates with indices 0, 1, ...
std::vector<Template> generateTemplates(
  const Material& material, const GeneratorSettings& settings);

// Seed used for material `materialIndex` by generateAllTemplates, so materials do not
// share random streams.
std::uint64_t materialSeed(std::uint64_t seed, int materialIndex);

// Templates of several materials: result[m] = generateTemplates(materials[m], settings
// with seed = materialSeed(settings.seed, m)).
std::vector<std::vector<Template>> generateAllTemplates(
  const std::vector<Material>& materials, const GeneratorSettings& settings);

// FNV-1a 64 over the little-endian bit patterns of every photon (x, y, z, intensity):
// a compact fingerprint for golden tests and cache keys.
std::uint64_t templateChecksum(const Template& t);

} // namespace scatterer
