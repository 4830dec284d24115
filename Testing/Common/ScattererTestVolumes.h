// Small synthetic volumes for rendering tests (real data is for examples and
// benchmarks). Every volume is built in memory, so the tests need no files.
#ifndef ScattererTestVolumes_h
#define ScattererTestVolumes_h

#include "vtkSmartPointer.h"

#include <functional>

class vtkColorTransferFunction;
class vtkGPUVolumeRayCastMapper;
class vtkImageData;
class vtkPiecewiseFunction;
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

/**
 * A dims^3 mask split at x = @p cut: binary (255 up to the cut, 0 beyond), or with
 * @p labels a label map (label 1 up to the cut, 2 beyond).
 */
vtkSmartPointer<vtkImageData> MakeMaskBeyond(int dims, double cut, bool labels);

/**
 * @p labels (MakeMaskBeyond with labels) as @p mapper's label-map mask: label 1 drawn
 * with @p color and @p opacity, label 2 transparent.
 */
void HideLabelTwo(vtkGPUVolumeRayCastMapper* mapper, vtkVolumeProperty* property,
  vtkImageData* labels, vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity);
}

#endif
