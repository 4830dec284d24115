// Many labels (issue 14: more labels than the 8 materials). A label-map mask with 200
// labels (the per-label medium lives in a table, not in material slots): the
// illumination applies, leaves no black hole where the stock mapper shows something, and
// every label keeps its own colour (the last label, 200, is the only red one and shows
// red). A label's colour bleeds onto its neighbour through the scattered light. And 20
// labels used as scalars, more than the materials: no label is left flat (no patchwork).
#include "Common/ScattererMapperSetup.h"
#include "ScattererErrorObserver.h"
#include "ScattererRenderHarness.h"
#include "ScattererTestVolumes.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

namespace
{
constexpr int N = 48;
constexpr int Labels = 200;

// A cube of value 200; the mask gives each 1-voxel slab along x and y its own label
// (1..199), and the front quarter (i < 12) label 200.
vtkSmartPointer<vtkImageData> Grid(bool mask)
{
  return scatterer_testing::MakeComponentVolume(N, 1,
    [mask](int i, int j, int k, int) -> unsigned char
    {
      const bool inside = i > 4 && i < N - 5 && j > 4 && j < N - 5 && k > 4 && k < N - 5;
      if (!mask)
        return inside ? 200 : 0;
      return i < 12 ? Labels : static_cast<unsigned char>(1 + (i * 7 + j * 13) % (Labels - 1));
    });
}

// The label-map mask scenes' mapper settings: data, mask, and a fixed, unjittered step.
void SetUpLabelMapper(
  vtkGPUVolumeRayCastMapper* mapper, vtkImageData* data, vtkImageData* labelMask)
{
  mapper->SetInputData(data);
  mapper->SetMaskInput(labelMask);
  mapper->SetMaskTypeToLabelMap();
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.5);
  mapper->UseJitteringOff();
}

std::vector<unsigned char> Render(bool ours)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(100, 0.0);
  opacity->AddPoint(200, 0.3);
  opacity->AddPoint(255, 0.3);
  vtkNew<vtkColorTransferFunction> grey;
  grey->AddRGBPoint(0, 0.8, 0.8, 0.8);
  grey->AddRGBPoint(255, 0.8, 0.8, 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(grey);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToNearest();
  std::vector<vtkSmartPointer<vtkColorTransferFunction>> colors;
  for (int label = 1; label <= Labels; ++label)
  {
    // Labels 1..199 green to blue; label 200 red.
    auto c = vtkSmartPointer<vtkColorTransferFunction>::New();
    const double t = (label - 1) / double(Labels - 2);
    if (label == Labels)
      c->AddRGBPoint(0, 1.0, 0.1, 0.1);
    else
      c->AddRGBPoint(0, 0.1, 1.0 - 0.8 * t, 0.2 + 0.8 * t);
    colors.push_back(c);
    property->SetLabelColor(label, c);
    property->SetLabelScalarOpacity(label, opacity);
  }
  vtkNew<vtkScattererTemplateVolumeMapper> scatterer;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  vtkGPUVolumeRayCastMapper* mapper = ours ? static_cast<vtkGPUVolumeRayCastMapper*>(scatterer)
                                           : static_cast<vtkGPUVolumeRayCastMapper*>(stock);
  SetUpLabelMapper(mapper, Grid(false), Grid(true));
  vtkNew<vtkRenderer> renderer;
  scatterer_examples::AddVolume(renderer, mapper, property);
  renderer->AutomaticLightCreationOff();
  // From the camera's side: every face the camera sees is lit, so a black pixel there
  // is a hole, not a shadow.
  scatterer_testing::AddSceneLight(renderer, -1.0, -0.7, 0.5);
  vtkCamera* camera = renderer->GetActiveCamera();
  const double c = 0.5 * (N - 1);
  camera->SetFocalPoint(c, c, c);
  camera->SetPosition(c - 100, c - 70, c + 50);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  auto pixels = scatterer_testing::RenderSceneOnce(renderer, mapper);
  if (ours)
  {
    EXPECT_NE(scatterer->GetLastShaderFeatures().find("labelmask"), std::string::npos)
      << scatterer->GetLastShaderFeatures();
  }
  return pixels;
}
}

TEST(LabelMapMask, TwoHundredLabelsAreLitWithoutHolesAndKeepTheirColours)
{
  const auto stock = Render(false);
  const auto lit = Render(true);
  ASSERT_EQ(stock.size(), lit.size());
  int shown = 0, holes = 0, redStock = 0, redLit = 0;
  for (size_t p = 0; p + 3 < stock.size(); p += 4)
  {
    const int s = stock[p] + stock[p + 1] + stock[p + 2];
    const int l = lit[p] + lit[p + 1] + lit[p + 2];
    if (s > 60)
    {
      ++shown;
      holes += l < 9 ? 1 : 0;
    }
    auto red = [](const std::vector<unsigned char>& x, size_t q)
    { return x[q] > 40 && x[q] > 2 * x[q + 1] && x[q] > 2 * x[q + 2]; };
    redStock += red(stock, p) ? 1 : 0;
    redLit += red(lit, p) ? 1 : 0;
  }
  std::printf("stock shows %d pixels; %d black in the lit picture; red: stock %d, lit %d\n", shown,
    holes, redStock, redLit);
  ASSERT_GT(shown, 1000) << "the cube is visible";
  EXPECT_LE(holes, shown / 100) << "black holes where the stock mapper shows the volume";
  ASSERT_GT(redStock, 200) << "label 200's region shows red in the stock picture";
  EXPECT_GT(redLit, redStock / 2) << "label 200 lost its own colour";
  EXPECT_GT(scatterer_testing::MaxDifference(stock, lit), 20) << "no illumination was applied";
}

namespace
{
// A white floor (label 1) and a red wall standing on it (label 2), one scalar, the
// volume's own colour grey: lit from the camera's side, with or without the
// multiple-scattering term. Returns the stock and the lit pictures.
std::pair<std::vector<unsigned char>, std::vector<unsigned char>> RenderWall(
  double multipleScattering)
{
  const auto make = [](bool mask)
  {
    return scatterer_testing::MakeComponentVolume(N, 1,
      [mask](int i, int j, int k, int) -> unsigned char
      {
        const bool floor = k >= 4 && k <= 9;
        const bool wall = i >= 20 && i <= 27 && j >= 8 && j <= 40 && k >= 10 && k <= 40;
        return mask ? (wall ? 2 : floor ? 1 : 0) : (wall || floor ? 200 : 0);
      });
  };
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(100, 0.0);
  opacity->AddPoint(200, 0.8);
  opacity->AddPoint(255, 0.8);
  const auto flat = [](double r, double g, double b)
  {
    auto c = vtkSmartPointer<vtkColorTransferFunction>::New();
    c->AddRGBPoint(0, r, g, b);
    c->AddRGBPoint(255, r, g, b);
    return c;
  };
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(flat(0.5, 0.5, 0.5));
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToLinear();
  property->SetLabelColor(1, flat(0.9, 0.9, 0.9));
  property->SetLabelScalarOpacity(1, opacity);
  property->SetLabelColor(2, flat(1.0, 0.1, 0.1));
  property->SetLabelScalarOpacity(2, opacity);
  std::pair<std::vector<unsigned char>, std::vector<unsigned char>> out;
  for (bool ours : { false, true })
  {
    vtkNew<vtkScattererTemplateVolumeMapper> scatterer;
    vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
    vtkGPUVolumeRayCastMapper* mapper = ours ? static_cast<vtkGPUVolumeRayCastMapper*>(scatterer)
                                             : static_cast<vtkGPUVolumeRayCastMapper*>(stock);
    scatterer->SetMultipleScattering(multipleScattering);
    SetUpLabelMapper(mapper, make(false), make(true));
    vtkNew<vtkRenderer> renderer;
    scatterer_examples::AddVolume(renderer, mapper, property);
    renderer->AutomaticLightCreationOff();
    scatterer_testing::AddSceneLight(renderer, -100.0, 23.5, 60.0, 23.5, 23.5, 0.0);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(23.5, 23.5, 10);
    camera->SetPosition(-60, 23.5, 90);
    camera->SetViewUp(0, 0, 1);
    renderer->ResetCameraClippingRange();
    (ours ? out.second : out.first) = scatterer_testing::RenderSceneOnce(renderer, mapper);
  }
  return out;
}

// Pixels the stock picture shows white (the floor, label 1) that the lit one shows red.
int RedOnWhite(const std::pair<std::vector<unsigned char>, std::vector<unsigned char>>& p)
{
  int count = 0;
  for (size_t q = 0; q + 3 < p.first.size(); q += 4)
  {
    const auto& s = p.first;
    const auto& l = p.second;
    const bool white =
      s[q] > 60 && std::abs(s[q] - s[q + 1]) < 10 && std::abs(s[q] - s[q + 2]) < 10;
    count += white && l[q] > 40 && l[q] > 3 * l[q + 1] / 2 ? 1 : 0;
  }
  return count;
}
}

TEST(LabelMapMask, ALabelsColourBleedsOntoItsNeighbourThroughScatteredLight)
{
  // Every label is a material of its own colour in the light too: light scattered off
  // the red wall (label 2) tints the white floor (label 1) beside it. The volume's own
  // colour is grey, so red on the floor can only come from the wall's label; without
  // the multiple-scattering term, the floor keeps its own colour.
  const int scattered = RedOnWhite(RenderWall(1.0));
  const int direct = RedOnWhite(RenderWall(0.0));
  std::printf(
    "white floor pixels shown red: %d with scattered light, %d without\n", scattered, direct);
  EXPECT_GT(scattered, 200) << "the red label's colour does not reach its neighbour";
  EXPECT_LT(direct, 10) << "the floor is red without any light scattered off the wall";
}

namespace
{
constexpr int ScalarLabels = 20;

// Label L's colour: hue L / 20.
void LabelColour(int label, double rgb[3])
{
  const double h = 6.0 * label / ScalarLabels, f = h - std::floor(h);
  const double v = 0.9, p = v * 0.3, q = v * (1 - 0.7 * f), t = v * (1 - 0.7 * (1 - f));
  const double table[6][3] = { { v, t, p }, { q, v, p }, { p, v, t }, { p, q, v }, { t, p, v },
    { v, p, q } };
  const int i = static_cast<int>(std::floor(h)) % 6;
  for (int c = 0; c < 3; ++c)
    rgb[c] = table[i][c];
}

// The label whose colour has the hue of @p px (its stock colour), 1..20.
int LabelOf(const unsigned char* px)
{
  const double r = px[0], g = px[1], b = px[2];
  const double mx = std::max({ r, g, b }), mn = std::min({ r, g, b }), d = mx - mn;
  if (d <= 0.0)
    return 0;
  double h = mx == r ? std::fmod((g - b) / d, 6.0)
    : mx == g        ? (b - r) / d + 2.0
                     : (r - g) / d + 4.0;
  h = h < 0.0 ? h + 6.0 : h;
  const int label = static_cast<int>(std::lround(h / 6.0 * ScalarLabels)) % ScalarLabels;
  return label == 0 ? ScalarLabels : label;
}

// A cube of 6-voxel blocks, each one of 20 labels used as the scalar, with a transfer
// function that shows every label in its own colour: more visible labels than materials.
std::vector<unsigned char> RenderScalarLabels(bool ours, vtkTest::ErrorObserver* warnings)
{
  const int n = 64;
  const auto image = scatterer_testing::MakeComponentVolume(n, 1,
    [](int i, int j, int k, int) -> unsigned char
    {
      const bool inside = i > 4 && i < n - 5 && j > 4 && j < n - 5 && k > 4 && k < n - 5;
      return inside ? static_cast<unsigned char>(1 + (i / 6 + 3 * (j / 6) + 5 * (k / 6)) % 20) : 0;
    });
  vtkNew<vtkPiecewiseFunction> opacity;
  vtkNew<vtkColorTransferFunction> colour;
  opacity->AddPoint(0, 0.0);
  for (int label = 1; label <= ScalarLabels; ++label)
  {
    opacity->AddPoint(label - 0.49, 0.0);
    opacity->AddPoint(label - 0.4, 0.5);
    opacity->AddPoint(label + 0.4, 0.5);
    opacity->AddPoint(label + 0.49, 0.0);
    double rgb[3];
    LabelColour(label, rgb);
    colour->AddRGBPoint(label - 0.4, rgb[0], rgb[1], rgb[2]);
    colour->AddRGBPoint(label + 0.4, rgb[0], rgb[1], rgb[2]);
  }
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(colour);
  property->SetInterpolationTypeToNearest();
  vtkNew<vtkScattererTemplateVolumeMapper> scatterer;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  vtkGPUVolumeRayCastMapper* mapper = ours ? static_cast<vtkGPUVolumeRayCastMapper*>(scatterer)
                                           : static_cast<vtkGPUVolumeRayCastMapper*>(stock);
  scatterer->AddObserver(vtkCommand::WarningEvent, warnings);
  mapper->SetInputData(image);
  vtkNew<vtkRenderer> renderer;
  scatterer_examples::AddVolume(renderer, mapper, property);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(20);
  renderer->ResetCameraClippingRange();
  return scatterer_testing::RenderSceneOnce(renderer, mapper);
}
}

TEST(LabelMapMask, MoreLabelsThanMaterialsAsScalarsMakeNoPatchwork)
{
  // 20 labels used as scalars, 8 materials: the transport volume lights the matter of
  // the 12 labels without a material too (shadows, multiple scattering; only their
  // template in-scattering is missing), so no label is left flat beside the others:
  // every label keeps about the same share of its stock brightness. (Lighting matter
  // without a material as if unshadowed spread the shares from 0.66 to 0.86.)
  vtkNew<vtkTest::ErrorObserver> warnings;
  const auto stock = RenderScalarLabels(false, warnings);
  const auto lit = RenderScalarLabels(true, warnings);
  double stockSum[ScalarLabels + 1] = {}, litSum[ScalarLabels + 1] = {};
  int count[ScalarLabels + 1] = {};
  int shown = 0, holes = 0;
  for (size_t q = 0; q + 3 < stock.size(); q += 4)
  {
    const int s = stock[q] + stock[q + 1] + stock[q + 2];
    const int l = lit[q] + lit[q + 1] + lit[q + 2];
    const int label = LabelOf(&stock[q]);
    if (s > 60 && label > 0)
    {
      ++shown;
      holes += l < 9 ? 1 : 0;
      stockSum[label] += s;
      litSum[label] += l;
      ++count[label];
    }
  }
  double lowest = 1e9, highest = 0.0;
  for (int label = 1; label <= ScalarLabels; ++label)
  {
    if (count[label] >= 50)
    {
      const double share = litSum[label] / stockSum[label];
      lowest = std::min(lowest, share);
      highest = std::max(highest, share);
    }
  }
  std::printf("%d pixels shown, %d black; lit / stock per label from %.3f to %.3f\n", shown, holes,
    lowest, highest);
  ASSERT_GT(shown, 5000) << "the cube is visible";
  EXPECT_LE(holes, shown / 100) << "black holes where the stock mapper shows the volume";
  EXPECT_GT(lowest, 0.5) << "a label is dark";
  EXPECT_LE(highest / lowest, 1.25) << "the labels are lit unevenly: a patchwork";
  EXPECT_EQ(scatterer_testing::WarningCount(warnings), 1u);
  EXPECT_NE(scatterer_testing::LastWarning(warnings).find(
              "12 more are lit by the transport volume without scatterer templates"),
    std::string::npos)
    << scatterer_testing::LastWarning(warnings);
}
