// The placement of the light transport volume in the world follows the ray caster's:
// an image whose direction matrix rotates it must be lit like the same image, with an
// identity direction, rotated by the vtkVolume's user matrix about the image origin.
// The object (an L-shaped block beside a translucent ball, anisotropic spacing, origin
// off zero) has no symmetry that would hide a wrong or missing rotation, and the one
// directional light is aligned with neither the data axes nor the rotated ones.
//
// First the stock ray caster (no lighting) must place both the same, so the comparison
// is about the lighting and not about VTK's own handling of the direction matrix.
//
// A direction matrix that mirrors (determinant -1) must render, lit and unlit, like the
// same voxels stored in the opposite order along the mirrored axis under a rotation: the
// same values at the same points. VTK 9.1's ray caster alone draws the wrong faces of
// such a volume's bounding box and shows slivers of it
// (Module/Rendering/ScattererMirroredWinding.h).
#include "Common/ScattererMapperSetup.h"
#include "ScattererErrorObserver.h"
#include "ScattererRenderHarness.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace
{
constexpr int NX = 40, NY = 32, NZ = 28;
const double kOrigin[3] = { 5.0, -3.0, 2.0 };
const double kSpacing[3] = { 1.0, 1.25, 0.9 };

// The rotation: 30 degrees about z, then 20 about x (as a matrix: Rx(20) Rz(30)).
vtkSmartPointer<vtkMatrix4x4> Rotation()
{
  vtkNew<vtkTransform> t;
  t->PostMultiply();
  t->RotateZ(30.0);
  t->RotateX(20.0);
  auto m = vtkSmartPointer<vtkMatrix4x4>::New();
  m->DeepCopy(t->GetMatrix());
  return m;
}

// An L-shaped block (200, dense) in one corner and a translucent ball (100) off
// centre: two materials, so the kernels' photon offsets (world to grid) count too.
unsigned char LAndBallVoxel(int i, int j, int k)
{
  const bool foot = i >= 4 && i < 30 && j >= 4 && j < 12 && k >= 3 && k < 9;
  const bool stem = i >= 4 && i < 11 && j >= 4 && j < 12 && k >= 3 && k < 24;
  const double r2 = (i - 27.0) * (i - 27.0) + (j - 21.0) * (j - 21.0) + (k - 16.0) * (k - 16.0);
  return r2 <= 7.5 * 7.5 ? 100 : (foot || stem) ? 200 : 0;
}

// The object on @p nx x NY x NZ points at @p origin with direction @p direction (4x4,
// its 3x3 part; null: identity); @p reversed stores it in the opposite order along x.
vtkSmartPointer<vtkImageData> LAndBallImage(
  int nx, const double origin[3], vtkMatrix4x4* direction, bool reversed)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, NY, NZ);
  image->SetOrigin(origin);
  image->SetSpacing(kSpacing);
  if (direction)
  {
    double d[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        d[3 * i + j] = direction->GetElement(i, j);
    image->SetDirectionMatrix(d);
  }
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < NZ; ++k)
    for (int j = 0; j < NY; ++j)
      for (int i = 0; i < nx; ++i)
        *p++ = LAndBallVoxel(reversed ? nx - 1 - i : i, j, k);
  return image;
}

vtkSmartPointer<vtkImageData> LAndBall(bool rotated)
{
  return LAndBallImage(NX, kOrigin, rotated ? Rotation().GetPointer() : nullptr, false);
}

// The world point of the object's local point @p local (spacing times index, before the
// rotation) under Rotation() about kOrigin.
void RotatedPoint(const double local[3], double world[3])
{
  auto r = Rotation();
  const double in[4] = { local[0], local[1], local[2], 0.0 };
  double out[4];
  r->MultiplyPoint(in, out);
  for (int a = 0; a < 3; ++a)
  {
    world[a] = out[a] + kOrigin[a];
  }
}

enum class Mode
{
  Stock,           // vtkOpenGLGPUVolumeRayCastMapper
  IlluminationOff, // ours, illumination off
  Transport,       // ours, the defaults
  PerSample        // ours, the paper's per-sample photon test
};

// Renders @p image (with user matrix @p user) seen from a fixed offset to @p centre (a
// twentieth of it where @p inside: the camera then stands in the volume), at
// @p imageSampleDistance; the mapper's warnings go to @p warnings where given.
std::vector<unsigned char> Render(vtkImageData* image, vtkMatrix4x4* user, Mode mode,
  const double centre[3], float imageSampleDistance = 1.0f,
  vtkTest::ErrorObserver* warnings = nullptr, bool inside = false)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(60, 0.0);
  opacity->AddPoint(100, 0.06);
  opacity->AddPoint(140, 0.0);
  opacity->AddPoint(160, 0.0);
  opacity->AddPoint(200, 0.5);
  opacity->AddPoint(255, 0.5);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.3, 0.6, 0.9);
  color->AddRGBPoint(100, 0.3, 0.6, 0.9);
  color->AddRGBPoint(200, 0.95, 0.85, 0.7);
  color->AddRGBPoint(255, 0.95, 0.85, 0.7);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToLinear();

  vtkNew<vtkScattererTemplateVolumeMapper> ours;
  ours->SetIlluminationEnabled(mode != Mode::IlluminationOff);
  if (mode == Mode::PerSample)
  {
    ours->SetIlluminationModeToPerSample();
  }
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  vtkGPUVolumeRayCastMapper* mapper = mode == Mode::Stock
    ? static_cast<vtkGPUVolumeRayCastMapper*>(stock)
    : static_cast<vtkGPUVolumeRayCastMapper*>(ours);
  mapper->SetInputData(image);
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.5);
  mapper->UseJitteringOff();
  mapper->SetImageSampleDistance(imageSampleDistance);
  if (warnings)
  {
    mapper->AddObserver(vtkCommand::WarningEvent, warnings);
  }
  vtkNew<vtkRenderer> renderer;
  vtkVolume* volume = scatterer_examples::AddVolume(renderer, mapper, property);
  if (user)
  {
    volume->SetUserMatrix(user);
  }
  renderer->AutomaticLightCreationOff();
  // From -x and above: the stem shadows the foot.
  scatterer_testing::AddSceneLight(renderer, -0.7, 0.25, 0.65);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(centre);
  const double away = inside ? 0.05 : 1.0;
  camera->SetPosition(centre[0] + 55 * away, centre[1] - 70 * away, centre[2] + 45 * away);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();

  auto pixels = scatterer_testing::RenderSceneOnce(renderer, mapper);
  if (mode == Mode::Transport || mode == Mode::PerSample)
  {
    const char* kind = mode == Mode::Transport ? "transport" : "per-sample";
    EXPECT_EQ(ours->GetLastShaderFeatures().rfind(kind, 0), 0u) << ours->GetLastShaderFeatures();
  }
  return pixels;
}

// The user matrix that places an identity-direction image as the direction matrix
// does: world = origin + R (x - origin) for dataset point x.
vtkSmartPointer<vtkMatrix4x4> RotationAboutOrigin()
{
  vtkNew<vtkTransform> t;
  t->PostMultiply();
  t->Translate(-kOrigin[0], -kOrigin[1], -kOrigin[2]);
  t->Concatenate(Rotation());
  t->Translate(kOrigin);
  auto m = vtkSmartPointer<vtkMatrix4x4>::New();
  m->DeepCopy(t->GetMatrix());
  return m;
}

// The centre of the rotated object of @p nx points along x, mirrored (x negated before
// the rotation) or not.
void Centre(int nx, bool mirrored, double centre[3])
{
  const double local[3] = { (mirrored ? -0.5 : 0.5) * kSpacing[0] * (nx - 1),
    0.5 * kSpacing[1] * (NY - 1), 0.5 * kSpacing[2] * (NZ - 1) };
  RotatedPoint(local, centre);
}

void Print(const char* what, const scatterer_testing::ImageDifference& d)
{
  std::printf("%s: mean %.3f levels, %.3f %% over 8 levels, worst %d\n", what, d.Mean,
    100.0 * d.FractionOver, d.Worst);
}

// Expects @p a and @p b to be the same picture to within a level on average and 8 levels
// on all but 1 % of the pixels, and prints how they differ under @p what.
void ExpectSame(
  const char* what, const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  const auto d = scatterer_testing::CompareRgb(a, b, 8);
  Print(what, d);
  EXPECT_LE(d.Mean, 1.0) << what;
  EXPECT_LE(d.FractionOver, 0.01) << what;
}

// The transport grid takes every second point from index 0 (22 texels here), and the
// diffusion's coarse grid pairs them from its texel 0: with 43 points along x both have
// the same points and blocks whichever end index 0 is at.
constexpr int kMirroredNX = 43;

// The object under direction R diag(-1, 1, 1): point i lies at origin + R (-sx i, sy j, sz k).
vtkSmartPointer<vtkImageData> Mirrored()
{
  auto mirror = Rotation();
  for (int r = 0; r < 3; ++r)
  {
    mirror->SetElement(r, 0, -mirror->GetElement(r, 0));
  }
  EXPECT_LT(mirror->Determinant(), 0.0);
  return LAndBallImage(kMirroredNX, kOrigin, mirror, false);
}

// The same points and values stored in the opposite order along x under R alone: index
// nx - 1 - i holds voxel i, the origin where Mirrored() puts voxel nx - 1.
vtkSmartPointer<vtkImageData> Reversed()
{
  const double last[3] = { -kSpacing[0] * (kMirroredNX - 1), 0.0, 0.0 };
  double origin[3];
  RotatedPoint(last, origin);
  return LAndBallImage(kMirroredNX, origin, Rotation(), true);
}
}

TEST(DirectionEquivalence, DirectionMatrixIsLitLikeTheSameUserMatrix)
{
  const auto directed = LAndBall(true);
  const auto plain = LAndBall(false);
  const auto user = RotationAboutOrigin();

  // VTK 9.1's ray caster places both the same (measured: at most 1 level apart).
  double centre[3];
  Centre(NX, false, centre);
  const auto stockA = Render(directed, nullptr, Mode::Stock, centre);
  const auto stockB = Render(plain, user, Mode::Stock, centre);
  ASSERT_GT(scatterer_testing::MeanBrightness(stockA), 5.0) << "the object is visible";
  const auto placement = scatterer_testing::CompareRgb(stockA, stockB, 8);
  Print("stock, direction matrix vs user matrix", placement);
  ASSERT_LE(placement.Mean, 1.0) << "VTK itself places the two differently";
  ASSERT_LE(placement.FractionOver, 0.01) << "VTK itself places the two differently";

  // Measured (llvmpipe): mean 0.000 levels, no pixel over 8, worst 1. A transport
  // placed without the direction matrix: mean 4.0 levels, 9.0 % over 8 levels.
  ExpectSame("transport, direction matrix vs user matrix",
    Render(directed, nullptr, Mode::Transport, centre),
    Render(plain, user, Mode::Transport, centre));

  // The per-sample mode's photons step along the texture axes that a world offset maps
  // to, through the direction matrix too.
  const auto perSample =
    scatterer_testing::CompareRgb(Render(directed, nullptr, Mode::PerSample, centre),
      Render(plain, user, Mode::PerSample, centre), 8);
  Print("per-sample, direction matrix vs user matrix", perSample);
  // Measured: mean 0.000 levels, worst 2. Photons stepped along the index axes as if the
  // direction were the identity: mean 0.31 levels, 0.6 % over 8 levels, worst 38 (this
  // scene's per-sample shadows are small; the worst pixel is what shows it).
  EXPECT_LE(perSample.Mean, 0.1);
  EXPECT_LE(perSample.Worst, 8);
}

TEST(DirectionEquivalence, MirroringDirectionMatrixRendersLikeTheVoxelsReversed)
{
  const auto mirrored = Mirrored();
  const auto reversed = Reversed();
  double centre[3];
  Centre(kMirroredNX, true, centre);

  // The mapper with its illumination off (VTK's own ray caster would show slivers).
  const auto offB = Render(reversed, nullptr, Mode::IlluminationOff, centre);
  ASSERT_GT(scatterer_testing::MeanBrightness(offB), 5.0) << "the object is visible";
  ExpectSame("illumination off, mirrored vs reversed",
    Render(mirrored, nullptr, Mode::IlluminationOff, centre), offB);

  ExpectSame("transport, mirrored vs reversed", Render(mirrored, nullptr, Mode::Transport, centre),
    Render(reversed, nullptr, Mode::Transport, centre));
}

// VTK draws a frame of ImageSampleDistance != 1 with a full-screen quad that the reversed
// winding would cull: a mirrored volume renders at the full resolution instead, and says
// so once.
TEST(DirectionEquivalence, MirroredVolumeIgnoresImageSampleDistanceAndSaysSo)
{
  const auto mirrored = Mirrored();
  double centre[3];
  Centre(kMirroredNX, true, centre);
  const auto full = Render(mirrored, nullptr, Mode::Transport, centre);
  vtkNew<vtkTest::ErrorObserver> warnings;
  const auto coarse = Render(mirrored, nullptr, Mode::Transport, centre, 2.0f, warnings);
  ASSERT_GT(scatterer_testing::MeanBrightness(full), 5.0) << "the object is visible";
  EXPECT_LE(scatterer_testing::MaxDifference(full, coarse), 1);
  ASSERT_EQ(scatterer_testing::WarningCount(warnings), 1u) << warnings->GetWarningMessage();
  EXPECT_NE(
    warnings->GetWarningMessage().find("ImageSampleDistance 2 is not applied"), std::string::npos)
    << warnings->GetWarningMessage();
}

// With the camera inside it, VTK 9.1 clips a mirrored volume's box on the wrong side and
// draws nothing (ScattererMirroredWinding.h): the mapper says so, once.
TEST(DirectionEquivalence, MirroredVolumeSeenFromInsideSaysWhyNothingIsDrawn)
{
  const auto mirrored = Mirrored();
  double centre[3];
  Centre(kMirroredNX, true, centre);
  vtkNew<vtkTest::ErrorObserver> warnings;
  const auto seen = Render(mirrored, nullptr, Mode::Transport, centre, 1.0f, warnings, true);
  EXPECT_LT(scatterer_testing::MeanBrightness(seen), 0.5)
    << "VTK draws it now: the warning is out of date";
  ASSERT_EQ(scatterer_testing::WarningCount(warnings), 1u) << warnings->GetWarningMessage();
  EXPECT_NE(
    warnings->GetWarningMessage().find("camera's near plane cuts through it"), std::string::npos)
    << warnings->GetWarningMessage();
  // The same voxels stored unmirrored are drawn from there.
  const auto reversed = Reversed();
  EXPECT_GT(scatterer_testing::MeanBrightness(
              Render(reversed, nullptr, Mode::Transport, centre, 1.0f, nullptr, true)),
    1.0); // measured 4.4 (the mirrored volume 0)
  // From outside, no such warning.
  vtkNew<vtkTest::ErrorObserver> outside;
  Render(mirrored, nullptr, Mode::Transport, centre, 1.0f, outside);
  EXPECT_EQ(scatterer_testing::WarningCount(outside), 0u) << outside->GetWarningMessage();
}
