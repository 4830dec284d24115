// With illumination off, vtkScattererTemplateVolumeMapper must render
// pixel-identically to vtkOpenGLGPUVolumeRayCastMapper. This program renders
// one named case with both mappers in one window and compares every pixel
// (max difference 0). CTest runs it once per case (see CMakeLists.txt).
#include "ScattererTestVolumes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Case
{
  const char* Name;
  int ScalarType;
  int BlendMode;
  bool Shade = false;
  bool Crop = false;
  bool Clip = false;
  bool Geometry = false;
  bool Inverted = false;
};

const std::vector<Case>& Cases()
{
  using M = vtkVolumeMapper;
  static const std::vector<Case> cases = {
    { "composite_u8", VTK_UNSIGNED_CHAR, M::COMPOSITE_BLEND },
    { "composite_i16", VTK_SHORT, M::COMPOSITE_BLEND },
    { "composite_u16", VTK_UNSIGNED_SHORT, M::COMPOSITE_BLEND },
    { "composite_f32", VTK_FLOAT, M::COMPOSITE_BLEND },
    { "shade_u8", VTK_UNSIGNED_CHAR, M::COMPOSITE_BLEND, true },
    { "shade_f32", VTK_FLOAT, M::COMPOSITE_BLEND, true },
    { "mip_i16", VTK_SHORT, M::MAXIMUM_INTENSITY_BLEND },
    { "minip_i16", VTK_SHORT, M::MINIMUM_INTENSITY_BLEND, false, false, false, false, true },
    { "average_f32", VTK_FLOAT, M::AVERAGE_INTENSITY_BLEND },
    { "additive_u8", VTK_UNSIGNED_CHAR, M::ADDITIVE_BLEND },
    { "crop_i16", VTK_SHORT, M::COMPOSITE_BLEND, true, true },
    { "clip_f32", VTK_FLOAT, M::COMPOSITE_BLEND, true, false, true },
    { "geometry_u8", VTK_UNSIGNED_CHAR, M::COMPOSITE_BLEND, true, false, false, true },
  };
  return cases;
}

std::vector<unsigned char> Grab(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, size[0] - 1, size[1] - 1, /*front=*/0, pixels);
  const auto* data = pixels->GetPointer(0);
  return std::vector<unsigned char>(data, data + pixels->GetNumberOfValues());
}
}

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: TestStockIdentity CASE\ncases:";
    for (const auto& c : Cases())
    {
      std::cerr << " " << c.Name;
    }
    std::cerr << "\n";
    return 2;
  }
  const Case* found = nullptr;
  for (const auto& c : Cases())
  {
    found = std::strcmp(c.Name, argv[1]) == 0 ? &c : found;
  }
  if (!found)
  {
    std::cerr << "unknown case '" << argv[1] << "'\n";
    return 2;
  }
  const Case& c = *found;

  const int dims = 48;
  auto image = scatterer_testing::MakeShellBallPlate(dims, c.ScalarType, c.Inverted);
  vtkNew<vtkVolumeProperty> property;
  scatterer_testing::ApplyShellBallPlateProperty(property);
  property->SetShade(c.Shade);
  if (c.Inverted)
  {
    // Minimum intensity: low values (the inverted ball) must be visible.
    property->GetScalarOpacity()->RemoveAllPoints();
    property->GetScalarOpacity()->AddPoint(0.0, 1.0);
    property->GetScalarOpacity()->AddPoint(250.0, 0.2);
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.2);
  window->AddRenderer(renderer);
  vtkNew<vtkVolume> volume;
  volume->SetProperty(property);
  renderer->AddVolume(volume);

  if (c.Geometry)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(0.7 * dims, 0.5 * dims, 0.5 * dims);
    sphere->SetRadius(0.25 * dims);
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(32);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(sphereMapper);
    actor->GetProperty()->SetColor(0.2, 0.8, 0.3);
    renderer->AddActor(actor);
  }

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.5 * dims, 0.5 * dims, 0.5 * dims);
  camera->SetPosition(2.2 * dims, -0.9 * dims, 1.4 * dims);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.5 * dims, 0.5 * dims, 0.5 * dims);
  plane->SetNormal(-1.0, 0.3, 0.2);

  auto render = [&](vtkGPUVolumeRayCastMapper* mapper)
  {
    mapper->SetInputData(image);
    mapper->SetBlendMode(c.BlendMode);
    mapper->AutoAdjustSampleDistancesOff();
    mapper->SetSampleDistance(0.5);
    if (c.Crop)
    {
      mapper->CroppingOn();
      mapper->SetCroppingRegionPlanes(4, 0.6 * dims, 4, 0.7 * dims, 0, 0.55 * dims);
      mapper->SetCroppingRegionFlagsToSubVolume();
    }
    if (c.Clip)
    {
      mapper->AddClippingPlane(plane);
    }
    volume->SetMapper(mapper);
    window->Render();
    return Grab(window);
  };

  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  vtkNew<vtkScattererTemplateVolumeMapper> ours;
  ours->IlluminationEnabledOff();
  const std::vector<unsigned char> expected = render(stock);
  const std::vector<unsigned char> actual = render(ours);

  // A blank picture would make the comparison meaningless.
  size_t lit = 0;
  for (size_t i = 0; i < expected.size(); i += 4)
  {
    lit += (expected[i] > 40 || expected[i + 1] > 40 || expected[i + 2] > 60) ? 1 : 0;
  }
  if (lit < expected.size() / 4 / 50)
  {
    std::cerr << c.Name << ": the stock image is nearly empty (" << lit
              << " lit pixels); the case does not test anything\n";
    return 1;
  }
  if (expected.size() != actual.size())
  {
    std::cerr << c.Name << ": image sizes differ\n";
    return 1;
  }
  int maxDiff = 0;
  size_t differing = 0;
  for (size_t i = 0; i < expected.size(); ++i)
  {
    const int d = std::abs(int(expected[i]) - int(actual[i]));
    maxDiff = d > maxDiff ? d : maxDiff;
    differing += d ? 1 : 0;
  }
  std::cout << c.Name << ": " << lit << " lit pixels, max channel difference " << maxDiff << ", "
            << differing << " differing channels\n";
  return maxDiff == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
