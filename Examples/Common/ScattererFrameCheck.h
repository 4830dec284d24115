// Checks on what a render produced, so that scatterer-render (and scatterer-viewer
// with --output) never hand back a frame that VTK reported an error for, or a blank
// frame of a volume that has something to show, with exit status 0.
#ifndef ScattererFrameCheck_h
#define ScattererFrameCheck_h

#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;
class vtkOutputWindow;
class vtkRenderer;
class vtkVolumeProperty;

namespace scatterer_examples
{
/**
 * Counts the errors VTK reports while it is alive. It installs an output window that
 * counts every error message and prints it as VTK's own would, and puts the previous
 * output window back when destroyed. The output window is where every vtkErrorMacro
 * without an ErrorEvent observer ends up, whichever object raised it (the mapper's
 * internal textures and shader programs included, which observers on the render
 * window, renderer and mapper would miss).
 */
class VtkErrorCounter
{
public:
  VtkErrorCounter();
  ~VtkErrorCounter();
  VtkErrorCounter(const VtkErrorCounter&) = delete;
  VtkErrorCounter& operator=(const VtkErrorCounter&) = delete;

  int Count() const;
  /** The first error's message, without VTK's "ERROR: In file, line" prefix. */
  std::string First() const;

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkSmartPointer<vtkOutputWindow> Counter;
};

/**
 * Whether the volume has something to show: the scalar opacity of @p property (first
 * component) is above 0 somewhere in @p range, the data's finite value range. A
 * blank frame of such a volume is a failure; of a volume without, it is the picture.
 */
bool OpacityVisibleOver(vtkVolumeProperty* property, const double range[2]);

/** True when every pixel of @p frame (RGB or RGBA, 8 bits) is the renderer's background. */
bool IsBlank(vtkImageData* frame, vtkRenderer* renderer);
}

#endif
