// Transfer-function presets and the automatic transfer function (issue 16): the
// histogram statistics on volumes whose answer is known, the window/level mapping,
// and, on the real MRI and CT angiography, that the automatic choice shows structure
// (a lit, bright, varied picture rather than nothing, dim fog or a solid box).
#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererTransferPresets.h"
#include "ScattererInProcessRender.h"

#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererVolumeReader.h"
#include "vtkShortArray.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace se = scatterer_examples;

namespace
{
/** A 32^3 volume: a fraction @p shareA of the voxels at @p a, the rest at @p b, plus a ramp of
 * noise. */
vtkSmartPointer<vtkImageData> TwoClassVolume(short a, short b, double shareA)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(32, 32, 32);
  vtkNew<vtkShortArray> values;
  values->SetNumberOfValues(32 * 32 * 32);
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    const bool inA = static_cast<double>(i) < shareA * values->GetNumberOfValues();
    values->SetValue(i, static_cast<short>((inA ? a : b) + (i % 7) - 3));
  }
  image->GetPointData()->SetScalars(values);
  return image;
}
}

TEST(TransferPresets, OtsuSplitsTwoClassesBetweenThem)
{
  const se::VolumeHistogram h(TwoClassVolume(0, 1000, 0.7));
  const double t = h.OtsuThreshold(h.Minimum(), h.Maximum());
  // Halfway across the empty gap, not on either class's edge.
  EXPECT_NEAR(t, 500.0, 20.0);
  EXPECT_NEAR(h.ShareBelow(t), 0.7, 0.01);
}

TEST(TransferPresets, QuantileCountsFromTheGivenValue)
{
  const se::VolumeHistogram h(TwoClassVolume(0, 1000, 0.7));
  EXPECT_LT(h.Quantile(0.5), 10.0);         // most voxels are near 0
  EXPECT_GT(h.Quantile(0.5, 500.0), 990.0); // above 500 only the 1000 class
  EXPECT_NEAR(h.Quantile(0.9), 1000.0, 10.0);
}

TEST(TransferPresets, CtInHounsfieldUnitsGetsTheCtPresetAndOtherDataTheAutomaticOne)
{
  EXPECT_EQ(
    se::DefaultTransferPreset(se::VolumeHistogram(TwoClassVolume(-1024, 700, 0.5))), "ct-head");
  EXPECT_EQ(se::DefaultTransferPreset(se::VolumeHistogram(TwoClassVolume(0, 255, 0.5))), "auto");
  // No air: a CT-like range with hardly any voxel near -1000 HU is not taken for CT.
  EXPECT_EQ(
    se::DefaultTransferPreset(se::VolumeHistogram(TwoClassVolume(-1024, 700, 0.01))), "auto");
}

TEST(TransferPresets, EveryPresetIsVisibleSomewhereAndAnUnknownNameListsTheKnownOnes)
{
  const se::VolumeHistogram h(TwoClassVolume(-1024, 1500, 0.5));
  for (const std::string& name : se::TransferPresetNames())
  {
    se::TransferPoints points;
    std::string why;
    ASSERT_TRUE(se::MakeTransferPreset(name, h, points, why)) << name << ": " << why;
    EXPECT_EQ(points.Name, name);
    double most = 0.0;
    for (const auto& p : points.Opacity)
    {
      most = std::max(most, p[1]);
    }
    EXPECT_GT(most, 0.2) << name;
  }
  se::TransferPoints points;
  std::string why;
  EXPECT_FALSE(se::MakeTransferPreset("bones", h, points, why));
  EXPECT_NE(why.find("bones"), std::string::npos) << why;
  EXPECT_NE(why.find("ct-bone"), std::string::npos) << why;
}

// VTK sizes its lookup tables by the range over the smallest gap between points: on a
// two-valued volume the automatic preset's points lay a millionth of the range apart,
// and VTK asked for a table of 10^6 texels (past the GPU's limit, two warnings a frame).
TEST(TransferPresets, PointsOfABinaryVolumeLieAtLeastA4096thOfTheRangeApart)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(32, 32, 32);
  vtkNew<vtkShortArray> values; // 0 and 100 only: a mask
  values->SetNumberOfValues(32 * 32 * 32);
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    values->SetValue(i, static_cast<short>(i % 3 == 0 ? 100 : 0));
  }
  image->GetPointData()->SetScalars(values);
  const se::VolumeHistogram h(image);
  for (const std::string name : { "auto", "mri" })
  {
    se::TransferPoints points;
    std::string why;
    ASSERT_TRUE(se::MakeTransferPreset(name, h, points, why)) << name << ": " << why;
    for (size_t i = 1; i < points.Opacity.size(); ++i)
    {
      const double gap = points.Opacity[i][0] - points.Opacity[i - 1][0];
      EXPECT_TRUE(gap == 0.0 || gap >= 100.0 / 4096.0 * (1.0 - 1e-9))
        << name << ": points " << i - 1 << " and " << i << " lie " << gap << " apart";
    }
  }
}

TEST(TransferPresets, WindowLevelMovesAndScalesAboutTheRampCentre)
{
  const se::TransferPoints points{ "test",
    { { 0, 0.0 }, { 100, 0.0 }, { 300, 0.8 }, { 1000, 0.8 } },
    { { 0, 1, 0, 0 }, { 1000, 0, 0, 1 } } };
  EXPECT_DOUBLE_EQ(se::TransferCenter(points), 200.0);
  vtkNew<vtkVolumeProperty> property;
  // Unchanged at level 0, window 1: the benchmark scene's points come back exactly.
  se::ApplyTransferPoints(points, 0.0, 1.0, property);
  double node[4];
  property->GetScalarOpacity()->GetNodeValue(1, node);
  EXPECT_EQ(node[0], 100.0);
  // Level +50: every point 50 higher; window x2: twice as far from the centre 200.
  se::ApplyTransferPoints(points, 50.0, 2.0, property);
  property->GetScalarOpacity()->GetNodeValue(1, node);
  EXPECT_DOUBLE_EQ(node[0], 200.0 + 2.0 * (100.0 - 200.0) + 50.0);
  property->GetScalarOpacity()->GetNodeValue(2, node);
  EXPECT_DOUBLE_EQ(node[0], 200.0 + 2.0 * (300.0 - 200.0) + 50.0);
  // Colours follow the opacity.
  double colorNode[6];
  property->GetRGBTransferFunction()->GetNodeValue(1, colorNode);
  EXPECT_DOUBLE_EQ(colorNode[0], 200.0 + 2.0 * (1000.0 - 200.0) + 50.0);
}

TEST(TransferPresets, CtHeadSceneKeepsItsTransferFunction)
{
  // The benchmark scene (shared/scenes/ct-head.json) is defined in HU; moving its
  // points into the preset table must not change a single value.
  vtkNew<vtkVolumeProperty> property;
  se::ApplyCtHeadProperty(property);
  const double expected[][2] = { { -1024, 0.0 }, { -600, 0.0 }, { -450, 0.1 }, { -50, 0.1 },
    { 0, 0.0 }, { 150, 0.0 }, { 300, 0.8 }, { 2986, 0.9 } };
  ASSERT_EQ(property->GetScalarOpacity()->GetSize(), 8);
  for (int i = 0; i < 8; ++i)
  {
    double node[4];
    property->GetScalarOpacity()->GetNodeValue(i, node);
    EXPECT_EQ(node[0], expected[i][0]);
    EXPECT_EQ(node[1], expected[i][1]);
  }
}

namespace
{
/** What a picture shows: share of lit pixels, and the mean and spread of their luminance. */
struct PictureStats
{
  double LitShare = 0.0;
  double MeanLuminance = 0.0;
  double LuminanceSpread = 0.0;
};

/** Renders @p path with the automatic scene and the template illumination at 160x160. */
PictureStats RenderAutomatic(const std::string& path)
{
  PictureStats stats;
  std::string error;
  auto image = vtkScattererVolumeReader::ReadVolume(path, &error);
  if (!image)
  {
    ADD_FAILURE() << error;
    return stats;
  }
  const std::vector<unsigned char> rgb = scatterer_testing::RenderRgb(image,
    [&](
      vtkVolumeProperty* property, vtkRenderer* renderer, vtkScattererTemplateVolumeMapper* mapper)
    {
      mapper->SetBlendModeToComposite();
      se::ApplyAutoScene(image, property, renderer);
    });
  double lit = 0.0, sum = 0.0, squares = 0.0;
  for (size_t i = 0; i + 2 < rgb.size(); i += 3)
  {
    const double y = 0.2126 * rgb[i] + 0.7152 * rgb[i + 1] + 0.0722 * rgb[i + 2];
    if (y > 8.0)
    {
      lit += 1.0;
      sum += y;
      squares += y * y;
    }
  }
  stats.LitShare = lit / static_cast<double>(rgb.size() / 3);
  if (lit > 0.0)
  {
    stats.MeanLuminance = sum / lit;
    stats.LuminanceSpread =
      std::sqrt(std::max(0.0, squares / lit - stats.MeanLuminance * stats.MeanLuminance));
  }
  return stats;
}

/**
 * Structure: something shows, it is not dim, and it varies (not one flat colour).
 * Measured at 160x160: the automatic function gives MRI lit 24 %, mean 155, spread 47;
 * stent lit 12 %, mean 84, spread 50 (2026-12-07; 166 and 87 before that day's changes
 * to the multiple scattering, docs/model.md: the diffusion now carries less of dense
 * matter's light into the thin matter around it). The former
 * ramp over the upper half of the range gave MRI mean 79 and stent lit 1.4 %, mean 73:
 * both fail here.
 */
void ExpectStructure(const std::string& path)
{
  if (!std::filesystem::exists(path))
  {
    GTEST_SKIP() << path
                 << " is missing (scripts/install-deps.sh and scripts/prepare-data.sh make it)";
  }
  const PictureStats s = RenderAutomatic(path);
  EXPECT_GT(s.LitShare, 0.05) << path << ": hardly anything shows";
  EXPECT_LT(s.LitShare, 0.9) << path << ": the picture is filled";
  EXPECT_GT(s.MeanLuminance, 80.0) << path << ": dim";
  EXPECT_GT(s.LuminanceSpread, 25.0) << path << ": flat, no structure";
  std::printf("%s: lit %.1f %%, luminance mean %.0f, spread %.0f\n", path.c_str(),
    100.0 * s.LitShare, s.MeanLuminance, s.LuminanceSpread);
}
}

TEST(AutomaticTransfer, ShowsStructureOnTheRealMri)
{
  ExpectStructure("/usr/share/mricron/templates/ch2.nii.gz");
}

TEST(AutomaticTransfer, ShowsStructureOnTheCtAngiography)
{
  ExpectStructure(se::DataDirectory() + "/stent.mhd");
}
