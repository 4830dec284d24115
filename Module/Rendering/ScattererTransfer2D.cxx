#include "ScattererTransfer2D.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"

#include <scatterer/Transport.h>

#include <algorithm>
#include <cmath>

namespace scatterer_render
{
namespace
{
constexpr int kMaxWidth = 4096;
constexpr int kMaxRows = 1024;

double Clamped01(double v)
{
  return std::isfinite(v) ? std::min(std::max(v, 0.0), 1.0) : 0.0;
}
}

std::string Transfer2DProblem(vtkImageData* table)
{
  if (!table)
  {
    return "no 2D transfer function is set";
  }
  vtkDataArray* rgba = table->GetPointData()->GetScalars();
  int dims[3];
  table->GetDimensions(dims);
  if (!rgba || rgba->GetNumberOfComponents() != 4)
  {
    return "the 2D transfer function is not a 4-component (RGBA) image";
  }
  if (dims[0] < 1 || dims[1] < 1 || dims[2] != 1 ||
    rgba->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    return "the 2D transfer function is not a 2D image";
  }
  return "";
}

void TabulateTransfer2D(
  vtkImageData* table, double sampleDistance, std::vector<float>& medium, int& rows)
{
  int dims[3];
  table->GetDimensions(dims);
  vtkDataArray* rgba = table->GetPointData()->GetScalars();
  const int width = std::min(dims[0], kMaxWidth);
  rows = std::min(dims[1], kMaxRows);
  medium.assign(static_cast<size_t>(4) * width * rows, 0.0f);
  for (int y = 0; y < rows; ++y)
  {
    const int sy = static_cast<int>((y + 0.5) * dims[1] / rows);
    for (int x = 0; x < width; ++x)
    {
      const int sx = static_cast<int>((x + 0.5) * dims[0] / width);
      const vtkIdType tuple = static_cast<vtkIdType>(sy) * dims[0] + sx;
      float* out = medium.data() + 4 * (static_cast<size_t>(y) * width + x);
      for (int c = 0; c < 3; ++c)
      {
        out[c] = static_cast<float>(Clamped01(rgba->GetComponent(tuple, c)));
      }
      // The table's alpha is one ray step's opacity (no correction in VTK 9.1).
      out[3] = static_cast<float>(
        scatterer::extinctionFromOpacity(rgba->GetComponent(tuple, 3), sampleDistance));
    }
  }
}

void TabulateGradientOpacity(const float* row, int width, vtkPiecewiseFunction* gradientOpacity,
  double rangeWidth, double step, int rows, std::vector<float>& medium)
{
  medium.assign(static_cast<size_t>(4) * width * rows, 0.0f);
  for (int y = 0; y < rows; ++y)
  {
    // Row y is read at the normalised magnitude (y + 0.5) / rows (its texel's centre), so
    // that the linear read between rows follows the function as VTK's finer table does.
    // Not clamped: VTK multiplies the step's opacity by the function's value as it is
    // (above 1 it thickens the matter); the product is an opacity, at most 1.
    const double gy =
      std::max(gradientOpacity->GetValue((y + 0.5) / rows * 0.25 * rangeWidth), 0.0);
    for (int x = 0; x < width; ++x)
    {
      const float* in = row + 4 * static_cast<size_t>(x);
      float* out = medium.data() + 4 * (static_cast<size_t>(y) * width + x);
      std::copy(in, in + 3, out);
      const double alpha = -std::expm1(-static_cast<double>(in[3]) * step);
      out[3] =
        static_cast<float>(scatterer::extinctionFromOpacity(std::min(gy * alpha, 1.0), step));
    }
  }
}

void Transfer2DVisibility(vtkImageData* table, double lo, double hi, double sampleDistance,
  double unit, vtkPiecewiseFunction* opacity, vtkColorTransferFunction* color)
{
  int dims[3];
  table->GetDimensions(dims);
  vtkDataArray* rgba = table->GetPointData()->GetScalars();
  opacity->RemoveAllPoints();
  color->RemoveAllPoints();
  for (int x = 0; x < dims[0]; ++x)
  {
    double best = 0.0;
    vtkIdType bestTuple = x;
    for (int y = 0; y < dims[1]; ++y)
    {
      const vtkIdType tuple = static_cast<vtkIdType>(y) * dims[0] + x;
      const double alpha = Clamped01(rgba->GetComponent(tuple, 3));
      if (alpha > best)
      {
        best = alpha;
        bestTuple = tuple;
      }
    }
    // Texel x covers the normalised scalar [x, x + 1) / width.
    const double value = lo + (hi - lo) * (x + 0.5) / dims[0];
    const double sigma = scatterer::extinctionFromOpacity(best, sampleDistance);
    opacity->AddPoint(value, 1.0 - std::exp(-sigma * unit));
    color->AddRGBPoint(value, Clamped01(rgba->GetComponent(bestTuple, 0)),
      Clamped01(rgba->GetComponent(bestTuple, 1)), Clamped01(rgba->GetComponent(bestTuple, 2)));
  }
}
}
