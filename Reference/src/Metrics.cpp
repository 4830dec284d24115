#include "scatterer_reference/Metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace scatterer_reference
{
namespace
{
void checkSizes(const std::vector<float>& a, const std::vector<float>& b, int width, int height)
{
  if (width <= 0 || height <= 0 || a.size() != b.size() ||
    a.size() != static_cast<size_t>(width) * height * 3)
    throw std::invalid_argument("metrics: images must both be width * height * 3 floats");
}

std::vector<double> lum(const std::vector<float>& a, double scale, bool clamp)
{
  std::vector<double> l(a.size() / 3);
  for (size_t i = 0; i < l.size(); ++i)
  {
    double v = scale * (0.2126 * a[3 * i] + 0.7152 * a[3 * i + 1] + 0.0722 * a[3 * i + 2]);
    l[i] = clamp ? std::clamp(v, 0.0, 1.0) : v;
  }
  return l;
}
}

double leastSquaresScale(const std::vector<float>& test, const std::vector<float>& reference)
{
  double tr = 0.0, tt = 0.0;
  for (size_t i = 0; i < test.size() && i < reference.size(); ++i)
  {
    tr += double(test[i]) * reference[i];
    tt += double(test[i]) * test[i];
  }
  return tt > 0.0 ? tr / tt : 1.0;
}

double rmse(const std::vector<float>& a, const std::vector<float>& b, double scaleA)
{
  if (a.size() != b.size() || a.empty())
    throw std::invalid_argument("rmse: images differ in size or are empty");
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    const double d = scaleA * a[i] - b[i];
    sum += d * d;
  }
  return std::sqrt(sum / a.size());
}

double psnr(double e, double peak)
{
  if (e <= 0.0)
    return std::numeric_limits<double>::infinity();
  return 20.0 * std::log10(std::max(peak, 1e-12) / e);
}

double ssim(
  const std::vector<float>& a, const std::vector<float>& b, int width, int height, double scaleA)
{
  checkSizes(a, b, width, height);
  const std::vector<double> x = lum(a, scaleA, true), y = lum(b, 1.0, true);
  constexpr int R = 5; // 11x11
  double w[2 * R + 1];
  double wsum = 0.0;
  for (int i = -R; i <= R; ++i)
    wsum += (w[i + R] = std::exp(-(i * i) / (2.0 * 1.5 * 1.5)));
  const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
  auto window = [&](int cx, int cy, int x0, int x1, int y0, int y1)
  {
    double sw = 0, mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0;
    for (int j = y0; j <= y1; ++j)
      for (int i = x0; i <= x1; ++i)
      {
        const double wi = w[std::clamp(i - cx + R, 0, 2 * R)] * w[std::clamp(j - cy + R, 0, 2 * R)];
        const size_t p = static_cast<size_t>(j) * width + i;
        sw += wi;
        mx += wi * x[p];
        my += wi * y[p];
        sxx += wi * x[p] * x[p];
        syy += wi * y[p] * y[p];
        sxy += wi * x[p] * y[p];
      }
    mx /= sw;
    my /= sw;
    const double vx = std::max(0.0, sxx / sw - mx * mx), vy = std::max(0.0, syy / sw - my * my);
    const double cxy = sxy / sw - mx * my;
    return ((2 * mx * my + C1) * (2 * cxy + C2)) / ((mx * mx + my * my + C1) * (vx + vy + C2));
  };
  (void)wsum;
  if (width < 2 * R + 1 || height < 2 * R + 1)
    return window(width / 2, height / 2, std::max(0, width / 2 - R),
      std::min(width - 1, width / 2 + R), std::max(0, height / 2 - R),
      std::min(height - 1, height / 2 + R));
  double sum = 0.0;
  int count = 0;
  for (int cy = R; cy < height - R; ++cy)
    for (int cx = R; cx < width - R; ++cx)
    {
      sum += window(cx, cy, cx - R, cx + R, cy - R, cy + R);
      ++count;
    }
  return sum / count;
}

std::vector<float> errorMap(
  const std::vector<float>& a, const std::vector<float>& b, int width, int height, double scaleA)
{
  checkSizes(a, b, width, height);
  const std::vector<double> x = lum(a, scaleA, false), y = lum(b, 1.0, false);
  std::vector<float> e(x.size());
  for (size_t i = 0; i < e.size(); ++i)
    e[i] = static_cast<float>(std::abs(x[i] - y[i]));
  return e;
}

Metrics compare(const std::vector<float>& test, const std::vector<float>& reference, int width,
  int height, Normalisation normalisation)
{
  checkSizes(test, reference, width, height);
  Metrics m;
  m.scale = normalisation == Normalisation::LeastSquares ? leastSquaresScale(test, reference) : 1.0;
  m.rmse = rmse(test, reference, m.scale);
  const double peak = *std::max_element(reference.begin(), reference.end());
  m.psnr = psnr(m.rmse, peak);
  m.ssim = ssim(test, reference, width, height, m.scale);
  return m;
}

} // namespace scatterer_reference
