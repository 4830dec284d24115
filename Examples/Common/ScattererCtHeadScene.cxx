#include "ScattererCtHeadScene.h"
#include "ScattererVolumeCheck.h"

#include "vtkCamera.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
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

TransferPoints CtHeadTransferPoints()
{
  // Piecewise linear in HU; opacity per 1 mm (scalar opacity unit distance).
  return TransferPoints{ "ct-head",
    { { -1024, 0.0 }, { -600, 0.0 }, { -450, 0.1 }, { -50, 0.1 }, { 0, 0.0 }, { 150, 0.0 },
      { 300, 0.8 }, { 2986, 0.9 } },
    { { -1024, 0.8, 0.55, 0.42 }, { -600, 0.85, 0.6, 0.45 }, { 0, 0.95, 0.75, 0.6 },
      { 150, 0.95, 0.85, 0.75 }, { 300, 1.0, 1.0, 0.95 }, { 2986, 1.0, 1.0, 1.0 } } };
}

void ApplyCtHeadProperty(vtkVolumeProperty* property)
{
  ApplyTransferPoints(CtHeadTransferPoints(), 0.0, 1.0, property);
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
  // The transfer function comes from the finite values' histogram (NaN and infinities
  // ignored: one infinite voxel must not stretch the ramp over nothing). Volumes with
  // no finite value, or a constant one, are refused before this (CheckVolume).
  const VolumeHistogram histogram(image);
  TransferPoints points;
  std::string unused;
  MakeTransferPreset(DefaultTransferPreset(histogram), histogram, points, unused);
  ApplyTransferPoints(points, 0.0, 1.0, property);
  property->SetInterpolationTypeToLinear();
  double spacing[3];
  image->GetSpacing(spacing);
  // Opacities are per voxel: the unit distance is the mean spacing.
  property->SetScalarOpacityUnitDistance((spacing[0] + spacing[1] + spacing[2]) / 3.0);
  property->SetAmbient(0.1);
  property->SetDiffuse(0.9);
  property->SetSpecular(0.2);
  property->SetSpecularPower(10.0);
  // A front view with the third axis up: scanners stack slices along the body's
  // long axis, so this shows a patient upright rather than from above.
  double bounds[6];
  image->GetBounds(bounds);
  vtkCamera* camera = renderer->GetActiveCamera();
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0], center[1] - 1.0, center[2]);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera(bounds);
}
}
