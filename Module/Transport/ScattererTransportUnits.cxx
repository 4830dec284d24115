#include "ScattererTransportUnits.h"

#include "ScattererTransportGrid.h" // for VoxelLengths

#include <algorithm>
#include <cmath>

namespace scatterer_gpu
{
double TransportLengthUnit(const vtkScattererTransportVolume::Inputs& in)
{
  if (!in.Volume && in.Parts.empty())
  {
    return 1.0;
  }
  int dims[3];
  in.GetGridSourceDims(dims);
  double lengths[3];
  VoxelLengths(dims, in.TexToWorld, lengths);
  double logVoxel = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    logVoxel += std::log2(lengths[a]) / 3.0;
  }
  return std::isfinite(logVoxel) ? std::exp2(std::round(logVoxel)) : 1.0;
}

void ToTransportUnits(vtkScattererTransportVolume::Inputs& in, double unit)
{
  if (unit == 1.0)
  {
    return;
  }
  const double perUnit = 1.0 / unit;
  for (int i = 0; i < 12; ++i) // the rows of x, y and z, translation included
  {
    in.TexToWorld[i] *= perUnit;
  }
  for (size_t p = 3; p < in.ClipPlanes.size(); p += 4) // n.x + d >= 0: d per unit
  {
    in.ClipPlanes[p] = static_cast<float>(in.ClipPlanes[p] * perUnit);
  }
  for (auto& light : in.Lights)
  {
    for (float& x : light.Position)
    {
      x = static_cast<float>(x * perUnit);
    }
    light.Attenuation[1] = static_cast<float>(light.Attenuation[1] * unit);
    light.Attenuation[2] = static_cast<float>(light.Attenuation[2] * unit * unit);
  }
  for (size_t k = 0; k + 3 < in.Kernels.size(); k += 4)
  {
    for (size_t c = 0; c < 3; ++c)
    {
      in.Kernels[k + c] = static_cast<float>(in.Kernels[k + c] * perUnit);
    }
  }
  for (size_t e = 3; e < in.Medium.size(); e += 4) // sigma_t per unit
  {
    in.Medium[e] = static_cast<float>(in.Medium[e] * unit);
  }
}
}
