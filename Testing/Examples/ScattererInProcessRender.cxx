#include "ScattererInProcessRender.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

namespace scatterer_testing
{
namespace
{
// One window for the whole program: opening X connections one after another under
// Xvfb sometimes fails ("bad X server connection", and VTK aborts).
vtkRenderWindow* SharedWindow()
{
  static vtkSmartPointer<vtkRenderWindow> window = [] {
    auto w = vtkSmartPointer<vtkRenderWindow>::New();
    w->SetMultiSamples(0);
    w->OffScreenRenderingOn();
    return w;
  }();
  return window;
}
}

std::vector<unsigned char> RenderRgb(vtkImageData* image, const SceneSetup& setup, int size)
{
  vtkRenderWindow* window = SharedWindow();
  window->SetSize(size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkScattererTemplateVolumeMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  setup(property, renderer, mapper);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  std::vector<unsigned char> rgb(pixels->GetPointer(0), pixels->GetPointer(0) + pixels->GetNumberOfValues());
  mapper->ReleaseGraphicsResources(window);
  window->RemoveRenderer(renderer);
  return rgb;
}
}
