// The reference renderer: unbiased Monte Carlo volumetric path tracing of a scalar
// volume classified by 1D transfer functions. VTK-free (C++17 + GLM + std::thread);
// Examples/reference/scatterer-reference.cxx converts a VTK scene into a Scene.
//
// Conventions
// - World units are those of the volume (mm for the CT head). Grid point (i,j,k) lies at
//   origin + (i,j,k) * spacing, x fastest in `scalars` (VTK's point-data layout). The
//   medium fills the box spanned by the grid points; outside it is vacuum.
// - Classification as in VTK's GPU ray caster: the scalar is interpolated trilinearly,
//   then looked up (linearly) in the transfer-function table. The table holds, per entry,
//   the extinction sigma_t (per world unit) and the single-scattering albedo per RGB
//   channel. For a VTK opacity alpha per ScalarOpacityUnitDistance u,
//   sigma_t = -ln(1 - alpha) / u (sigmaFromOpacity below; alpha clamped to 1 - 1e-6), so
//   a ray through d world units of constant alpha has opacity 1 - (1 - alpha)^(d / u),
//   VTK's own opacity correction. The albedo is the colour transfer function's colour
//   (times an optional scalar albedo).
// - Phase function: Henyey-Greenstein with anisotropy g (g = 0: isotropic, 1 / 4 pi).
// - Lights: directional (irradiance E on a plane normal to the light, colour RGB,
//   `toLight` unit direction), point (intensity I, radiance arriving I / r^2 or, with
//   inverseSquare off, I as VTK's default attenuation (1,0,0) does), and a uniform
//   environment of radiance L_env seen by every ray that leaves the box (also the
//   background: default black).
// - Camera: pinhole (VTK's perspective camera: position, focal point, view up, vertical
//   view angle). Pixel (x, y) has y = 0 at the bottom row, as vtkImageData.
//
// Estimator (per pixel, per sample; all RGB):
// - Free-flight sampling by delta tracking against a piecewise-constant majorant
//   (macro cells of `macroCell` grid cells, majorant = the largest table extinction
//   over the scalar interval the cell's points span, so it bounds the trilinear field).
//   A real collision happens with probability sigma_t / majorant; it is a scattering
//   event weighted by the albedo (the absorption part is accounted for by the weight,
//   no absorption termination). Null collisions continue.
// - At each scattering vertex, next-event estimation to every directional and point
//   light: throughput * albedo * phase(wo, wl) * L_light * T, with the transmittance T
//   to the light estimated by ratio tracking (unbiased, product of 1 - sigma / majorant).
//   Delta lights cannot be hit by a sampled direction, so there is no double counting.
// - The new direction is sampled from the phase function exactly (weight 1); the path
//   stops after `maxScatteringOrder` scattering events (maxScatteringOrder = 1: single
//   scattering only), or by Russian roulette from order `rouletteStart` on (survival
//   probability = max throughput channel, at most 0.95, weight divided by it).
// - A path leaving the box picks up throughput * L_env (unidirectional; no NEE for the
//   environment).
// Unbiased for orders up to maxScatteringOrder. With a finite maxScatteringOrder the
// missing orders are a stated truncation (docs/accuracy.md gives the numbers).
//
// Noise estimate: per pixel, the sample variance of the per-sample estimates (Welford,
// per channel); the standard error of the pixel is sqrt(var / n). RenderResult reports
// the per-pixel standard error of the luminance and its RMS over the image.
//
// Determinism: sample s of pixel p uses Pcg32(seed, p) (the stream continues across
// samples of the pixel), so the image depends only on the seed and the settings, not on
// the number of threads.
#pragma once

#include "scatterer_reference/Random.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace scatterer_reference
{

/** sigma_t per world unit from a VTK opacity alpha per unit distance u. */
double sigmaFromOpacity(double alpha, double unitDistance);

struct TransferTable
{
  double scalarMin = 0.0, scalarMax = 1.0; // entries span [min, max] uniformly, clamped outside
  std::vector<float> sigmaT;               // per world unit
  std::vector<glm::vec3> albedo;           // single-scattering albedo per channel, in [0, 1]
  // Optional emitted radiance Le per channel (empty: no emission). The source
  // term is sigma_a * Le with sigma_a = sigma_t * (1 - albedo); collected at every
  // real collision as (1 - albedo) * Le (the collision estimator). VTK's transfer
  // functions have no emission; this serves the emission-absorption closed form.
  std::vector<glm::vec3> emission;
};

struct Volume
{
  glm::ivec3 dims{ 0 }; // grid points per axis, each >= 2
  glm::dvec3 origin{ 0.0 }, spacing{ 1.0 };
  std::vector<float> scalars; // dims.x * dims.y * dims.z, x fastest
  TransferTable table;
};

struct DirectionalLight
{
  glm::dvec3 toLight{ 0, 0, 1 }; // unit vector toward the light
  glm::dvec3 irradiance{ 1.0 };  // RGB, on a plane normal to the light
};

struct PointLight
{
  glm::dvec3 position{ 0.0 };
  glm::dvec3 intensity{ 1.0 };
  bool inverseSquare = true;
};

struct Camera
{
  glm::dvec3 position{ 0, 0, 1 }, focalPoint{ 0.0 }, viewUp{ 0, 1, 0 };
  double viewAngleDeg = 30.0;
  int width = 64, height = 64;
};

struct Scene
{
  Volume volume;
  std::vector<DirectionalLight> directionalLights;
  std::vector<PointLight> pointLights;
  glm::dvec3 environment{ 0.0 }; // radiance of the uniform environment / background
  double anisotropy = 0.0;       // Henyey-Greenstein g in (-1, 1)
  Camera camera;
};

struct RenderSettings
{
  int samplesPerPixel = 16;
  int maxScatteringOrder = 64;
  int rouletteStart = 3;
  int macroCell = 8;
  unsigned threads = 0; // 0: std::thread::hardware_concurrency()
  std::uint64_t seed = 1;
  /** Called from the calling thread about every 0.5 s with the finished fraction. */
  std::function<void(double)> progress;
};

struct RenderResult
{
  int width = 0, height = 0, samplesPerPixel = 0;
  std::vector<float> rgb;           // linear HDR, width * height * 3, bottom row first
  std::vector<float> standardError; // per pixel, standard error of the luminance
  double rmsStandardError = 0.0;    // RMS of standardError over the image
  double meanLuminance = 0.0;
  double seconds = 0.0;
};

/** A prepared scene: macro-cell majorants built once; thread-safe to query. */
class PathTracer
{
public:
  explicit PathTracer(Scene scene, int macroCell = 8);

  const Scene& scene() const { return scene_; }

  /** Extinction at a world point (0 outside the box). */
  double sigmaT(const glm::dvec3& p) const;

  /** One-sample ratio-tracking estimate of the transmittance along o + t d, t in [0, tMax]. */
  double transmittance(const glm::dvec3& o, const glm::dvec3& d, double tMax, std::uint64_t seed,
    std::uint64_t stream) const;

  /** One path-traced radiance sample along a ray (d unit). */
  glm::dvec3 radiance(
    const glm::dvec3& o, const glm::dvec3& d, Pcg32& rng, const RenderSettings& settings) const;

  /** The camera image. */
  RenderResult render(const RenderSettings& settings) const;

  /** Ray through pixel (x, y) at sub-pixel offset (u, v) in [0, 1). */
  void cameraRay(int x, int y, double u, double v, glm::dvec3& o, glm::dvec3& d) const;

private:
  bool boxInterval(const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) const;
  // Delta tracking: true and t of the real collision if one happens in [t0, t1].
  bool deltaTrack(const glm::dvec3& o, const glm::dvec3& d, double t0, double t1, Pcg32& rng,
    double& tHit, glm::vec3* albedo) const;
  double ratioTrack(
    const glm::dvec3& o, const glm::dvec3& d, double t0, double t1, Pcg32& rng) const;
  void lookup(
    const glm::dvec3& p, float& sigma, glm::vec3* albedo, glm::vec3* emission = nullptr) const;

  Scene scene_;
  int macro_ = 8;
  glm::ivec3 macroDims_{ 1 };
  glm::dvec3 macroSize_{ 1.0 };
  std::vector<float> majorant_;
  glm::dvec3 boxMin_{ 0.0 }, boxMax_{ 0.0 };
};

/** Luminance (Rec. 709 weights) of a linear RGB colour. */
inline double luminance(const glm::dvec3& c)
{
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

} // namespace scatterer_reference
