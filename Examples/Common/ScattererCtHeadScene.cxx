#include "ScattererCtHeadScene.h"
#include "ScattererVolumeCheck.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScattererVolumeReader.h"
#include "vtkVolumeProperty.h"

#include <cstdlib>

namespace scatterer_examples
{
std::string DataDirectory()
{
  if (const char* dir = std::getenv("SCATTERER_DATA_DIR"); dir && *dir)
  {
    return dir;
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
  {
    return std::string(xdg) + "/scatterer-template";
  }
  const char* home = std::getenv("HOME");
  return std::string(home && *home ? home : ".") + "/.cache/scatterer-template";
}

std::string CtHeadPath()
{
  return DataDirectory() + "/ct-head.mhd";
}

vtkSmartPointer<vtkImageData> ReadVolumeOrCtHead(const std::string& input, std::string& error)
{
  const std::string path = input.empty() ? CtHeadPath() : input;
  auto image = vtkScattererVolumeReader::ReadVolume(path, &error);
  if (!image && input.empty())
  {
    error += "\nThe default CT head is prepared by: bash scripts/prepare-data.sh";
  }
  return image;
}

void ApplyCtHeadProperty(vtkVolumeProperty* property)
{
  // Piecewise linear in HU; opacity per 1 mm (scalar opacity unit distance).
  vtkNew<vtkPiecewiseFunction> opacity;
  const double opacityPoints[][2] = { { -1024, 0.0 }, { -600, 0.0 }, { -450, 0.1 }, { -50, 0.1 },
    { 0, 0.0 }, { 150, 0.0 }, { 300, 0.8 }, { 2986, 0.9 } };
  for (const auto& p : opacityPoints)
  {
    opacity->AddPoint(p[0], p[1]);
  }
  vtkNew<vtkColorTransferFunction> color;
  const double colorPoints[][4] = { { -1024, 0.8, 0.55, 0.42 }, { -600, 0.85, 0.6, 0.45 },
    { 0, 0.95, 0.75, 0.6 }, { 150, 0.95, 0.85, 0.75 }, { 300, 1.0, 1.0, 0.95 },
    { 2986, 1.0, 1.0, 1.0 } };
  for (const auto& p : colorPoints)
  {
    color->AddRGBPoint(p[0], p[1], p[2], p[3]);
  }
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetAmbient(0.1);
  property->SetDiffuse(0.9);
  property->SetSpecular(0.2);
  property->SetSpecularPower(10.0);
  property->ShadeOff();
}

void ApplyCtHeadCamera(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(-96.0, 572.0, 252.0);
  camera->SetFocalPoint(122.0, 135.0, 75.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(30.0);
  camera->ParallelProjectionOff();
  camera->SetClippingRange(200.0, 1200.0);
}

void ApplyCtHeadLight(vtkRenderer* renderer)
{
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetPosition(222.0, 435.0, 319.0);
  light->SetFocalPoint(122.0, 135.0, 75.0);
  light->SetIntensity(1.0);
  light->SetAmbientColor(1.0, 1.0, 1.0);
  light->SetDiffuseColor(1.0, 1.0, 1.0);
  light->SetSpecularColor(1.0, 1.0, 1.0);
  renderer->AddLight(light);
  renderer->TwoSidedLightingOn();
}

void ApplyCtHeadMapperSettings(vtkGPUVolumeRayCastMapper* mapper)
{
  mapper->SetBlendModeToComposite();
  mapper->AutoAdjustSampleDistancesOff();
  mapper->LockSampleDistanceToInputSpacingOff();
  mapper->SetSampleDistance(0.5);
  mapper->SetImageSampleDistance(1.0);
  mapper->UseJitteringOff();
}

void ApplyCtHeadWindowSettings(vtkRenderWindow* window)
{
  window->SetDesiredUpdateRate(0.0001);
  window->SetMultiSamples(0);
}

void ApplyAutoScene(vtkImageData* image, vtkVolumeProperty* property, vtkRenderer* renderer)
{
  // The finite range: one infinite voxel must not stretch the ramp to infinity
  // (vtkDataSet::GetScalarRange includes infinities), which leaves every finite
  // voxel transparent. Volumes with no finite value, or a constant one, are refused
  // before this (CheckVolume); the fallbacks keep this function total for other callers.
  double range[2] = { 0.0, 1.0 };
  FiniteScalarRange(image, range);
  if (!(range[1] > range[0]))
  {
    range[1] = range[0] + 1.0;
  }
  const double span = range[1] - range[0];
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[0] + 0.5 * span, 0.0);
  opacity->AddPoint(range[1], 0.8);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.9, 0.7, 0.6);
  color->AddRGBPoint(range[1], 1.0, 1.0, 1.0);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  double spacing[3];
  image->GetSpacing(spacing);
  property->SetScalarOpacityUnitDistance((spacing[0] + spacing[1] + spacing[2]) / 3.0);
  property->SetAmbient(0.1);
  property->SetDiffuse(0.9);
  property->SetSpecular(0.2);
  property->SetSpecularPower(10.0);
  renderer->ResetCamera(image->GetBounds());
}
}
