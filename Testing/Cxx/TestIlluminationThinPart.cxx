// Baseline-image test of scatterer-template illumination: the "thin" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationThinPart(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("thin", argc, argv);
}
