#include "ScattererOcclusionField.h"

#include "vtkDataArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSMPTools.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace scatterer_scene
{
namespace
{
constexpr int kTableSize = 4096;
}

scatterer::OcclusionField BuildOcclusionField(vtkDataArray* scalars, const int dims[3],
  const double range[2], vtkVolumeProperty* property, const MaterialSet& materials)
{
  scatterer::OcclusionField field;
  for (int a = 0; a < 3; ++a)
  {
    field.dims[a] = dims[a];
  }
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2];
  field.extinction.assign(static_cast<size_t>(n), 0.0f);
  field.material.assign(static_cast<size_t>(n), -1);
  if (scalars->GetNumberOfTuples() < n)
  {
    return field;
  }

  // Extinction per table entry: sigma = -ln(1 - alpha) / unit distance.
  std::vector<double> alpha(kTableSize);
  const double lo = range[0], hi = range[1] > range[0] ? range[1] : range[0] + 1.0;
  property->GetScalarOpacity(0)->GetTable(lo, hi, kTableSize, alpha.data());
  const double unit = std::max(property->GetScalarOpacityUnitDistance(0), 1e-12);
  std::vector<float> sigma(kTableSize);
  for (int i = 0; i < kTableSize; ++i)
  {
    const double a = std::min(std::max(alpha[i], 0.0), 0.999999);
    sigma[i] = static_cast<float>(-std::log1p(-a) / unit);
  }
  std::vector<std::pair<double, double>> ranges;
  for (const auto& m : materials.Materials)
  {
    ranges.emplace_back(m.Physics.selector.lo, m.Physics.selector.hi);
    if (m.Physics.selector.kind == scatterer::Selector::Kind::Label)
    {
      ranges.back() = { m.Physics.selector.label - 0.5, m.Physics.selector.label + 0.5 };
    }
  }
  const double toTable = (kTableSize - 1) / (hi - lo);
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
    {
      const double v = scalars->GetComponent(id, 0);
      if (!std::isfinite(v))
      {
        continue;
      }
      const int t = static_cast<int>(std::lround(std::min(std::max((v - lo) * toTable, 0.0),
        static_cast<double>(kTableSize - 1))));
      field.extinction[id] = sigma[t];
      if (sigma[t] > 0.0f)
      {
        for (size_t m = 0; m < ranges.size(); ++m)
        {
          if (v >= ranges[m].first && v <= ranges[m].second)
          {
            field.material[id] = static_cast<std::int8_t>(m);
            break;
          }
        }
      }
    }
  });
  return field;
}

Unassigned CountUnassigned(vtkDataArray* scalars, const scatterer::OcclusionField& field)
{
  Unassigned result;
  for (size_t id = 0; id < field.material.size(); ++id)
  {
    if (field.material[id] < 0 && field.extinction[id] > 0.0f)
    {
      if (result.Count++ == 0)
      {
        result.Example = scalars->GetComponent(static_cast<vtkIdType>(id), 0);
      }
    }
  }
  return result;
}
}
