// Template generation: the paper's Eq. 1-5 with an explicit packet work list (a heap).
// docs/model.md explains each modelling choice; the comments here say where it applies.
#include <scatterer/Snell.h>
#include <scatterer/Template.h>

#include "Lattice.h"
#include "Sampling.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace scatterer {

namespace {

struct Packet {
  glm::dvec3 position;
  glm::dvec3 direction; // unit
  double energy;
  std::uint64_t serial; // creation order: makes the heap order strict and portable
};

// Max-heap order: the most energetic packet first, the older one on ties. Strict and
// total (serials are unique), so every std::*_heap implementation pops the same sequence.
// Energy order matters when a cap stops generation: what is left undone is the weakest
// light, not a whole initial light as with a depth-first stack.
bool weaker(const Packet& a, const Packet& b)
{
  if (a.energy != b.energy) {
    return a.energy < b.energy;
  }
  return a.serial > b.serial;
}

// Photon being accumulated in one lattice cell.
struct Cell {
  std::uint64_t key;
  glm::dvec3 position; // intensity-weighted mean of the arrivals: stays inside the sphere
  double intensity;
};

// Initial light directions: L latitude bands of equal area (z stratified), random
// azimuth, then one random rotation, so the lights spread evenly (the point of Table 2)
// without a preferred axis.
std::vector<glm::dvec3> initialDirections(int lights, Pcg32& rng)
{
  const glm::dquat rotation = detail::randomRotation(rng);
  std::vector<glm::dvec3> directions;
  directions.reserve(static_cast<std::size_t>(lights));
  for (int l = 0; l < lights; ++l) {
    const double z = 1.0 - 2.0 * (static_cast<double>(l) + rng.uniform()) / lights;
    const double r = std::sqrt(std::fmax(0.0, (1.0 - z) * (1.0 + z)));
    const glm::dvec2 c = detail::randomUnitCircle(rng);
    directions.push_back(glm::normalize(rotation * glm::dvec3(r * c.x, r * c.y, z)));
  }
  return directions;
}

// Distance from `p` (inside the unit sphere) along unit `d` to the sphere.
double distanceToSphere(const glm::dvec3& p, const glm::dvec3& d)
{
  const double b = glm::dot(p, d);
  const double c = glm::dot(p, p) - 1.0;
  return -b + std::sqrt(std::fmax(0.0, b * b - c));
}

} // namespace

Template generateTemplate(
  const Material& material, const GeneratorSettings& settings, int templateIndex)
{
  material.validate();
  settings.validate();
  if (templateIndex < 0) {
    throw std::invalid_argument(
      "generateTemplate: templateIndex must be >= 0, got " + std::to_string(templateIndex));
  }

  Pcg32 rng = Pcg32::forStream(settings.seed, static_cast<std::uint64_t>(templateIndex));
  const double alpha = material.opacity; // 1 - T(d)
  const double n = material.refractiveIndex;
  const double lambda = meanFreePath(material);
  const double dx = settings.stepLength;
  // Eq. 2's e^(-dx/lambda) for the fixed step: the only libm call that shapes photons.
  const double stepTransmission = std::exp(-dx / lambda);
  // Scatterer facets are interfaces from the material (n) into the reference medium
  // (n = 1). The incidence angle is drawn within the critical angle, so every facet
  // refracts; with n <= 1 there is no critical angle and any angle up to 90 deg occurs.
  const std::optional<double> cosCritical = cosCriticalAngle(n, 1.0);
  const double cos2Max = cosCritical ? *cosCritical * *cosCritical : 0.0;
  const int lights = settings.initialLights;
  const double lightEnergy = 1.0 / lights;
  // The threshold is relative to one light's energy, so each light's tree has the same
  // depth whatever L is (docs/model.md, "Threshold").
  const double branchFloor = settings.threshold * lightEnergy;
  const auto maxEvents = static_cast<std::uint64_t>(settings.maxEventsPerTemplate);
  const auto maxPhotons = static_cast<std::size_t>(settings.maxPhotonsPerTemplate);

  Template out;
  EnergyLedger& ledger = out.ledger;
  ledger.initial = 1.0;

  // The work list is an explicit heap rather than recursion: depth is unbounded at tiny
  // thresholds, and the heap's size is bounded by the event cap.
  std::vector<Packet> heap;
  heap.reserve(64);
  std::uint64_t serial = 0;
  const auto push = [&heap, &serial](const glm::dvec3& x, const glm::dvec3& d, double e) {
    heap.push_back({ x, d, e, serial++ });
    std::push_heap(heap.begin(), heap.end(), weaker);
  };
  for (const glm::dvec3& d : initialDirections(lights, rng)) {
    push(glm::dvec3(0.0), d, lightEnergy);
  }

  detail::Lattice lattice(settings.latticeCell);
  std::vector<Cell> cells;

  while (!heap.empty()) {
    if (out.events >= maxEvents) {
      out.capped = true;
      break;
    }
    std::pop_heap(heap.begin(), heap.end(), weaker);
    const Packet p = heap.back();
    heap.pop_back();
    ++out.events;

    // Eq. 2, travel: the packet moves dx; leaving the unit sphere means escaping, with
    // the energy that reaches the surface. The surface itself counts as outside (up to
    // a 1e-9 band, so rounding in |direction| cannot decide it).
    const glm::dvec3 x = p.position + dx * p.direction;
    if (glm::dot(x, x) >= 1.0 - 1e-9) {
      const double reach = std::exp(-distanceToSphere(p.position, p.direction) / lambda);
      const double escaped = p.energy * reach;
      ledger.escaped += escaped;
      ledger.lostInTransit += p.energy - escaped;
      continue;
    }

    // Eq. 2, arrival: a facet with incidence theta intercepts cos(theta) of the packet
    // (Lambert). Facets are hit in proportion to their projected area, so cos(theta) is
    // drawn cosine-weighted within the cone: cos^2 uniform in [cos2Max, 1].
    const double cosTheta = std::sqrt(1.0 - rng.uniform() * (1.0 - cos2Max));
    const glm::dvec3 facetNormal = detail::directionInCone(-p.direction, cosTheta, rng);
    const double intensity = p.energy * stepTransmission * cosTheta;
    ledger.lostInTransit += p.energy - intensity;

    // Eq. 3: A = (1 - T) I is stored where the packet landed; the lattice merges it with
    // a photon already in the same cell.
    const double absorbed = alpha * intensity;
    if (absorbed > 0.0) {
      const std::uint64_t key = lattice.key(x);
      int index = lattice.find(key);
      if (index < 0) {
        if (cells.size() >= maxPhotons) {
          out.capped = true;
          ledger.droppedAtCap += intensity;
          break;
        }
        index = static_cast<int>(cells.size());
        cells.push_back({ key, x, 0.0 });
        lattice.insert(key, index);
      }
      Cell& cell = cells[static_cast<std::size_t>(index)];
      cell.intensity += absorbed;
      cell.position += (absorbed / cell.intensity) * (x - cell.position);
      ledger.stored += absorbed;
    }

    // Energy conservation: only what was not absorbed scatters on (docs/model.md).
    const double scattered = intensity - absorbed;
    if (intensity < branchFloor) {
      ledger.droppedBelowThreshold += scattered; // stops branching: stored A, drops the rest
      continue;
    }
    if (!(scattered > 0.0)) {
      continue; // opacity 1: everything was absorbed
    }

    // Eq. 4-5: the refracted packet takes cos(theta'), the reflected one the rest.
    double cosThetaT = 0.0;
    glm::dvec3 refractedDir(0.0);
    if (const auto t = refract(p.direction, facetNormal, n, 1.0)) {
      refractedDir = *t;
      const double sin2T = n * n * ((1.0 - cosTheta) * (1.0 + cosTheta));
      cosThetaT = std::sqrt(std::fmax(0.0, 1.0 - sin2T));
    } // else: total internal reflection at the cone's rim (rounding): all is reflected
    const double refracted = scattered * cosThetaT;
    const double reflected = scattered - refracted;
    if (refracted > 0.0) {
      push(x, refractedDir, refracted);
    }
    if (reflected > 0.0) {
      push(x, glm::normalize(reflect(p.direction, facetNormal)), reflected);
    }
  }

  for (const Packet& p : heap) { // non-empty only when a cap stopped the loop
    ledger.droppedAtCap += p.energy;
  }

  // Sort by descending float intensity (what the GPU sees), ties by lattice cell, which
  // is unique: a strict total order, so any correct sort gives the same result.
  std::vector<Photon> photons;
  std::vector<std::uint64_t> keys;
  photons.reserve(cells.size());
  keys.reserve(cells.size());
  for (const Cell& c : cells) {
    const auto value = static_cast<float>(c.intensity);
    if (!(value > 0.0f)) { // underflows float: cannot be a photon (0 ends a GPU row)
      ledger.stored -= c.intensity;
      ledger.droppedBelowThreshold += c.intensity;
      continue;
    }
    photons.push_back({ glm::vec3(c.position), value });
    keys.push_back(c.key);
  }
  // ledger.stored summed the arrivals in event order, the cells summed them per cell, so
  // when every cell underflowed the subtractions above leave a rounding residue instead
  // of 0, possibly negative (-4e-315 found by fuzzing an opacity of 7.6e-298), which the
  // template file writer refuses. With no photon nothing is stored: the residue joins
  // the dropped energy it came from.
  if (photons.empty() || ledger.stored < 0.0) {
    ledger.droppedBelowThreshold += ledger.stored;
    ledger.stored = 0.0;
  }
  std::vector<std::size_t> order(photons.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (photons[a].intensity != photons[b].intensity) {
      return photons[a].intensity > photons[b].intensity;
    }
    return keys[a] < keys[b];
  });
  out.photons.reserve(photons.size());
  for (std::size_t i : order) {
    out.photons.push_back(photons[i]);
  }
  return out;
}

std::vector<Template> generateTemplates(const Material& material, const GeneratorSettings& settings)
{
  settings.validate();
  std::vector<Template> templates;
  templates.reserve(static_cast<std::size_t>(settings.templatesPerMaterial));
  for (int t = 0; t < settings.templatesPerMaterial; ++t) {
    templates.push_back(generateTemplate(material, settings, t));
  }
  return templates;
}

std::uint64_t materialSeed(std::uint64_t seed, int materialIndex)
{
  SplitMix64 mix(seed ^ (static_cast<std::uint64_t>(materialIndex) * 0xA24BAED4963EE407ull));
  return mix.next();
}

std::vector<std::vector<Template>> generateAllTemplates(
  const std::vector<Material>& materials, const GeneratorSettings& settings)
{
  std::vector<std::vector<Template>> all;
  all.reserve(materials.size());
  for (std::size_t m = 0; m < materials.size(); ++m) {
    GeneratorSettings s = settings;
    s.seed = materialSeed(settings.seed, static_cast<int>(m));
    all.push_back(generateTemplates(materials[m], s));
  }
  return all;
}

std::uint64_t templateChecksum(const Template& t)
{
  std::uint64_t hash = 0xCBF29CE484222325ull;
  const auto add = [&hash](float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    for (int byte = 0; byte < 4; ++byte) { // little-endian byte order, on any host
      hash ^= (bits >> (8 * byte)) & 0xFFu;
      hash *= 0x100000001B3ull;
    }
  };
  for (const Photon& p : t.photons) {
    add(p.position.x);
    add(p.position.y);
    add(p.position.z);
    add(p.intensity);
  }
  return hash;
}

} // namespace scatterer
