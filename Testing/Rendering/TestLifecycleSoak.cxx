// Lifecycle soak (bounded, well under a minute): 500 frames with parameter
// changes, window resizes, ReleaseGraphicsResources, and the volume handed to
// the stock mapper and back. Process memory must not grow beyond a stated
// bound, no replacement may be left on the volume while the stock mapper draws
// it, and the last picture must equal a fresh mapper's picture.
#include "ScattererRenderHarness.h"
#include "ScattererShaderInstaller.h"
#include "ScattererTestVolumes.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <fstream>
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
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
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
