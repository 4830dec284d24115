// Small synthetic volumes for rendering tests (real data is for examples and
// benchmarks). Every volume is built in memory, so the tests need no files.
#ifndef ScattererTestVolumes_h
#define ScattererTestVolumes_h

#include "vtkSmartPointer.h"

#include <functional>

class vtkImageData;
class vtkVolumeProperty;

namespace scatterer_testing
{
/**
 * A dims^3 volume of the given VTK scalar type (VTK_UNSIGNED_CHAR, VTK_SHORT,
 * VTK_UNSIGNED_SHORT, VTK_FLOAT, ...) holding a hollow shell (value 100), a
 * dense ball inside it off centre (value 200) and a thin plate (value 150)
 * beside them, on a background of 0. Values are the same for every type.
 * With @p inverted every value v becomes 250 - v (for minimum-intensity tests).
 */
vtkSmartPointer<vtkImageData> MakeShellBallPlate(int dims, int scalarType, bool inverted = false);

/** Transfer functions for MakeShellBallPlate: translucent shell, opaque ball, plate. */
void ApplyShellBallPlateProperty(vtkVolumeProperty* property);

/** Component c of voxel (i, j, k), 0..255. */
using ComponentFill = std::function<unsigned char(int i, int j, int k, int c)>;

/** A dims^3 unsigned-char volume of @p components components filled by @p fill. */
vtkSmartPointer<vtkImageData> MakeComponentVolume(
  int dims, int components, const ComponentFill& fill);
}

#endif
