#include "ScattererViewerTransfer.h"

#include <algorithm>
#include <cstdio>

namespace scatterer_viewer
{
ViewerTransfer::ViewerTransfer(vtkImageData* image, vtkVolumeProperty* property)
  : Histogram(image)
  , Property(property)
{
}

bool ViewerTransfer::Select(const std::string& name, std::string& why)
{
  scatterer_examples::TransferPoints points;
  if (!scatterer_examples::MakeTransferPreset(name, this->Histogram, points, why))
  {
    return false;
  }
  this->Points = points;
  this->Reset();
  return true;
}

void ViewerTransfer::Next()
{
  const auto& names = scatterer_examples::TransferPresetNames();
  const auto at = std::find(names.begin(), names.end(), this->Points.Name);
  const size_t next =
    at == names.end() ? 0 : (static_cast<size_t>(at - names.begin()) + 1) % names.size();
  std::string unused;
  this->Select(names[next], unused);
}

void ViewerTransfer::Shift(double fraction)
{
  this->Offset += fraction * (this->Histogram.Maximum() - this->Histogram.Minimum());
  this->Apply();
}

void ViewerTransfer::Scale(double factor)
{
  this->Width = std::clamp(this->Width * factor, MinimumScale, MaximumScale);
  this->Apply();
}

void ViewerTransfer::Reset()
{
  this->Offset = 0.0;
  this->Width = 1.0;
  this->Apply();
}

std::string ViewerTransfer::Describe() const
{
  char text[128];
  std::snprintf(text, sizeof(text), "%s  level %+.4g  window x%.2f", this->Points.Name.c_str(),
    this->Offset, this->Width);
  return text;
}

void ViewerTransfer::Apply()
{
  scatterer_examples::ApplyTransferPoints(this->Points, this->Offset, this->Width, this->Property);
}
}
