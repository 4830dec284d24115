// Baseline-image test of scatterer-template illumination: the "cthead" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationCtHead(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("cthead", argc, argv);
}
