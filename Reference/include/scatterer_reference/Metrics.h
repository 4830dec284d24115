// Error metrics of the accuracy benchmark, in one place (docs/accuracy.md).
//
// Images are linear RGB floats, width * height * 3, any row order (both the same).
//
// Exposure normalisation (stated): the stock and template renderings are displayed
// colours, the reference is radiance under a light of irradiance 1, so their scales
// differ by a global factor. Before RMSE/PSNR/SSIM/error map the test image is
// multiplied by the least-squares factor s = sum(t * r) / sum(t * t) over all channels
// (the s minimising |s t - r|^2); Normalisation::None skips this.
//
// - RMSE: sqrt(mean over pixels and channels of (s t - r)^2), linear values.
// - PSNR: 20 log10(peak / RMSE), peak = the largest reference value (at least 1e-12);
//   +infinity for RMSE = 0.
// - SSIM: Wang et al. 2004 on luminance (Rec. 709: 0.2126 R + 0.7152 G + 0.0722 B) of
//   both images clamped to [0, 1] (dynamic range L = 1), 11x11 Gaussian window with
//   sigma 1.5 (normalised), K1 = 0.01, K2 = 0.03, mean over the window positions that
//   fit inside the image ("valid"); images smaller than 11 pixels use one window
//   truncated to the image.
// - Error map: per pixel |luminance(s t) - luminance(r)|.
#pragma once

#include <vector>

namespace scatterer_reference
{

enum class Normalisation
{
  None,
  LeastSquares
};

struct Metrics
{
  double scale = 1.0; // exposure factor applied to the test image
  double rmse = 0.0;
  double psnr = 0.0;
  double ssim = 1.0;
};

/** The least-squares exposure factor s of `test` toward `reference` (1 if test is all zero). */
double leastSquaresScale(const std::vector<float>& test, const std::vector<float>& reference);

/** All metrics of `test` against `reference` (same size; throws std::invalid_argument otherwise).
 */
Metrics compare(const std::vector<float>& test, const std::vector<float>& reference, int width,
  int height, Normalisation normalisation = Normalisation::LeastSquares);

double rmse(const std::vector<float>& a, const std::vector<float>& b, double scaleA = 1.0);
double psnr(double rmse, double peak);
double ssim(const std::vector<float>& a, const std::vector<float>& b, int width, int height,
  double scaleA = 1.0);

/** Per-pixel |luminance(scaleA * a) - luminance(b)|, width * height. */
std::vector<float> errorMap(const std::vector<float>& a, const std::vector<float>& b, int width,
  int height, double scaleA = 1.0);

} // namespace scatterer_reference
