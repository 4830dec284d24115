// Inputs beyond one scalar with 1D transfer functions, lit through the transport volume
// (issue 14): independent components (each with its own transfer functions), luminance +
// alpha, RGBA, and a 2D transfer function. A ball above a plate, lit from above: with illumination
// off the picture is the stock mapper's to the pixel; on, the ball's shadow darkens the plate, and
// a second frame is the same picture. Without the ball nothing shadows the plate, and no black hole
// appears where the stock mapper shows something (with it, the ball's umbra is black: the ball is
// opaque and the scene has no ambient light). SCATTERER_TEST_IMAGES=<dir> writes the pictures
// there to look at.
#include "Common/ScattererMapperSetup.h"
#include "ScattererLitPictures.h"
#include "ScattererRenderHarness.h"
#include "ScattererTestVolumes.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
constexpr int N = 48;

enum class Kind
{
  Independent, // component 0: the ball (red), component 1: the plate (green)
  LuminanceAlpha,
  RGBA,
  Transfer2D // one scalar (ball 200, plate 150), colour and opacity from a 2D table
};

bool InBall(int i, int j, int k)
{
  const int di = i - N / 2, dj = j - N / 2, dk = k - 30;
  return di * di + dj * dj + dk * dk <= 8 * 8;
}

bool InPlate(int, int, int k)
{
  return k >= 6 && k <= 10;
}

vtkSmartPointer<vtkImageData> Volume(Kind kind, bool withBall = true)
{
  const int components = kind == Kind::RGBA ? 4 : kind == Kind::Transfer2D ? 1 : 2;
  return scatterer_testing::MakeComponentVolume(N, components,
    [kind, withBall](int i, int j, int k, int c) -> unsigned char
    {
      const bool ball = withBall && InBall(i, j, k), plate = InPlate(i, j, k);
      const unsigned char matter = ball || plate ? 200 : 0;
      switch (kind)
      {
        case Kind::Independent: // ball in component 0, plate in component 1
          return (c == 0 ? ball : plate) ? 200 : 0;
        case Kind::LuminanceAlpha: // ball bright, plate darker; alpha = matter
          return c == 0 ? (ball ? 250 : 120) : matter;
        case Kind::RGBA:
        { // the colour is the data's: ball orange, plate light blue
          const unsigned char ballRgb[3] = { 240, 150, 40 }, plateRgb[3] = { 150, 190, 230 };
          return c == 3 ? matter : ball ? ballRgb[c] : plateRgb[c];
        }
        default: // Kind::Transfer2D
          return ball ? 200 : plate ? 150 : 0;
      }
    });
}

vtkSmartPointer<vtkPiecewiseFunction> Opacity()
{
  auto o = vtkSmartPointer<vtkPiecewiseFunction>::New();
  o->AddPoint(0, 0.0);
  o->AddPoint(100, 0.0);
  o->AddPoint(200, 0.6);
  o->AddPoint(255, 0.6);
  return o;
}

vtkSmartPointer<vtkColorTransferFunction> Colour(double r, double g, double b)
{
  auto c = vtkSmartPointer<vtkColorTransferFunction>::New();
  c->AddRGBPoint(0, r, g, b);
  c->AddRGBPoint(255, r, g, b);
  return c;
}

// Over the scalar range [0, 200] and every gradient: the plate's 150 green, the ball's
// 200 orange; opacity 0.4 per ray step (as a 1D function's 0.6 per unit at step 0.5).
vtkSmartPointer<vtkImageData> Table2D()
{
  const int w = 128, h = 16;
  auto table = vtkSmartPointer<vtkImageData>::New();
  table->SetDimensions(w, h, 1);
  table->AllocateScalars(VTK_FLOAT, 4);
  auto* p = static_cast<float*>(table->GetScalarPointer());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x, p += 4)
    {
      const double value = 200.0 * (x + 0.5) / w;
      const bool ball = value > 175, plate = value > 125 && !ball;
      p[0] = ball ? 1.0f : 0.3f;
      p[1] = ball ? 0.6f : 0.9f;
      p[2] = ball ? 0.2f : 0.3f;
      p[3] = ball || plate ? 0.4f : 0.0f;
    }
  return table;
}

void SetUpMapper(vtkGPUVolumeRayCastMapper* mapper, vtkImageData* image)
{
  mapper->SetInputData(image);
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.5);
  mapper->UseJitteringOff();
}

// The scene's light and camera: the ball's shadow on the plate, in view.
void SetUpScene(vtkRenderer* renderer)
{
  scatterer_testing::LightAndViewBallAbovePlate(renderer, N);
}

using Pictures = scatterer_testing::LitPictures;

// The transfer functions of @p kind on @p property.
void SetUpProperty(vtkVolumeProperty* property, Kind kind)
{
  property->SetScalarOpacityUnitDistance(1.0);
  if (kind == Kind::Independent)
  {
    property->SetIndependentComponents(true);
    property->SetScalarOpacity(0, Opacity());
    property->SetScalarOpacity(1, Opacity());
    property->SetColor(0, Colour(1.0, 0.3, 0.2));
    property->SetColor(1, Colour(0.3, 0.9, 0.3));
    property->SetScalarOpacityUnitDistance(1, 1.0);
  }
  else if (kind == Kind::Transfer2D)
  {
    property->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
    property->SetTransferFunction2D(Table2D());
  }
  else
  {
    property->SetIndependentComponents(false);
    property->SetScalarOpacity(Opacity());
    auto ramp = vtkSmartPointer<vtkColorTransferFunction>::New(); // luminance -> colour
    ramp->AddRGBPoint(0, 0.2, 0.2, 0.6);
    ramp->AddRGBPoint(255, 1.0, 0.9, 0.6);
    property->SetColor(ramp);
  }
}

Pictures Render(Kind kind, bool withBall = true)
{
  const auto image = Volume(kind, withBall);
  vtkNew<vtkVolumeProperty> property;
  SetUpProperty(property, kind);
  vtkNew<vtkScattererTemplateVolumeMapper> ours;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  vtkNew<vtkRenderer> renderer;
  vtkVolume* volume = scatterer_examples::AddVolume(renderer, stock, property);
  SetUpMapper(stock, image);
  SetUpMapper(ours, image);
  SetUpScene(renderer);

  vtkRenderWindow* window = scatterer_testing::SharedWindow();
  window->AddRenderer(renderer);
  Pictures out;
  out.Stock = scatterer_testing::RenderAndGrab(window);
  volume->SetMapper(ours);
  scatterer_testing::RenderOffAndLit(window, ours, out);
  window->RemoveRenderer(renderer);
  ours->ReleaseGraphicsResources(window);
  stock->ReleaseGraphicsResources(window);

  if (const char* dir = std::getenv("SCATTERER_TEST_IMAGES"))
  {
    const char* const names[] = { "independent", "luminance-alpha", "rgba", "transfer2d" };
    const std::string base =
      std::string(dir) + "/lit-input-" + names[static_cast<int>(kind)] + (withBall ? "" : "-open");
    const int* size = window->GetSize();
    scatterer_testing::SavePng(base + "-stock.png", out.Stock, size[0], size[1]);
    scatterer_testing::SavePng(base + "-lit.png", out.Lit, size[0], size[1]);
  }
  return out;
}

// One scalar (ball 200, plate 150; the 2D-table scene's volume) with 1D functions,
// rendered by the stock mapper or ours (illumination on), split by the ray caster into
// `parts` x `parts` x 1 textures.
std::vector<unsigned char> RenderOneScalar(bool ours, int parts, std::string* features)
{
  const auto image = Volume(Kind::Transfer2D);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetScalarOpacity(Opacity());
  auto colour = vtkSmartPointer<vtkColorTransferFunction>::New();
  colour->AddRGBPoint(0, 0.3, 0.9, 0.3);
  colour->AddRGBPoint(170, 0.3, 0.9, 0.3);
  colour->AddRGBPoint(190, 1.0, 0.6, 0.2);
  colour->AddRGBPoint(255, 1.0, 0.6, 0.2);
  property->SetColor(colour);
  property->SetInterpolationTypeToLinear();
  vtkNew<vtkScattererTemplateVolumeMapper> scatterer;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  vtkOpenGLGPUVolumeRayCastMapper* mapper = ours
    ? static_cast<vtkOpenGLGPUVolumeRayCastMapper*>(scatterer)
    : static_cast<vtkOpenGLGPUVolumeRayCastMapper*>(stock);
  SetUpMapper(mapper, image);
  mapper->SetPartitions(parts, parts, 1);
  vtkNew<vtkRenderer> renderer;
  scatterer_examples::AddVolume(renderer, mapper, property);
  SetUpScene(renderer);
  auto pixels = scatterer_testing::RenderSceneOnce(renderer, mapper);
  if (features)
  {
    *features = scatterer->GetLastShaderFeatures();
  }
  return pixels;
}

void Check(Kind kind, const char* feature)
{
  const Pictures p = Render(kind);
  const Pictures open = Render(kind, false);
  EXPECT_EQ(scatterer_testing::MaxDifference(p.Stock, p.Off), 0)
    << "illumination off is not the stock picture";
  EXPECT_NE(p.Features.find(feature), std::string::npos) << p.Features;
  EXPECT_EQ(scatterer_testing::MaxDifference(p.Lit, p.LitAgain), 0)
    << "the lit picture changes from frame to frame";
  ASSERT_EQ(p.Stock.size(), p.Lit.size());
  ASSERT_EQ(open.Stock.size(), open.Lit.size());
  auto sum = [](const std::vector<unsigned char>& rgba, size_t q)
  { return rgba[q] + rgba[q + 1] + rgba[q + 2]; };
  int shown = 0, holes = 0, shadowed = 0;
  double stockSum = 0.0, litSum = 0.0;
  for (size_t q = 0; q + 3 < p.Stock.size(); q += 4)
  {
    const int s = sum(p.Stock, q), l = sum(p.Lit, q);
    if (s > 60)
    {
      ++shown;
      stockSum += s;
      litSum += l;
      shadowed += 2 * l < s ? 1 : 0;
    }
    if (sum(open.Stock, q) > 60)
    {
      holes += sum(open.Lit, q) < 9 ? 1 : 0;
    }
  }
  const double brightness = litSum / std::max(stockSum, 1.0);
  std::printf("%s: stock shows %d pixels; lit: %d under half as bright, %.2fx as bright "
              "overall; without the ball %d black\n",
    feature, shown, shadowed, brightness, holes);
  ASSERT_GT(shown, 2000) << "the scene is visible";
  EXPECT_LE(holes, shown / 100) << "black holes where the stock mapper shows the volume";
  EXPECT_GT(shadowed, 200) << "no shadow: the ball does not occlude the plate's light";
  // Shadow and all, the picture keeps about half of unshaded stock's brightness or more
  // (no dark mud, no colour counted twice: that measured 0.28x). An unoccluded face
  // shows kd 0.7 (VTK's default) times the display's exposure 0.8 of its colour.
  EXPECT_GT(brightness, 0.45);
  EXPECT_LT(brightness, 1.3);
}
}

TEST(LitInputKinds, IndependentComponentsAreLitAsTheirComposite)
{
  Check(Kind::Independent, "independent");
}

TEST(LitInputKinds, LuminanceAlphaIsLit)
{
  Check(Kind::LuminanceAlpha, "dependent");
}

TEST(LitInputKinds, RgbaIsLitWithTheDataColour)
{
  Check(Kind::RGBA, "dependent");
}

TEST(LitInputKinds, Transfer2DIsLit)
{
  Check(Kind::Transfer2D, "transport");
}

TEST(LitInputKinds, PartitionedVolumeIsLitAsTheWholeWithoutSeams)
{
  // The ray caster streams a partitioned volume block by block; the transport reads the
  // whole volume from a texture of its own, and each block looks its light up through
  // VTK's per-block texture -> dataset matrix: the picture is the unpartitioned one.
  std::string features;
  const auto whole = RenderOneScalar(true, 1, nullptr);
  const auto parts = RenderOneScalar(true, 2, &features);
  const auto stockWhole = RenderOneScalar(false, 1, nullptr);
  const auto stockParts = RenderOneScalar(false, 2, nullptr);
  EXPECT_EQ(features.find("stock"), std::string::npos) << features;
  const auto e =
    scatterer_testing::CompareWays("partitioned vs whole", whole, parts, stockWhole, stockParts);
  if (const char* dir = std::getenv("SCATTERER_TEST_IMAGES"))
  {
    const int* size = scatterer_testing::SharedWindow()->GetSize();
    scatterer_testing::SavePng(std::string(dir) + "/lit-partitioned.png", parts, size[0], size[1]);
    scatterer_testing::SavePng(std::string(dir) + "/lit-whole.png", whole, size[0], size[1]);
    scatterer_testing::SavePng(
      std::string(dir) + "/stock-partitioned.png", stockParts, size[0], size[1]);
    scatterer_testing::SavePng(std::string(dir) + "/stock-whole.png", stockWhole, size[0], size[1]);
  }
  ASSERT_GT(e.Illumination.Mean, 5.0) << "the illumination changes nothing: the test sees nothing";
  // Block borders may differ as the stock ray caster's own do, no more (the light looked
  // up half a texel off in the blocks measured 0.60 / 2.09 % here, against 0.50 / 1.86 %).
  EXPECT_LE(e.Lit.Mean, e.Stock.Mean + 0.05);
  EXPECT_LE(e.Lit.FractionOver, e.Stock.FractionOver);
}

// VTK 9.1's ray caster makes a table per component when the volume property changes, not
// when the scalars' components do: a one-scalar volume replaced by a two-component one
// under the same property crashed the next frame (the stock mapper too). The mapper
// starts afresh instead, and draws what a fresh mapper draws.
TEST(LitInputKinds, ScalarsThatGainComponentsUnderTheSamePropertyRender)
{
  vtkNew<vtkVolumeProperty> property;
  SetUpProperty(property, Kind::Independent);
  const auto before = Volume(Kind::Transfer2D); // one scalar: the ball and plate
  const auto after = Volume(Kind::Independent);
  vtkRenderWindow* window = scatterer_testing::SharedWindow();

  vtkNew<vtkScattererTemplateVolumeMapper> reused;
  vtkNew<vtkRenderer> renderer;
  scatterer_examples::AddVolume(renderer, reused, property);
  SetUpMapper(reused, before);
  SetUpScene(renderer);
  window->AddRenderer(renderer);
  const auto first = scatterer_testing::RenderAndGrab(window);
  ASSERT_GT(scatterer_testing::MeanBrightness(first), 5.0) << "the object is visible";
  reused->SetInputData(after);
  const auto second = scatterer_testing::RenderAndGrab(window);
  window->RemoveRenderer(renderer);
  reused->ReleaseGraphicsResources(window);
  EXPECT_EQ(reused->GetLastShaderFeatures().rfind("transport", 0), 0u)
    << reused->GetLastShaderFeatures();

  vtkNew<vtkScattererTemplateVolumeMapper> fresh;
  vtkNew<vtkRenderer> freshRenderer;
  scatterer_examples::AddVolume(freshRenderer, fresh, property);
  SetUpMapper(fresh, after);
  SetUpScene(freshRenderer);
  EXPECT_LE(scatterer_testing::MaxDifference(
              second, scatterer_testing::RenderSceneOnce(freshRenderer, fresh)),
    1);
}
