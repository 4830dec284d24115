#include "ScattererIlluminationScenes.h"

#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererMapperSetup.h"
#include "ScattererTestVolumes.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererVolumeReader.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace scatterer_testing
{
namespace
{
vtkSmartPointer<vtkLight> DirectionalLight(
  double x, double y, double z, double r, double g, double b)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetPosition(x, y, z);
  light->SetFocalPoint(0, 0, 0);
  light->SetColor(r, g, b);
  // Some ambient light, so regions in full shadow still show their shape.
  light->SetAmbientColor(0.4 * r, 0.4 * g, 0.4 * b);
  return light;
}

// A thin plate (2 voxels) in the shadow of an opaque block, seen from the
// side away from the light: it must stay dark (paper Fig. 4).
vtkSmartPointer<vtkImageData> MakeThinPlateBehindBlock(int n)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const bool inYZ = j > n / 5 && j < 4 * n / 5 && k > n / 5 && k < 4 * n / 5;
        unsigned char v = 0;
        if (inYZ && i >= n / 3 && i < n / 3 + 2)
          v = 120; // the thin plate
        if (j > n / 8 && j < 7 * n / 8 && k > n / 8 && k < 7 * n / 8 && i >= n / 2 + 2 &&
          i < n / 2 + 12)
          v = 200; // the block between plate and light
        *p++ = v;
      }
  return image;
}

// Three labelled blobs (labels 1, 2, 3) in a label map.
vtkSmartPointer<vtkImageData> MakeLabelMap(int n)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  const double c = 0.5 * (n - 1);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = i - c, y = j - c, z = k - c;
        unsigned char v = 0;
        if (x * x + y * y + z * z < 0.16 * n * n)
          v = 1;
        if ((x - 0.15 * n) * (x - 0.15 * n) + y * y + z * z < 0.03 * n * n)
          v = 2;
        if (std::abs(x + 0.1 * n) < 0.06 * n && std::abs(y) < 0.25 * n && std::abs(z) < 0.25 * n)
          v = 3;
        *p++ = v;
      }
  return image;
}

// Shell (orange, translucent) around a ball (white-blue, dense), with gaps in
// the opacity so the mapper derives two materials.
void ApplyTwoMaterialProperty(vtkVolumeProperty* property)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(70, 0.0);
  opacity->AddPoint(90, 0.15);
  opacity->AddPoint(110, 0.15);
  opacity->AddPoint(130, 0.0);
  opacity->AddPoint(170, 0.0);
  opacity->AddPoint(190, 0.9);
  opacity->AddPoint(255, 0.9);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.0, 0.0, 0.0);
  color->AddRGBPoint(100, 1.0, 0.55, 0.3);
  color->AddRGBPoint(150, 1.0, 0.55, 0.3);
  color->AddRGBPoint(190, 0.6, 0.8, 1.0);
  color->AddRGBPoint(255, 0.6, 0.8, 1.0);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetAmbient(0.15);
  property->SetDiffuse(0.85);
}
}

int RunIlluminationScene(const std::string& name, int argc, char* argv[])
{
  const int n = 64;
  vtkNew<vtkScattererTemplateVolumeMapper> mapper;
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.5);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.2);
  scatterer_examples::AddVolume(renderer, mapper, property);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.5 * n, 0.5 * n, 0.5 * n);
  camera->SetPosition(2.2 * n, -0.9 * n, 1.4 * n);
  camera->SetViewUp(0, 0, 1);
  vtkSmartPointer<vtkImageData> image;
  auto keyLight = DirectionalLight(1.0, 0.4, 0.8, 1, 1, 1);

  if (name == "occlusion" || name == "cropping" || name == "persample")
  {
    image = MakeShellBallPlate(n, VTK_UNSIGNED_CHAR);
    ApplyShellBallPlateProperty(property);
    mapper->ColorBleedingEnabledOff();
    renderer->AddLight(keyLight);
    if (name == "cropping")
    {
      mapper->CroppingOn();
      mapper->SetCroppingRegionPlanes(0, 0.75 * n, 0, n, 0, 0.6 * n);
      mapper->SetCroppingRegionFlagsToSubVolume();
    }
    if (name == "persample")
    {
      mapper->SetIlluminationModeToPerSample();
      mapper->SetIlluminationInterval(1);
    }
  }
  else if (name == "bleeding" || name == "boundary" || name == "twolights")
  {
    image = MakeShellBallPlate(n, VTK_UNSIGNED_CHAR);
    ApplyTwoMaterialProperty(property);
    if (name == "boundary")
    {
      // Explicit materials with very different refractive indices.
      mapper->AddScalarRangeMaterial(70, 130, 1.0, 1.0, 0.55, 0.3);
      mapper->AddScalarRangeMaterial(170, 255, 2.5, 0.6, 0.8, 1.0);
      mapper->ColorBleedingEnabledOff();
    }
    if (name == "twolights")
    {
      renderer->AddLight(DirectionalLight(1.0, -0.2, 0.3, 1.0, 0.35, 0.3));
      renderer->AddLight(DirectionalLight(-0.3, -1.0, 0.4, 0.3, 0.45, 1.0));
    }
    else
    {
      renderer->AddLight(keyLight);
    }
  }
  else if (name == "thin")
  {
    image = MakeThinPlateBehindBlock(n);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0, 0.0);
    opacity->AddPoint(60, 0.0);
    opacity->AddPoint(100, 0.9);
    opacity->AddPoint(255, 0.95);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0, 1, 1, 1);
    color->AddRGBPoint(255, 1, 1, 1);
    property->SetScalarOpacity(opacity);
    property->SetColor(color);
    property->SetAmbient(0.1);
    property->SetDiffuse(0.9);
    renderer->AddLight(DirectionalLight(1.0, 0.0, 0.0, 1, 1, 1));
    camera->SetPosition(-1.2 * n, -1.0 * n, 1.0 * n);
  }
  else if (name == "labelmap")
  {
    image = MakeLabelMap(n);
    vtkNew<vtkPiecewiseFunction> opacity;
    vtkNew<vtkColorTransferFunction> color;
    const double colors[4][3] = { { 0, 0, 0 }, { 0.9, 0.7, 0.6 }, { 0.3, 0.5, 1.0 },
      { 0.9, 0.9, 0.3 } };
    const double alphas[4] = { 0.0, 0.05, 0.9, 0.9 };
    for (int l = 0; l < 4; ++l)
    {
      opacity->AddPoint(l - 0.49, alphas[l]);
      opacity->AddPoint(l + 0.49, alphas[l]);
      color->AddRGBPoint(l - 0.49, colors[l][0], colors[l][1], colors[l][2]);
      color->AddRGBPoint(l + 0.49, colors[l][0], colors[l][1], colors[l][2]);
      if (l > 0)
      {
        mapper->AddLabelMaterial(l, 1.3 + 0.1 * l, colors[l][0], colors[l][1], colors[l][2]);
      }
    }
    property->SetScalarOpacity(opacity);
    property->SetColor(color);
    property->SetInterpolationTypeToNearest();
    renderer->AddLight(keyLight);
  }
  else if (name == "cthead")
  {
    std::string error;
    image = vtkScattererVolumeReader::ReadVolume(scatterer_examples::CtHeadPath(), &error);
    if (!image)
    {
      std::cerr << error << "\nPrepare the CT head with: bash scripts/prepare-data.sh\n";
      return 1;
    }
    // The benchmark scene's transfer functions (where the examples define them) and light.
    scatterer_examples::ApplyTransferPoints(
      scatterer_examples::CtHeadTransferPoints(), 0.0, 1.0, property);
    property->SetAmbient(0.1);
    property->SetDiffuse(0.9);
    property->SetInterpolationTypeToLinear();
    mapper->SetSampleDistance(1.0);
    auto light = DirectionalLight(222, 435, 319, 1, 1, 1);
    light->SetFocalPoint(122, 135, 75);
    renderer->AddLight(light);
    camera->SetPosition(-96, 572, 252);
    camera->SetFocalPoint(122, 135, 75);
    camera->SetViewUp(0, 0, 1);
    camera->SetViewAngle(30);
  }
  else
  {
    std::cerr << "unknown illumination scene '" << name << "'\n";
    return 1;
  }
  mapper->SetInputData(image);
  renderer->ResetCameraClippingRange();
  window->Render();
  const std::string features = mapper->GetLastShaderFeatures();
  std::cout << name << ": " << features << "\n";
  if (features.rfind("stock", 0) == 0)
  {
    std::cerr << name << ": the mapper fell back to stock rendering (" << features << ")\n";
    return 1;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? 1 : 0;
}
}
