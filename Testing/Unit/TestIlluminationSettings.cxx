// The one record of the illumination's settings (scatterer/IlluminationSettings.h):
// every default lies in its range, and a new mapper starts at the record's defaults
// and clamps to its ranges. (The ParaView XML's defaults and ranges are held to the
// mapper by Testing/Python/TestScattererParaViewProperties.py.)
#include "scatterer/GeneratorSettings.h"
#include "scatterer/IlluminationSettings.h"
#include "vtkNew.h"
#include "vtkScattererTemplateVolumeMapper.h"

#include <gtest/gtest.h>

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
