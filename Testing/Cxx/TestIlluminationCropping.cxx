// Baseline-image test of scatterer-template illumination: the "cropping" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationCropping(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("cropping", argc, argv);
}
