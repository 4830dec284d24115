#include "ScattererScreenshot.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkWindowToImageFilter.h"

namespace scatterer_examples
{
vtkSmartPointer<vtkImageData> GrabWindow(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(grab->GetOutput());
  return image;
}

bool WriteImagePng(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  return writer->GetErrorCode() == 0;
}

bool WriteWindowPng(vtkRenderWindow* window, const std::string& path)
{
  return WriteImagePng(GrabWindow(window), path);
}
}
