#include <scatterer/Illumination.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

namespace scatterer {

bool OcclusionField::valid() const
{
  const long long n = static_cast<long long>(dims[0]) * dims[1] * dims[2];
  return dims[0] > 0 && dims[1] > 0 && dims[2] > 0 &&
    extinction.size() == static_cast<size_t>(n) && material.size() == static_cast<size_t>(n);
}

namespace {

struct Lookup {
  const OcclusionField& field;
  // Nearest voxel at index position p: extinction and material; outside: nothing.
  void at(const glm::vec3& p, float& sigma, int& material) const
  {
    const int i = static_cast<int>(std::floor(p.x + 0.5f));
    const int j = static_cast<int>(std::floor(p.y + 0.5f));
    const int k = static_cast<int>(std::floor(p.z + 0.5f));
    if (i < 0 || j < 0 || k < 0 || i >= field.dims[0] || j >= field.dims[1] || k >= field.dims[2]) {
      sigma = 0.0f;
      material = -1;
      return;
    }
    const size_t id = static_cast<size_t>(i) +
      static_cast<size_t>(field.dims[0]) * (static_cast<size_t>(j) + static_cast<size_t>(field.dims[1]) * k);
    sigma = field.extinction[id];
    material = field.material[id];
  }

  // Extinction integrated along the segment a -> b (index space) whose world
  // length is `worldLength`, from midpoint samples at most `step` voxels apart,
  // leaving out the first `skip` voxels (the sample's own neighbourhood is the
  // scattering medium the template models, not an occluder). With step 0.7 a
  // one-voxel opaque sheet on the segment is never stepped over.
  float opticalDepth(const glm::vec3& a, const glm::vec3& b, float worldLength, float step,
    float skip) const
  {
    const float len = glm::length(b - a);
    if (len <= skip) {
      return 0.0f;
    }
    const float from = skip / len; // fraction of the segment left out
    const float span = (len - skip);
    const int n = std::min(64, std::max(1, static_cast<int>(std::ceil(span / step))));
    float sum = 0.0f;
    for (int j = 0; j < n; ++j) {
      float sigma;
      int material;
      at(a + (b - a) * (from + (1.0f - from) * (j + 0.5f) / n), sigma, material);
      sum += sigma;
    }
    return sum * worldLength * (1.0f - from) / n;
  }
};


// The same voxel hash as the shader's st_templateIndex.
int templateIndex(int i, int j, int k, int salt, int count)
{
  std::uint32_t x = static_cast<std::uint32_t>(i + salt), y = static_cast<std::uint32_t>(j + salt),
                z = static_cast<std::uint32_t>(k + salt);
  std::uint32_t h = (x * 73856093u) ^ (y * 19349663u) ^ (z * 83492791u);
  h ^= h >> 13u;
  h *= 0x5bd1e995u;
  h ^= h >> 15u;
  return static_cast<int>(h % static_cast<std::uint32_t>(count));
}

std::uint8_t toByte(float v)
{
  if (!(v >= 0.0f)) {
    return 0; // negative or NaN (never expected: every factor is finite and >= 0)
  }
  return static_cast<std::uint8_t>(std::lround(std::min(v, 1.0f) * 255.0f));
}

void validate(const OcclusionField& field, const std::vector<std::vector<Template>>& templates,
  const IlluminationSettings& s)
{
  if (!field.valid()) {
    throw std::invalid_argument("computeIllumination: the occlusion field's sizes do not match its dims");
  }
  for (int a = 0; a < 3; ++a) {
    if (s.cacheDims[a] <= 0 || s.cacheDims[a] > field.dims[a]) {
      throw std::invalid_argument("computeIllumination: cacheDims must be in 1..field dims, got " +
        std::to_string(s.cacheDims[a]) + " on axis " + std::to_string(a));
    }
  }
  const bool lattice = s.cacheStep.x != 0.0f || s.cacheStep.y != 0.0f || s.cacheStep.z != 0.0f;
  for (int a = 0; lattice && a < 3; ++a) {
    if (!(s.cacheStep[a] > 0.0f) || !std::isfinite(s.cacheStep[a]) ||
      !std::isfinite(s.cacheFirstCentre[a])) {
      throw std::invalid_argument("computeIllumination: cacheStep must be positive and finite on "
        "every axis (or 0 on all), and cacheFirstCentre finite");
    }
  }
  const size_t m = templates.size();
  if (m == 0 || m > 127 || s.materialColors.size() != m || s.speedRatios.size() != m * m ||
    s.opacityRatios.size() != m * m) {
    throw std::invalid_argument("computeIllumination: materials, colours and ratio tables disagree in size");
  }
  for (const auto& mt : templates) {
    if (mt.empty()) {
      throw std::invalid_argument("computeIllumination: a material has no template");
    }
  }
  if (!(s.radius > 0.0f) || !std::isfinite(s.radius) || !(s.occlusionStrength >= 0.0f) ||
    !std::isfinite(s.occlusionStrength) || !(s.longRange >= 1.0f) || !std::isfinite(s.longRange) ||
    !(s.photonThreshold >= 0.0f) || s.photonCap < 1 || s.templatesPerEstimate < 1 ||
    s.templatesPerEstimate > 1024 || s.lights.empty() || s.lights.size() > 64) {
    throw std::invalid_argument("computeIllumination: radius, strength, long range, threshold, photon "
                                "cap, templates per estimate or light count out of range");
  }
}

// Cells without material get the mean of their computed face neighbours, for
// `passes` rings: a ray sample at a surface reads the cache trilinearly, and
// must not mix in "unoccluded" values from the empty cells just outside.
void dilate(IlluminationGrid& grid, std::vector<std::uint8_t>& computed, int passes)
{
  const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  auto index = [&](int i, int j, int k) {
    return static_cast<size_t>(i) + static_cast<size_t>(nx) * (static_cast<size_t>(j) + static_cast<size_t>(ny) * k);
  };
  const int offsets[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<std::uint8_t> next = computed;
    for (int k = 0; k < nz; ++k) {
      for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
          const size_t id = index(i, j, k);
          if (computed[id]) {
            continue;
          }
          int sum[8] = {0, 0, 0, 0, 0, 0, 0, 0};
          int count = 0;
          for (const auto& o : offsets) {
            const int a = i + o[0], b = j + o[1], c = k + o[2];
            if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz || !computed[index(a, b, c)]) {
              continue;
            }
            const size_t n = index(a, b, c);
            for (int ch = 0; ch < 4; ++ch) {
              sum[ch] += grid.light[4 * n + ch];
              if (!grid.bleed.empty()) {
                sum[4 + ch] += grid.bleed[4 * n + ch];
              }
            }
            ++count;
          }
          if (count == 0) {
            continue;
          }
          for (int ch = 0; ch < 4; ++ch) {
            grid.light[4 * id + ch] = static_cast<std::uint8_t>((sum[ch] + count / 2) / count);
            if (!grid.bleed.empty()) {
              grid.bleed[4 * id + ch] = static_cast<std::uint8_t>((sum[4 + ch] + count / 2) / count);
            }
          }
          next[id] = 1;
        }
      }
    }
    computed.swap(next);
  }
}

} // namespace

bool singleChromaticity(const IlluminationSettings& settings)
{
  std::vector<glm::vec3> colors{settings.ambient};
  for (const auto& l : settings.lights) {
    colors.push_back(l.color);
  }
  glm::vec3 reference(0.0f);
  for (const auto& c : colors) {
    if (c.x + c.y + c.z > 0.0f) {
      reference = c / (c.x + c.y + c.z);
      break;
    }
  }
  for (const auto& c : colors) {
    const float sum = c.x + c.y + c.z;
    if (sum > 0.0f && glm::length(c / sum - reference) > 1e-4f) {
      return false;
    }
  }
  return true;
}

IlluminationGrid computeIllumination(const OcclusionField& field,
  const std::vector<std::vector<Template>>& templates, const IlluminationSettings& s)
{
  validate(field, templates, s);
  IlluminationGrid grid;
  for (int a = 0; a < 3; ++a) {
    grid.dims[a] = s.cacheDims[a];
  }
  const size_t cells = static_cast<size_t>(grid.dims[0]) * grid.dims[1] * grid.dims[2];
  grid.light.assign(cells * 4, 255);
  grid.bleed.assign(s.bleed && !s.packInOne ? cells * 4 : 0, 0);
  if (s.packInOne) {
    // rgb = bleed 0, a = visibility 1 for cells no material touches.
    for (size_t c = 0; c < cells; ++c) {
      grid.light[4 * c] = grid.light[4 * c + 1] = grid.light[4 * c + 2] = 0;
    }
  }
  const int nm = static_cast<int>(templates.size());
  const int nl = static_cast<int>(s.lights.size());
  glm::vec3 unlit = s.ambient;
  for (const auto& l : s.lights) {
    unlit += l.color;
  }
  grid.unlit = unlit;
  const glm::vec3 invUnlit(unlit.x > 0 ? 1.0f / unlit.x : 0.0f, unlit.y > 0 ? 1.0f / unlit.y : 0.0f,
    unlit.z > 0 ? 1.0f / unlit.z : 0.0f);
  const glm::mat3 worldToIndex = glm::inverse(s.indexToWorld);
  // The voxels a cache cell stands for are the scattering medium the template
  // models, not occluders: shadow rays start outside the cell's own extent
  // (one voxel at full resolution). Without this, a cell centred inside a
  // thin plate would shadow the plate's own lit face.
  const bool lattice = s.cacheStep.x > 0.0f;
  float step[3], firstCentre[3];
  for (int a = 0; a < 3; ++a) {
    step[a] = lattice ? s.cacheStep[a] : static_cast<float>(field.dims[a]) / grid.dims[a];
    firstCentre[a] = lattice ? s.cacheFirstCentre[a] : 0.5f * step[a] - 0.5f;
  }
  const float ownNeighbourhood = 0.5f + 0.5f * std::max({1.0f, step[0], step[1], step[2]});
  const Lookup lookup{field};

  std::vector<std::uint8_t> computed(cells, 0);
  std::atomic<int> nextSlice{0};
  std::atomic<std::uint64_t> tested{0};
  auto worker = [&]() {
    std::vector<float> den(nl), lit(nl);
    std::vector<glm::vec3> tinted(nl), toLight(nl);
    std::uint64_t localTested = 0;
    for (int k = nextSlice++; k < grid.dims[2]; k = nextSlice++) {
      for (int j = 0; j < grid.dims[1]; ++j) {
        for (int i = 0; i < grid.dims[0]; ++i) {
          const glm::vec3 x(firstCentre[0] + i * step[0], firstCentre[1] + j * step[1],
            firstCentre[2] + k * step[2]);
          float sigma;
          int m;
          lookup.at(x, sigma, m);
          if (m < 0 || m >= nm) {
            continue; // no material: filled from its neighbours below
          }
          computed[static_cast<size_t>(i) + static_cast<size_t>(grid.dims[0]) *
            (static_cast<size_t>(j) + static_cast<size_t>(grid.dims[1]) * k)] = 1;
          const glm::vec3 world = s.worldOrigin + s.indexToWorld * x;
          for (int l = 0; l < nl; ++l) {
            toLight[l] = s.lights[l].positional ? s.lights[l].position - world : s.lights[l].toLight;
            const float len = glm::length(toLight[l]);
            toLight[l] = len > 0.0f ? toLight[l] / len : glm::vec3(0, 0, 1);
            den[l] = 0.0f;
            lit[l] = 0.0f;
            tinted[l] = glm::vec3(0.0f);
          }
          const auto& materialTemplates = templates[m];
          const int count = static_cast<int>(materialTemplates.size());
          // Distinct templates, starting at the hashed one (decorrelated per voxel).
          const int first = templateIndex(s.cacheIndexOrigin[0] + i, s.cacheIndexOrigin[1] + j,
            s.cacheIndexOrigin[2] + k, 0, count);
          const int estimates = std::min(s.templatesPerEstimate, count);
          for (int e = 0; e < estimates; ++e) {
            const Template& t = materialTemplates[(first + e) % count];
            const int n = std::min(static_cast<int>(t.photons.size()), s.photonCap);
            for (int p = 0; p < n; ++p) {
              const Photon& photon = t.photons[p];
              if (photon.intensity < s.photonThreshold) {
                break;
              }
              bool toward = false;
              for (int l = 0; l < nl; ++l) {
                toward = toward || glm::dot(photon.position, toLight[l]) > 0.0f;
              }
              if (!toward) {
                continue;
              }
              ++localTested;
              float weight = photon.intensity;
              glm::vec3 offset = worldToIndex * (photon.position * s.radius);
              float dist = glm::length(photon.position);
              float sp;
              int mp;
              lookup.at(x + offset, sp, mp);
              if (s.boundary && mp >= 0 && mp != m) {
                const float speed = s.speedRatios[m * nm + mp];
                offset *= speed;
                dist *= speed;
                weight *= s.opacityRatios[m * nm + mp];
                lookup.at(x + offset, sp, mp);
              }
              if (s.shadow) {
                // A short shadow ray from the sample to the photon (Fig. 3).
                weight *= std::exp(-s.occlusionStrength * lookup.opticalDepth(x, x + offset, dist * s.radius, 0.7f, ownNeighbourhood));
              }
              const bool foreign = s.bleed && mp >= 0 && mp != m;
              const float far = (s.longRange - 1.0f) * dist * s.radius; // world length
              for (int l = 0; l < nl; ++l) {
                if (glm::dot(photon.position, toLight[l]) > 0.0f) {
                  den[l] += photon.intensity;
                  float w = weight;
                  if (s.shadow && s.thin && w > 0.0f && far > 0.0f) {
                    // Thin parts (Fig. 4): from the photon, march on toward
                    // the light for (longRange - 1) photon offsets, so an ear
                    // behind the head, or anything behind a thin opaque sheet,
                    // stays dark.
                    const glm::vec3 start = x + offset;
                    const glm::vec3 end = start + worldToIndex * (toLight[l] * far);
                    w *= std::exp(-s.occlusionStrength * lookup.opticalDepth(start, end, far, 0.7f,
                      std::max(0.0f, ownNeighbourhood - glm::length(offset))));
                  }
                  if (foreign) {
                    tinted[l] += w * s.materialColors[mp];
                  } else {
                    lit[l] += w;
                  }
                }
              }
            }
          }
          glm::vec3 F = s.ambient, B(0.0f);
          for (int l = 0; l < nl; ++l) {
            if (den[l] > 0.0f) {
              F += s.lights[l].color * (lit[l] / den[l]);
              B += s.lights[l].color * tinted[l] / den[l];
            } else {
              F += s.lights[l].color; // no photon toward this light: unoccluded
            }
          }
          const size_t id = 4 * (static_cast<size_t>(i) +
                                  static_cast<size_t>(grid.dims[0]) * (static_cast<size_t>(j) + static_cast<size_t>(grid.dims[1]) * k));
          const glm::vec3 f = F * invUnlit;
          if (s.packInOne) {
            const glm::vec3 b = B * invUnlit;
            grid.light[id] = toByte(b.x);
            grid.light[id + 1] = toByte(b.y);
            grid.light[id + 2] = toByte(b.z);
            grid.light[id + 3] = toByte((f.x + f.y + f.z) / 3.0f);
            continue;
          }
          grid.light[id] = toByte(f.x);
          grid.light[id + 1] = toByte(f.y);
          grid.light[id + 2] = toByte(f.z);
          if (s.bleed) {
            const glm::vec3 b = B * invUnlit;
            grid.bleed[id] = toByte(b.x);
            grid.bleed[id + 1] = toByte(b.y);
            grid.bleed[id + 2] = toByte(b.z);
          }
        }
      }
    }
    tested += localTested;
  };
  int threads = s.threads > 0 ? s.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min(threads, 64));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) {
    pool.emplace_back(worker);
  }
  worker();
  for (auto& th : pool) {
    th.join();
  }
  grid.photonsTested = tested;
  dilate(grid, computed, 2);
  return grid;
}

} // namespace scatterer
