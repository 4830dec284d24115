// The one record of the illumination's settings (scatterer/IlluminationSettings.h):
// every default lies in its range, and a new mapper starts at the record's defaults
// and clamps to its ranges. (The ParaView XML's defaults and ranges are held to the
// mapper by Testing/Python/TestScattererParaViewProperties.py.)
#include "scatterer/GeneratorSettings.h"
#include "scatterer/IlluminationSettings.h"
#include "vtkNew.h"
#include "vtkScattererTemplateVolumeMapper.h"

#include <gtest/gtest.h>

#include <limits>

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
  EXPECT_EQ(il::transportVoxelsAt(head, 2), 129LL * 129 * 55);
  EXPECT_EQ(il::transportScaleFor(2, head, budget), 2);
  EXPECT_EQ(il::transportScaleFor(2, mid, budget), 3);
  EXPECT_EQ(il::transportScaleFor(2, big, budget), 4);
  EXPECT_EQ(il::transportVoxelsAt(mid, 3), il::transportVoxelsAt(head, 2));
  EXPECT_EQ(il::transportVoxelsAt(big, 4), il::transportVoxelsAt(head, 2));
  EXPECT_EQ(il::interactiveTransportScaleFor(2, 4, 2), 4);
  EXPECT_EQ(il::interactiveTransportScaleFor(2, 4, 3), 6);
  EXPECT_EQ(il::interactiveTransportScaleFor(2, 4, 4), 8);
  EXPECT_EQ(il::interactiveTransportScaleFor(2, 2, 4), 4); // no coarser than asked: still's
  EXPECT_EQ(il::transportScaleFor(2, big, 0), 2);          // 0: no limit
  const int small[3] = { 48, 48, 48 }, flat[3] = { 4000, 4000, 1 };
  EXPECT_EQ(il::transportScaleFor(1, small, budget), 1);
  EXPECT_LE(il::transportVoxelsAt(flat, il::transportScaleFor(1, flat, budget)), budget);
  const int one[3] = { 1, 1, 1 };
  EXPECT_EQ(il::transportScaleFor(3, one, 1), 3); // nothing to coarsen: it stops
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
