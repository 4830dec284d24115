// A piece of a split volume (what each rank renders in ParaView with MPI) must light
// its voxels as the whole volume does when everything between them and the light is
// in the piece: the transport volume sits on a lattice anchored to extent index 0,
// and with SetMaterialDerivationRange(the whole range) a piece derives the whole
// volume's materials even when it lacks some scalars. The piece here starts at an
// odd extent index and lacks the opaque sheet that gives the whole volume its
// densest material; the light comes from the piece's side (+x), so the sheet's
// shadow falls away from it. (Shadows cast into a piece from other pieces are not
// seen by it: docs/paraview.md.)
#include "Common/ScattererMapperSetup.h"
#include "ScattererRenderHarness.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace
{
constexpr int NX = 96, NY = 24, NZ = 24;
constexpr int kOwnedFrom = 48; // the piece owns x >= 48
constexpr int kPieceFrom = 33; // and holds ghost layers from x = 33 (odd on purpose)

// Translucent medium (100) everywhere, an opaque sheet (250) at x = 4, 5 over the
// lower half: far outside the piece, but it sets the whole volume's densest material.
vtkSmartPointer<vtkImageData> Volume(int fromX)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(fromX, NX - 1, 0, NY - 1, 0, NZ - 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  for (int k = 0; k < NZ; ++k)
    for (int j = 0; j < NY; ++j)
      for (int i = fromX; i < NX; ++i)
      {
        const bool sheet = (i == 4 || i == 5) && k < NZ / 2;
        *static_cast<unsigned char*>(image->GetScalarPointer(i, j, k)) = sheet ? 250 : 100;
      }
  return image;
}

// Renders `image` cropped to the owned part, lit from +x.
std::vector<unsigned char> RenderOwnedPart(
  vtkImageData* image, bool wholeRange, int mode = vtkScattererTemplateVolumeMapper::TRANSPORT)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(90, 0.0);
  opacity->AddPoint(100, 0.08);
  opacity->AddPoint(200, 0.08);
  opacity->AddPoint(250, 1.0);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 1, 1);
  color->AddRGBPoint(255, 1, 1, 1);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();

  vtkNew<vtkScattererTemplateVolumeMapper> mapper;
  mapper->SetInputData(image);
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.5);
  mapper->SetTemplateRadius(3.0);
  mapper->SetIlluminationMode(mode);
  // Per-sample: the photon test reads the voxels cropping hides, which a piece's ghost
  // voxels are meant to be (as the ParaView plugin sets it).
  mapper->SetCroppedMatterCastsShadows(mode == vtkScattererTemplateVolumeMapper::PER_SAMPLE);
  mapper->CroppingOn();
  mapper->SetCroppingRegionFlagsToSubVolume();
  mapper->SetCroppingRegionPlanes(kOwnedFrom, NX - 1, 0, NY - 1, 0, NZ - 1);
  if (wholeRange)
  {
    mapper->SetMaterialDerivationRange(100, 250);
  }
  vtkNew<vtkRenderer> renderer;
  scatterer_examples::AddVolume(renderer, mapper, property);
  renderer->AutomaticLightCreationOff();
  scatterer_testing::AddSceneLight(renderer, NX + 100, 0.5 * NY, 0.5 * NZ, NX, 0.5 * NY, 0.5 * NZ);
  vtkCamera* camera = renderer->GetActiveCamera();
  // From the far end, so rays reach the crop plane x = 48 at its back rather than
  // grazing along it (where a sample just inside or outside the plane would flip
  // with the rounding of the texture coordinates, whole or piece alike).
  camera->SetFocalPoint(72, 0.5 * NY, 0.5 * NZ);
  camera->SetPosition(170, -60, 45);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();

  auto pixels = scatterer_testing::RenderSceneOnce(renderer, mapper);
  EXPECT_EQ(mapper->GetLastShaderFeatures().rfind(
              mode == vtkScattererTemplateVolumeMapper::TRANSPORT ? "transport" : "per-sample", 0),
    0u)
    << mapper->GetLastShaderFeatures();
  return pixels;
}

struct Difference
{
  double Mean = 0.0;          // mean absolute difference per channel (0..255)
  double FractionOver4 = 0.0; // pixels with a channel more than 4 levels off
};

Difference Compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  Difference d;
  const size_t pixels = std::min(a.size(), b.size()) / 4;
  size_t over = 0;
  double sum = 0.0;
  for (size_t p = 0; p < pixels; ++p)
  {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
    {
      const int v = std::abs(static_cast<int>(a[4 * p + c]) - static_cast<int>(b[4 * p + c]));
      sum += v;
      worst = std::max(worst, v);
    }
    over += worst > 4;
  }
  if (pixels > 0)
  {
    d.Mean = sum / (3.0 * pixels);
    d.FractionOver4 = static_cast<double>(over) / pixels;
  }
  std::cout << "mean difference " << d.Mean << ", pixels over 4 levels " << 100.0 * d.FractionOver4
            << " %\n";
  return d;
}

TEST(VolumePieces, PieceWithTheWholeRangeIsLitAsTheWholeVolume)
{
  const auto whole = RenderOwnedPart(Volume(0), false);
  const auto piece = RenderOwnedPart(Volume(kPieceFrom), true);
  ASSERT_GT(scatterer_testing::MeanBrightness(whole), 5.0) << "the owned part is visible";
  // Same samples, same transport lattice, same materials. Only the silhouette of the crop
  // plane moves by rounding (its texture coordinate is relative to each image).
  const Difference d = Compare(whole, piece);
  EXPECT_LE(d.Mean, 0.25);
  EXPECT_LE(d.FractionOver4, 0.01);
}

TEST(VolumePieces, PieceWithItsOwnRangeDerivesOtherMaterials)
{
  // The control: from its own data range (medium only) the piece derives a
  // translucent material with other templates, and lights its voxels differently.
  // Shown in per-sample mode, where the templates are the whole light model; the
  // transport volume's kernels here reach the template radius in both cases.
  const auto whole =
    RenderOwnedPart(Volume(0), false, vtkScattererTemplateVolumeMapper::PER_SAMPLE);
  const auto piece =
    RenderOwnedPart(Volume(kPieceFrom), false, vtkScattererTemplateVolumeMapper::PER_SAMPLE);
  const Difference d = Compare(whole, piece);
  EXPECT_TRUE(d.Mean > 0.25 || d.FractionOver4 > 0.01);
}
}
