#include "ScattererTransferPresets.h"
#include "ScattererCtHeadScene.h"
#include "ScattererVolumeCheck.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace scatterer_examples
{
VolumeHistogram::VolumeHistogram(vtkImageData* image, int bins)
  : Counts(static_cast<size_t>(std::max(bins, 2)), 0.0)
{
  double range[2] = { 0.0, 1.0 };
  if (!image || !FiniteScalarRange(image, range))
  {
    return;
  }
  this->Low = range[0];
  this->High = range[1] > range[0] ? range[1] : range[0] + 1.0;
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    const double v = scalars->GetComponent(i, 0);
    if (std::isfinite(v))
    {
      this->Counts[static_cast<size_t>(this->BinOf(v))] += 1.0;
      this->Total += 1.0;
    }
  }
}

double VolumeHistogram::BinValue(int bin) const
{
  const double width = (this->High - this->Low) / static_cast<double>(this->Counts.size());
  return this->Low + (bin + 0.5) * width;
}

int VolumeHistogram::BinOf(double value) const
{
  const int n = static_cast<int>(this->Counts.size());
  const double t = (value - this->Low) / (this->High - this->Low);
  return std::clamp(static_cast<int>(t * n), 0, n - 1);
}

double VolumeHistogram::Quantile(double q, double from) const
{
  const int n = static_cast<int>(this->Counts.size());
  const int first = from <= this->Low ? 0 : this->BinOf(from);
  double total = 0.0;
  for (int b = first; b < n; ++b)
  {
    total += this->Counts[b];
  }
  double sum = 0.0;
  for (int b = first; b < n; ++b)
  {
    sum += this->Counts[b];
    if (sum >= q * total)
    {
      return this->BinValue(b);
    }
  }
  return this->High;
}

double VolumeHistogram::OtsuThreshold(double from, double to) const
{
  const int first = this->BinOf(from);
  const int last = this->BinOf(to);
  double weight = 0.0, moment = 0.0;
  for (int b = first; b <= last; ++b)
  {
    weight += this->Counts[b];
    moment += this->Counts[b] * this->BinValue(b);
  }
  // Maximise w0 w1 (mu0 - mu1)^2 over the split bin. Empty bins between two classes
  // tie; the threshold is the middle of the tied run, not its first bin (which would
  // sit on the lower class's edge).
  double w0 = 0.0, m0 = 0.0, best = -1.0;
  int firstBest = first, lastBest = first;
  for (int b = first; b < last; ++b)
  {
    w0 += this->Counts[b];
    m0 += this->Counts[b] * this->BinValue(b);
    const double w1 = weight - w0;
    if (w0 <= 0.0 || w1 <= 0.0)
    {
      continue;
    }
    const double d = m0 / w0 - (moment - m0) / w1;
    const double between = w0 * w1 * d * d;
    if (between > best * (1.0 + 1e-12))
    {
      best = between;
      firstBest = lastBest = b;
    }
    else if (between >= best * (1.0 - 1e-12))
    {
      lastBest = b;
    }
  }
  if (best < 0.0)
  {
    return 0.5 * (from + to);
  }
  // The split lies after bin b: at the upper edge of the bin.
  const double width = (this->High - this->Low) / this->Counts.size();
  return 0.5 * (this->BinValue(firstBest) + this->BinValue(lastBest)) + 0.5 * width;
}

double VolumeHistogram::ShareBelow(double value) const
{
  if (this->Total <= 0.0)
  {
    return 0.0;
  }
  double below = 0.0;
  for (int b = 0; b < this->BinOf(value); ++b)
  {
    below += this->Counts[b];
  }
  return below / this->Total;
}

namespace
{
// The least gap between a preset's points: VTK sizes its lookup tables by the range over
// the smallest gap, and points a millionth of the range apart (a binary volume's
// classes) asked for a table of 10^6 entries, past the GPU's texture width (16384 on
// llvmpipe), with two warnings a frame.
double MinimumPointGap(double lo, double hi)
{
  return (hi - lo) / 4096.0;
}

struct PresetInfo
{
  const char* Name;
  const char* Shows;
};
// What each preset is for; the points are in MakeTransferPreset.
const PresetInfo Presets[] = {
  { "auto", "any data: from the histogram (Otsu thresholds): faint tissue, opaque dense parts" },
  { "ct-head", "CT (HU): skin and bone, the benchmark scene's transfer function" },
  { "ct-skin", "CT (HU): the skin surface" },
  { "ct-bone", "CT (HU): bone and teeth" },
  { "ct-soft-tissue", "CT (HU): muscle and organs translucent, bone behind" },
  { "ct-angio", "CT angiography (HU): contrast-filled vessels red, bone and metal white" },
  { "mri", "MRI: tissue above the background (Otsu), grey to white by intensity" },
};

TransferPoints Hounsfield(const char* name, std::vector<std::array<double, 2>> opacity,
  std::vector<std::array<double, 4>> color)
{
  return TransferPoints{ name, std::move(opacity), std::move(color) };
}
}

const std::vector<std::string>& TransferPresetNames()
{
  static const std::vector<std::string> names = []
  {
    std::vector<std::string> all;
    for (const PresetInfo& p : Presets)
    {
      all.emplace_back(p.Name);
    }
    return all;
  }();
  return names;
}

std::string TransferPresetHelp()
{
  std::ostringstream out;
  for (const PresetInfo& p : Presets)
  {
    out << (&p == Presets ? "" : "\n") << "  " << p.Name
        << std::string(16 - std::string(p.Name).size(), ' ') << p.Shows;
  }
  return out.str();
}

bool MakeTransferPreset(const std::string& name, const VolumeHistogram& histogram,
  TransferPoints& points, std::string& why)
{
  const double lo = histogram.Minimum();
  const double hi = histogram.Maximum();
  if (name == "ct-head")
  {
    points = CtHeadTransferPoints();
  }
  else if (name == "ct-skin")
  {
    points = Hounsfield("ct-skin", { { -1024, 0.0 }, { -600, 0.0 }, { -400, 0.4 }, { 3000, 0.9 } },
      { { -1024, 0.75, 0.5, 0.4 }, { -400, 0.9, 0.65, 0.5 }, { 0, 0.95, 0.75, 0.62 },
        { 3000, 1.0, 0.95, 0.9 } });
  }
  else if (name == "ct-bone")
  {
    points = Hounsfield("ct-bone",
      { { -1024, 0.0 }, { 150, 0.0 }, { 300, 0.3 }, { 700, 0.9 }, { 3000, 0.95 } },
      { { -1024, 0.8, 0.6, 0.45 }, { 150, 0.85, 0.7, 0.55 }, { 400, 0.95, 0.9, 0.8 },
        { 3000, 1.0, 1.0, 1.0 } });
  }
  else if (name == "ct-soft-tissue")
  {
    // Fat (-100 HU) faint, muscle and organs (20..80 HU) translucent red, bone white.
    points = Hounsfield("ct-soft-tissue",
      { { -1024, 0.0 }, { -200, 0.0 }, { -80, 0.01 }, { 20, 0.02 }, { 80, 0.08 }, { 200, 0.1 },
        { 400, 0.6 }, { 3000, 0.8 } },
      { { -1024, 0.6, 0.4, 0.3 }, { -80, 0.85, 0.7, 0.45 }, { 40, 0.8, 0.35, 0.3 },
        { 200, 0.9, 0.6, 0.5 }, { 400, 1.0, 0.95, 0.9 }, { 3000, 1.0, 1.0, 1.0 } });
  }
  else if (name == "ct-angio")
  {
    // Iodine contrast in vessels: about 150..500 HU; bone above, metal (stents) far above.
    points = Hounsfield("ct-angio",
      { { -1024, 0.0 }, { 100, 0.0 }, { 180, 0.3 }, { 500, 0.7 }, { 3000, 0.9 } },
      { { -1024, 0.6, 0.1, 0.1 }, { 180, 0.8, 0.15, 0.1 }, { 400, 0.95, 0.4, 0.3 },
        { 700, 1.0, 0.9, 0.8 }, { 3000, 1.0, 1.0, 1.0 } });
  }
  else if (name == "mri")
  {
    // MRI intensities have no absolute scale: the tissue/background split is Otsu's
    // threshold, and the ramp spans the tissue's intensity quantiles.
    const double t = histogram.OtsuThreshold(lo, hi);
    const double eps = MinimumPointGap(lo, hi);
    const double median = std::max(histogram.Quantile(0.5, t), t + eps);
    const double top = std::max(histogram.Quantile(0.99, t), median + eps);
    points = TransferPoints{ "mri",
      { { lo, 0.0 }, { t, 0.0 }, { median, 0.25 }, { top, 0.7 }, { hi, 0.7 } },
      { { lo, 0.5, 0.4, 0.4 }, { t, 0.7, 0.55, 0.5 }, { median, 0.9, 0.8, 0.75 },
        { top, 1.0, 1.0, 1.0 }, { hi, 1.0, 1.0, 1.0 } } };
  }
  else if (name == "auto")
  {
    // Two Otsu splits: background | tissue | dense. Background is transparent;
    // opacity rises through the tissue class (0.15 per voxel at its median: vessels
    // and organs show, translucent) to 0.8 at the dense class's median (bone, metal
    // opaque). The medians, not the maximum, set the scale, so that a few extreme
    // voxels (metal, noise) cannot leave everything else faint.
    const double eps = MinimumPointGap(lo, hi);
    const double t1 = histogram.OtsuThreshold(lo, hi);
    const double t2 = std::max(histogram.OtsuThreshold(t1, hi), t1 + 2 * eps);
    const double tissue = std::clamp(histogram.Quantile(0.5, t1), t1 + eps, t2 - eps);
    const double dense = std::max(histogram.Quantile(0.5, t2), t2 + eps);
    const double end = std::max(hi, dense);
    points = TransferPoints{ "auto",
      { { lo, 0.0 }, { t1, 0.0 }, { tissue, 0.15 }, { t2, 0.5 }, { dense, 0.8 }, { end, 0.8 } },
      { { lo, 0.7, 0.4, 0.3 }, { t1, 0.8, 0.45, 0.35 }, { tissue, 0.9, 0.6, 0.5 },
        { t2, 0.95, 0.85, 0.75 }, { dense, 1.0, 1.0, 0.97 }, { end, 1.0, 1.0, 1.0 } } };
  }
  else
  {
    why = "unknown preset '" + name + "' (known:";
    for (const std::string& known : TransferPresetNames())
    {
      why += " " + known;
    }
    why += ")";
    return false;
  }
  return true;
}

std::string DefaultTransferPreset(const VolumeHistogram& histogram)
{
  // CT in Hounsfield units: air near -1000 HU fills a good part of any scan.
  const bool hounsfield = histogram.Minimum() <= -900.0 && histogram.Minimum() >= -3100.0 &&
    histogram.Maximum() >= 300.0 && histogram.ShareBelow(-800.0) >= 0.05;
  return hounsfield ? "ct-head" : "auto";
}

double TransferCenter(const TransferPoints& points)
{
  // From the last transparent point before the first visible one to the first
  // point at the largest opacity.
  const auto& o = points.Opacity;
  if (o.empty())
  {
    return 0.0;
  }
  size_t rise = 0;
  while (rise + 1 < o.size() && o[rise + 1][1] <= 0.0)
  {
    ++rise;
  }
  size_t peak = rise;
  for (size_t i = rise; i < o.size(); ++i)
  {
    if (o[i][1] > o[peak][1])
    {
      peak = i;
    }
  }
  return 0.5 * (o[rise][0] + o[peak][0]);
}

void ApplyTransferPoints(
  const TransferPoints& points, double shift, double scale, vtkVolumeProperty* property)
{
  // x + shift + (scale - 1)(x - c) rather than c + (x - c) scale + shift: the points
  // come back bit for bit at shift 0, scale 1 (the benchmark scene's values).
  const double center = TransferCenter(points);
  auto move = [&](double x) { return x + shift + (scale - 1.0) * (x - center); };
  vtkNew<vtkPiecewiseFunction> opacity;
  for (const auto& p : points.Opacity)
  {
    opacity->AddPoint(move(p[0]), p[1]);
  }
  vtkNew<vtkColorTransferFunction> color;
  for (const auto& p : points.Color)
  {
    color->AddRGBPoint(move(p[0]), p[1], p[2], p[3]);
  }
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
}
}
