// Light-space maps: carrying a light between the pieces of a distributed volume.
//
// When a volume is split into pieces (one per MPI rank), the light that reaches a
// point of piece k has crossed every piece between k and the light. By
// Beer-Lambert the transmittance along a path is the product over its parts, so
//   T(p) = T_k(p) * exp(-sum_{j in front of k} tau_j(line through p))
// where T_k is the transmittance through piece k's own matter (its local sweep)
// and tau_j = integral of sigma_t ds over the part of the line inside piece j
// (its optical depth). A light-space map holds one tau per line of the light:
//   - directional light: the lines are parallel; the map is a square grid on a plane
//     orthogonal to the light, covering the whole volume (orthographic);
//   - positional light: the lines are rays from the light; the map is an octahedral
//     map of the directions (Engelhardt & Dachsbacher 2008), which covers a light
//     inside the volume as well as one outside.
// Each piece computes tau_j on every line of the map (opticalDepth), the pieces
// exchange their maps, and each adds the maps of the pieces in front of it
// (enteringDepth). Pieces are disjoint boxes, so along one line they are ordered by
// where the line crosses them. A piece also holds ghost layers (copies of its
// neighbours' voxels) and sweeps through them itself; the part of the pieces in front
// that lies in its ghost layers is taken off their sum, so nothing counts twice and
// the ghost layers get the light they would get in the whole volume too.
//
// Coordinates: continuous structured indices (i, j, k) of the whole volume, the
// frame every piece of one image shares; world lengths come from indexToWorld.
// Plain C++17 + GLM; the GLSL that reads the maps mirrors Map::coordinate
// (Module/Transport/scatterer_transport_sweep.glsl).
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace scatterer {
namespace lightspace {

// An axis-aligned box in structured-index space; empty when lo > hi on any axis.
struct Box {
  glm::dvec3 lo{ 0.0 };
  glm::dvec3 hi{ -1.0 };
  bool empty() const;
};

// The points origin + t * direction for t >= tMin; t grows the way the light
// travels (away from the light).
struct Line {
  glm::dvec3 origin{ 0.0 };
  glm::dvec3 direction{ 0.0, 0.0, 1.0 };
  double tMin = 0.0;
};

// The lines of one light, size x size of them (texel (i, j) at row j).
struct Map {
  bool positional = false;
  glm::dvec3 light{ 0.0 };             // positional: the light's position
  glm::dvec3 travel{ 0.0, 0.0, -1.0 }; // directional: unit direction the light travels
  glm::dvec3 u{ 1.0, 0.0, 0.0 };       // directional: orthonormal plane basis, orthogonal
  glm::dvec3 v{ 0.0, 1.0, 0.0 };       //   to travel
  glm::dvec2 lo{ 0.0 };                // directional: plane coordinates of the map's corner
  double texel = 1.0;                  // directional: texel size in index units
  int size = 1;                        // texels per side

  // The line through the centre of texel (i, j).
  Line line(int i, int j) const;
  // Texture coordinate in [0, 1]^2 of the line through point p (texel centres at
  // (i + 0.5) / size).
  glm::dvec2 coordinate(const glm::dvec3& p) const;
};

// A directional light toward `towardLight` (index space, any length > 0): lines
// `texel` index units apart covering `whole` with a margin of one texel; at most
// maxSize per side (the texel grows instead). Throws std::invalid_argument for a
// zero direction, an empty box, texel <= 0 or maxSize < 2.
Map directionalMap(const glm::dvec3& towardLight, const Box& whole, double texel, int maxSize);

// A positional light at `light` (index space): size x size directions,
// octahedral. Throws std::invalid_argument for size < 2.
Map positionalMap(const glm::dvec3& light, int size);

// Octahedral map of unit directions to [-1, 1]^2 and back.
glm::dvec2 octahedralEncode(const glm::dvec3& direction);
glm::dvec3 octahedralDecode(const glm::dvec2& p);

// The part of `line` inside `box`, [t0, t1] with t0 >= line.tMin; false if none.
bool clip(const Line& line, const Box& box, double& t0, double& t1);

// sigma_t per world unit on a grid of points (x fastest), structured index of the
// first point `origin`. With a `table`, `values` are normalised scalars in [0, 1]:
// interpolated trilinearly first and then looked up (linearly) in the table of sigma_t
// over [0, 1], as a GPU ray caster reads its transfer function; without one, `values`
// are sigma_t. Clamped at the grid's border.
struct ExtinctionGrid {
  glm::ivec3 origin{ 0 };
  glm::ivec3 dims{ 0 };
  std::vector<float> values;
  std::vector<float> table;
  double at(const glm::dvec3& p) const;

  // Empty-space skipping: after values and table are filled, prepare() marks the
  // bricks of kBrick^3 points where sigma_t can be > 0 (a brick's scalar range, its
  // far neighbours included, against the table); empty() is then true where at() is
  // surely 0 (air, transparent tissue), and opticalDepth skips it. Without prepare()
  // nothing is skipped.
  static constexpr int kBrick = 8;
  void prepare();
  bool empty(const glm::dvec3& p) const;
  glm::ivec3 bricks{ 0 };
  std::vector<unsigned char> occupied;
};

// Optical depth of the matter inside `owned` along every line of `map`:
//   tau = integral over the line inside owned of sigma_t ds,
// ds = |indexToWorld * direction| dt (world length), midpoint rule with steps of at
// most `step` index units. size * size values, row j = texel row j. Throws
// std::invalid_argument for step <= 0.
std::vector<float> opticalDepth(const Map& map, const ExtinctionGrid& grid, const Box& owned,
  const glm::dmat3& indexToWorld, double step);

// A piece's optical depths over a window of a map's lines: lines (i, j) with
// x0 <= i < x0 + width, y0 <= j < y0 + height, row j at depth + (j - y0) * stride. The
// piece crosses no line outside it: depth 0 there. What a piece sends the others: its
// map's non-zero window, about size^2 / P^(2/3) lines of P pieces in a 3D split
// instead of size^2.
struct DepthWindow {
  const float* depth = nullptr;
  int x0 = 0, y0 = 0, width = 0, height = 0, stride = 0;
  bool empty() const { return !depth || width <= 0 || height <= 0; }
  float at(int i, int j) const
  {
    return empty() || i < x0 || j < y0 || i >= x0 + width || j >= y0 + height
             ? 0.0f
             : depth[static_cast<size_t>(j - y0) * stride + (i - x0)];
  }
};

// The smallest window of `depth` (a size x size map, row-major) outside which every
// value is 0; it points into `depth` (stride size). Empty when all are 0.
DepthWindow nonZeroWindow(const std::vector<float>& depth, int size);

// The window's values, row after row (width * height floats, stride width).
std::vector<float> packWindow(const DepthWindow& window);

// The optical depth in front of piece `self`'s reach on every line: what the light
// crosses before it enters the box `selfReach` (everything the piece holds: its own
// voxels and its ghost layers). The piece's own sweep covers the reach, so
//   entering = sum over the pieces j in front of self (whose part of the line lies
//              before self's, nearer the light) of depths[j]
//            - the depth of their matter inside selfReach (from `grid`, the piece's
//              own copy of its ghost layers),
// clamped at 0. Where the line misses self's owned box, the reach says where self is
// on it; lines missing both get 0. depths[j] may be empty for a piece that holds
// nothing. grid, indexToWorld and step as for opticalDepth.
std::vector<float> enteringDepth(const Map& map, const std::vector<Box>& owned, int self,
  const Box& selfReach, const std::vector<DepthWindow>& depths, const ExtinctionGrid& grid,
  const glm::dmat3& indexToWorld, double step);

} // namespace lightspace
} // namespace scatterer
