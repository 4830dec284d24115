#include "ScattererViewerOverlay.h"

#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

#include <algorithm>
#include <cmath>

namespace scatterer_viewer
{
void ViewerOverlay::Attach(
  vtkRenderWindow* window, vtkRenderer* volumeRenderer, const std::string& help)
{
  this->Window = window;
  this->VolumeRenderer = volumeRenderer;
  this->Strip->SetBackground(0.12, 0.12, 0.14);
  this->Strip->InteractiveOff(); // the camera keys and drags belong to the volume's renderer
  this->Strip->AddActor2D(this->Status);
  this->Status->GetTextProperty()->SetColor(0.95, 0.95, 0.85);
  this->Status->GetTextProperty()->SetFontFamilyToCourier();
  window->AddRenderer(this->Strip);

  // Help: light text on an opaque dark panel, top left of the picture.
  vtkTextProperty* text = this->Help->GetTextProperty();
  text->SetColor(0.85, 0.93, 1.0);
  text->SetBackgroundColor(0.05, 0.05, 0.08);
  text->SetBackgroundOpacity(0.85);
  text->SetFrame(true);
  text->SetFrameColor(0.4, 0.45, 0.55);
  text->SetFontFamilyToCourier();
  text->SetVerticalJustificationToTop();
  this->Help->SetInput(help.c_str());
  this->Help->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Help->GetPositionCoordinate()->SetValue(0.02, 0.98);
  this->Help->SetVisibility(false);
  volumeRenderer->AddActor2D(this->Help);
  this->Layout();
}

void ViewerOverlay::Layout()
{
  const int* size = this->Window->GetSize();
  if (size[0] == this->LaidOutFor[0] && size[1] == this->LaidOutFor[1])
  {
    return;
  }
  this->LaidOutFor[0] = size[0];
  this->LaidOutFor[1] = size[1];
  // Monospace at 11 px fits the status's 46 columns into 300 px; larger windows get
  // up to 16 px.
  const int font = std::clamp(size[0] / 28, 11, 16);
  this->Status->GetTextProperty()->SetFontSize(font);
  this->Help->GetTextProperty()->SetFontSize(font);
  const int stripPixels = StatusLines * static_cast<int>(std::ceil(1.5 * font)) + 8;
  const double split = std::min(0.5, static_cast<double>(stripPixels) / std::max(size[1], 1));
  this->Strip->SetViewport(0.0, 0.0, 1.0, split);
  this->VolumeRenderer->SetViewport(0.0, split, 1.0, 1.0);
  this->Status->SetDisplayPosition(6, 4);
}

void ViewerOverlay::SetStatus(const std::string& text)
{
  this->Status->SetInput(text.c_str());
}

void ViewerOverlay::ToggleHelp()
{
  this->Help->SetVisibility(!this->Help->GetVisibility());
}

bool ViewerOverlay::HelpVisible() const
{
  return this->Help->GetVisibility() != 0;
}

void ViewerOverlay::GetVolumeViewportSize(int size[2]) const
{
  const int* window = this->Window->GetSize();
  const double* viewport = this->VolumeRenderer->GetViewport();
  size[0] = static_cast<int>(std::lround((viewport[2] - viewport[0]) * window[0]));
  size[1] = static_cast<int>(std::lround((viewport[3] - viewport[1]) * window[1]));
}
}
