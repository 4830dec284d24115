// Distributed rendering splits a volume into pieces with ghost layers (ParaView
// plugin). These tests check the physics side of that promise: a piece whose ghost
// margin covers the illumination reach, with its cache voxels on the whole volume's
// lattice (IlluminationSettings::cacheStep/cacheFirstCentre/cacheIndexOrigin), lights
// its own voxels as the whole volume does; with too thin a margin it does not.
#include <scatterer/Scatterer.h>
#include <scatterer/Illumination.h>
#include <scatterer/Material.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace {

using namespace scatterer;

constexpr int kNx = 100, kNy = 16, kNz = 12; // whole volume (voxels)
constexpr int kSlabX = 52;                   // opaque sheet at x = 52, 53 (y < 8)
constexpr int kSplit = 56;                   // the piece owns x >= 56
constexpr int kScale = 2;                    // volume voxels per cache voxel
constexpr float kRadius = 12.0f;             // voxels; reach = 3 radii + 1 cache voxel

// Translucent medium everywhere, an opaque sheet between the light (-x) and the
// piece's first owned voxels, over half of y so the shadow has an edge.
OcclusionField wholeField()
{
  OcclusionField f;
  f.dims[0] = kNx;
  f.dims[1] = kNy;
  f.dims[2] = kNz;
  const size_t n = static_cast<size_t>(kNx) * kNy * kNz;
  f.extinction.assign(n, 0.05f);
  f.material.assign(n, 0);
  for (int k = 0; k < kNz; ++k) {
    for (int j = 0; j < kNy / 2; ++j) {
      for (int i = kSlabX; i <= kSlabX + 1; ++i) {
        f.extinction[static_cast<size_t>(i) + kNx * (static_cast<size_t>(j) + kNy * k)] = 50.0f;
      }
    }
  }
  return f;
}

// Voxels x in [x0, kNx) of the whole field.
OcclusionField pieceOf(const OcclusionField& whole, int x0)
{
  OcclusionField f;
  f.dims[0] = kNx - x0;
  f.dims[1] = kNy;
  f.dims[2] = kNz;
  for (int k = 0; k < kNz; ++k) {
    for (int j = 0; j < kNy; ++j) {
      for (int i = x0; i < kNx; ++i) {
        const size_t id = static_cast<size_t>(i) + kNx * (static_cast<size_t>(j) + kNy * k);
        f.extinction.push_back(whole.extinction[id]);
        f.material.push_back(whole.material[id]);
      }
    }
  }
  return f;
}

IlluminationSettings baseSettings()
{
  IlluminationSettings s;
  s.radius = kRadius;
  s.longRange = 3.0f;
  s.materialColors = {glm::vec3(1.0f)};
  s.speedRatios = {1.0f};
  s.opacityRatios = {1.0f};
  s.ambient = glm::vec3(0.1f);
  GridLight light;
  light.toLight = glm::vec3(-1.0f, 0.0f, 0.0f);
  light.color = glm::vec3(0.9f);
  s.lights = {light};
  s.threads = 2;
  return s;
}

// The cache lattice of a piece starting at global voxel x0 (what the mapper does
// with the image extent): cache voxel G of the whole volume is centred at global
// index (G + 0.5) * kScale - 0.5.
void placeOnLattice(IlluminationSettings& s, const int dims[3], int x0)
{
  const int origin[3] = {x0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    const int first = origin[a] / kScale;
    const int last = (origin[a] + dims[a] - 1) / kScale;
    s.cacheDims[a] = last - first + 1;
    s.cacheStep[a] = static_cast<float>(kScale);
    s.cacheFirstCentre[a] = (first + 0.5f) * kScale - 0.5f - origin[a];
    s.cacheIndexOrigin[a] = first;
  }
  s.worldOrigin = glm::vec3(static_cast<float>(x0), 0.0f, 0.0f);
}

struct Comparison {
  int compared = 0;
  int exact = 0;
  int maxDifference = 0;
};

// Owned cache voxels (centre x >= kSplit) of the piece against the whole volume's.
Comparison compareOwned(const IlluminationGrid& whole, const IlluminationGrid& piece, int pieceFirstG)
{
  Comparison c;
  for (int k = 0; k < whole.dims[2]; ++k) {
    for (int j = 0; j < whole.dims[1]; ++j) {
      for (int g = 0; g < whole.dims[0]; ++g) {
        if ((g + 0.5f) * kScale - 0.5f < kSplit) {
          continue;
        }
        const int p = g - pieceFirstG;
        const size_t w = 4 * (static_cast<size_t>(g) + whole.dims[0] * (static_cast<size_t>(j) + whole.dims[1] * k));
        const size_t q = 4 * (static_cast<size_t>(p) + piece.dims[0] * (static_cast<size_t>(j) + piece.dims[1] * k));
        int worst = 0;
        for (int ch = 0; ch < 3; ++ch) {
          worst = std::max(worst, std::abs(int(whole.light[w + ch]) - int(piece.light[q + ch])));
          worst = std::max(worst, std::abs(int(whole.bleed[w + ch]) - int(piece.bleed[q + ch])));
        }
        ++c.compared;
        c.exact += worst == 0;
        c.maxDifference = std::max(c.maxDifference, worst);
      }
    }
  }
  return c;
}

std::vector<std::vector<Template>> someTemplates()
{
  Material medium;
  medium.opacity = 0.3;
  return {generateTemplates(medium, GeneratorSettings{})};
}

TEST(IlluminationPieces, LatticeSettingsReproduceTheDefaultLayoutWhenDimsDivide)
{
  const OcclusionField field = wholeField();
  const auto templates = someTemplates();
  IlluminationSettings plain = baseSettings();
  for (int a = 0; a < 3; ++a) {
    plain.cacheDims[a] = field.dims[a] / kScale;
  }
  IlluminationSettings lattice = baseSettings();
  placeOnLattice(lattice, field.dims, 0);
  const IlluminationGrid a = computeIllumination(field, templates, plain);
  const IlluminationGrid b = computeIllumination(field, templates, lattice);
  ASSERT_EQ(a.dims[0], b.dims[0]);
  EXPECT_EQ(a.light, b.light);
  EXPECT_EQ(a.bleed, b.bleed);
}

// The piece of voxels x >= x0 (ghost layers from x0 up to kSplit) against the whole
// volume, over the voxels the piece owns.
Comparison pieceAgainstWhole(int x0)
{
  const OcclusionField whole = wholeField();
  const auto templates = someTemplates();
  IlluminationSettings ws = baseSettings();
  placeOnLattice(ws, whole.dims, 0);
  const IlluminationGrid wholeGrid = computeIllumination(whole, templates, ws);
  const OcclusionField piece = pieceOf(whole, x0);
  IlluminationSettings ps = baseSettings();
  placeOnLattice(ps, piece.dims, x0);
  const IlluminationGrid pieceGrid = computeIllumination(piece, templates, ps);
  return compareOwned(wholeGrid, pieceGrid, ps.cacheIndexOrigin[0]);
}

TEST(IlluminationPieces, PieceWithGhostsAsWideAsTheReachIsLitAsTheWholeVolume)
{
  // Reach: photons within one radius, the thin-part check to 3 radii, one cache voxel.
  const int ghosts = static_cast<int>(3 * kRadius) + kScale + 1;
  // x0 = 17: the sheet is in the ghost layers.
  const Comparison c = pieceAgainstWhole(kSplit - ghosts);
  ASSERT_GT(c.compared, 0);
  // The same samples on the same lattice; only float rounding of shifted
  // coordinates may move a value by one step of 255.
  EXPECT_LE(c.maxDifference, 1);
  EXPECT_GE(c.exact, c.compared * 99 / 100) << c.exact << " of " << c.compared << " exact";
}

TEST(IlluminationPieces, PieceWithoutEnoughGhostsMissesTheShadowAcrossItsBorder)
{
  // The control for the test above: the same comparison fails when the sheet that
  // shadows the piece's first voxels lies outside its ghost layers.
  const Comparison c = pieceAgainstWhole(kSplit - 2);
  EXPECT_GT(c.maxDifference, 10);
}

TEST(IlluminationPieces, RejectsAPartialOrNegativeLattice)
{
  const OcclusionField field = wholeField();
  const auto templates = someTemplates();
  IlluminationSettings s = baseSettings();
  placeOnLattice(s, field.dims, 0);
  s.cacheStep.y = 0.0f;
  EXPECT_THROW(computeIllumination(field, templates, s), std::invalid_argument);
  s.cacheStep.y = -2.0f;
  EXPECT_THROW(computeIllumination(field, templates, s), std::invalid_argument);
}

} // namespace
