// Small synthetic scenes for the illumination baseline tests, one per effect
// the mapper simulates. Each builds a volume, a property, lights and a camera,
// renders through vtkScattererTemplateVolumeMapper at 200x200 and compares
// with Testing/Data/Baseline/<TestName>.png (vtkRegressionTestImage).
#ifndef ScattererIlluminationScenes_h
#define ScattererIlluminationScenes_h

#include <string>

class vtkRenderWindow;

namespace scatterer_testing
{
/**
 * Renders scene @p name ("occlusion", "bleeding", "boundary", "thin",
 * "labelmap", "twolights", "cropping", "persample", "cthead") and runs the
 * baseline comparison. Returns 0 on success (for a VTK test main).
 */
int RunIlluminationScene(const std::string& name, int argc, char* argv[]);
}

#endif
