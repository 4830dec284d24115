// The photon test of the scatterer-template method (paper section 3.3-3.4) for
// points of a volume, on the CPU.
//
// The mapper's cached mode evaluates it at the voxels of a coarse grid that
// lines up with the volume texture, uploads the result as a 3D texture and
// lets every ray sample read it: the photon loop then runs once per cache
// voxel and light change instead of once per ray sample and frame. The same
// estimator runs per sample on the GPU in the mapper's per-sample mode
// (Module/Shaders/scatterer_illumination_dec.glsl); keep the two in step.
//
// Units: positions in volume index space (voxel i of axis a at index i);
// photon offsets in template radii; extinction in 1 / world length.
//
// Occlusion of a photon is the transmittance of a short shadow ray from the
// point to the photon, exp(-k * integral of extinction), marched at most 0.7
// voxel per step, so a one-voxel opaque sheet in between always blocks it; the
// thin-part check marches on from the photon toward each light for
// (longRange - 1) times the photon's offset (the paper looks along the photon
// direction; toward the light also stops light leaking through thin sheets).
#pragma once

#include <scatterer/Template.h>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace scatterer {

// The volume as the photon test sees it: extinction and material per voxel.
struct OcclusionField {
  int dims[3] = {0, 0, 0};
  std::vector<float> extinction;     // sigma >= 0 per voxel (x fastest), 1 / world length
  std::vector<std::int8_t> material; // material index per voxel, -1 for none
  bool valid() const;
};

struct GridLight {
  glm::vec3 toLight{0.0f, 0.0f, 1.0f}; // unit vector toward a directional light (world)
  glm::vec3 position{0.0f};            // world position of a positional light
  bool positional = false;
  glm::vec3 color{1.0f};               // diffuse coefficient x colour x intensity
};

struct IlluminationSettings {
  int cacheDims[3] = {0, 0, 0};  // the grid evaluated; cache voxel i sits at index
                                 // (i + 0.5) * dims / cacheDims - 0.5 of the field,
                                 // unless cacheStep is set:
  // For a piece of a larger volume (distributed rendering): cache voxel i sits at
  // field index cacheFirstCentre + i * cacheStep, on a lattice anchored to the whole
  // volume, and cacheIndexOrigin is the lattice index of cache voxel 0, so a piece
  // places and hashes its cache voxels exactly as the whole volume does.
  // cacheStep 0 (default): the cache spans the field (the rule above).
  glm::vec3 cacheStep{0.0f};
  glm::vec3 cacheFirstCentre{0.0f};
  int cacheIndexOrigin[3] = {0, 0, 0};
  glm::mat3 indexToWorld{1.0f};  // linear part: index offset -> world offset
  glm::vec3 worldOrigin{0.0f};   // world position of index (0, 0, 0)
  float radius = 1.0f;           // template radius, world length
  float occlusionStrength = 1.0f;
  float longRange = 3.0f;        // thin-part check distance, in photon offsets
  float photonThreshold = 0.002f; // stop a template's photon loop below this intensity
  int photonCap = 24;
  int templatesPerEstimate = 4;  // distinct templates averaged per voxel (1..1024)
  bool shadow = true, thin = true, bleed = true, boundary = true;
  std::vector<glm::vec3> materialColors;
  std::vector<float> speedRatios;   // materials^2, row = the sample's material
  std::vector<float> opacityRatios; // materials^2, at most 1
  glm::vec3 ambient{0.0f};
  std::vector<GridLight> lights;
  int threads = 0;                  // 0: all hardware threads
  // When the ambient term and every light have one chromaticity (white light,
  // the usual case), F is a scalar multiple of `unlit`: then one RGBA8 texel
  // holds everything (rgb = B / unlit, a = F / unlit) and the shader reads one
  // texture instead of two.
  bool packInOne = false;
};

// Per cache voxel: light = F / unlit and bleed = B / unlit as RGBA8 (alpha
// unused), where a sample of colour c is lit as c * F + B, and
// unlit = ambient + sum of light colours (what an unoccluded sample gets).
// With packInOne: light = (B / unlit, F / unlit averaged over channels), no bleed.
struct IlluminationGrid {
  int dims[3] = {0, 0, 0};
  std::vector<std::uint8_t> light;
  std::vector<std::uint8_t> bleed;
  glm::vec3 unlit{1.0f};
  std::uint64_t photonsTested = 0;
};

// True when the ambient colour and all light colours are proportional to one
// another (within 1e-4), so packInOne loses nothing.
bool singleChromaticity(const IlluminationSettings& settings);

// templates[m] are the templates of material m, positions in template radii.
// Throws std::invalid_argument for inconsistent inputs (sizes, counts, NaN).
IlluminationGrid computeIllumination(const OcclusionField& field,
  const std::vector<std::vector<Template>>& templates, const IlluminationSettings& settings);

} // namespace scatterer
