// Lifecycle soak (bounded, well under a minute): 500 frames with parameter
// changes, window resizes, ReleaseGraphicsResources, and the volume handed to
// the stock mapper and back. Process memory must not grow beyond a stated
// bound, no replacement may be left on the volume while the stock mapper draws
// it, and the last picture must equal a fresh mapper's picture.
#include "Common/ScattererMapperSetup.h"
#include "ScattererProgramBudget.h"
#include "ScattererRenderHarness.h"
#include "ScattererShaderInstaller.h"
#include "ScattererTestVolumes.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <random>
#include <vector>
#include <unistd.h>

namespace
{
// Resident memory of this process in MiB (Linux /proc).
double ResidentMiB()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Allowed growth between frame 100 and frame 500. A leak of one template
// texture (a few KiB) or cache (24^3 RGBA8 = 54 KiB) per frame over 400
// frames would exceed it; allocator and driver noise stays well below.
constexpr double kGrowthBoundMiB = 16.0;
}

TEST(LifecycleSoak, FiveHundredFramesStayBoundedAndCorrect)
{
  auto image = scatterer_testing::MakeShellBallPlate(24, VTK_UNSIGNED_CHAR);
  vtkNew<vtkVolumeProperty> property;
  scatterer_testing::ApplyShellBallPlateProperty(property);
  vtkNew<vtkScattererTemplateVolumeMapper> mapper;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> stock;
  for (vtkGPUVolumeRayCastMapper* m : { static_cast<vtkGPUVolumeRayCastMapper*>(mapper),
         static_cast<vtkGPUVolumeRayCastMapper*>(stock) })
  {
    m->SetInputData(image);
    m->AutoAdjustSampleDistancesOff();
    m->SetSampleDistance(1.0);
  }
  vtkNew<vtkRenderer> renderer;
  vtkVolume* volume = scatterer_examples::AddVolume(renderer, mapper, property);
  renderer->AutomaticLightCreationOff();
  scatterer_testing::AddSceneLight(renderer, 1, 0.5, 0.8);
  renderer->GetActiveCamera()->SetPosition(60, -25, 40);
  renderer->GetActiveCamera()->SetFocalPoint(12, 12, 12);
  vtkRenderWindow* window = scatterer_testing::SharedWindow();
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);

  double memoryAt100 = 0.0;
  int leftoversWhileStock = 0;
  for (int frame = 0; frame < 500; ++frame)
  {
    mapper->SetOcclusionStrength(0.5 + 0.1 * (frame % 10));
    mapper->SetPhotonCap(8 + frame % 17);
    if (frame % 25 == 0)
    {
      window->SetSize(64 + (frame / 25) % 3 * 16, 64 + (frame / 25) % 2 * 16);
    }
    if (frame % 50 == 10)
    {
      mapper->ReleaseGraphicsResources(window);
    }
    if (frame % 100 == 50)
    {
      volume->SetMapper(stock);
      leftoversWhileStock += scatterer_shader::CountIlluminationLeftovers(volume);
      window->Render();
      volume->SetMapper(mapper);
    }
    if (frame % 125 == 60)
    {
      mapper->SetIlluminationMode(frame % 250 == 60 ? vtkScattererTemplateVolumeMapper::PER_SAMPLE
                                                    : vtkScattererTemplateVolumeMapper::TRANSPORT);
    }
    window->Render();
    if (frame == 100)
    {
      memoryAt100 = ResidentMiB();
    }
  }
  const double growth = ResidentMiB() - memoryAt100;
  std::cout << "resident memory growth over frames 100..500: " << growth << " MiB\n";
  EXPECT_LT(growth, kGrowthBoundMiB);
  EXPECT_EQ(leftoversWhileStock, 0);
  EXPECT_EQ(mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos);

  // The final picture equals a fresh mapper's with the same settings.
  window->SetSize(96, 96);
  mapper->SetOcclusionStrength(1.0);
  mapper->SetPhotonCap(24);
  mapper->SetIlluminationModeToTransport();
  const auto soaked = scatterer_testing::RenderAndGrab(window);
  vtkNew<vtkScattererTemplateVolumeMapper> fresh;
  fresh->SetInputData(image);
  fresh->AutoAdjustSampleDistancesOff();
  fresh->SetSampleDistance(1.0);
  volume->SetMapper(fresh);
  const auto reference = scatterer_testing::RenderAndGrab(window);
  EXPECT_EQ(scatterer_testing::MaxDifference(soaked, reference), 0);
  window->RemoveRenderer(renderer);
  window->SetSize(160, 160);
}

// Long interactive use: 4 renderers and 8 volumes for 1,000 frames; every frame,
// two volumes get random effects, illumination mode, shading and materials (1-4)
// and one renderer random lights (1-4, some positional). Each such change can ask
// for another illumination program; the texts do not depend on the light and
// material counts, and a window keeps only the most recently used programs
// compiled (ScattererProgramBudget), so resident memory after frame 200 must grow
// by at most kGrowthBoundMiB. Released programs compile again when used: the
// last picture equals the first one rendered with the same settings.
TEST(LifecycleSoak, RandomTogglesOnEightVolumesStayBounded)
{
  auto image = scatterer_testing::MakeShellBallPlate(16, VTK_UNSIGNED_CHAR);
  vtkRenderWindow* window = scatterer_testing::SharedWindow();
  window->GetRenderers()->RemoveAllItems();
  window->SetSize(128, 128);
  std::vector<vtkSmartPointer<vtkRenderer>> renderers;
  std::vector<vtkSmartPointer<vtkScattererTemplateVolumeMapper>> mappers;
  std::vector<vtkSmartPointer<vtkVolumeProperty>> properties;
  for (int r = 0; r < 4; ++r)
  {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetViewport(0.5 * (r % 2), 0.5 * (r / 2), 0.5 * (r % 2) + 0.5, 0.5 * (r / 2) + 0.5);
    renderer->AutomaticLightCreationOff();
    for (int v = 0; v < 2; ++v)
    {
      auto mapper = vtkSmartPointer<vtkScattererTemplateVolumeMapper>::New();
      mapper->SetInputData(image);
      mapper->AutoAdjustSampleDistancesOff();
      mapper->SetSampleDistance(1.0);
      mapper->SetTemplatesPerMaterial(2);
      auto property = vtkSmartPointer<vtkVolumeProperty>::New();
      scatterer_testing::ApplyShellBallPlateProperty(property);
      scatterer_examples::AddVolume(renderer, mapper, property)->SetPosition(20.0 * v, 0.0, 0.0);
      mappers.push_back(mapper);
      properties.push_back(property);
    }
    window->AddRenderer(renderer);
    renderers.push_back(renderer);
  }

  std::mt19937 random(13);
  auto coin = [&random]() { return (random() & 1u) != 0; };
  auto setLights = [](vtkRenderer* renderer, int count, bool positional)
  {
    renderer->RemoveAllLights();
    for (int l = 0; l < count; ++l)
    {
      vtkLight* light = scatterer_testing::AddSceneLight(renderer, 1.0 - 0.3 * l, 0.5, 0.8);
      if (l == 0 && positional)
      {
        light->PositionalOn();
        light->SetPosition(8.0, 8.0, 40.0);
      }
    }
  };
  auto setVolume = [&](size_t i, int materials, bool lit, bool transport, bool shade,
                     const std::array<bool, 6>& switches)
  {
    vtkScattererTemplateVolumeMapper* m = mappers[i];
    m->RemoveAllMaterials();
    for (int k = 0; k < materials; ++k)
    {
      m->AddScalarRangeMaterial(256.0 * k / materials, 256.0 * (k + 1) / materials - 0.5,
        1.2 + 0.1 * k, 1.0, 0.5 + 0.1 * k, 0.4 + 0.1 * (k % 2));
    }
    properties[i]->SetShade(shade);
    m->SetIlluminationEnabled(lit);
    m->SetIlluminationMode(transport ? vtkScattererTemplateVolumeMapper::TRANSPORT
                                     : vtkScattererTemplateVolumeMapper::PER_SAMPLE);
    m->SetShadowsEnabled(switches[0]);
    m->SetColorBleedingEnabled(switches[1]);
    m->SetThinPartCheckEnabled(switches[2]);
    m->SetBoundaryRefractionEnabled(switches[3]);
    m->SetTemplateBlendingEnabled(switches[4]);
    m->SetShaderPathSelection(switches[5] ? vtkScattererTemplateVolumeMapper::AUTOMATIC
                                          : vtkScattererTemplateVolumeMapper::AS_REQUESTED);
  };
  auto setFirstScene = [&]()
  {
    for (size_t r = 0; r < renderers.size(); ++r)
    {
      setLights(renderers[r], 1 + static_cast<int>(r) % 2, r == 3);
    }
    for (size_t i = 0; i < mappers.size(); ++i)
    {
      // Unshaded: with Phong the picture keeps a trace of earlier frames (a few
      // pixels off by up to 47 levels; docs/hard-cases.md), which this test is not about.
      setVolume(i, 1 + static_cast<int>(i) % 3, true, i % 2 == 0, false,
        { true, true, true, true, false, true });
    }
  };
  setFirstScene();
  for (auto& renderer : renderers)
  {
    renderer->ResetCamera();
  }
  const auto first = scatterer_testing::RenderAndGrab(window);

  double memoryAt200 = 0.0;
  for (int frame = 0; frame < 1000; ++frame)
  {
    setLights(renderers[random() % renderers.size()], 1 + static_cast<int>(random() % 4), coin());
    for (int changed = 0; changed < 2; ++changed)
    {
      const size_t i = random() % mappers.size();
      const int materials = 1 + static_cast<int>(random() % 4);
      const bool lit = random() % 4 != 0;
      const bool transport = coin();
      const bool shade = coin();
      setVolume(
        i, materials, lit, transport, shade, { coin(), coin(), coin(), coin(), coin(), coin() });
    }
    window->Render();
    if (frame == 200)
    {
      memoryAt200 = ResidentMiB();
    }
    if (frame % 100 == 0)
    {
      std::cout << "frame " << frame << ": " << ResidentMiB() << " MiB\n";
    }
  }
  const double growth = ResidentMiB() - memoryAt200;
  std::cout << "resident memory growth over frames 200..1000: " << growth << " MiB\n";
  EXPECT_LT(growth, kGrowthBoundMiB);
  EXPECT_LE(scatterer_shader::CountCompiledIlluminationPrograms(
              vtkOpenGLRenderWindow::SafeDownCast(window)),
    scatterer_shader::kCompiledProgramsPerWindow);

  setFirstScene();
  const auto last = scatterer_testing::RenderAndGrab(window);
  EXPECT_EQ(scatterer_testing::TakeGLError(), 0u);
  EXPECT_EQ(scatterer_testing::MaxDifference(first, last), 0);

  for (auto& m : mappers)
  {
    EXPECT_EQ(m->GetLastShaderFeatures().rfind("stock", 0), std::string::npos)
      << m->GetLastShaderFeatures();
  }
  for (auto& renderer : renderers)
  {
    window->RemoveRenderer(renderer);
  }
  window->SetSize(160, 160);
}
