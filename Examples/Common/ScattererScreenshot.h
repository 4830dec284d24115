// Writes what a render window shows to a PNG (the back buffer, as rendered).
#ifndef ScattererScreenshot_h
#define ScattererScreenshot_h

#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;
class vtkRenderWindow;

namespace scatterer_examples
{
/** The window's back buffer as an 8-bit RGB image (what WriteWindowPng writes). */
vtkSmartPointer<vtkImageData> GrabWindow(vtkRenderWindow* window);

/** False if the file cannot be written. */
bool WriteImagePng(vtkImageData* image, const std::string& path);

/** GrabWindow, then WriteImagePng. */
bool WriteWindowPng(vtkRenderWindow* window, const std::string& path);
}

#endif
