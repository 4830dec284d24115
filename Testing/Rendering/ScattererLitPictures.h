// The pictures the input-kind tests compare (TestLitInputKinds, TestLitMultiVolume): the
// stock mapper's, then ours with illumination off, on, and on again (a second frame).
#ifndef ScattererLitPictures_h
#define ScattererLitPictures_h

#include "ScattererRenderHarness.h"

#include "vtkRenderWindow.h"
#include "vtkScattererTemplateVolumeMapper.h"

#include <string>
#include <vector>

namespace scatterer_testing
{
struct LitPictures
{
  std::vector<unsigned char> Stock, Off, Lit, LitAgain;
  std::string Features; ///< the lit frames' GetLastShaderFeatures()
};

/** Renders @p window with illumination off, on, and on again, into @p out. */
inline void RenderOffAndLit(
  vtkRenderWindow* window, vtkScattererTemplateVolumeMapper* mapper, LitPictures& out)
{
  mapper->IlluminationEnabledOff();
  out.Off = RenderAndGrab(window);
  mapper->IlluminationEnabledOn();
  out.Lit = RenderAndGrab(window);
  out.LitAgain = RenderAndGrab(window);
  out.Features = mapper->GetLastShaderFeatures();
}
}

#endif
