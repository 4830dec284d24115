// Baseline-image test of scatterer-template illumination: the "boundary" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationBoundary(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("boundary", argc, argv);
}
