#include "ScattererFrameCheck.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace scatterer_examples
{
namespace
{
/** Counts error messages and otherwise behaves as VTK's default output window. */
class ErrorCountingOutputWindow : public vtkOutputWindow
{
public:
  static ErrorCountingOutputWindow* New();
  vtkTypeMacro(ErrorCountingOutputWindow, vtkOutputWindow);

  int Errors = 0;
  std::string FirstError;

  void DisplayErrorText(const char* text) override
  {
    if (this->Errors++ == 0)
    {
      this->FirstError = Shorten(text ? text : "");
    }
    this->Superclass::DisplayErrorText(text);
  }

private:
  /**
   * "ERROR: In /path/vtkX.cxx, line 12\nvtkX (0x55..): what\n\n" -> "vtkX: what": the
   * source line and address mean nothing to a user of the program.
   */
  static std::string Shorten(std::string text)
  {
    if (text.rfind("ERROR: In ", 0) == 0)
    {
      const auto newline = text.find('\n');
      text = newline == std::string::npos ? std::string() : text.substr(newline + 1);
    }
    const auto address = text.find(" (0x");
    const auto close = address == std::string::npos ? address : text.find("): ", address);
    if (close != std::string::npos)
    {
      text.erase(address, close + 1 - address);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    return text;
  }
};
vtkStandardNewMacro(ErrorCountingOutputWindow);
}

VtkErrorCounter::VtkErrorCounter()
  : Previous(vtkOutputWindow::GetInstance())
  , Counter(vtkSmartPointer<ErrorCountingOutputWindow>::New())
{
  this->Counter->SetDisplayMode(this->Previous->GetDisplayMode());
  vtkOutputWindow::SetInstance(this->Counter);
}

VtkErrorCounter::~VtkErrorCounter()
{
  vtkOutputWindow::SetInstance(this->Previous);
}

int VtkErrorCounter::Count() const
{
  return static_cast<ErrorCountingOutputWindow*>(this->Counter.Get())->Errors;
}

std::string VtkErrorCounter::First() const
{
  return static_cast<ErrorCountingOutputWindow*>(this->Counter.Get())->FirstError;
}

bool OpacityVisibleOver(vtkVolumeProperty* property, const double range[2])
{
  vtkPiecewiseFunction* opacity = property ? property->GetScalarOpacity(0) : nullptr;
  if (!opacity)
  {
    return false;
  }
  // Piecewise (linear or with midpoint/sharpness, which stay between the two node
  // values): the largest value over [lo, hi] is at an end or at a node inside.
  double largest = std::max(opacity->GetValue(range[0]), opacity->GetValue(range[1]));
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double node[4];
    opacity->GetNodeValue(i, node);
    if (node[0] >= range[0] && node[0] <= range[1])
    {
      largest = std::max(largest, node[1]);
    }
  }
  return largest > 0.0;
}

bool IsBlank(vtkImageData* frame, vtkRenderer* renderer)
{
  auto* pixels =
    frame ? vtkUnsignedCharArray::SafeDownCast(frame->GetPointData()->GetScalars()) : nullptr;
  if (!pixels || pixels->GetNumberOfComponents() < 3)
  {
    return true;
  }
  double background[3];
  renderer->GetBackground(background);
  int expected[3];
  for (int c = 0; c < 3; ++c)
  {
    expected[c] = static_cast<int>(std::lround(255.0 * std::clamp(background[c], 0.0, 1.0)));
  }
  const int components = pixels->GetNumberOfComponents();
  const vtkIdType count = pixels->GetNumberOfTuples();
  const unsigned char* p = pixels->GetPointer(0);
  for (vtkIdType i = 0; i < count; ++i, p += components)
  {
    for (int c = 0; c < 3; ++c)
    {
      // 1 of 255 for the rounding of the background colour to 8 bits.
      if (std::abs(static_cast<int>(p[c]) - expected[c]) > 1)
      {
        return false;
      }
    }
  }
  return true;
}
}
