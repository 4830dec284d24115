// Makes the mapper a --mode asks for and applies the illumination options, so
// scatterer-render and the benchmarks configure it the same way.
#ifndef ScattererMapperSetup_h
#define ScattererMapperSetup_h

#include "ScattererRenderOptions.h"

#include "vtkSmartPointer.h"

#include <string>

class vtkGPUVolumeRayCastMapper;

namespace scatterer_examples
{
/** stock/phong: vtkOpenGLGPUVolumeRayCastMapper; template: ours, configured. */
vtkSmartPointer<vtkGPUVolumeRayCastMapper> MakeMapper(const RenderOptions& options);

/** The quality settings of a template mapper ("" for the stock mapper). */
std::string DescribeSettings(vtkGPUVolumeRayCastMapper* mapper);
}

#endif
