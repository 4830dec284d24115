// Baseline-image test of scatterer-template illumination: the "twolights" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationTwoColoredLights(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("twolights", argc, argv);
}
