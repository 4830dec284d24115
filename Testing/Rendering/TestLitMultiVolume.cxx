// A vtkMultiVolume lit through one transport volume (issue 14): VTK 9.1's ray caster
// composites several inputs, each with its own transform and transfer functions, in one
// ray cast; the light is carried through all of them, so one input's shadow falls on
// another. A ball (input 1, voxels half the size, moved by its volume's position) above a
// plate (input 0, turned 30 degrees about its centre), lit from above: with illumination
// off the picture is the stock mapper's to the pixel; on, the ball's shadow darkens the
// plate, and a ball of zero opacity casts none. SCATTERER_TEST_IMAGES=<dir> writes the
// pictures there to look at.
#include "ScattererErrorObserver.h"
#include "ScattererLitPictures.h"
#include "ScattererRenderHarness.h"
#include "ScattererTestVolumes.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkMultiVolume.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
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

// The plate: 5 voxels thick, spacing 1, index space = world before its volume's turn.
vtkSmartPointer<vtkImageData> Plate()
{
  return scatterer_testing::MakeComponentVolume(
    N, 1, [](int, int, int k, int) -> unsigned char { return k >= 6 && k <= 10 ? 200 : 0; });
}

// The ball: radius 8 world units in voxels of 0.5 (or, empty, no matter at all).
vtkSmartPointer<vtkImageData> Ball(bool empty)
{
  auto image = scatterer_testing::MakeComponentVolume(N, 1,
    [empty](int i, int j, int k, int) -> unsigned char
    {
      const int di = i - N / 2, dj = j - N / 2, dk = k - N / 2;
      return !empty && di * di + dj * dj + dk * dk <= 16 * 16 ? 200 : 0;
    });
  image->SetSpacing(0.5, 0.5, 0.5);
  return image;
}

vtkSmartPointer<vtkVolumeProperty> Property(double r, double g, double b, double opacity)
{
  auto o = vtkSmartPointer<vtkPiecewiseFunction>::New();
  o->AddPoint(0, 0.0);
  o->AddPoint(100, 0.0);
  o->AddPoint(200, opacity);
  o->AddPoint(255, opacity);
  auto c = vtkSmartPointer<vtkColorTransferFunction>::New();
  c->AddRGBPoint(0, r, g, b);
  c->AddRGBPoint(255, r, g, b);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetScalarOpacity(o);
  property->SetColor(c);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToLinear();
  return property;
}

struct MultiScene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkMultiVolume> Multi;
  vtkNew<vtkVolume> PlateVolume, BallVolume;

  explicit MultiScene(
    vtkGPUVolumeRayCastMapper* mapper, double ballOpacity = 0.6, bool emptyBall = false)
  {
    mapper->AutoAdjustSampleDistancesOff();
    mapper->SetSampleDistance(0.5);
    mapper->UseJitteringOff();
    mapper->SetInputDataObject(0, Plate());
    mapper->SetInputDataObject(1, Ball(emptyBall));
    this->PlateVolume->SetProperty(Property(0.3, 0.9, 0.3, 0.6));
    this->PlateVolume->SetOrigin(23.5, 23.5, 8.0);
    this->PlateVolume->SetOrientation(0.0, 0.0, 30.0);
    this->BallVolume->SetProperty(Property(1.0, 0.4, 0.2, ballOpacity));
    this->BallVolume->SetPosition(12.0, 12.0, 18.0); // centre (24, 24, 30)
    this->Multi->SetMapper(mapper);
    this->Multi->SetVolume(this->PlateVolume, 0);
    this->Multi->SetVolume(this->BallVolume, 1);
    this->Renderer->AddVolume(this->Multi);
    scatterer_testing::LightAndViewBallAbovePlate(this->Renderer, N);
  }
};

using Pictures = scatterer_testing::LitPictures;

Pictures Render(double ballOpacity, bool emptyBall = false)
{
  vtkNew<vtkScattererTemplateVolumeMapper> ours;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  MultiScene stockScene(stock, ballOpacity, emptyBall);
  MultiScene scene(ours, ballOpacity, emptyBall);
  vtkRenderWindow* window = scatterer_testing::SharedWindow();
  Pictures out;
  window->AddRenderer(stockScene.Renderer);
  out.Stock = scatterer_testing::RenderAndGrab(window);
  window->RemoveRenderer(stockScene.Renderer);
  window->AddRenderer(scene.Renderer);
  scatterer_testing::RenderOffAndLit(window, ours, out);
  window->RemoveRenderer(scene.Renderer);
  ours->ReleaseGraphicsResources(window);
  stock->ReleaseGraphicsResources(window);
  if (const char* dir = std::getenv("SCATTERER_TEST_IMAGES"))
  {
    const std::string base = std::string(dir) +
      (emptyBall              ? "/lit-multivolume-empty"
          : ballOpacity > 0.0 ? "/lit-multivolume"
                              : "/lit-multivolume-clear");
    const int* size = window->GetSize();
    scatterer_testing::SavePng(base + "-stock.png", out.Stock, size[0], size[1]);
    scatterer_testing::SavePng(base + "-lit.png", out.Lit, size[0], size[1]);
  }
  return out;
}

struct Counts
{
  int Shown = 0, Holes = 0, Shadowed = 0;
  double Brightness = 0.0;
};

// Over the pixels where the stock mapper shows the scene: black ones outside the ball's
// shadow, ones under half as bright as in `unshadowed` (the same scene without the
// ball's matter), and the brightness relative to stock. The umbra of the dense ball may
// be black: one light, no ambient, and the plate's own multiple scattering escapes
// through its faces before it gets far under the ball.
Counts Count(const Pictures& p, const Pictures& unshadowed)
{
  Counts n;
  double stockSum = 0.0, litSum = 0.0;
  for (size_t q = 0; q + 3 < p.Stock.size(); q += 4)
  {
    const int s = p.Stock[q] + p.Stock[q + 1] + p.Stock[q + 2];
    const int l = p.Lit[q] + p.Lit[q + 1] + p.Lit[q + 2];
    const int u = unshadowed.Lit[q] + unshadowed.Lit[q + 1] + unshadowed.Lit[q + 2];
    if (s > 60)
    {
      ++n.Shown;
      stockSum += s;
      litSum += l;
      const bool shadowed = 2 * l < u;
      n.Holes += l < 9 && !shadowed ? 1 : 0;
      n.Shadowed += shadowed ? 1 : 0;
    }
  }
  n.Brightness = litSum / std::max(stockSum, 1.0);
  return n;
}
}

TEST(LitMultiVolume, ShadowsCrossTheInputs)
{
  const Pictures p = Render(0.6);
  const Pictures clear = Render(0.0);
  const Pictures empty = Render(0.6, true);
  EXPECT_EQ(scatterer_testing::MaxDifference(p.Stock, p.Off), 0)
    << "illumination off is not the stock picture";
  EXPECT_EQ(scatterer_testing::MaxDifference(clear.Stock, clear.Off), 0);
  EXPECT_NE(p.Features.find("parts=2"), std::string::npos) << p.Features;
  EXPECT_EQ(scatterer_testing::MaxDifference(p.Lit, p.LitAgain), 0)
    << "the lit picture changes from frame to frame";
  ASSERT_EQ(p.Stock.size(), p.Lit.size());
  const Counts ball = Count(p, empty), clearBall = Count(clear, empty);
  const auto clearVsEmpty = scatterer_testing::CompareRgb(clear.Lit, empty.Lit, 16);
  std::printf("ball: stock shows %d pixels; lit: %d black, %d under half as bright as without "
              "the ball, %.2fx as bright as stock; clear ball: %d black, %d under half, "
              "%.2fx; clear vs no ball: mean %.3f, %.2f%% over 16 levels\n",
    ball.Shown, ball.Holes, ball.Shadowed, ball.Brightness, clearBall.Holes, clearBall.Shadowed,
    clearBall.Brightness, clearVsEmpty.Mean, 100.0 * clearVsEmpty.FractionOver);
  ASSERT_GT(ball.Shown, 2000) << "the scene is visible";
  EXPECT_LE(ball.Holes, ball.Shown / 100) << "black holes where the stock mapper shows the volume";
  EXPECT_LE(clearBall.Holes, clearBall.Shown / 100);
  // The ball (one input) shadows the plate (the other) ...
  EXPECT_GT(ball.Shadowed, 200) << "no shadow: the ball does not occlude the plate's light";
  // ... and a ball of zero opacity lights the scene as no ball at all.
  EXPECT_EQ(clearBall.Shadowed, 0) << "a clear input casts a shadow";
  EXPECT_LT(clearVsEmpty.Mean, 0.5);
  // No dark mud: shadow and all, the picture keeps most of stock's brightness.
  EXPECT_GT(ball.Brightness, 0.5);
  EXPECT_LT(ball.Brightness, 1.3);
}

TEST(LitMultiVolume, PerSampleModeRendersAsStockWithOneWarning)
{
  // The per-sample photon test reads one texture; the transport mode lights the inputs.
  vtkNew<vtkScattererTemplateVolumeMapper> ours;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  MultiScene scene(ours), stockScene(stock);
  ours->SetIlluminationMode(vtkScattererTemplateVolumeMapper::PER_SAMPLE);
  vtkNew<vtkTest::ErrorObserver> warnings;
  ours->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkRenderWindow* window = scatterer_testing::SharedWindow();
  window->AddRenderer(stockScene.Renderer);
  const auto expected = scatterer_testing::RenderAndGrab(window);
  window->RemoveRenderer(stockScene.Renderer);
  window->AddRenderer(scene.Renderer);
  const auto first = scatterer_testing::RenderAndGrab(window);
  scatterer_testing::RenderAndGrab(window);
  window->RemoveRenderer(scene.Renderer);
  ours->ReleaseGraphicsResources(window);
  stock->ReleaseGraphicsResources(window);
  EXPECT_EQ(scatterer_testing::WarningCount(warnings), 1u);
  EXPECT_NE(scatterer_testing::LastWarning(warnings).find("vtkMultiVolume in per-sample mode"),
    std::string::npos)
    << scatterer_testing::LastWarning(warnings);
  EXPECT_EQ(scatterer_testing::MaxDifference(first, expected), 0);
}

TEST(LitMultiVolume, MoreThanFourInputsRenderAsStockWithOneWarning)
{
  // The transport reads at most 4 inputs (its passes bind one texture per input).
  vtkNew<vtkScattererTemplateVolumeMapper> ours;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  vtkNew<vtkRenderer> renderer, stockRenderer;
  vtkNew<vtkMultiVolume> multi, stockMulti;
  std::vector<vtkSmartPointer<vtkVolume>> volumes;
  const auto ball = Ball(false);
  for (int port = 0; port < 5; ++port)
  {
    for (auto* mapper : { static_cast<vtkGPUVolumeRayCastMapper*>(ours),
           static_cast<vtkGPUVolumeRayCastMapper*>(stock) })
    {
      mapper->SetInputDataObject(port, ball);
      auto volume = vtkSmartPointer<vtkVolume>::New();
      volume->SetProperty(Property(1.0, 0.4, 0.2, 0.6));
      volume->SetPosition(30.0 * port, 0.0, 0.0);
      (mapper == ours ? multi : stockMulti)->SetVolume(volume, port);
      volumes.push_back(volume);
    }
  }
  multi->SetMapper(ours);
  stockMulti->SetMapper(stock);
  renderer->AddVolume(multi);
  stockRenderer->AddVolume(stockMulti);
  renderer->ResetCamera();
  stockRenderer->ResetCamera();
  vtkNew<vtkTest::ErrorObserver> warnings;
  ours->AddObserver(vtkCommand::WarningEvent, warnings);
  const auto expected = scatterer_testing::RenderSceneOnce(stockRenderer, stock);
  const auto first = scatterer_testing::RenderSceneOnce(renderer, ours);
  ASSERT_GT(scatterer_testing::MeanBrightness(expected), 1.0) << "the scene is visible";
  EXPECT_EQ(scatterer_testing::WarningCount(warnings), 1u);
  EXPECT_NE(scatterer_testing::LastWarning(warnings).find("more than 4 inputs"), std::string::npos)
    << scatterer_testing::LastWarning(warnings);
  EXPECT_NE(ours->GetLastShaderFeatures().find("stock"), std::string::npos);
  EXPECT_EQ(scatterer_testing::MaxDifference(first, expected), 0);
}

namespace
{
// The ball above the plate in one volume (spacing 1), rendered alone or as input 0 of a
// vtkMultiVolume whose input 1 is an empty volume on the same lattice, by the stock
// mapper or ours (illumination on).
std::vector<unsigned char> RenderScene(bool ours, bool multi)
{
  const auto scene = scatterer_testing::MakeComponentVolume(N, 1,
    [](int i, int j, int k, int) -> unsigned char
    {
      const int di = i - N / 2, dj = j - N / 2, dk = k - 30;
      return di * di + dj * dj + dk * dk <= 8 * 8 || (k >= 6 && k <= 10) ? 200 : 0;
    });
  const auto empty = scatterer_testing::MakeComponentVolume(
    8, 1, [](int i, int, int, int) -> unsigned char { return i == 0 ? 1 : 0; });
  vtkNew<vtkScattererTemplateVolumeMapper> scatterer;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  vtkGPUVolumeRayCastMapper* mapper = ours ? static_cast<vtkGPUVolumeRayCastMapper*>(scatterer)
                                           : static_cast<vtkGPUVolumeRayCastMapper*>(stock);
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.5);
  mapper->UseJitteringOff();
  // A vtkMultiVolume reads the light at every sample; the volume alone does too here, so
  // that the two differ only in how they look the light up.
  scatterer->SetMaximumLightReadStrideForTesting(1);
  // A vtkMultiVolume has no light inside a dense texel (st_surfaceChange): nor here.
  scatterer->SetSurfaceDetailForTesting(false);
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkVolume> volume, emptyVolume;
  vtkNew<vtkMultiVolume> multiVolume;
  volume->SetProperty(Property(0.3, 0.9, 0.3, 0.6));
  emptyVolume->SetProperty(Property(1.0, 0.4, 0.2, 0.6));
  emptyVolume->SetPosition(20.0, 20.0, 20.0); // inside the ball
  if (multi)
  {
    mapper->SetInputDataObject(0, scene);
    mapper->SetInputDataObject(1, empty);
    multiVolume->SetMapper(mapper);
    multiVolume->SetVolume(volume, 0);
    multiVolume->SetVolume(emptyVolume, 1);
    renderer->AddVolume(multiVolume);
  }
  else
  {
    mapper->SetInputDataObject(0, scene);
    volume->SetMapper(mapper);
    renderer->AddVolume(volume);
  }
  scatterer_testing::LightAndViewBallAbovePlate(renderer, N);
  return scatterer_testing::RenderSceneOnce(renderer, mapper);
}
}

TEST(LitMultiVolume, AnInputOnTheFirstLatticeIsLitAsAlone)
{
  // The transport box lies on input 0's voxel lattice: input 0 gets the light it gets
  // alone, looked up through VTK's multi-volume matrices, and an empty input inside it
  // changes nothing. The stock ray casts are the same picture (measured); so are the lit
  // ones (measured; a medium without the colour of empty texels, which the diffusion's
  // coarse grid averages in for one volume, differed by 0.42 levels, 2.6 % of pixels
  // over 16).
  const auto litAlone = RenderScene(true, false);
  const auto litMulti = RenderScene(true, true);
  const auto stockAlone = RenderScene(false, false);
  const auto stockMulti = RenderScene(false, true);
  const auto e = scatterer_testing::CompareWays(
    "multi-volume vs alone", litAlone, litMulti, stockAlone, stockMulti);
  if (const char* dir = std::getenv("SCATTERER_TEST_IMAGES"))
  {
    const int* size = scatterer_testing::SharedWindow()->GetSize();
    scatterer_testing::SavePng(std::string(dir) + "/lit-alone.png", litAlone, size[0], size[1]);
    scatterer_testing::SavePng(std::string(dir) + "/lit-multi.png", litMulti, size[0], size[1]);
  }
  ASSERT_GT(e.Illumination.Mean, 5.0) << "the illumination changes nothing: the test sees nothing";
  EXPECT_LE(e.Lit.Mean, e.Stock.Mean + 0.05);
  EXPECT_LE(e.Lit.FractionOver, e.Stock.FractionOver + 0.001);
}

TEST(LitMultiVolume, AnInputOfZeroScaleRendersAsStockWithOneWarning)
{
  // A flattened input has no texture -> world inverse to read it through.
  vtkNew<vtkScattererTemplateVolumeMapper> ours;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  MultiScene scene(ours), stockScene(stock);
  scene.BallVolume->SetScale(1.0, 1.0, 0.0);
  stockScene.BallVolume->SetScale(1.0, 1.0, 0.0);
  vtkNew<vtkTest::ErrorObserver> warnings;
  ours->AddObserver(vtkCommand::WarningEvent, warnings);
  const auto expected = scatterer_testing::RenderSceneOnce(stockScene.Renderer, stock);
  const auto first = scatterer_testing::RenderSceneOnce(scene.Renderer, ours);
  ASSERT_GT(scatterer_testing::MeanBrightness(expected), 1.0) << "the scene is visible";
  EXPECT_EQ(scatterer_testing::WarningCount(warnings), 1u);
  EXPECT_NE(
    scatterer_testing::LastWarning(warnings).find("zero spacing or scale"), std::string::npos)
    << scatterer_testing::LastWarning(warnings);
  EXPECT_EQ(scatterer_testing::MaxDifference(first, expected), 0);
}

TEST(LitMultiVolume, ClippedInputCastsNoShadow)
{
  // VTK 9.1 clips a vtkMultiVolume's inputs: clipped-away matter neither shows nor casts a
  // shadow, so the plate is lit as with no ball at all.
  const auto render = [](bool emptyBall, vtkPlane* plane)
  {
    vtkNew<vtkScattererTemplateVolumeMapper> ours;
    MultiScene scene(ours, 0.6, emptyBall);
    if (plane)
    {
      ours->AddClippingPlane(plane);
    }
    return scatterer_testing::RenderSceneOnce(scene.Renderer, ours);
  };
  vtkNew<vtkPlane> plane; // keeps z < 16: the plate, not the ball
  plane->SetOrigin(0.0, 0.0, 16.0);
  plane->SetNormal(0.0, 0.0, -1.0);
  const auto d = scatterer_testing::CompareRgb(render(false, plane), render(true, nullptr), 16);
  std::printf(
    "clipped ball vs no ball: mean %.3f, %.2f%% over 16 levels\n", d.Mean, 100.0 * d.FractionOver);
  EXPECT_LT(d.Mean, 0.5) << "clipped matter still shades the plate";
  EXPECT_LT(d.FractionOver, 0.01);
}

TEST(LitMultiVolume, CroppingSaysOnceThatTheLightIsNotCropped)
{
  vtkNew<vtkScattererTemplateVolumeMapper> ours;
  MultiScene scene(ours);
  ours->CroppingOn();
  ours->SetCroppingRegionPlanes(0.0, 47.0, 0.0, 47.0, 0.0, 16.0);
  vtkNew<vtkTest::ErrorObserver> warnings;
  ours->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkRenderWindow* window = scatterer_testing::SharedWindow();
  window->AddRenderer(scene.Renderer);
  scatterer_testing::RenderAndGrab(window);
  scatterer_testing::RenderAndGrab(window);
  window->RemoveRenderer(scene.Renderer);
  ours->ReleaseGraphicsResources(window);
  EXPECT_EQ(ours->GetLastShaderFeatures().find("stock"), std::string::npos)
    << ours->GetLastShaderFeatures();
  EXPECT_EQ(scatterer_testing::WarningCount(warnings), 1u);
  EXPECT_NE(
    scatterer_testing::LastWarning(warnings).find("does not crop the light"), std::string::npos)
    << scatterer_testing::LastWarning(warnings);
}
