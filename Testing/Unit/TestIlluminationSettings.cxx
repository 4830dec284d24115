// The one record of the illumination's settings (scatterer/IlluminationSettings.h):
// every default lies in its range, and a new mapper starts at the record's defaults
// and clamps to its ranges. (The ParaView XML's defaults and ranges are held to the
// mapper by Testing/Python/TestScattererParaViewProperties.py.)
#include "scatterer/GeneratorSettings.h"
#include "scatterer/IlluminationSettings.h"
#include "vtkNew.h"
#include "vtkScattererTemplateVolumeMapper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace il = scatterer::illumination;

namespace
{
template <typename T>
void ExpectDefaultInRange(const il::Setting<T>& s)
{
  EXPECT_LE(s.Minimum, s.Default) << s.Name;
  EXPECT_LE(s.Default, s.Maximum) << s.Name;
  EXPECT_LT(s.Minimum, s.Maximum) << s.Name;
}
}

TEST(IlluminationSettings, EveryDefaultLiesInItsRange)
{
  ExpectDefaultInRange(il::IlluminationMode);
  ExpectDefaultInRange(il::ShaderPathSelection);
  ExpectDefaultInRange(il::TransportScale);
  ExpectDefaultInRange(il::InteractiveTransportScale);
  ExpectDefaultInRange(il::MaximumTransportVoxels);
  ExpectDefaultInRange(il::MultipleScattering);
  ExpectDefaultInRange(il::TemplateRadius);
  ExpectDefaultInRange(il::TemplatesPerMaterial);
  ExpectDefaultInRange(il::PhotonCap);
  ExpectDefaultInRange(il::OcclusionStrength);
  ExpectDefaultInRange(il::IlluminationInterval);
  ExpectDefaultInRange(il::LongRangeMultiple);
  ExpectDefaultInRange(il::PhotonThreshold);
  ExpectDefaultInRange(il::GeneratorThreshold);
}

TEST(IlluminationSettings, TheMapperAndTheGeneratorStartAtTheRecord)
{
  vtkNew<vtkScattererTemplateVolumeMapper> m;
  EXPECT_EQ(m->GetIlluminationEnabled(), il::Illumination.Default);
  EXPECT_EQ(m->GetShadowsEnabled(), il::Shadows.Default);
  EXPECT_EQ(m->GetColorBleedingEnabled(), il::ColorBleeding.Default);
  EXPECT_EQ(m->GetThinPartCheckEnabled(), il::ThinPartCheck.Default);
  EXPECT_EQ(m->GetBoundaryRefractionEnabled(), il::BoundaryRefraction.Default);
  EXPECT_EQ(m->GetTemplateBlendingEnabled(), il::TemplateBlending.Default);
  EXPECT_EQ(m->GetCroppedMatterCastsShadows(), il::CroppedMatterCastsShadows.Default);
  EXPECT_EQ(m->GetIlluminationMode(), il::IlluminationMode.Default);
  EXPECT_EQ(m->GetTransportScale(), il::TransportScale.Default);
  EXPECT_EQ(m->GetInteractiveTransportScale(), il::InteractiveTransportScale.Default);
  EXPECT_EQ(m->GetMaximumTransportVoxels(), il::MaximumTransportVoxels.Default);
  EXPECT_EQ(m->GetMultipleScattering(), il::MultipleScattering.Default);
  EXPECT_EQ(m->GetTemplatesPerMaterial(), il::TemplatesPerMaterial.Default);
  EXPECT_EQ(m->GetPhotonCap(), il::PhotonCap.Default);
  EXPECT_EQ(m->GetOcclusionStrength(), il::OcclusionStrength.Default);
  EXPECT_EQ(m->GetIlluminationInterval(), il::IlluminationInterval.Default);
  EXPECT_EQ(m->GetLongRangeMultiple(), il::LongRangeMultiple.Default);
  EXPECT_EQ(m->GetPhotonThreshold(), il::PhotonThreshold.Default);
  EXPECT_EQ(m->GetGeneratorThreshold(), il::GeneratorThreshold.Default);
  const scatterer::GeneratorSettings generator;
  EXPECT_EQ(generator.threshold, il::GeneratorThreshold.Default);
  EXPECT_EQ(generator.templatesPerMaterial, il::TemplatesPerMaterial.Default);
}

TEST(IlluminationSettings, TheMapperClampsToTheRecordsRanges)
{
  vtkNew<vtkScattererTemplateVolumeMapper> m;
  m->GlobalWarningDisplayOff();
  m->SetTransportScale(il::TransportScale.Maximum + 5);
  EXPECT_EQ(m->GetTransportScale(), il::TransportScale.Maximum);
  m->SetPhotonCap(il::PhotonCap.Minimum - 1);
  EXPECT_EQ(m->GetPhotonCap(), il::PhotonCap.Minimum);
  m->SetMultipleScattering(il::MultipleScattering.Maximum * 2);
  EXPECT_EQ(m->GetMultipleScattering(), il::MultipleScattering.Maximum);
  m->GlobalWarningDisplayOn();
}

// The budget of transport voxels (MaximumTransportVoxels): the CT head keeps TransportScale,
// its resamples to 383x383x161 and 511x511x215 (the benchmark's sizes) take the scale that
// stores their light as finely in the object (the same 129x129x55 grid), dragging frames
// stay twice as coarse as still ones, and no budget or a small volume changes nothing.
TEST(IlluminationSettings, ALargeVolumeIsBuiltAtTheScaleThatFitsTheBudget)
{
  const int budget = il::MaximumTransportVoxels.Default;
  const int head[3] = { 256, 256, 108 }, mid[3] = { 383, 383, 161 }, big[3] = { 511, 511, 215 };
  // Their voxels (mm): 1.5 mm slices, less than twice the pixels: every axis at the scale.
  const double headMm[3] = { 0.957, 0.957, 1.5 }, midMm[3] = { 0.640, 0.640, 1.006 },
               bigMm[3] = { 0.479, 0.479, 0.754 }, cubic[3] = { 1, 1, 1 };
  const int two[3] = { 2, 2, 2 }, three[3] = { 3, 3, 3 }, four[3] = { 4, 4, 4 };
  EXPECT_EQ(il::transportVoxelsAt(head, two), 129LL * 129 * 55);
  EXPECT_EQ(il::transportScaleFor(2, head, headMm, budget), 2);
  EXPECT_EQ(il::transportScaleFor(2, mid, midMm, budget), 3);
  EXPECT_EQ(il::transportScaleFor(2, big, bigMm, budget), 4);
  EXPECT_EQ(il::transportVoxelsAt(mid, three), il::transportVoxelsAt(head, two));
  EXPECT_EQ(il::transportVoxelsAt(big, four), il::transportVoxelsAt(head, two));
  EXPECT_EQ(il::interactiveTransportScaleFor(2, 4, 2), 4);
  EXPECT_EQ(il::interactiveTransportScaleFor(2, 4, 3), 6);
  EXPECT_EQ(il::interactiveTransportScaleFor(2, 4, 4), 8);
  EXPECT_EQ(il::interactiveTransportScaleFor(2, 2, 4), 4); // no coarser than asked: still's
  EXPECT_EQ(il::transportScaleFor(2, big, bigMm, 0), 2);   // 0: no limit
  const int small[3] = { 48, 48, 48 }, flat[3] = { 4000, 4000, 1 };
  EXPECT_EQ(il::transportScaleFor(1, small, cubic, budget), 1);
  const int flatScale = il::transportScaleFor(1, flat, cubic, budget);
  const int flatStrides[3] = { flatScale, flatScale, flatScale };
  EXPECT_LE(il::transportVoxelsAt(flat, flatStrides), budget);
  const int one[3] = { 1, 1, 1 };
  EXPECT_EQ(il::transportScaleFor(3, one, cubic, 1), 3); // nothing to coarsen: it stops
  // Long voxels take fewer per texel, so the budget counts more texels: a 1 x 1 x 3 mm
  // volume of 256x256x86 holds 129x129x86 at scale 2, over the budget, and 86^3 at 3.
  const int mri[3] = { 256, 256, 86 };
  const double mriMm[3] = { 1, 1, 3 };
  EXPECT_EQ(il::transportScaleFor(2, mri, mriMm, budget), 3);
}

// Voxels at least twice as long along an axis as along the shortest take fewer per
// transport texel there, and per diffusion texel, so that both stay about as long as along
// the shortest axis; below twice, every axis keeps the scale (the CT head's 1.5 mm slices
// under 0.96 mm pixels).
TEST(IlluminationSettings, AxesOfLongVoxelsTakeFewerVoxelsPerTexel)
{
  auto strides = [](int scale, double x, double y, double z)
  {
    const double spacing[3] = { x, y, z };
    int s[3];
    il::transportStridesFor(scale, spacing, s);
    return std::vector<int>{ s[0], s[1], s[2] };
  };
  auto blocks = [](int still, std::vector<int> fine, double x, double y, double z)
  {
    const double spacing[3] = { x, y, z };
    int b[3];
    il::diffusionBlocksFor(still, fine.data(), spacing, b);
    return std::vector<int>{ b[0], b[1], b[2] };
  };
  using V = std::vector<int>;
  EXPECT_EQ(strides(2, 0.957, 0.957, 1.5), V({ 2, 2, 2 }));
  EXPECT_EQ(blocks(2, { 2, 2, 2 }, 0.957, 0.957, 1.5), V({ 2, 2, 2 }));
  EXPECT_EQ(strides(2, 1, 1, 3), V({ 2, 2, 1 }));             // texels 2 x 2 x 3 (were 2 x 2 x 6)
  EXPECT_EQ(blocks(2, { 2, 2, 1 }, 1, 1, 3), V({ 2, 2, 1 })); // diffusion 4 x 4 x 3 (12 deep)
  EXPECT_EQ(strides(2, 3, 1, 1), V({ 1, 2, 2 }));             // whichever axis is long
  EXPECT_EQ(strides(2, -1, 1, -3), V({ 2, 2, 1 }));           // signs (a flipped axis) aside
  EXPECT_EQ(strides(2, 1, 1, 2), V({ 2, 2, 1 }));             // twice: 2 x 2 x 2
  EXPECT_EQ(blocks(2, { 2, 2, 1 }, 1, 1, 2), V({ 2, 2, 2 }));
  EXPECT_EQ(strides(4, 1, 1, 1.9), V({ 4, 4, 4 }));     // below twice: as cubic voxels
  EXPECT_EQ(strides(6, 0.5, 0.5, 2.5), V({ 6, 6, 1 })); // clinical CT: 3 x 3 x 2.5 mm
  EXPECT_EQ(strides(2, 1, 1, 1e6), V({ 2, 2, 1 }));     // at least one voxel
  // A frame the user drags (scale 4 over a still frame's 2) keeps the still frames'
  // diffusion texels: 4 x 4 x 3 mm.
  EXPECT_EQ(strides(4, 1, 1, 3), V({ 4, 4, 1 }));
  EXPECT_EQ(blocks(2, { 4, 4, 1 }, 1, 1, 3), V({ 1, 1, 1 }));
  // Lengths that are not positive and finite count as the shortest.
  EXPECT_EQ(strides(2, 0, 1, 3), V({ 2, 2, 1 }));
  EXPECT_EQ(strides(2, std::nan(""), 1, 1), V({ 2, 2, 2 }));
  EXPECT_EQ(strides(2, 0, 0, 0), V({ 2, 2, 2 }));
  // The texel's size for the ray's shared light reads: the geometric mean of its edges.
  const double mm[3] = { 1, 1, 3 }, head[3] = { 0.957, 0.957, 1.5 };
  EXPECT_NEAR(il::transportTexelSize(2, mm), std::cbrt(2.0 * 2.0 * 3.0), 1e-12);
  EXPECT_NEAR(il::transportTexelSize(2, head), 2.0 * std::cbrt(0.957 * 0.957 * 1.5), 1e-12);
}

TEST(IlluminationSettings, RaySamplesShareALightReadWhileTheirSpanFitsInATexel)
{
  // The CT head's benchmark scene: 0.5 mm steps, texels of 2 voxels of 0.96 x 0.96 x 1.5
  // mm (geometric mean 2.22 mm): 4 samples span 2 mm.
  EXPECT_EQ(il::lightReadStride(0.5, 2.22), 4);
  EXPECT_EQ(il::lightReadStride(0.5, 2.0), 4); // exactly one texel
  EXPECT_EQ(il::lightReadStride(0.5, 1.99), 2);
  // Exactly one texel in metres, the step rounded to single precision as it arrives.
  EXPECT_EQ(il::lightReadStride(static_cast<double>(0.5e-3f), 2.0e-3), 4);
  EXPECT_EQ(il::lightReadStride(0.957, 2.22), 2); // VTK's automatic step: one voxel
  EXPECT_EQ(il::lightReadStride(1.2, 2.22), 1);
  EXPECT_EQ(il::lightReadStride(0.01, 100.0), il::kMaximumLightReadStride);
  // Nothing known, or nothing sensible: every sample reads the light.
  for (double bad : { 0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
         std::numeric_limits<double>::infinity() })
  {
    EXPECT_EQ(il::lightReadStride(bad, 2.0), 1) << bad;
    EXPECT_EQ(il::lightReadStride(0.5, bad), 1) << bad;
  }
}

// The illumination's reach, over the finest spacing, is the ghost layers a piece of a split
// volume needs: the transport's grids count voxels along every axis (fewer along an axis of
// long voxels), so their terms are measured along the finest axis; the template radius is
// 10 x the mean spacing.
TEST(IlluminationSettings, TheReachCountsTheGridsVoxelsAlongTheFinestAxis)
{
  vtkNew<vtkScattererTemplateVolumeMapper> m;
  const double cubic[3] = { 1, 1, 1 }, head[3] = { 0.957, 0.957, 1.5 }, thick[3] = { 0.5, 0.5, 5 };
  EXPECT_DOUBLE_EQ(m->GetIlluminationReach(cubic), 8 * 4 + 4);
  EXPECT_DOUBLE_EQ(m->GetIlluminationReach(head), (8 * 4 + 4) * 0.957); // 37 layers, not 58
  // Radius 10 x 2 mm over the diffusion's 8 x 4 x 0.5: 22 mm, 45 layers (not 361).
  EXPECT_DOUBLE_EQ(m->GetIlluminationReach(thick), 10 * 2.0 + 4 * 0.5);
  const double none[3] = { 0, 0, 0 }; // was 3.6e300 once measured along the finest axis
  EXPECT_EQ(m->GetIlluminationReach(none), 0.0);
}
