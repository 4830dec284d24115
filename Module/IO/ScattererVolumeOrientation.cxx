#include "ScattererVolumeOrientation.h"

#include <cmath>
#include <sstream>

namespace scatterer_io
{
namespace
{
double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

const char* AxisName(int c)
{
  static const char* const names[3] = { "i", "j", "k" };
  return names[c];
}
}

std::string PlaceInPatientSpace(const double matrix[16], const double origin[3],
  const double spacing[3], PatientFrame frame, VolumePlacement* placement)
{
  // RAS -> LPS negates x and y (NIfTI-1 nifti1.h vs DICOM PS3.3 C.7.6.2.1.1).
  const double sign[3] = { frame == PatientFrame::RAS ? -1.0 : 1.0,
    frame == PatientFrame::RAS ? -1.0 : 1.0, 1.0 };
  for (const double* m = matrix; m != matrix + 16; ++m)
  {
    if (!std::isfinite(*m))
    {
      return "its orientation matrix holds a value that is not a number.";
    }
  }
  // Columns of the 3x3 part: where one step along i, j, k of the data coordinates goes.
  double axis[3][3];
  double length[3];
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      axis[c][r] = sign[r] * matrix[4 * r + c];
    }
    length[c] = std::sqrt(Dot(axis[c], axis[c]));
    if (!(length[c] > 1e-12))
    {
      return std::string("its orientation matrix gives the ") + AxisName(c) +
        " axis no direction (a zero column).";
    }
    for (double& v : axis[c])
    {
      v /= length[c];
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    for (int b = a + 1; b < 3; ++b)
    {
      const double cosine = Dot(axis[a], axis[b]);
      if (std::fabs(cosine) > kMaxAxisCosine)
      {
        std::ostringstream why;
        why << "its orientation matrix is sheared: the " << AxisName(a) << " and " << AxisName(b)
            << " axes meet at " << std::acos(cosine) * 180.0 / std::acos(-1.0)
            << " degrees, and a rotation (with or without a reflection) cannot place such a "
               "grid without distorting it; resample the volume onto a rectangular grid first.";
        return why.str();
      }
    }
  }
  // Gram-Schmidt removes the rounding of float headers; k keeps the file's handedness.
  const double ixj[3] = { axis[0][1] * axis[1][2] - axis[0][2] * axis[1][1],
    axis[0][2] * axis[1][0] - axis[0][0] * axis[1][2],
    axis[0][0] * axis[1][1] - axis[0][1] * axis[1][0] };
  const double handedness = Dot(axis[2], ixj) < 0 ? -1.0 : 1.0;
  double i[3] = { axis[0][0], axis[0][1], axis[0][2] };
  double j[3] = { axis[1][0], axis[1][1], axis[1][2] };
  const double ij = Dot(i, j);
  for (int r = 0; r < 3; ++r)
  {
    j[r] -= ij * i[r];
  }
  const double jl = std::sqrt(Dot(j, j));
  for (double& v : j)
  {
    v /= jl;
  }
  const double k[3] = { handedness * (i[1] * j[2] - i[2] * j[1]),
    handedness * (i[2] * j[0] - i[0] * j[2]), handedness * (i[0] * j[1] - i[1] * j[0]) };

  VolumePlacement result;
  for (int r = 0; r < 3; ++r)
  {
    result.Direction[3 * r + 0] = i[r];
    result.Direction[3 * r + 1] = j[r];
    result.Direction[3 * r + 2] = k[r];
    // world = M3 (o + s .* idx) + t, so the new origin is M3 o + t.
    double o = sign[r] * matrix[4 * r + 3];
    for (int c = 0; c < 3; ++c)
    {
      o += sign[r] * matrix[4 * r + c] * origin[c];
    }
    result.Origin[r] = o;
    result.Spacing[r] = spacing[r] * length[r];
  }
  for (int r = 0; r < 3; ++r)
  {
    if (!std::isfinite(result.Origin[r]) || !std::isfinite(result.Spacing[r]))
    {
      return "its orientation matrix places the volume at a point that is not a number.";
    }
  }
  *placement = result;
  return {};
}
}
