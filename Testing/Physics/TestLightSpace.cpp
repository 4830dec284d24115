// Light-space maps: the optical depth each piece of a split volume holds along a
// light's lines, and the depth in front of a piece, which must add up to what the
// whole volume holds (Beer-Lambert over the parts of a path).
#include <scatterer/LightSpace.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ls = scatterer::lightspace;

namespace {
ls::Box box(double x0, double x1, double y0, double y1, double z0, double z1)
{
  ls::Box b;
  b.lo = glm::dvec3(x0, y0, z0);
  b.hi = glm::dvec3(x1, y1, z1);
  return b;
}

// sigma on points 0..n-1 per axis: constant, or varying (a smooth bump plus a ramp).
ls::ExtinctionGrid grid(int n, bool varying)
{
  ls::ExtinctionGrid g;
  g.dims = glm::ivec3(n);
  g.values.resize(static_cast<size_t>(n) * n * n);
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const double r2 = (x - 9.0) * (x - 9.0) + (y - 7.0) * (y - 7.0) + (z - 8.0) * (z - 8.0);
        g.values[x + n * (y + static_cast<size_t>(n) * z)] =
          varying ? static_cast<float>(0.05 + 0.4 * std::exp(-r2 / 30.0) + 0.01 * x) : 0.5f;
      }
    }
  }
  return g;
}

size_t at(const ls::Map& m, int i, int j)
{
  return static_cast<size_t>(j) * m.size + i;
}

// The texel of the line through p.
size_t texelOf(const ls::Map& m, const glm::dvec3& p)
{
  const glm::dvec2 c = m.coordinate(p) * static_cast<double>(m.size);
  return at(m, static_cast<int>(c.x), static_cast<int>(c.y));
}

// Each piece's optical depth along the map's lines, and pointers to them.
// Each piece's map and what it sends: its non-zero window (as the exchange does).
struct PieceDepths {
  std::vector<std::vector<float>> maps;
  std::vector<ls::DepthWindow> pointers;
};

PieceDepths depthsOf(const ls::Map& m, const ls::ExtinctionGrid& g,
  const std::vector<ls::Box>& owned, const glm::dmat3& indexToWorld, double step)
{
  PieceDepths d;
  for (const auto& b : owned) {
    d.maps.push_back(ls::opticalDepth(m, g, b, indexToWorld, step));
  }
  for (const auto& v : d.maps) {
    d.pointers.push_back(ls::nonZeroWindow(v, m.size));
  }
  return d;
}
} // namespace

TEST(LightSpace, OctahedralMapRoundTrips)
{
  for (const glm::dvec3 d : { glm::dvec3(1, 0, 0), glm::dvec3(0.3, -0.5, 0.8),
         glm::dvec3(-0.2, 0.4, -0.9), glm::dvec3(0, 0, -1), glm::dvec3(-1, -1, -1) }) {
    const glm::dvec3 u = glm::normalize(d);
    EXPECT_LT(glm::length(ls::octahedralDecode(ls::octahedralEncode(u)) - u), 1e-12);
  }
}

TEST(LightSpace, EveryPointOfALineLooksUpItsOwnTexel)
{
  const ls::Box whole = box(0, 20, 0, 16, 0, 12);
  const ls::Map maps[] = { ls::directionalMap(glm::dvec3(0.3, -1.0, 0.4), whole, 1.5, 256),
    ls::positionalMap(glm::dvec3(8, 5, 30), 64), ls::positionalMap(glm::dvec3(8, 5, 6), 64) };
  for (const ls::Map& m : maps) {
    for (int j = 1; j < m.size - 1; j += 5) {
      for (int i = 1; i < m.size - 1; i += 7) {
        const ls::Line l = m.line(i, j);
        for (double t : { 0.5, 3.0, 11.0 }) {
          const glm::dvec2 c =
            m.coordinate(l.origin + l.direction * t) * static_cast<double>(m.size);
          EXPECT_NEAR(c.x, i + 0.5, 1e-9);
          EXPECT_NEAR(c.y, j + 0.5, 1e-9);
        }
      }
    }
  }
}

TEST(LightSpace, DirectionalMapCoversTheWholeVolume)
{
  const ls::Box whole = box(0, 40, 0, 30, 0, 20);
  const ls::Map m = ls::directionalMap(glm::dvec3(1, 2, 3), whole, 2.0, 1024);
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? 40 : 0, (c & 2) ? 30 : 0, (c & 4) ? 20 : 0);
    const glm::dvec2 t = m.coordinate(p);
    EXPECT_GT(t.x, 0.0);
    EXPECT_LT(t.x, 1.0);
    EXPECT_GT(t.y, 0.0);
    EXPECT_LT(t.y, 1.0);
  }
  // Capped: the texel grows instead.
  const ls::Map capped = ls::directionalMap(glm::dvec3(1, 2, 3), whole, 0.01, 64);
  EXPECT_EQ(capped.size, 64);
  EXPECT_GT(capped.texel, 0.5);
  EXPECT_THROW(ls::directionalMap(glm::dvec3(0.0), whole, 1.0, 64), std::invalid_argument);
  EXPECT_THROW(ls::directionalMap(glm::dvec3(1.0), ls::Box(), 1.0, 64), std::invalid_argument);
  EXPECT_THROW(ls::positionalMap(glm::dvec3(1.0), 1), std::invalid_argument);
}

TEST(LightSpace, OpticalDepthOfAUniformSlabIsSigmaTimesWorldLength)
{
  // sigma 0.5 per world unit, 10 index units of 2 world units along the light.
  const ls::ExtinctionGrid g = grid(16, false);
  const glm::dmat3 indexToWorld(2.0);
  const ls::Map m = ls::directionalMap(glm::dvec3(1, 0, 0), box(0, 15, 0, 15, 0, 15), 1.0, 64);
  const std::vector<float> depth =
    ls::opticalDepth(m, g, box(2, 12, 0, 15, 0, 15), indexToWorld, 0.7);
  const glm::dvec3 centre(7.0, 7.5, 7.5);
  const glm::dvec2 c = m.coordinate(centre) * static_cast<double>(m.size);
  EXPECT_NEAR(depth[at(m, static_cast<int>(c.x), static_cast<int>(c.y))], 0.5 * 10 * 2, 1e-4);
  // Outside the box: nothing.
  EXPECT_EQ(depth[at(m, 0, 0)], 0.0f);
  EXPECT_THROW(
    ls::opticalDepth(m, g, box(0, 1, 0, 1, 0, 1), indexToWorld, 0.0), std::invalid_argument);
}

TEST(LightSpace, ThePieceNearerTheLightIsInFront)
{
  const ls::ExtinctionGrid g = grid(16, false);
  const glm::dmat3 unit(1.0);
  const ls::Box whole = box(0, 15, 0, 15, 0, 15);
  const std::vector<ls::Box> owned = { box(0, 5, 0, 15, 0, 15), box(5, 15, 0, 15, 0, 15) };
  const glm::dvec3 p(2.0, 7.5, 7.5); // in piece 0
  for (const bool fromPlusX : { true, false }) {
    const ls::Map m = ls::directionalMap(glm::dvec3(fromPlusX ? 1 : -1, 0, 0), whole, 1.0, 64);
    const PieceDepths d = depthsOf(m, g, owned, unit, 0.5);
    const std::vector<ls::DepthWindow>& depths = d.pointers;
    const size_t texel = texelOf(m, p);
    const std::vector<float> e0 = ls::enteringDepth(m, owned, 0, owned[0], depths, g, unit, 0.5);
    const std::vector<float> e1 = ls::enteringDepth(m, owned, 1, owned[1], depths, g, unit, 0.5);
    // Light from +x: piece 1 (x 5..15, depth 0.5 * 10) shades piece 0, not the reverse.
    EXPECT_NEAR(e0[texel], fromPlusX ? 5.0 : 0.0, 1e-4);
    EXPECT_NEAR(e1[texel], fromPlusX ? 0.0 : 2.5, 1e-4);
  }
  // A positional light inside piece 1, at x = 9: piece 0 is shaded by x 5..9 only,
  // and piece 1 by nothing.
  const ls::Map m = ls::positionalMap(glm::dvec3(9.0, 7.5, 7.5), 128);
  const PieceDepths d = depthsOf(m, g, owned, unit, 0.25);
  const std::vector<ls::DepthWindow>& depths = d.pointers;
  const size_t texel = texelOf(m, p);
  EXPECT_NEAR(
    ls::enteringDepth(m, owned, 0, owned[0], depths, g, unit, 0.25)[texel], 0.5 * 4.0, 0.05);
  EXPECT_NEAR(ls::enteringDepth(m, owned, 1, owned[1], depths, g, unit, 0.25)[texel], 0.0, 1e-6);
  // With 2 ghost layers, piece 0 crosses x 5..7 itself: 2 less in front.
  EXPECT_NEAR(ls::enteringDepth(m, owned, 0, box(0, 7, 0, 15, 0, 15), depths, g, unit, 0.25)[texel],
    0.5 * 2.0, 0.05);
}

TEST(LightSpace, FourPiecesAddUpToTheWholeVolume)
{
  // Exactness of the exchange: on every line, the depth in front of the farthest piece
  // plus that piece's own is what one process sees through the whole volume.
  const ls::ExtinctionGrid g = grid(20, true);
  const glm::dmat3 indexToWorld(
    glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.2, 0.0), glm::dvec3(0.0, 0.0, 0.8));
  const ls::Box whole = box(0, 19, 0, 19, 0, 19);
  const std::vector<ls::Box> owned = { box(0, 8, 0, 11, 0, 19), box(8, 19, 0, 11, 0, 19),
    box(0, 8, 11, 19, 0, 19), box(8, 19, 11, 19, 0, 19) };
  const ls::Map maps[] = { ls::directionalMap(glm::dvec3(0.6, 0.8, 0.3), whole, 1.0, 256),
    ls::positionalMap(glm::dvec3(30.0, 25.0, 9.0), 128),
    ls::positionalMap(glm::dvec3(14.0, 14.0, 9.0), 128) };
  for (const ls::Map& m : maps) {
    const std::vector<float> all = ls::opticalDepth(m, g, whole, indexToWorld, 0.25);
    const PieceDepths d = depthsOf(m, g, owned, indexToWorld, 0.25);
    const std::vector<ls::DepthWindow>& depths = d.pointers;
    std::vector<ls::Box> reach;
    std::vector<std::vector<float>> entering, local;
    for (int k = 0; k < 4; ++k) {
      ls::Box r = owned[k];
      r.lo = glm::max(r.lo - glm::dvec3(3.0), whole.lo);
      r.hi = glm::min(r.hi + glm::dvec3(3.0), whole.hi);
      reach.push_back(r);
      entering.push_back(ls::enteringDepth(m, owned, k, r, depths, g, indexToWorld, 0.25));
      local.push_back(ls::opticalDepth(m, g, r, indexToWorld, 0.25));
    }
    int checked = 0;
    for (int j = 0; j < m.size; ++j) {
      for (int i = 0; i < m.size; ++i) {
        // The piece the line crosses last.
        const ls::Line l = m.line(i, j);
        int last = -1;
        double lastMid = -1e300, t0, t1;
        for (int k = 0; k < 4; ++k) {
          if (ls::clip(l, owned[k], t0, t1) && 0.5 * (t0 + t1) > lastMid) {
            last = k;
            lastMid = 0.5 * (t0 + t1);
          }
        }
        if (last < 0) {
          continue;
        }
        const double total = all[at(m, i, j)];
        EXPECT_NEAR(
          entering[last][at(m, i, j)] + local[last][at(m, i, j)], total, 0.02 * total + 1e-3)
          << i << "," << j;
        ++checked;
      }
    }
    EXPECT_GT(checked, 200);
  }
}

TEST(LightSpace, SkippingEmptySpaceChangesNothing)
{
  // A grid that is mostly transparent (table 0 below 0.5), with a dense ball: the depths
  // with empty-space skipping are those without.
  ls::ExtinctionGrid g;
  const int n = 40;
  g.dims = glm::ivec3(n);
  g.values.resize(static_cast<size_t>(n) * n * n);
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const double r = glm::length(glm::dvec3(x, y, z) - glm::dvec3(25.0, 18.0, 21.0));
        g.values[x + n * (y + static_cast<size_t>(n) * z)] =
          static_cast<float>(r < 7.0 ? 0.9 : 0.3);
      }
    }
  }
  g.table = { 0.0f, 0.0f, 0.0f, 0.5f, 2.0f };
  const ls::Box whole = box(0, n - 1, 0, n - 1, 0, n - 1);
  const glm::dmat3 unit(1.0);
  for (const ls::Map& m : { ls::directionalMap(glm::dvec3(0.3, 0.5, 0.8), whole, 1.0, 256),
         ls::positionalMap(glm::dvec3(5.0, 30.0, 20.0), 64) }) {
    const std::vector<float> plain = ls::opticalDepth(m, g, whole, unit, 0.5);
    ls::ExtinctionGrid skipping = g;
    skipping.prepare();
    EXPECT_LT(std::count(skipping.occupied.begin(), skipping.occupied.end(), 1),
      static_cast<long>(skipping.occupied.size()));
    const std::vector<float> skipped = ls::opticalDepth(m, skipping, whole, unit, 0.5);
    double total = 0.0;
    for (size_t i = 0; i < plain.size(); ++i) {
      EXPECT_EQ(plain[i], skipped[i]) << i;
      total += plain[i];
    }
    EXPECT_GT(total, 1.0);
  }
}

TEST(LightSpace, ScalarsAreInterpolatedBeforeTheTransferFunction)
{
  // As the ray caster reads its transfer function: halfway between a scalar of 0 and
  // one of 1 the scalar is 0.5, whose sigma is the table's middle entry, not the mean
  // of the ends.
  ls::ExtinctionGrid g;
  g.dims = glm::ivec3(2, 1, 1);
  g.values = { 0.0f, 1.0f };
  g.table = { 0.0f, 0.0f, 0.0f, 2.0f, 8.0f };
  EXPECT_NEAR(g.at(glm::dvec3(0.5, 0.0, 0.0)), 0.0, 1e-12);
  EXPECT_NEAR(g.at(glm::dvec3(0.875, 0.0, 0.0)), 5.0, 1e-12);
  EXPECT_NEAR(g.at(glm::dvec3(1.0, 0.0, 0.0)), 8.0, 1e-12);
}

TEST(LightSpace, DepthWindowHoldsEveryNonZeroLine)
{
  // A piece crosses lines (3..5, 2) and (4, 6) of an 8 x 8 map: its window is columns
  // 3..5, rows 2..6, and the packed window reads back every line, zeros outside.
  const int size = 8;
  std::vector<float> map(size * size, 0.0f);
  map[2 * size + 3] = 1.0f;
  map[2 * size + 5] = 2.0f;
  map[6 * size + 4] = 3.0f;
  const ls::DepthWindow window = ls::nonZeroWindow(map, size);
  EXPECT_EQ(window.x0, 3);
  EXPECT_EQ(window.y0, 2);
  EXPECT_EQ(window.width, 3);
  EXPECT_EQ(window.height, 5);
  const std::vector<float> packed = ls::packWindow(window);
  ASSERT_EQ(packed.size(), 15u);
  ls::DepthWindow sent = window;
  sent.depth = packed.data();
  sent.stride = window.width;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      EXPECT_EQ(sent.at(i, j), map[static_cast<size_t>(j) * size + i]) << i << "," << j;
    }
  }
  EXPECT_TRUE(ls::nonZeroWindow(std::vector<float>(size * size, 0.0f), size).empty());
  EXPECT_THROW(ls::nonZeroWindow(map, size + 1), std::invalid_argument);
}
