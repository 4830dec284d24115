// Renders one volume in this process (off screen, no multisampling) and hands back
// the pixels, for the tests that judge a whole picture made with the examples'
// scenes (Examples/Common).
#ifndef ScattererInProcessRender_h
#define ScattererInProcessRender_h

#include <functional>
#include <vector>

class vtkImageData;
class vtkRenderer;
class vtkScattererTemplateVolumeMapper;
class vtkVolumeProperty;

namespace scatterer_testing
{
/** What a test sets up before the one frame: transfer functions, camera, light, mapper. */
using SceneSetup =
  std::function<void(vtkVolumeProperty*, vtkRenderer*, vtkScattererTemplateVolumeMapper*)>;

/** RGB pixels (3 bytes each) of one frame of @p image at @p size x @p size. */
std::vector<unsigned char> RenderRgb(vtkImageData* image, const SceneSetup& setup, int size = 160);
}

#endif
