#include "ScattererInProcessRender.h"

#include "Common/ScattererMapperSetup.h"
#include "ScattererRenderHarness.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

namespace scatterer_testing
{
std::vector<unsigned char> RenderRgb(vtkImageData* image, const SceneSetup& setup, int size)
{
  // The render harness's one window for the whole program (opening X connections one
  // after another under Xvfb sometimes fails), off screen here; setting it again is a
  // no-op, and it is set before the first frame.
  vtkRenderWindow* window = SharedWindow();
  window->OffScreenRenderingOn();
  window->SetSize(size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkScattererTemplateVolumeMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vtkVolumeProperty> property;
  scatterer_examples::AddVolume(renderer, mapper, property);
  setup(property, renderer, mapper);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  auto* pixels =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  std::vector<unsigned char> rgb(
    pixels->GetPointer(0), pixels->GetPointer(0) + pixels->GetNumberOfValues());
  mapper->ReleaseGraphicsResources(window);
  window->RemoveRenderer(renderer);
  return rgb;
}
}
