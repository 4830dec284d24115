// Makes the mapper a --mode asks for and applies the illumination options, so
// scatterer-render and the benchmarks configure it the same way; puts a mapper's
// volume into a renderer.
#ifndef ScattererMapperSetup_h
#define ScattererMapperSetup_h

#include "ScattererRenderOptions.h"

#include "vtkSmartPointer.h"

#include <string>

class vtkAbstractVolumeMapper;
class vtkGPUVolumeRayCastMapper;
class vtkRenderer;
class vtkVolume;
class vtkVolumeProperty;

namespace scatterer_examples
{
/** stock/phong: vtkOpenGLGPUVolumeRayCastMapper; template: ours, configured. */
vtkSmartPointer<vtkGPUVolumeRayCastMapper> MakeMapper(const RenderOptions& options);

/** The quality settings of a template mapper ("" for the stock mapper). */
std::string DescribeSettings(vtkGPUVolumeRayCastMapper* mapper);

/**
 * Adds a volume of @p mapper and @p property to @p renderer and returns it (the
 * renderer holds it): the set-up of the examples, the benchmarks and the rendering tests.
 */
vtkVolume* AddVolume(
  vtkRenderer* renderer, vtkAbstractVolumeMapper* mapper, vtkVolumeProperty* property);
}

#endif
