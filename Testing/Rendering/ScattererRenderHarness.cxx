#include "ScattererRenderHarness.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkAbstractMapper.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace scatterer_testing
{
vtkRenderWindow* SharedWindow()
{
  static vtkNew<vtkRenderWindow> window;
  static bool ready = false;
  if (!ready)
  {
    window->SetSize(160, 160);
    window->SetMultiSamples(0);
    ready = true;
  }
  return window;
}

std::vector<unsigned char> RenderAndGrab(vtkRenderWindow* window)
{
  window->Render();
  const int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels);
  const unsigned char* p = pixels->GetPointer(0);
  return std::vector<unsigned char>(p, p + pixels->GetNumberOfValues());
}

std::vector<unsigned char> RenderSceneOnce(vtkRenderer* renderer, vtkAbstractMapper* mapper)
{
  vtkRenderWindow* window = SharedWindow();
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  std::vector<unsigned char> pixels = RenderAndGrab(window);
  window->RemoveRenderer(renderer);
  mapper->ReleaseGraphicsResources(window);
  return pixels;
}

vtkLight* AddSceneLight(
  vtkRenderer* renderer, double px, double py, double pz, double fx, double fy, double fz)
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetPosition(px, py, pz);
  light->SetFocalPoint(fx, fy, fz);
  renderer->AddLight(light);
  return light;
}

unsigned int TakeGLError()
{
  unsigned int first = 0;
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
  {
    first = first ? first : e;
  }
  return first;
}

int MaxDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  int worst = a.size() == b.size() ? 0 : 256;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  }
  return worst;
}

void SavePng(const std::string& path, const std::vector<unsigned char>& rgba, int w, int h)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  std::copy(rgba.begin(), rgba.end(), static_cast<unsigned char*>(image->GetScalarPointer()));
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}

ImageDifference CompareRgb(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
  int levels, const std::vector<bool>* include)
{
  ImageDifference d;
  if (a.size() != b.size() || (include && include->size() != a.size() / 4))
  {
    d.Worst = 256;
    return d;
  }
  double sum = 0.0;
  size_t over = 0;
  for (size_t p = 0; p < a.size() / 4; ++p)
  {
    if (include && !(*include)[p])
    {
      continue;
    }
    int worst = 0;
    for (int c = 0; c < 3; ++c)
    {
      const int v = std::abs(int(a[4 * p + c]) - int(b[4 * p + c]));
      sum += v;
      worst = std::max(worst, v);
    }
    over += worst > levels;
    d.Worst = std::max(d.Worst, worst);
    ++d.Pixels;
  }
  if (d.Pixels > 0)
  {
    d.Mean = sum / (3.0 * d.Pixels);
    d.FractionOver = static_cast<double>(over) / d.Pixels;
  }
  return d;
}

void LightAndViewBallAbovePlate(vtkRenderer* renderer, int n)
{
  renderer->AutomaticLightCreationOff();
  AddSceneLight(renderer, 0.35, 0.0, 1.0);
  vtkCamera* camera = renderer->GetActiveCamera();
  const double c = 0.5 * (n - 1);
  camera->SetFocalPoint(c, c, 14);
  camera->SetPosition(c - 40, c - 110, 90);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();
}

Equivalence CompareWays(const char* what, const std::vector<unsigned char>& litA,
  const std::vector<unsigned char>& litB, const std::vector<unsigned char>& stockA,
  const std::vector<unsigned char>& stockB)
{
  Equivalence e;
  e.Lit = CompareRgb(litA, litB, 16);
  e.Stock = CompareRgb(stockA, stockB, 16);
  e.Illumination = CompareRgb(litA, stockA, 16);
  std::printf("%s: lit mean %.3f, %.2f%% over 16 levels; stock mean %.3f, %.2f%%; lit vs stock "
              "mean %.2f\n",
    what, e.Lit.Mean, 100.0 * e.Lit.FractionOver, e.Stock.Mean, 100.0 * e.Stock.FractionOver,
    e.Illumination.Mean);
  return e;
}

double MeanBrightness(const std::vector<unsigned char>& image)
{
  double sum = 0;
  for (size_t i = 0; i + 3 < image.size(); i += 4)
  {
    sum += image[i] + image[i + 1] + image[i + 2];
  }
  return image.empty() ? 0.0 : sum / (image.size() / 4 * 3);
}

EventCounter::EventCounter(vtkObject* object, unsigned long event)
{
  this->Command->SetClientData(this);
  this->Command->SetCallback(
    [](vtkObject*, unsigned long, void* client, void* call)
    {
      auto* self = static_cast<EventCounter*>(client);
      ++self->Count;
      self->Last = call ? static_cast<const char*>(call) : "";
    });
  object->AddObserver(event, this->Command);
}
}
