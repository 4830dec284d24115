// Writes what a render window shows to a PNG (the back buffer, as rendered).
#ifndef ScattererScreenshot_h
#define ScattererScreenshot_h

#include <string>

class vtkRenderWindow;

namespace scatterer_examples
{
/** False if the file cannot be written. */
bool WriteWindowPng(vtkRenderWindow* window, const std::string& path);
}

#endif
