#include "scatterer_reference/PathTracer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace scatterer_reference
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Exponential free path for rate `rate` from a uniform u in [0, 1).
inline double freePath(double rate, float u)
{
  return -std::log(1.0 - static_cast<double>(u)) / rate;
}

double hgPhase(double cosTheta, double g)
{
  const double denom = 1.0 + g * g - 2.0 * g * cosTheta;
  return (1.0 - g * g) / (4.0 * kPi * denom * std::sqrt(denom));
}

// Direction from HG about `w` (the direction of travel before scattering).
glm::dvec3 sampleHg(const glm::dvec3& w, double g, Pcg32& rng)
{
  const double u1 = rng.uniform(), u2 = rng.uniform();
  double cosTheta;
  if (std::abs(g) < 1e-4)
  {
    cosTheta = 1.0 - 2.0 * u1;
  }
  else
  {
    const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
    cosTheta = (1.0 + g * g - s * s) / (2.0 * g);
  }
  cosTheta = std::clamp(cosTheta, -1.0, 1.0);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const double phi = 2.0 * kPi * u2;
  const glm::dvec3 a = std::abs(w.x) > 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 t = glm::normalize(glm::cross(a, w));
  const glm::dvec3 b = glm::cross(w, t);
  return glm::normalize(sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * w);
}
}

double sigmaFromOpacity(double alpha, double unitDistance)
{
  alpha = std::clamp(alpha, 0.0, 1.0 - 1e-6);
  return -std::log(1.0 - alpha) / unitDistance;
}

PathTracer::PathTracer(Scene scene, int macroCell)
  : scene_(std::move(scene))
  , macro_(std::max(1, macroCell))
{
  const Volume& v = scene_.volume;
  if (v.dims.x < 2 || v.dims.y < 2 || v.dims.z < 2)
    throw std::invalid_argument("reference volume needs at least 2 points per axis");
  if (v.scalars.size() != static_cast<size_t>(v.dims.x) * v.dims.y * v.dims.z)
    throw std::invalid_argument("reference volume: scalar count does not match dims");
  if (v.table.sigmaT.empty() || v.table.sigmaT.size() != v.table.albedo.size())
    throw std::invalid_argument("reference volume: empty or inconsistent transfer table");
  if (v.spacing.x <= 0 || v.spacing.y <= 0 || v.spacing.z <= 0)
    throw std::invalid_argument("reference volume: spacing must be positive");
  boxMin_ = v.origin;
  boxMax_ = v.origin + glm::dvec3(v.dims - 1) * v.spacing;
  const glm::ivec3 cells = v.dims - 1;
  macroDims_ = (cells + macro_ - 1) / macro_;
  macroSize_ = double(macro_) * v.spacing;
  majorant_.assign(static_cast<size_t>(macroDims_.x) * macroDims_.y * macroDims_.z, 0.0f);
  const TransferTable& tt = v.table;
  const int n = static_cast<int>(tt.sigmaT.size());
  const double span = tt.scalarMax > tt.scalarMin ? tt.scalarMax - tt.scalarMin : 1.0;
  auto entry = [&](double s)
  { return std::clamp((s - tt.scalarMin) / span * (n - 1), 0.0, double(n - 1)); };
  for (int mz = 0; mz < macroDims_.z; ++mz)
    for (int my = 0; my < macroDims_.y; ++my)
      for (int mx = 0; mx < macroDims_.x; ++mx)
      {
        float lo = std::numeric_limits<float>::max(), hi = -lo;
        for (int k = mz * macro_; k <= std::min((mz + 1) * macro_, v.dims.z - 1); ++k)
          for (int j = my * macro_; j <= std::min((my + 1) * macro_, v.dims.y - 1); ++j)
            for (int i = mx * macro_; i <= std::min((mx + 1) * macro_, v.dims.x - 1); ++i)
            {
              const float s = v.scalars[(static_cast<size_t>(k) * v.dims.y + j) * v.dims.x + i];
              lo = std::min(lo, s);
              hi = std::max(hi, s);
            }
        // Table lookups are linear between entries: the maximum over [lo, hi] is at an
        // entry inside the interval or at its ends, so take entries floor(lo)..ceil(hi).
        const int e0 = static_cast<int>(std::floor(entry(lo)));
        const int e1 = static_cast<int>(std::ceil(entry(hi)));
        float m = 0.0f;
        for (int e = e0; e <= e1; ++e)
          m = std::max(m, tt.sigmaT[e]);
        majorant_[(static_cast<size_t>(mz) * macroDims_.y + my) * macroDims_.x + mx] = m;
      }
}

void PathTracer::lookup(
  const glm::dvec3& p, float& sigma, glm::vec3* albedo, glm::vec3* emission) const
{
  const Volume& v = scene_.volume;
  const glm::dvec3 g = (p - v.origin) / v.spacing;
  if (!(g.x >= 0.0 && g.y >= 0.0 && g.z >= 0.0 && g.x <= v.dims.x - 1 && g.y <= v.dims.y - 1 &&
        g.z <= v.dims.z - 1))
  {
    sigma = 0.0f;
    if (albedo)
      *albedo = glm::vec3(0.0f);
    if (emission)
      *emission = glm::vec3(0.0f);
    return;
  }
  const int i = std::min(static_cast<int>(g.x), v.dims.x - 2);
  const int j = std::min(static_cast<int>(g.y), v.dims.y - 2);
  const int k = std::min(static_cast<int>(g.z), v.dims.z - 2);
  const double fx = g.x - i, fy = g.y - j, fz = g.z - k;
  const size_t sx = 1, sy = static_cast<size_t>(v.dims.x), sz = sy * v.dims.y;
  const float* s = v.scalars.data() + k * sz + j * sy + i;
  const double c00 = s[0] + fx * (s[sx] - s[0]);
  const double c10 = s[sy] + fx * (s[sy + sx] - s[sy]);
  const double c01 = s[sz] + fx * (s[sz + sx] - s[sz]);
  const double c11 = s[sz + sy] + fx * (s[sz + sy + sx] - s[sz + sy]);
  const double c0 = c00 + fy * (c10 - c00), c1 = c01 + fy * (c11 - c01);
  const double value = c0 + fz * (c1 - c0);
  const TransferTable& tt = v.table;
  const int n = static_cast<int>(tt.sigmaT.size());
  if (n == 1)
  {
    sigma = tt.sigmaT[0];
    if (albedo)
      *albedo = tt.albedo[0];
    if (emission)
      *emission = tt.emission.empty() ? glm::vec3(0.0f) : tt.emission[0];
    return;
  }
  const double span = tt.scalarMax > tt.scalarMin ? tt.scalarMax - tt.scalarMin : 1.0;
  const double e = std::clamp((value - tt.scalarMin) / span * (n - 1), 0.0, double(n - 1));
  const int e0 = std::min(static_cast<int>(e), n - 2);
  const float f = static_cast<float>(e - e0);
  sigma = tt.sigmaT[e0] + f * (tt.sigmaT[e0 + 1] - tt.sigmaT[e0]);
  if (albedo)
    *albedo = tt.albedo[e0] + f * (tt.albedo[e0 + 1] - tt.albedo[e0]);
  if (emission)
    *emission = tt.emission.size() != static_cast<size_t>(n)
      ? glm::vec3(0.0f)
      : tt.emission[e0] + f * (tt.emission[e0 + 1] - tt.emission[e0]);
}

double PathTracer::sigmaT(const glm::dvec3& p) const
{
  float s;
  lookup(p, s, nullptr);
  return s;
}

bool PathTracer::boxInterval(const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) const
{
  t0 = 0.0;
  t1 = kInf;
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] == 0.0)
    {
      if (o[a] < boxMin_[a] || o[a] > boxMax_[a])
        return false;
      continue;
    }
    double ta = (boxMin_[a] - o[a]) / d[a], tb = (boxMax_[a] - o[a]) / d[a];
    if (ta > tb)
      std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 < t1;
}

namespace
{
// Amanatides-Woo walk over the macro cells between t0 and t1; calls f(tEnterCell, tLeaveCell,
// majorant) in order until f returns true.
template <class F>
bool walkCells(const glm::dvec3& o, const glm::dvec3& d, double t0, double t1,
  const glm::dvec3& boxMin, const glm::dvec3& cellSize, const glm::ivec3& dims,
  const std::vector<float>& maj, F&& f)
{
  const double tMid = t0 + 1e-9 * (t1 - t0);
  const glm::dvec3 p = o + tMid * d;
  glm::ivec3 c;
  glm::dvec3 tMax, tDelta;
  glm::ivec3 step;
  for (int a = 0; a < 3; ++a)
  {
    c[a] =
      std::clamp(static_cast<int>(std::floor((p[a] - boxMin[a]) / cellSize[a])), 0, dims[a] - 1);
    if (d[a] > 0)
    {
      step[a] = 1;
      tMax[a] = (boxMin[a] + (c[a] + 1) * cellSize[a] - o[a]) / d[a];
      tDelta[a] = cellSize[a] / d[a];
    }
    else if (d[a] < 0)
    {
      step[a] = -1;
      tMax[a] = (boxMin[a] + c[a] * cellSize[a] - o[a]) / d[a];
      tDelta[a] = -cellSize[a] / d[a];
    }
    else
    {
      step[a] = 0;
      tMax[a] = kInf;
      tDelta[a] = kInf;
    }
  }
  double t = t0;
  while (t < t1)
  {
    const int a = tMax.x < tMax.y ? (tMax.x < tMax.z ? 0 : 2) : (tMax.y < tMax.z ? 1 : 2);
    const double tEnd = std::min(tMax[a], t1);
    const float m = maj[(static_cast<size_t>(c.z) * dims.y + c.y) * dims.x + c.x];
    if (tEnd > t && f(t, tEnd, m))
      return true;
    t = std::max(t, tEnd);
    c[a] += step[a];
    if (c[a] < 0 || c[a] >= dims[a])
      break;
    tMax[a] += tDelta[a];
  }
  return false;
}
}

bool PathTracer::deltaTrack(const glm::dvec3& o, const glm::dvec3& d, double t0, double t1,
  Pcg32& rng, double& tHit, glm::vec3* albedo) const
{
  return walkCells(o, d, t0, t1, boxMin_, macroSize_, macroDims_, majorant_,
    [&](double ta, double tb, float m)
    {
      if (m <= 0.0f)
        return false;
      double t = ta;
      for (;;)
      {
        t += freePath(m, rng.uniform());
        if (t >= tb)
          return false;
        float s;
        lookup(o + t * d, s, albedo);
        if (rng.uniform() * m < s)
        {
          tHit = t;
          return true;
        }
      }
    });
}

double PathTracer::ratioTrack(
  const glm::dvec3& o, const glm::dvec3& d, double t0, double t1, Pcg32& rng) const
{
  double T = 1.0;
  walkCells(o, d, t0, t1, boxMin_, macroSize_, macroDims_, majorant_,
    [&](double ta, double tb, float m)
    {
      if (m <= 0.0f)
        return false;
      double t = ta;
      for (;;)
      {
        t += freePath(m, rng.uniform());
        if (t >= tb)
          return false;
        float s;
        lookup(o + t * d, s, nullptr);
        T *= std::max(0.0, 1.0 - double(s) / m);
        if (T < 1e-4)
        {
          // Russian roulette on tiny transmittances (unbiased).
          if (rng.uniform() < 0.5f)
          {
            T = 0.0;
            return true;
          }
          T *= 2.0;
        }
      }
    });
  return T;
}

double PathTracer::transmittance(const glm::dvec3& o, const glm::dvec3& d, double tMax,
  std::uint64_t seed, std::uint64_t stream) const
{
  Pcg32 rng(seed, stream);
  double t0, t1;
  if (!boxInterval(o, d, t0, t1))
    return 1.0;
  t1 = std::min(t1, tMax);
  if (t1 <= t0)
    return 1.0;
  return ratioTrack(o, d, t0, t1, rng);
}

glm::dvec3 PathTracer::radiance(
  const glm::dvec3& origin, const glm::dvec3& dir, Pcg32& rng, const RenderSettings& settings) const
{
  glm::dvec3 L(0.0), beta(1.0);
  glm::dvec3 o = origin, d = dir;
  const double g = scene_.anisotropy;
  for (int order = 0;; ++order)
  {
    double t0, t1, tHit = 0.0;
    glm::vec3 albedo(0.0f);
    if (!boxInterval(o, d, t0, t1) || !deltaTrack(o, d, t0, t1, rng, tHit, &albedo))
    {
      L += beta * scene_.environment;
      break;
    }
    if (order >= settings.maxScatteringOrder)
      break;
    const glm::dvec3 p = o + tHit * d;
    if (!scene_.volume.table.emission.empty())
    {
      // Collision estimator of the emission integral: sigma_a / sigma_t * Le.
      float sigma;
      glm::vec3 alb, emitted;
      lookup(p, sigma, &alb, &emitted);
      L += beta * glm::dvec3(glm::vec3(1.0f) - albedo) * glm::dvec3(emitted);
    }
    beta *= glm::dvec3(albedo);
    // Next-event estimation to the delta lights.
    for (const DirectionalLight& l : scene_.directionalLights)
    {
      const glm::dvec3 wl = l.toLight;
      double a0, a1;
      double T = 1.0;
      if (boxInterval(p, wl, a0, a1))
        T = ratioTrack(p, wl, a0, a1, rng);
      if (T > 0.0)
        L += beta * l.irradiance * (hgPhase(glm::dot(d, wl), g) * T);
    }
    for (const PointLight& l : scene_.pointLights)
    {
      glm::dvec3 wl = l.position - p;
      const double r = glm::length(wl);
      if (r <= 0.0)
        continue;
      wl /= r;
      double a0, a1;
      double T = 1.0;
      if (boxInterval(p, wl, a0, a1) && std::min(a1, r) > a0)
        T = ratioTrack(p, wl, a0, std::min(a1, r), rng);
      const double falloff = l.inverseSquare ? 1.0 / (r * r) : 1.0;
      if (T > 0.0)
        L += beta * l.intensity * (hgPhase(glm::dot(d, wl), g) * T * falloff);
    }
    if (order + 1 >= settings.maxScatteringOrder)
    {
      // No further orders: the environment seen after this vertex is not counted either.
      return L;
    }
    if (order + 1 >= settings.rouletteStart)
    {
      const double q = std::min(0.95, std::max({ beta.r, beta.g, beta.b }));
      if (q <= 0.0 || rng.uniform() >= q)
        break;
      beta /= q;
    }
    o = p;
    d = sampleHg(d, g, rng);
  }
  return L;
}

void PathTracer::cameraRay(int x, int y, double u, double v, glm::dvec3& o, glm::dvec3& d) const
{
  const Camera& c = scene_.camera;
  const glm::dvec3 forward = glm::normalize(c.focalPoint - c.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, c.viewUp));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(0.5 * c.viewAngleDeg * kPi / 180.0);
  const double aspect = double(c.width) / double(c.height);
  const double sx = (2.0 * (x + u) / c.width - 1.0) * tanHalf * aspect;
  const double sy = (2.0 * (y + v) / c.height - 1.0) * tanHalf;
  o = c.position;
  d = glm::normalize(forward + sx * right + sy * up);
}

RenderResult PathTracer::render(const RenderSettings& settings) const
{
  const auto start = std::chrono::steady_clock::now();
  const Camera& c = scene_.camera;
  RenderResult r;
  r.width = c.width;
  r.height = c.height;
  r.samplesPerPixel = std::max(1, settings.samplesPerPixel);
  const size_t npix = static_cast<size_t>(c.width) * c.height;
  r.rgb.assign(npix * 3, 0.0f);
  r.standardError.assign(npix, 0.0f);
  std::atomic<int> nextRow{ 0 }, rowsDone{ 0 };
  auto worker = [&]()
  {
    for (int y; (y = nextRow.fetch_add(1)) < c.height;)
    {
      for (int x = 0; x < c.width; ++x)
      {
        const size_t p = static_cast<size_t>(y) * c.width + x;
        Pcg32 rng(settings.seed, p);
        glm::dvec3 mean(0.0);
        double lumMean = 0.0, lumM2 = 0.0;
        for (int s = 0; s < r.samplesPerPixel; ++s)
        {
          glm::dvec3 o, d;
          const double u = rng.uniform(), v = rng.uniform();
          cameraRay(x, y, u, v, o, d);
          const glm::dvec3 L = radiance(o, d, rng, settings);
          mean += (L - mean) / double(s + 1);
          const double lum = luminance(L);
          const double delta = lum - lumMean;
          lumMean += delta / double(s + 1);
          lumM2 += delta * (lum - lumMean);
        }
        for (int k = 0; k < 3; ++k)
          r.rgb[3 * p + k] = static_cast<float>(mean[k]);
        const int n = r.samplesPerPixel;
        r.standardError[p] = n > 1 ? static_cast<float>(std::sqrt(lumM2 / (n - 1) / n)) : 0.0f;
      }
      rowsDone.fetch_add(1);
    }
  };
  unsigned nThreads =
    settings.threads ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < nThreads; ++i)
    pool.emplace_back(worker);
  if (settings.progress)
  {
    // The calling thread reports progress and works between reports.
    std::thread last(worker);
    while (rowsDone.load() < c.height)
    {
      settings.progress(double(rowsDone.load()) / c.height);
      for (int i = 0; i < 50 && rowsDone.load() < c.height; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    last.join();
    settings.progress(1.0);
  }
  else
  {
    worker();
  }
  for (auto& t : pool)
    t.join();
  double se2 = 0.0, lum = 0.0;
  for (size_t p = 0; p < npix; ++p)
  {
    se2 += double(r.standardError[p]) * r.standardError[p];
    lum += luminance(glm::dvec3(r.rgb[3 * p], r.rgb[3 * p + 1], r.rgb[3 * p + 2]));
  }
  r.rmsStandardError = npix ? std::sqrt(se2 / npix) : 0.0;
  r.meanLuminance = npix ? lum / npix : 0.0;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

} // namespace scatterer_reference
