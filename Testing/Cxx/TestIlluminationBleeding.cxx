// Baseline-image test of scatterer-template illumination: the "bleeding" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationBleeding(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("bleeding", argc, argv);
}
