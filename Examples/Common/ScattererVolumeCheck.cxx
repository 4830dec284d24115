#include "ScattererVolumeCheck.h"

#include "ScattererRenderOptions.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <cmath>

namespace scatterer_examples
{
namespace
{
std::string Triple(const double v[3])
{
  return "(" + FormatNumber(v[0]) + ", " + FormatNumber(v[1]) + ", " + FormatNumber(v[2]) + ")";
}
}

bool FiniteScalarRange(vtkImageData* image, double range[2])
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars || scalars->GetNumberOfTuples() == 0)
  {
    return false;
  }
  double r[2];
  scalars->GetFiniteRange(r, 0);
  // With no finite value VTK leaves the range empty (lo > hi: VTK_DOUBLE_MAX,
  // VTK_DOUBLE_MIN or the float equivalents); test for that rather than for a
  // particular sentinel.
  if (!(std::isfinite(r[0]) && std::isfinite(r[1]) && r[0] <= r[1]))
  {
    return false;
  }
  range[0] = r[0];
  range[1] = r[1];
  return true;
}

std::string CheckVolume(vtkImageData* image, const std::string& path, bool autoScene)
{
  const std::string refused = "refusing volume '" + path + "': ";
  if (!image || !image->GetPointData()->GetScalars())
  {
    return refused + "it has no voxel values (point scalars), so there is nothing to draw.";
  }

  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    return refused + "it has " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
      std::to_string(dims[2]) +
      " points; the ray caster needs at least 2 along each axis (a single voxel, row or "
      "slice has no thickness to march through and draws nothing).";
  }

  // These hold for any vtkImageData, read from a file or not; the reader also refuses
  // them (with its precision limits), so for files this is a second line of defence.
  double spacing[3];
  image->GetSpacing(spacing);
  for (const double s : spacing)
  {
    if (!std::isfinite(s) || s <= 0.0)
    {
      return refused + "its spacing is " + Triple(spacing) +
        "; each spacing must be a finite number > 0 (NaN or infinity places no voxel, zero "
        "collapses the volume to nothing, and a negative spacing would mirror an axis, which "
        "vtkImageData and the ray caster do not support; a flip belongs in the orientation).";
    }
  }
  double origin[3];
  image->GetOrigin(origin);
  double bounds[6];
  image->GetBounds(bounds);
  bool finite = true;
  for (const double v : origin)
  {
    finite = finite && std::isfinite(v);
  }
  for (const double v : bounds)
  {
    finite = finite && std::isfinite(v);
  }
  if (!finite)
  {
    return refused + "its origin is " + Triple(origin) +
      " and its bounds are not all finite numbers, so there is no place to draw it.";
  }

  double range[2];
  if (!FiniteScalarRange(image, range))
  {
    return refused + "none of its " + std::to_string(image->GetNumberOfPoints()) +
      " voxel values is a finite number (all NaN or infinite), so no value can be mapped to "
      "colour and opacity.";
  }
  if (autoScene && range[0] == range[1])
  {
    return refused + "every finite voxel value is " + FormatNumber(range[0]) +
      "; the automatic transfer function ramps opacity over the range of values, and a "
      "constant volume has none, so nothing would show.";
  }
  return std::string();
}
}
