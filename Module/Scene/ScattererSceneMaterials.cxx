#include "ScattererSceneMaterials.h"

#include "ScattererColourFunction.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <scatterer/Snell.h>

#include <algorithm>
#include <cmath>

namespace scatterer_scene
{
namespace
{
constexpr int kSamples = 2048;
constexpr double kVisible = 1e-4; // opacity below this is "nothing there"

// The template's opacity is the transfer function's opacity itself: the
// paper's 1 - T(d), with T the transfer function. The template radius (a world
// length the user sets) only scales where the photons land, so radius changes
// never regenerate templates and dense materials keep a useful photon spread.
double TemplateOpacity(double alphaUnit)
{
  return std::isfinite(alphaUnit) ? std::min(std::max(alphaUnit, 0.0), 1.0) : 1.0;
}

float Normalize(double value, const double range[2])
{
  const double span = range[1] - range[0];
  return static_cast<float>(span > 0 ? (value - range[0]) / span : 0.0);
}

SceneMaterial Make(double lo, double hi, double alphaUnit, double n, const double color[3],
  const double dataRange[2])
{
  SceneMaterial m;
  m.Physics.opacity = TemplateOpacity(alphaUnit);
  m.Physics.refractiveIndex = n;
  m.Physics.diffuse = glm::vec3(color[0], color[1], color[2]);
  m.Physics.selector = scatterer::Selector::range(lo, hi);
  m.OpacityPerUnit = alphaUnit;
  m.Range[0] = Normalize(lo, dataRange);
  m.Range[1] = Normalize(hi, dataRange);
  return m;
}
}

double MaxOpacity(vtkPiecewiseFunction* opacity, double lo, double hi)
{
  double best = std::max(opacity->GetValue(lo), opacity->GetValue(hi));
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double node[4];
    opacity->GetNodeValue(i, node);
    if (node[0] >= lo && node[0] <= hi)
    {
      best = std::max(best, node[1]);
    }
  }
  return best;
}

MaterialSet BuildMaterials(const std::vector<RequestedMaterial>& requested,
  vtkVolumeProperty* property, const double dataRange[2], const double derivationRange[2])
{
  MaterialSet set;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  if (!requested.empty())
  {
    for (const auto& r : requested)
    {
      if (static_cast<int>(set.Materials.size()) >= kMaxMaterials)
      {
        ++set.Dropped;
        continue;
      }
      const double lo = r.IsLabel ? r.Label - 0.5 : r.Lo;
      const double hi = r.IsLabel ? r.Label + 0.5 : r.Hi;
      auto m = Make(lo, hi, MaxOpacity(opacity, lo, hi), r.RefractiveIndex, r.Color, dataRange);
      if (r.IsLabel)
      {
        m.Physics.selector = scatterer::Selector::labelId(r.Label);
      }
      set.Materials.push_back(m);
    }
    return set;
  }

  // Derive: intervals of the derivation range where the opacity TF is visible.
  struct Interval
  {
    double Lo, Hi, MaxAlpha, Weight, WeightedScalar;
  };
  std::vector<Interval> intervals;
  const double step = (derivationRange[1] - derivationRange[0]) / (kSamples - 1);
  bool inside = false;
  for (int i = 0; i < kSamples; ++i)
  {
    const double s = derivationRange[0] + i * step;
    const double a = opacity->GetValue(s);
    if (a > kVisible)
    {
      if (!inside)
      {
        intervals.push_back({ s, s, 0.0, 0.0, 0.0 });
        inside = true;
      }
      Interval& cur = intervals.back();
      cur.Hi = s;
      cur.MaxAlpha = std::max(cur.MaxAlpha, a);
      cur.Weight += a;
      cur.WeightedScalar += a * s;
    }
    else
    {
      inside = false;
    }
  }
  if (static_cast<int>(intervals.size()) > kMaxMaterials)
  {
    // Keep the intervals that hold the most opacity; the rest stay unlit.
    std::vector<Interval> sorted = intervals;
    std::sort(sorted.begin(), sorted.end(),
      [](const Interval& a, const Interval& b) { return a.Weight > b.Weight; });
    const double cut = sorted[kMaxMaterials - 1].Weight;
    std::vector<Interval> kept;
    for (const auto& iv : intervals)
    {
      if (iv.Weight >= cut && static_cast<int>(kept.size()) < kMaxMaterials)
      {
        kept.push_back(iv);
      }
    }
    set.Dropped = static_cast<int>(intervals.size() - kept.size());
    intervals = kept;
  }
  vtkColorTransferFunction* colorTF = RayCasterColour(property, 0);
  for (size_t k = 0; k < intervals.size(); ++k)
  {
    const Interval& iv = intervals[k];
    // Half a sample of slack on both ends so the interval's own edges classify.
    const double lo = iv.Lo - 0.5 * step, hi = iv.Hi + 0.5 * step;
    double color[3];
    colorTF->GetColor(iv.WeightedScalar / iv.Weight, color);
    const double n = scatterer::defaultRefractiveIndex(static_cast<int>(k));
    set.Materials.push_back(Make(lo, hi, iv.MaxAlpha, n, color, dataRange));
  }
  return set;
}

namespace
{
// A row-major materials x materials table of f(material a, material b).
template <typename PairFunction>
std::vector<float> PairTable(const MaterialSet& set, PairFunction f)
{
  const size_t n = set.Materials.size();
  std::vector<float> table(n * n, 1.0f);
  for (size_t a = 0; a < n; ++a)
  {
    for (size_t b = 0; b < n; ++b)
    {
      table[a * n + b] = static_cast<float>(f(set.Materials[a].Physics, set.Materials[b].Physics));
    }
  }
  return table;
}
}

std::vector<float> SpeedRatios(const MaterialSet& set)
{
  return PairTable(set,
    [](const scatterer::Material& a, const scatterer::Material& b)
    { return scatterer::speedRatio(a.refractiveIndex, b.refractiveIndex); });
}

std::vector<float> OpacityRatios(const MaterialSet& set)
{
  return PairTable(set,
    [](const scatterer::Material& a, const scatterer::Material& b)
    { return b.opacity > 0 ? std::min(1.0, a.opacity / b.opacity) : 1.0; });
}

std::vector<float> MaterialTable(const MaterialSet& set, const double range[2], int size)
{
  std::vector<float> table(static_cast<size_t>(std::max(size, 1)), -1.0f);
  for (size_t i = 0; i < table.size(); ++i)
  {
    const double v = range[0] + (range[1] - range[0]) * (i + 0.5) / table.size();
    for (size_t m = 0; m < set.Materials.size(); ++m)
    {
      const scatterer::Selector& sel = set.Materials[m].Physics.selector;
      const bool label = sel.kind == scatterer::Selector::Kind::Label;
      const double lo = label ? sel.label - 0.5 : sel.lo, hi = label ? sel.label + 0.5 : sel.hi;
      if (v >= lo && v <= hi)
      {
        table[i] = static_cast<float>(m);
        break;
      }
    }
  }
  return table;
}

Unassigned CountUnassigned(vtkDataArray* scalars, const MaterialSet& set,
  vtkVolumeProperty* property, const double dataRange[2], int component)
{
  Unassigned result;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const int tableSize = 4096;
  std::vector<char> visible(tableSize);
  const double lo = dataRange[0], span = dataRange[1] - dataRange[0];
  for (int i = 0; i < tableSize; ++i)
  {
    visible[i] = opacity->GetValue(lo + span * i / (tableSize - 1.0)) > kVisible;
  }
  const vtkIdType n = scalars->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = scalars->GetComponent(i, component);
    if (!std::isfinite(v))
    {
      continue;
    }
    const int bin = span > 0.0
      ? std::min(tableSize - 1,
          std::max(0, static_cast<int>(std::lround((v - lo) / span * (tableSize - 1)))))
      : 0;
    if (!visible[bin])
    {
      continue;
    }
    bool assigned = false;
    for (const auto& m : set.Materials)
    {
      assigned = assigned || m.Physics.selector.matches(v);
    }
    if (!assigned)
    {
      if (result.Count == 0)
      {
        result.Example = v;
      }
      ++result.Count;
    }
  }
  return result;
}
}
