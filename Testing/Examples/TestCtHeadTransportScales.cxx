// The CT head's colours stay those of the default transport scale (2) when the
// transport volume is built coarser: scale 3 and 4 are what interactive frames use
// (InteractiveTransportScale, default 4). With a one-point medium per diffusion
// texel, scales 3 and 4 turned the skull's bright parts yellow-green (found while
// dragging in scatterer-viewer, 2026-11-30).
#include "Common/ScattererCtHeadScene.h"
#include "ScattererInProcessRender.h"
#include "ScattererRenderHarness.h"

#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "scatterer/IlluminationSettings.h"
#include "vtkScattererTemplateVolumeMapper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace se = scatterer_examples;

namespace
{
/** Greenness G - (R + B) / 2 of the lit pixels: the value 99 % of them stay below. */
double GreennessP99(const std::vector<unsigned char>& rgb)
{
  std::vector<double> green;
  for (size_t i = 0; i + 2 < rgb.size(); i += 3)
  {
    if (std::max({ rgb[i], rgb[i + 1], rgb[i + 2] }) > 8)
    {
      green.push_back(rgb[i + 1] - 0.5 * (rgb[i] + rgb[i + 2]));
    }
  }
  if (green.empty())
  {
    return 0.0;
  }
  std::sort(green.begin(), green.end());
  return green[static_cast<size_t>(0.99 * (green.size() - 1))];
}

/** Mean luminance (Rec. 709, 0-255) and redness (R - G) / (R + G + B) of the lit pixels. */
struct LitColour
{
  double Luminance = 0.0;
  double Redness = 0.0;
};

LitColour MeanLitColour(const std::vector<unsigned char>& rgb)
{
  LitColour mean;
  size_t lit = 0;
  for (size_t i = 0; i + 2 < rgb.size(); i += 3)
  {
    const double r = rgb[i], g = rgb[i + 1], b = rgb[i + 2];
    if (std::max({ r, g, b }) > 8)
    {
      mean.Luminance += 0.2126 * r + 0.7152 * g + 0.0722 * b;
      mean.Redness += (r - g) / (r + g + b);
      ++lit;
    }
  }
  if (lit > 0)
  {
    mean.Luminance /= static_cast<double>(lit);
    mean.Redness /= static_cast<double>(lit);
  }
  return mean;
}

/** RMS difference of two RGB images, in [0, 1]. */
double RmsDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  double sum = 0.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    const double d = (a[i] - b[i]) / 255.0;
    sum += d * d;
  }
  return a.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(a.size()));
}

/**
 * @p image rendered as the CT head scene, with @p configure's settings on the mapper, at
 * the window's desired update rate @p updateRate (frames per second: above 1, a frame
 * VTK's interactor renders while the user drags).
 */
std::vector<unsigned char> RenderCtHeadScene(vtkImageData* image,
  const std::function<void(vtkScattererTemplateVolumeMapper*)>& configure,
  double updateRate = 0.0001)
{
  vtkRenderWindow* window = scatterer_testing::SharedWindow();
  const double rate = window->GetDesiredUpdateRate();
  window->SetDesiredUpdateRate(updateRate);
  std::vector<unsigned char> rgb = scatterer_testing::RenderRgb(image,
    [&](
      vtkVolumeProperty* property, vtkRenderer* renderer, vtkScattererTemplateVolumeMapper* mapper)
    {
      se::ApplyCtHeadProperty(property);
      se::ApplyCtHeadCamera(renderer);
      se::ApplyCtHeadLight(renderer);
      se::ApplyCtHeadMapperSettings(mapper);
      configure(mapper);
    });
  window->SetDesiredUpdateRate(rate);
  return rgb;
}
}

/** The tests below read the prepared CT head, and skip when it is missing. */
class CtHeadTransportScales : public ::testing::Test
{
protected:
  void SetUp() override
  {
    if (!std::filesystem::exists(se::CtHeadPath()))
    {
      GTEST_SKIP() << se::CtHeadPath() << " is missing (bash scripts/prepare-data.sh)";
    }
    std::string error;
    this->Head = se::ReadVolumeOrCtHead("", error);
    ASSERT_TRUE(this->Head) << error;
  }

  vtkSmartPointer<vtkImageData> Head;
};

TEST_F(CtHeadTransportScales, CoarserTransportKeepsTheColours)
{
  auto render = [&](int scale)
  {
    return RenderCtHeadScene(this->Head,
      [&](vtkScattererTemplateVolumeMapper* mapper) { mapper->SetTransportScale(scale); });
  };
  // Measured at 300x300: scale 2 has 19.5; scales 3 and 4 had 32.5 and 39.5 with the
  // bug, 20.0 and 23.0 without.
  const double reference = GreennessP99(render(2));
  for (int scale : { 3, 4 })
  {
    const double greenness = GreennessP99(render(scale));
    EXPECT_LT(greenness, reference + 8.0)
      << "transport scale " << scale << ": greenness " << greenness << " vs " << reference
      << " at scale 2 (yellow-green blotches)";
  }
}

// A frame rendered while the user drags (allocated render time under a second) is built at
// InteractiveTransportScale (4) instead of 2, and keeps the still frames' diffusion grid
// (CoarseGrid::Over): the bone stays ivory. With the diffusion on blocks of 8 voxels, as
// the coarser scale alone gave, the bone turned pink and mottled while the user dragged.
// Measured (160x160), luminance of the lit pixels and their redness (R - G) / (R + G + B):
// still 132.9, 0.0744; dragging 143.7, 0.0698 (the coarser grid's single scattering alone
// is 7 % brighter: 101.4 against 94.7 without multiple scattering); with 8-voxel blocks
// 119.7, 0.0937, and with those blocks' medium averaged over 2^3 points per fine texel
// 140.6, 0.1018.
TEST_F(CtHeadTransportScales, ADraggingFrameKeepsTheStillColours)
{
  int scale = 0;
  auto render = [&](double updateRate)
  {
    return RenderCtHeadScene(
      this->Head,
      [&](vtkScattererTemplateVolumeMapper* mapper)
      {
        mapper->SetTransportScale(2);
        mapper->SetInteractiveTransportScale(4);
        scale = mapper->GetEffectiveTransportScale(
          this->Head->GetDimensions(), this->Head->GetSpacing(), updateRate > 1.0);
      },
      updateRate);
  };
  const LitColour still = MeanLitColour(render(0.0001));
  const LitColour dragging = MeanLitColour(render(30.0)); // 1/30 s a frame: interactive
  EXPECT_EQ(scale, 4);
  std::printf("still: luminance %.1f, redness %.4f; dragging: %.1f, %.4f\n", still.Luminance,
    still.Redness, dragging.Luminance, dragging.Redness);
  EXPECT_NEAR(dragging.Luminance / still.Luminance, 1.0, 0.15)
    << "the dragging frame's brightness differs from the still frame's";
  EXPECT_NEAR(dragging.Redness, still.Redness, 0.01)
    << "the dragging frame's colours differ from the still frame's (pink bone)";
}

// MaximumTransportVoxels: the same head sampled more finely is lit as the original. The CT
// head resampled to 1.5x its points per axis (383x383x161, as the render benchmark does),
// under a budget the head itself fills at scale 2 (129x129x55 transport voxels, the
// default budget's case), is built at scale 3: the same grid in the object. Without the
// budget (0) it is built at scale 2, with a finer diffusion, and looks different.
// Measured (160x160): RMS 0.024 from the original under the budget, 0.054 at scale 2;
// the rule left out (the budget ignored), 0.054 and 0.054.
TEST_F(CtHeadTransportScales, AResampledHeadIsLitAsTheOriginal)
{
  int dims[3];
  this->Head->GetDimensions(dims);
  vtkNew<vtkImageResize> resize;
  resize->SetInputData(this->Head);
  resize->SetOutputDimensions((3 * dims[0]) / 2, (3 * dims[1]) / 2, (3 * dims[2]) / 2);
  resize->Update();
  vtkImageData* resampled = resize->GetOutput();
  const int two[3] = { 2, 2, 2 }; // the CT head's 1.5 mm slices: the scale on every axis
  const int budget = static_cast<int>(scatterer::illumination::transportVoxelsAt(dims, two));
  int scales[2] = { 0, 0 };
  auto render = [&](vtkImageData* image, int maximumVoxels, int* scale)
  {
    return RenderCtHeadScene(image,
      [&](vtkScattererTemplateVolumeMapper* mapper)
      {
        mapper->SetMaximumTransportVoxels(maximumVoxels);
        if (scale)
        {
          *scale =
            mapper->GetEffectiveTransportScale(image->GetDimensions(), image->GetSpacing(), false);
        }
      });
  };
  const std::vector<unsigned char> original = render(this->Head, budget, nullptr);
  const std::vector<unsigned char> lit = render(resampled, budget, &scales[0]);
  const std::vector<unsigned char> unlimited = render(resampled, 0, &scales[1]);
  EXPECT_EQ(scales[0], 3);
  EXPECT_EQ(scales[1], 2);
  const double kept = RmsDifference(original, lit);
  const double changed = RmsDifference(original, unlimited);
  EXPECT_LT(kept, 0.6 * changed) << "the resampled head under the budget: RMS " << kept
                                 << " from the original; at scale 2: " << changed;
}
