// The viewer's text: a status strip below the picture and a help box over it.
// The strip is its own renderer under the volume's viewport, so the status never
// covers the volume and stays readable whatever the volume shows; the help box,
// shown on request, sits on an opaque dark panel.
#ifndef ScattererViewerOverlay_h
#define ScattererViewerOverlay_h

#include "vtkNew.h"
#include "vtkRenderer.h"  // for vtkNew<vtkRenderer> (the strip)
#include "vtkTextActor.h" // for vtkNew<vtkTextActor> (status and help)

#include <string>

class vtkRenderWindow;

namespace scatterer_viewer
{
class ViewerOverlay
{
public:
  /** Adds the strip's renderer to @p window and the help box to @p volumeRenderer. */
  void Attach(vtkRenderWindow* window, vtkRenderer* volumeRenderer, const std::string& help);

  /** Sizes the strip for the window's size (call on resize): font, height, viewports. */
  void Layout();

  void SetStatus(const std::string& text);
  void ToggleHelp();
  bool HelpVisible() const;

  /** The volume's viewport in pixels (what the ray caster covers). */
  void GetVolumeViewportSize(int size[2]) const;

  /** Lines the status holds; the strip is sized for them. */
  static constexpr int StatusLines = 2;

private:
  vtkRenderWindow* Window = nullptr;
  vtkRenderer* VolumeRenderer = nullptr;
  vtkNew<vtkRenderer> Strip;
  vtkNew<vtkTextActor> Status;
  vtkNew<vtkTextActor> Help;
  int LaidOutFor[2] = { -1, -1 };
};
}

#endif
