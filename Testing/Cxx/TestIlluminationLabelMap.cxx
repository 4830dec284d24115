// Baseline-image test of scatterer-template illumination: the "labelmap" scene
// (see Testing/Common/ScattererIlluminationScenes.cxx).
#include "ScattererIlluminationScenes.h"

int TestIlluminationLabelMap(int argc, char* argv[])
{
  return scatterer_testing::RunIlluminationScene("labelmap", argc, argv);
}
