// Baseline-image test: the synthetic shell/ball/plate volume through
// vtkScattererTemplateVolumeMapper at 200x200 with VTK's headlight.
#include "Common/ScattererMapperSetup.h"
#include "ScattererTestVolumes.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkVolumeProperty.h"

int TestScattererMapperShellBallPlate(int argc, char* argv[])
{
  const int dims = 64;
  auto image = scatterer_testing::MakeShellBallPlate(dims, VTK_UNSIGNED_CHAR);
  vtkNew<vtkScattererTemplateVolumeMapper> mapper;
  mapper->SetInputData(image);
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.5);
  vtkNew<vtkVolumeProperty> property;
  scatterer_testing::ApplyShellBallPlateProperty(property);
  vtkNew<vtkRenderer> renderer;
  scatterer_examples::AddVolume(renderer, mapper, property);
  renderer->SetBackground(0.1, 0.1, 0.2);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.5 * dims, 0.5 * dims, 0.5 * dims);
  camera->SetPosition(2.2 * dims, -0.9 * dims, 1.4 * dims);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();
  window->Render();

  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? 1 : 0;
}
