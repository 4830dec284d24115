#include "ScattererReferenceScene.h"

#include "Common/ScattererCtHeadScene.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightKit.h"
#include "vtkMetaImageWriter.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkScattererVolumeReader.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataWriter.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace scatterer_reference_vtk
{
bool MakeCtHeadScene(VtkScene& scene, std::string* error)
{
  scene.Name = "ct-head";
  scene.Image = vtkScattererVolumeReader::ReadVolume(scatterer_examples::CtHeadPath(), error);
  if (!scene.Image)
  {
    return false;
  }
  scene.Property = vtkSmartPointer<vtkVolumeProperty>::New();
  scatterer_examples::ApplyCtHeadProperty(scene.Property);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scatterer_examples::ApplyCtHeadCamera(scene.Renderer);
  scatterer_examples::ApplyCtHeadLight(scene.Renderer);
  scene.SampleDistance = 0.5;
  return true;
}

bool MakeCtHeadLightKitScene(VtkScene& scene, std::string* error)
{
  if (!MakeCtHeadScene(scene, error))
  {
    return false;
  }
  scene.Name = "ct-head-light-kit";
  ApplyLightKit(scene.Renderer);
  return true;
}

void ApplyLightKit(vtkRenderer* renderer)
{
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  vtkNew<vtkLightKit> kit;
  kit->AddLightsToRenderer(renderer);
}

namespace
{
// The synthetic scenes' volume property: linear interpolation, ambient 0.1, diffuse 0.9,
// specular 0.2 of power 10 (for the configurations that shade), shading off.
void ApplySyntheticProperty(vtkVolumeProperty* property, vtkPiecewiseFunction* opacity,
  vtkColorTransferFunction* color, double opacityUnitDistance)
{
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(opacityUnitDistance);
  property->SetAmbient(0.1);
  property->SetDiffuse(0.9);
  property->SetSpecular(0.2);
  property->SetSpecularPower(10.0);
  property->ShadeOff();
}

// The synthetic scenes' renderer: a camera at @p position looking at @p focal (view up
// +z, view angle 30 degrees, clipping range 50 to @p farClip) and no lights.
vtkSmartPointer<vtkRenderer> SyntheticRenderer(
  const double position[3], const double focal[3], double farClip)
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetPosition(position[0], position[1], position[2]);
  cam->SetFocalPoint(focal[0], focal[1], focal[2]);
  cam->SetViewUp(0.0, 0.0, 1.0);
  cam->SetViewAngle(30.0);
  cam->SetClippingRange(50.0, farClip);
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  return renderer;
}

// One white scene light of intensity 1 at @p position toward @p focal: directional, or
// with @p positional a point light (no cone, no attenuation).
void AddWhiteSceneLight(
  vtkRenderer* renderer, const double position[3], const double focal[3], bool positional)
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(positional);
  if (positional)
  {
    light->SetConeAngle(180.0);
  }
  light->SetPosition(position[0], position[1], position[2]);
  light->SetFocalPoint(focal[0], focal[1], focal[2]);
  light->SetIntensity(1.0);
  light->SetDiffuseColor(1.0, 1.0, 1.0);
  renderer->AddLight(light);
}

const double kHardSceneCentre[3] = { 48.0, 48.0, 48.0 };
}

void MakeHardScene(VtkScene& scene, int n)
{
  n = std::max(n, 8);
  scene.Name = n == 96 ? "shell-plate" : "shell-plate-" + std::to_string(n);
  // The geometry is in world units over the box [0, 95]^3 whatever n is, so the camera,
  // the light and the physical thicknesses stay; a coarser grid just samples it more
  // sparsely (n = 96: spacing 1, the benchmark's scene exactly).
  const double h = 95.0 / (n - 1);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(h, h, h);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* s = static_cast<unsigned char*>(image->GetScalarPointer());
  const double c[3] = { 56.0, 48.0, 48.0 };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = i * h, y = j * h, z = k * h;
        const double r =
          std::sqrt((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) + (z - c[2]) * (z - c[2]));
        unsigned char v = 0;
        if (std::abs(r - 26.0) <= 1.5)
          v = 100; // thin shell, material A
        // thin plate (x in [14, 15]: 2 voxels at n = 96) between the light (toward +x, +z)
        // and the shell
        if (x >= 14.0 && x <= 15.0 && y >= 20.0 && y <= 76.0 && z >= 50.0 && z <= 90.0)
          v = 200; // material B
        s[(static_cast<size_t>(k) * n + j) * n + i] = v;
      }
  scene.Image = image;
  scene.Property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(50, 0.0);
  opacity->AddPoint(100, 0.35);
  opacity->AddPoint(150, 0.0);
  opacity->AddPoint(200, 0.9);
  opacity->AddPoint(255, 0.9);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.9, 0.3, 0.2);
  color->AddRGBPoint(100, 0.9, 0.3, 0.2);
  color->AddRGBPoint(150, 0.9, 0.9, 0.9);
  color->AddRGBPoint(255, 0.9, 0.9, 0.9);
  ApplySyntheticProperty(scene.Property, opacity, color, 1.0);
  const double camera[3] = { -40.0, -200.0, 110.0 };
  scene.Renderer = SyntheticRenderer(camera, kHardSceneCentre, 800.0);
  const double light[3] = { -100.0, 40.0, 120.0 }; // from -x (behind the plate) and above
  AddWhiteSceneLight(scene.Renderer, light, kHardSceneCentre, false);
  scene.SampleDistance = 0.5;
}

void MakeHardPointLightScene(VtkScene& scene, int n)
{
  MakeHardScene(scene, n);
  scene.Name =
    std::max(n, 8) == 96 ? "shell-plate-point" : "shell-plate-point-" + std::to_string(n);
  scene.Renderer->RemoveAllLights();
  // Outside the box, 35 units behind the plate and below its lower edge: the edge's
  // shadow crosses the top of the shell (z about 62 at its centre), its lines spread 2.2
  // times from the plate to there.
  const double light[3] = { -20.0, 48.0, 40.0 };
  AddWhiteSceneLight(scene.Renderer, light, kHardSceneCentre, true);
}

void MakeDenseScene(VtkScene& scene)
{
  // Two labels of a segmentation, as users colour them: opaque at the voxel scale and
  // nearly white, so that multiple scattering carries most of their light and a channel
  // of colour exactly 1 scatters without absorbing.
  const int n = 64;
  scene.Name = "dense-ball";
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* s = static_cast<unsigned char*>(image->GetScalarPointer());
  const double c[3] = { 28.0, 32.0, 30.0 };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double r =
          std::sqrt((i - c[0]) * (i - c[0]) + (j - c[1]) * (j - c[1]) + (k - c[2]) * (k - c[2]));
        unsigned char v = 0;
        if (r <= 18.0)
          v = 200; // the ball: ivory
        if (i >= 52 && i <= 57 && j >= 6 && j <= 58 && k >= 4 && k <= 56)
          v = 120; // a plate beside it: warm white, its red channel exactly 1
        s[(static_cast<size_t>(k) * n + j) * n + i] = v;
      }
  scene.Image = image;
  scene.Property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(60, 0.0);
  opacity->AddPoint(100, 0.5);
  opacity->AddPoint(255, 0.9);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1.0, 0.8, 0.6);
  color->AddRGBPoint(255, 1.0, 1.0, 1.0);
  ApplySyntheticProperty(scene.Property, opacity, color, 0.25);
  const double camera[3] = { 20.0, -110.0, 120.0 }, focal[3] = { 34.0, 32.0, 30.0 };
  scene.Renderer = SyntheticRenderer(camera, focal, 600.0);
  const double light[3] = { -60.0, -50.0, 110.0 }; // from the ball's side, above and in front
  AddWhiteSceneLight(scene.Renderer, light, focal, false);
  scene.SampleDistance = 0.5;
}

void ApplySceneView(const VtkScene& scene, vtkRenderer* renderer)
{
  renderer->GetActiveCamera()->DeepCopy(scene.Renderer->GetActiveCamera());
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  vtkLightCollection* lights = scene.Renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* l = lights->GetNextItem())
  {
    auto copy = vtkSmartPointer<vtkLight>::New();
    copy->DeepCopy(l);
    renderer->AddLight(copy);
  }
  renderer->SetTwoSidedLighting(scene.Renderer->GetTwoSidedLighting());
}

scatterer_reference::Scene Convert(vtkImageData* image, vtkVolumeProperty* property,
  vtkRenderer* renderer, int width, int height, int tableSize, double albedoScale)
{
  namespace sr = scatterer_reference;
  sr::Scene scene;
  sr::Volume& v = scene.volume;
  int dims[3];
  image->GetDimensions(dims);
  v.dims = glm::ivec3(dims[0], dims[1], dims[2]);
  double o[3], sp[3];
  image->GetOrigin(o);
  image->GetSpacing(sp);
  v.origin = glm::dvec3(o[0], o[1], o[2]);
  v.spacing = glm::dvec3(sp[0], sp[1], sp[2]);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const vtkIdType n = scalars->GetNumberOfTuples();
  v.scalars.resize(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
    v.scalars[static_cast<size_t>(i)] = static_cast<float>(scalars->GetComponent(i, 0));
  double range[2];
  scalars->GetRange(range, 0);
  v.table.scalarMin = range[0];
  v.table.scalarMax = range[1] > range[0] ? range[1] : range[0] + 1.0;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  vtkColorTransferFunction* color = property->GetRGBTransferFunction();
  const double u = property->GetScalarOpacityUnitDistance();
  tableSize = std::max(2, tableSize);
  for (int e = 0; e < tableSize; ++e)
  {
    const double s =
      v.table.scalarMin + (v.table.scalarMax - v.table.scalarMin) * e / (tableSize - 1);
    v.table.sigmaT.push_back(static_cast<float>(sr::sigmaFromOpacity(opacity->GetValue(s), u)));
    double rgb[3];
    color->GetColor(s, rgb);
    v.table.albedo.push_back(
      glm::clamp(glm::vec3(rgb[0], rgb[1], rgb[2]) * float(albedoScale), 0.0f, 1.0f));
  }
  vtkCamera* cam = renderer->GetActiveCamera();
  double p[3], f[3], up[3];
  cam->GetPosition(p);
  cam->GetFocalPoint(f);
  cam->GetViewUp(up);
  scene.camera.position = glm::dvec3(p[0], p[1], p[2]);
  scene.camera.focalPoint = glm::dvec3(f[0], f[1], f[2]);
  scene.camera.viewUp = glm::dvec3(up[0], up[1], up[2]);
  scene.camera.viewAngleDeg = cam->GetViewAngle();
  scene.camera.width = width;
  scene.camera.height = height;
  // Headlights and camera lights where the renderer puts them before a frame (camera
  // lights are given in the camera's frame): their transformed position and focal point.
  renderer->UpdateLightsGeometryToFollowCamera();
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* l = lights->GetNextItem())
  {
    if (!l->GetSwitch())
      continue;
    double lp[3], lf[3], dc[3];
    l->GetTransformedPosition(lp);
    l->GetTransformedFocalPoint(lf);
    l->GetDiffuseColor(dc);
    const glm::dvec3 colour = glm::dvec3(dc[0], dc[1], dc[2]) * l->GetIntensity();
    if (l->GetPositional())
    {
      double att[3];
      l->GetAttenuationValues(att);
      scene.pointLights.push_back({ glm::dvec3(lp[0], lp[1], lp[2]), colour, att[2] > 0.0 });
    }
    else
    {
      const glm::dvec3 to = glm::dvec3(lp[0] - lf[0], lp[1] - lf[1], lp[2] - lf[2]);
      if (glm::length(to) > 0.0)
        scene.directionalLights.push_back({ glm::normalize(to), colour });
    }
  }
  return scene;
}

vtkSmartPointer<vtkImageData> ToImageData(const scatterer_reference::RenderResult& r)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(r.width, r.height, 1);
  vtkNew<vtkFloatArray> rgb;
  rgb->SetName("Radiance");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(r.width) * r.height);
  std::copy(r.rgb.begin(), r.rgb.end(), rgb->GetPointer(0));
  vtkNew<vtkFloatArray> se;
  se->SetName("StandardError");
  se->SetNumberOfTuples(static_cast<vtkIdType>(r.width) * r.height);
  std::copy(r.standardError.begin(), r.standardError.end(), se->GetPointer(0));
  img->GetPointData()->SetScalars(rgb);
  img->GetPointData()->AddArray(se);
  return img;
}

static bool WriteRgb8(
  const std::vector<unsigned char>& px, int width, int height, const std::string& path)
{
  vtkNew<vtkImageData> img;
  img->SetDimensions(width, height, 1);
  img->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(px.begin(), px.end(), static_cast<unsigned char*>(img->GetScalarPointer()));
  vtkNew<vtkPNGWriter> w;
  w->SetInputData(img);
  w->SetFileName(path.c_str());
  w->Write();
  return w->GetErrorCode() == 0;
}

bool WritePng(
  const std::vector<float>& rgb, int width, int height, double exposure, const std::string& path)
{
  std::vector<unsigned char> px(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i)
    px[i] =
      static_cast<unsigned char>(std::lround(255.0 * std::clamp(exposure * rgb[i], 0.0, 1.0)));
  return WriteRgb8(px, width, height, path);
}

std::vector<unsigned char> HeatMapBytes(const std::vector<float>& map, double maxValue)
{
  std::vector<unsigned char> px(map.size() * 3);
  for (size_t i = 0; i < map.size(); ++i)
  {
    // black -> red -> yellow -> white heat map
    const double t = std::clamp(maxValue > 0 ? map[i] / maxValue : 0.0, 0.0, 1.0);
    px[3 * i] = static_cast<unsigned char>(std::lround(255 * std::min(1.0, 3 * t)));
    px[3 * i + 1] = static_cast<unsigned char>(std::lround(255 * std::clamp(3 * t - 1, 0.0, 1.0)));
    px[3 * i + 2] = static_cast<unsigned char>(std::lround(255 * std::clamp(3 * t - 2, 0.0, 1.0)));
  }
  return px;
}

bool WriteMapPng(
  const std::vector<float>& map, int width, int height, double maxValue, const std::string& path)
{
  return WriteRgb8(HeatMapBytes(map, maxValue), width, height, path);
}

double AutoExposure(const std::vector<float>& rgb)
{
  std::vector<float> l(rgb.size() / 3);
  for (size_t i = 0; i < l.size(); ++i)
    l[i] = static_cast<float>(
      scatterer_reference::luminance({ rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2] }));
  if (l.empty())
    return 1.0;
  const size_t k = static_cast<size_t>(0.995 * (l.size() - 1));
  std::nth_element(l.begin(), l.begin() + k, l.end());
  return l[k] > 0 ? 1.0 / l[k] : 1.0;
}

std::vector<float> ToFloatRgb(vtkImageData* image)
{
  vtkDataArray* a = image->GetPointData()->GetScalars();
  const vtkIdType n = a->GetNumberOfTuples();
  const int nc = a->GetNumberOfComponents();
  const double scale = a->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  std::vector<float> out(static_cast<size_t>(n) * 3);
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      out[3 * i + c] = static_cast<float>(scale * a->GetComponent(i, std::min(c, nc - 1)));
  return out;
}

bool WriteFloatImage(vtkImageData* image, const std::string& path)
{
  if (path.size() > 4 && path.substr(path.size() - 4) == ".mha")
  {
    vtkNew<vtkMetaImageWriter> w;
    w->SetInputData(image);
    w->SetFileName(path.c_str());
    w->SetCompression(false);
    w->Write();
    return w->GetErrorCode() == 0;
  }
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(image);
  w->SetFileName(path.c_str());
  return w->Write() == 1;
}

const char* const kNamedScenes =
  "ct-head, ct-head-light-kit, shell-plate, shell-plate-point or dense-ball";

bool IsCtHeadScene(const std::string& name)
{
  return name == "ct-head" || name == "ct-head-light-kit";
}

bool IsNamedScene(const std::string& name)
{
  return IsCtHeadScene(name) || name == "shell-plate" || name == "shell-plate-point" ||
    name == "dense-ball";
}

bool MakeNamedScene(const std::string& name, VtkScene& scene, std::string& error, int& exitCode)
{
  if (IsCtHeadScene(name))
  {
    if (!(name == "ct-head" ? MakeCtHeadScene(scene, &error)
                            : MakeCtHeadLightKitScene(scene, &error)))
    {
      error += "\nPrepare the CT head with: bash scripts/prepare-data.sh";
      exitCode = 1;
      return false;
    }
    return true;
  }
  if (name == "shell-plate")
  {
    MakeHardScene(scene);
    return true;
  }
  if (name == "shell-plate-point")
  {
    MakeHardPointLightScene(scene);
    return true;
  }
  if (name == "dense-ball")
  {
    MakeDenseScene(scene);
    return true;
  }
  error = "unknown scene '" + name + "' (" + kNamedScenes + ")";
  exitCode = 2;
  return false;
}
}
