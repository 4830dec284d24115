// Baseline-image test of scatterer-template illumination: the "persample" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationPerSample(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("persample", argc, argv);
}
