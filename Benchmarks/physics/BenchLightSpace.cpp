// The CPU part of the light exchange between ranks (docs/paraview.md): the depth in
// front of one piece, for a volume split into k x k x k pieces, as the number of ranks
// P = k^3 grows. Each piece's window is the rectangle its box covers on the map, filled
// with depth 1 (what a piece full of matter sends); the piece asking is a middle one,
// with 3 ghost layers of empty space (the subtraction then costs one clip per piece in
// front). The map has lines one voxel apart across an oblique light: 660 x 660 for a
// 509^3 volume. Table and CSV: docs/paraview.md, "Beyond 4 ranks".
#include <scatterer/LightSpace.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace ls = scatterer::lightspace;

namespace
{
constexpr int kSide = 509; // voxels per side (512 lines a side for a light along an axis)

ls::Box Piece(int k, int x, int y, int z)
{
  const double w = static_cast<double>(kSide - 1) / k;
  ls::Box b;
  b.lo = glm::dvec3(x * w, y * w, z * w);
  b.hi = glm::dvec3((x + 1) * w, (y + 1) * w, (z + 1) * w);
  return b;
}

// The light from an oblique direction, as a scene light usually is.
void BM_EnteringDepth(benchmark::State& state)
{
  const int k = static_cast<int>(state.range(0));
  ls::Box whole;
  whole.lo = glm::dvec3(0.0);
  whole.hi = glm::dvec3(kSide - 1.0);
  const ls::Map map = ls::directionalMap(glm::dvec3(0.3, 0.2, 1.0), whole, 1.0, 1024);
  std::vector<ls::Box> owned;
  for (int z = 0; z < k; ++z)
    for (int y = 0; y < k; ++y)
      for (int x = 0; x < k; ++x)
        owned.push_back(Piece(k, x, y, z));
  // Windows: the map rectangle each box covers (its 8 corners), all depths 1.
  std::vector<float> ones(static_cast<size_t>(map.size) * map.size, 1.0f);
  std::vector<ls::DepthWindow> depths;
  for (const ls::Box& b : owned)
  {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int c = 0; c < 8; ++c)
    {
      const glm::dvec3 p(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z);
      const glm::dvec2 t = map.coordinate(p) * static_cast<double>(map.size);
      lo = glm::min(lo, t);
      hi = glm::max(hi, t);
    }
    ls::DepthWindow w;
    w.depth = ones.data();
    w.x0 = std::max(0, static_cast<int>(lo.x));
    w.y0 = std::max(0, static_cast<int>(lo.y));
    w.width = std::min(map.size, static_cast<int>(hi.x) + 1) - w.x0;
    w.height = std::min(map.size, static_cast<int>(hi.y) + 1) - w.y0;
    w.stride = map.size;
    depths.push_back(w);
  }
  const int self = (k / 2) * (1 + k + k * k);
  ls::Box reach = owned[self];
  reach.lo -= glm::dvec3(3.0);
  reach.hi += glm::dvec3(3.0);
  ls::ExtinctionGrid grid; // the ghost layers: empty space
  const glm::dmat3 unit(1.0);
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(ls::enteringDepth(map, owned, self, reach, depths, grid, unit, 0.5));
  }
  state.counters["ranks"] = static_cast<double>(owned.size());
  state.counters["lines"] = static_cast<double>(map.size) * map.size;
}
BENCHMARK(BM_EnteringDepth)
  ->Arg(1)
  ->Arg(2)
  ->Arg(4)
  ->Arg(8)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
}
