// Accuracy regression: on a small shell + plate scene the mapper's defaults (the light
// transport volume) must stay clearly closer to the Monte Carlo reference
// (Reference, rendered here, deterministic by seed) than stock Phong shading,
// in RMSE and SSIM after the least-squares exposure normalisation of Metrics.h. The
// plate shadows the shell from the light, a directional one and a point light: Phong
// has no shadows, so a transport that lost them (a broken sweep, no occlusion) fails
// here. The shell + plate scenes do not guard the multiple-scattering term (without it
// the transport is even closer on them); dense, nearly white labels do. Under the light
// kit (five camera lights) it also guards where the mapper places each light and that it
// adds them up.
#include "Common/ScattererMapperSetup.h"
#include "ScattererReferenceScene.h"
#include "ScattererRenderHarness.h"
#include "scatterer_reference/Metrics.h"
#include "scatterer_reference/PathTracer.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
constexpr int kGrid = 48; // the shell-plate scene on a 48^3 grid (spacing ~2)
constexpr int kSize = 64; // image width and height
// Reference samples per pixel: about 6 s on one core, RMS standard error 3e-4, about 1/25
// of stock Phong's RMSE here (errors add in quadrature: it moves the RMSEs by ~1e-5).
constexpr int kSpp = 1024;

// Renders the scene with `mapper` in the shared window at kSize^2 and returns linear
// RGB in [0, 1], bottom row first (as the reference).
std::vector<float> RenderGpu(
  const scatterer_reference_vtk::VtkScene& scene, vtkGPUVolumeRayCastMapper* mapper, bool shade)
{
  mapper->SetInputData(scene.Image);
  mapper->SetBlendModeToComposite();
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(scene.SampleDistance);
  mapper->SetImageSampleDistance(1.0);
  mapper->UseJitteringOff();
  vtkNew<vtkVolumeProperty> property;
  property->DeepCopy(scene.Property);
  property->SetShade(shade);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  scatterer_examples::AddVolume(renderer, mapper, property);
  scatterer_reference_vtk::ApplySceneView(scene, renderer);

  vtkRenderWindow* window = scatterer_testing::SharedWindow();
  const int oldSize[2] = { window->GetSize()[0], window->GetSize()[1] };
  window->SetSize(kSize, kSize);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  // A still frame (not an interactive one with a coarser transport volume).
  window->SetDesiredUpdateRate(0.0001);
  const auto rgba = scatterer_testing::RenderAndGrab(window);
  window->RemoveRenderer(renderer);
  mapper->ReleaseGraphicsResources(window);
  window->SetSize(oldSize[0], oldSize[1]);

  std::vector<float> rgb;
  rgb.reserve(rgba.size() / 4 * 3);
  for (size_t p = 0; p + 3 < rgba.size(); p += 4)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgb.push_back(rgba[p + c] / 255.0f);
    }
  }
  return rgb;
}

struct Reference
{
  std::vector<float> Rgb;
  double RmsStandardError = 0.0;
  double Peak = 0.0;
};

Reference RenderReference(const scatterer_reference_vtk::VtkScene& scene)
{
  scatterer_reference::PathTracer tracer(
    scatterer_reference_vtk::Convert(scene.Image, scene.Property, scene.Renderer, kSize, kSize));
  scatterer_reference::RenderSettings settings;
  settings.samplesPerPixel = kSpp;
  settings.seed = 1;
  // The image depends on the seed only, not on the threads; this machine has two cores.
  settings.threads = 2;
  const auto result = tracer.render(settings);
  std::printf("reference: %d spp in %.1f s, RMS standard error %.3g, mean luminance %.3g\n",
    result.samplesPerPixel, result.seconds, result.rmsStandardError, result.meanLuminance);
  Reference r;
  r.Rgb = result.rgb;
  r.RmsStandardError = result.rmsStandardError;
  for (float v : r.Rgb)
  {
    r.Peak = std::max(r.Peak, static_cast<double>(v));
  }
  return r;
}

// The defaults against stock Phong on @p scene, both against the reference.
void ExpectDefaultsBeatStockPhong(
  const scatterer_reference_vtk::VtkScene& scene, double maxRmseRatio = 0.7)
{
  const Reference reference = RenderReference(scene);
  ASSERT_GT(reference.Peak, 0.0) << "the reference is black";

  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  const auto phong = RenderGpu(scene, stock, true);
  vtkNew<vtkScattererTemplateVolumeMapper> mapper; // defaults: TRANSPORT
  const auto transport = RenderGpu(scene, mapper, false);
  EXPECT_EQ(mapper->GetLastShaderFeatures().rfind("transport", 0), 0u)
    << mapper->GetLastShaderFeatures();

  const auto mp = scatterer_reference::compare(phong, reference.Rgb, kSize, kSize);
  const auto mt = scatterer_reference::compare(transport, reference.Rgb, kSize, kSize);
  std::printf(
    "stock Phong:       RMSE %.5f  SSIM %.4f  (exposure %.3g)\n", mp.rmse, mp.ssim, mp.scale);
  std::printf(
    "transport default: RMSE %.5f  SSIM %.4f  (exposure %.3g)\n", mt.rmse, mt.ssim, mt.scale);
  std::printf("RMSE ratio %.3f, reference noise / Phong RMSE %.3f\n", mt.rmse / mp.rmse,
    reference.RmsStandardError / mp.rmse);

  // The reference's noise must not decide the outcome: its RMS standard error stays
  // below a third of the RMSE margin asked for (0.3 x Phong's RMSE).
  EXPECT_LT(reference.RmsStandardError, 0.1 * mp.rmse) << "reference too noisy for this margin";
  // Measured (llvmpipe, 2026-12-06, evening): transport 0.54 x Phong's RMSE, SSIM 0.985
  // vs 0.940 (0.49 x before the lines' steps followed their own path, 0.58 x before
  // texels held the light entering them). With OcclusionStrength 0 the
  // transport was 1.24 x Phong (SSIM 0.929), with a sweep that does not carry the light
  // from slice to slice 1.30 x (0.929): 0.7 holds with room and fails on a lighting that
  // lost the plate's shadow. (MultipleScattering 0: 0.45 x.) Under the point light: 0.48
  // x, SSIM 0.988 vs 0.951; a positional sweep that does not carry the light from slice
  // to slice measured 1.20 x (0.940). Under the light kit: below.
  EXPECT_LE(mt.rmse, maxRmseRatio * mp.rmse) << "the transport is not clearly closer than Phong";
  EXPECT_GT(mt.ssim, mp.ssim) << "the transport is not structurally closer than Phong";
}
}

TEST(TransportAccuracy, DefaultsBeatStockPhongOnShellPlate)
{
  scatterer_reference_vtk::VtkScene scene;
  scatterer_reference_vtk::MakeHardScene(scene, kGrid);
  ExpectDefaultsBeatStockPhong(scene);
}

// The same scene lit by a point light behind the plate: a positional light's sweep
// (its own direction per texel, away from its slice) against the reference.
TEST(TransportAccuracy, DefaultsBeatStockPhongUnderAPointLight)
{
  scatterer_reference_vtk::VtkScene scene;
  scatterer_reference_vtk::MakeHardPointLightScene(scene, kGrid);
  ExpectDefaultsBeatStockPhong(scene);
}

// The same scene under ParaView's default lighting, vtkLightKit's five lights that follow
// the camera (key, fill, head and two back lights, coloured by their warmth): every light
// placed where the renderer puts it, swept and added up, against the reference lit the
// same way (Convert, ScattererReferenceScene).
TEST(TransportAccuracy, DefaultsBeatStockPhongUnderTheLightKit)
{
  scatterer_reference_vtk::VtkScene scene;
  scatterer_reference_vtk::MakeHardScene(scene, kGrid);
  scatterer_reference_vtk::ApplyLightKit(scene.Renderer);
  // The view rolled so that the key light (50 degrees above the view direction) comes
  // from -x, as the scene's own light does: through the plate onto the shell.
  scene.Renderer->GetActiveCamera()->SetViewUp(-1.0, 0.0, 0.3);
  // Measured (llvmpipe): 0.81 x Phong's RMSE, SSIM 0.990 vs 0.983 (0.85 x before the dim
  // lights were swept on a coarser grid, 0.83 x before the lines' steps followed their
  // own path; the head and fill
  // lights light what the camera sees, as Phong does). Camera lights taken in the
  // camera's frame instead of the world's (the lights' untransformed positions):
  // 1.47 x, SSIM 0.971. Without the roll the key light misses the plate and that bug
  // measured 0.90 x against 0.86 x.
  ExpectDefaultsBeatStockPhong(scene, 0.9);
}

// Dense, nearly white labels (the accuracy benchmark's dense-ball, 64^3): there most of
// the light is scattered more than once, so this guards the multiple-scattering term
// that the shell + plate scenes do not.
TEST(TransportAccuracy, DefaultsBeatStockPhongOnDenseLabels)
{
  scatterer_reference_vtk::VtkScene scene;
  scatterer_reference_vtk::MakeDenseScene(scene);
  // Measured (llvmpipe, 2026-12-06; the reference about 11 s on two cores, its noise
  // 0.064 of Phong's RMSE): 0.65 x Phong's RMSE, SSIM 0.952 vs 0.894 (0.67 x before the
  // lines' steps followed their own path, 0.74 x before texels held the light entering
  // them). With the multiple scattering's source lost (pass 3a writing 0) 0.82 x, while
  // the three tests above still pass; the margin 0.75 lies between.
  ExpectDefaultsBeatStockPhong(scene, 0.75);
}
