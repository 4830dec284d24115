// Baseline-image test of scatterer-template illumination: the "occlusion" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationOcclusion(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("occlusion", argc, argv);
}
