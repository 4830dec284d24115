#include <scatterer/LightSpace.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace scatterer {
namespace lightspace {

bool Box::empty() const
{
  return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z;
}

Line Map::line(int i, int j) const
{
  Line l;
  if (positional) {
    const glm::dvec2 p((i + 0.5) / size * 2.0 - 1.0, (j + 0.5) / size * 2.0 - 1.0);
    l.origin = light;
    l.direction = octahedralDecode(p);
    l.tMin = 0.0;
  } else {
    l.origin = u * (lo.x + (i + 0.5) * texel) + v * (lo.y + (j + 0.5) * texel);
    l.direction = travel;
    l.tMin = -std::numeric_limits<double>::infinity();
  }
  return l;
}

glm::dvec2 Map::coordinate(const glm::dvec3& p) const
{
  if (positional) {
    const glm::dvec3 d = p - light;
    const double length = glm::length(d);
    const glm::dvec3 direction = length > 0.0 ? d / length : glm::dvec3(0.0, 0.0, 1.0);
    return octahedralEncode(direction) * 0.5 + glm::dvec2(0.5);
  }
  return (glm::dvec2(glm::dot(p, u), glm::dot(p, v)) - lo) / (texel * size);
}

Map directionalMap(const glm::dvec3& towardLight, const Box& whole, double texel, int maxSize)
{
  const double length = glm::length(towardLight);
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw std::invalid_argument("lightspace::directionalMap: the light direction is zero");
  }
  if (whole.empty()) {
    throw std::invalid_argument("lightspace::directionalMap: the volume's box is empty");
  }
  if (!(texel > 0.0) || maxSize < 2) {
    throw std::invalid_argument(
      "lightspace::directionalMap: the texel must be > 0 and the map at least 2 texels wide");
  }
  Map map;
  map.travel = -towardLight / length;
  // The plane basis: any two unit vectors orthogonal to the light and each other.
  const glm::dvec3 a = std::abs(map.travel.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  map.u = glm::normalize(glm::cross(map.travel, a));
  map.v = glm::cross(map.travel, map.u);
  glm::dvec2 lo(std::numeric_limits<double>::infinity());
  glm::dvec2 hi(-std::numeric_limits<double>::infinity());
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? whole.hi.x : whole.lo.x, (c & 2) ? whole.hi.y : whole.lo.y,
      (c & 4) ? whole.hi.z : whole.lo.z);
    const glm::dvec2 q(glm::dot(p, map.u), glm::dot(p, map.v));
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
  // One texel of margin on each side, so bilinear lookups at the border stay inside.
  map.texel = texel;
  map.size = static_cast<int>(std::ceil(extent / texel)) + 3;
  if (map.size > maxSize) {
    map.size = maxSize;
    map.texel = extent / (maxSize - 3);
  }
  map.lo = lo - glm::dvec2(map.texel);
  return map;
}

Map positionalMap(const glm::dvec3& light, int size)
{
  if (size < 2) {
    throw std::invalid_argument(
      "lightspace::positionalMap: the map must be at least 2 texels wide");
  }
  Map map;
  map.positional = true;
  map.light = light;
  map.size = size;
  return map;
}

glm::dvec2 octahedralEncode(const glm::dvec3& d)
{
  const double n = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  glm::dvec2 p(d.x / n, d.y / n);
  if (d.z < 0.0) {
    const glm::dvec2 s(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    p = (glm::dvec2(1.0) - glm::dvec2(std::abs(p.y), std::abs(p.x))) * s;
  }
  return p;
}

glm::dvec3 octahedralDecode(const glm::dvec2& p)
{
  glm::dvec3 d(p.x, p.y, 1.0 - std::abs(p.x) - std::abs(p.y));
  if (d.z < 0.0) {
    const glm::dvec2 s(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    const glm::dvec2 q = (glm::dvec2(1.0) - glm::dvec2(std::abs(p.y), std::abs(p.x))) * s;
    d.x = q.x;
    d.y = q.y;
  }
  return glm::normalize(d);
}

bool clip(const Line& line, const Box& box, double& t0, double& t1)
{
  if (box.empty()) {
    return false;
  }
  t0 = line.tMin;
  t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double o = line.origin[a], d = line.direction[a];
    if (std::abs(d) < 1e-300) {
      if (o < box.lo[a] || o > box.hi[a]) {
        return false;
      }
      continue;
    }
    double ta = (box.lo[a] - o) / d, tb = (box.hi[a] - o) / d;
    if (ta > tb) {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 < t1;
}

double ExtinctionGrid::at(const glm::dvec3& p) const
{
  if (dims.x < 1 || dims.y < 1 || dims.z < 1) {
    return 0.0;
  }
  int i0[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double x = std::min(std::max(p[a] - origin[a], 0.0), dims[a] - 1.0);
    i0[a] = std::min(static_cast<int>(x), std::max(dims[a] - 2, 0));
    f[a] = dims[a] > 1 ? x - i0[a] : 0.0;
  }
  const auto value = [&](int dx, int dy, int dz) {
    const size_t x = static_cast<size_t>(std::min(i0[0] + dx, dims.x - 1));
    const size_t y = static_cast<size_t>(std::min(i0[1] + dy, dims.y - 1));
    const size_t z = static_cast<size_t>(std::min(i0[2] + dz, dims.z - 1));
    return static_cast<double>(values[x + dims.x * (y + dims.y * z)]);
  };
  double result = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    const double w = (dx ? f[0] : 1.0 - f[0]) * (dy ? f[1] : 1.0 - f[1]) * (dz ? f[2] : 1.0 - f[2]);
    if (w > 0.0) {
      result += w * value(dx, dy, dz);
    }
  }
  if (table.size() < 2) {
    return result;
  }
  const double s = std::min(std::max(result, 0.0), 1.0) * (table.size() - 1.0);
  const size_t entry = std::min(static_cast<size_t>(s), table.size() - 2);
  const double w = s - static_cast<double>(entry);
  return table[entry] * (1.0 - w) + table[entry + 1] * w;
}

void ExtinctionGrid::prepare()
{
  occupied.clear();
  if (dims.x < 1 || dims.y < 1 || dims.z < 1 || values.empty()) {
    return;
  }
  bricks = (dims + glm::ivec3(kBrick - 1)) / kBrick;
  occupied.assign(static_cast<size_t>(bricks.x) * bricks.y * bricks.z, 0);
  for (int bz = 0; bz < bricks.z; ++bz) {
    for (int by = 0; by < bricks.y; ++by) {
      for (int bx = 0; bx < bricks.x; ++bx) {
        // The brick's points and the next one along each axis: what a sample inside the
        // brick interpolates.
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        for (int z = bz * kBrick; z <= std::min((bz + 1) * kBrick, dims.z - 1); ++z) {
          for (int y = by * kBrick; y <= std::min((by + 1) * kBrick, dims.y - 1); ++y) {
            for (int x = bx * kBrick; x <= std::min((bx + 1) * kBrick, dims.x - 1); ++x) {
              const float v =
                values[x + static_cast<size_t>(dims.x) * (y + static_cast<size_t>(dims.y) * z)];
              lo = std::min(lo, v);
              hi = std::max(hi, v);
            }
          }
        }
        bool any = hi > 0.0f;
        if (table.size() >= 2) {
          // Every table entry a scalar in [lo, hi] interpolates.
          const double n = table.size() - 1.0;
          const size_t first =
            static_cast<size_t>(std::floor(std::clamp(double(lo), 0.0, 1.0) * n));
          const size_t last = std::min(
            static_cast<size_t>(std::ceil(std::clamp(double(hi), 0.0, 1.0) * n)), table.size() - 1);
          any = false;
          for (size_t e = first; e <= last && !any; ++e) {
            any = table[e] > 0.0f;
          }
        }
        occupied[bx + static_cast<size_t>(bricks.x) * (by + static_cast<size_t>(bricks.y) * bz)] =
          any;
      }
    }
  }
}

bool ExtinctionGrid::empty(const glm::dvec3& p) const
{
  if (occupied.empty()) {
    return false;
  }
  int b[3];
  for (int a = 0; a < 3; ++a) {
    const double x = std::min(std::max(p[a] - origin[a], 0.0), dims[a] - 1.0);
    b[a] = std::min(static_cast<int>(x) / kBrick, bricks[a] - 1);
  }
  return !occupied[b[0] +
                   static_cast<size_t>(bricks.x) * (b[1] + static_cast<size_t>(bricks.y) * b[2])];
}

namespace {
// Optical depth of `grid` over [t0, t1] of `line` (midpoint rule, steps <= step).
double depthBetween(const Line& line, double t0, double t1, const ExtinctionGrid& grid,
  const glm::dmat3& indexToWorld, double step)
{
  const int n = std::max(1, static_cast<int>(std::ceil((t1 - t0) / step)));
  const double dt = (t1 - t0) / n;
  double sum = 0.0;
  for (int m = 0; m < n; ++m) {
    const glm::dvec3 p = line.origin + line.direction * (t0 + (m + 0.5) * dt);
    if (!grid.empty(p)) {
      sum += grid.at(p);
    }
  }
  return sum * dt * glm::length(indexToWorld * line.direction);
}

// Runs rows(first, last) over the map's rows [0, size) on the hardware's threads.
template <typename Rows> void forRows(int size, const Rows& rows)
{
  const int threads =
    std::max(1, std::min<int>(static_cast<int>(std::thread::hardware_concurrency()), size));
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) {
    workers.emplace_back(rows, size * t / threads, size * (t + 1) / threads);
  }
  rows(0, size / threads);
  for (auto& w : workers) {
    w.join();
  }
}
} // namespace

std::vector<float> opticalDepth(const Map& map, const ExtinctionGrid& grid, const Box& owned,
  const glm::dmat3& indexToWorld, double step)
{
  if (!(step > 0.0)) {
    throw std::invalid_argument("lightspace::opticalDepth: the step must be > 0");
  }
  std::vector<float> depth(static_cast<size_t>(map.size) * map.size, 0.0f);
  if (owned.empty() || grid.values.empty()) {
    return depth;
  }
  const auto rows = [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      for (int i = 0; i < map.size; ++i) {
        const Line l = map.line(i, j);
        double t0, t1;
        if (!clip(l, owned, t0, t1)) {
          continue;
        }
        // Beer-Lambert's exponent over this piece: sigma_t times world length.
        depth[static_cast<size_t>(j) * map.size + i] =
          static_cast<float>(depthBetween(l, t0, t1, grid, indexToWorld, step));
      }
    }
  };
  forRows(map.size, rows);
  return depth;
}

DepthWindow nonZeroWindow(const std::vector<float>& depth, int size)
{
  if (size <= 0 || depth.size() != static_cast<size_t>(size) * size) {
    throw std::invalid_argument("lightspace::nonZeroWindow: the map is not size x size");
  }
  int x0 = size, y0 = size, x1 = -1, y1 = -1;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      if (depth[static_cast<size_t>(j) * size + i] != 0.0f) {
        x0 = std::min(x0, i);
        x1 = std::max(x1, i);
        y0 = std::min(y0, j);
        y1 = std::max(y1, j);
      }
    }
  }
  DepthWindow w;
  if (x1 < 0) {
    return w;
  }
  w.depth = depth.data() + static_cast<size_t>(y0) * size + x0;
  w.x0 = x0;
  w.y0 = y0;
  w.width = x1 - x0 + 1;
  w.height = y1 - y0 + 1;
  w.stride = size;
  return w;
}

std::vector<float> packWindow(const DepthWindow& window)
{
  std::vector<float> packed;
  if (window.empty()) {
    return packed;
  }
  packed.reserve(static_cast<size_t>(window.width) * window.height);
  for (int j = 0; j < window.height; ++j) {
    const float* row = window.depth + static_cast<size_t>(j) * window.stride;
    packed.insert(packed.end(), row, row + window.width);
  }
  return packed;
}

std::vector<float> enteringDepth(const Map& map, const std::vector<Box>& owned, int self,
  const Box& selfReach, const std::vector<DepthWindow>& depths, const ExtinctionGrid& grid,
  const glm::dmat3& indexToWorld, double step)
{
  if (!(step > 0.0)) {
    throw std::invalid_argument("lightspace::enteringDepth: the step must be > 0");
  }
  std::vector<float> entering(static_cast<size_t>(map.size) * map.size, 0.0f);
  // The other pieces whose window crosses each row, in piece order: only their lines
  // carry depth (outside its window a piece has no matter on the line, so nothing to
  // add and nothing of it in the reach to take off). A line through this piece then
  // clips the few pieces it crosses, not all P of them.
  std::vector<std::vector<int>> byRow(static_cast<size_t>(map.size));
  for (size_t k = 0; k < owned.size(); ++k) {
    const DepthWindow& w = depths[k];
    if (static_cast<int>(k) == self || w.empty()) {
      continue;
    }
    for (int j = std::max(w.y0, 0); j < std::min(w.y0 + w.height, map.size); ++j) {
      byRow[static_cast<size_t>(j)].push_back(static_cast<int>(k));
    }
  }
  forRows(map.size, [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      const std::vector<int>& crossing = byRow[static_cast<size_t>(j)];
      for (int i = 0; i < map.size; ++i) {
        const Line l = map.line(i, j);
        double t0, t1, r0, r1;
        const bool inReach = clip(l, selfReach, r0, r1);
        if (!clip(l, owned[self], t0, t1)) {
          if (!inReach) {
            continue;
          }
          t0 = r0;
          t1 = r1;
        }
        const double here = 0.5 * (t0 + t1);
        const size_t texel = static_cast<size_t>(j) * map.size + i;
        double sum = 0.0;
        for (const int k : crossing) {
          const DepthWindow& w = depths[static_cast<size_t>(k)];
          double s0, s1;
          if (i < w.x0 || i >= w.x0 + w.width || !clip(l, owned[static_cast<size_t>(k)], s0, s1)) {
            continue;
          }
          // Disjoint boxes: the one whose part of the line comes first is in front.
          if (0.5 * (s0 + s1) >= here) {
            continue;
          }
          sum += w.at(i, j);
          // Its part inside the reach: this piece's sweep crosses that itself.
          const double a = std::max(s0, r0), b = std::min(s1, r1);
          if (inReach && a < b) {
            sum -= depthBetween(l, a, b, grid, indexToWorld, step);
          }
        }
        entering[texel] = static_cast<float>(std::max(sum, 0.0));
      }
    }
  });
  return entering;
}

} // namespace lightspace
} // namespace scatterer
