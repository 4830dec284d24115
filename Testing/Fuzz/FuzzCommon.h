// Shared by the fuzz targets and the seed writer: a byte decoder that turns fuzz input
// into parameters (typical values, special values such as NaN/inf/-0/huge, or raw bit
// patterns), a bit-exact TemplateSet comparison, and FNV-1a 64 (docs/model.md) so the
// reader target can also feed inputs whose checksum is right.
#pragma once

#include <scatterer/TemplateIO.h>

#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

namespace fuzz {

// Stops the fuzzer with a message; libFuzzer reports the trap as a crash and saves the input.
#define FUZZ_CHECK(cond, ...)                                                                      \
  do {                                                                                             \
    if (!(cond)) {                                                                                 \
      std::fprintf(stderr, "FUZZ_CHECK failed: %s (%s:%d): ", #cond, __FILE__, __LINE__);          \
      std::fprintf(stderr, __VA_ARGS__);                                                           \
      std::fprintf(stderr, "\n");                                                                  \
      __builtin_trap();                                                                            \
    }                                                                                              \
  } while (0)

// Reads the input front to back; past the end every read is 0 (a short input still
// decodes to complete, typical parameters).
class Bytes {
public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint32_t u32()
  {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) {
      v |= static_cast<std::uint32_t>(u8()) << (8 * i);
    }
    return v;
  }
  std::uint64_t u64()
  {
    const std::uint64_t lo = u32();
    return lo | (static_cast<std::uint64_t>(u32()) << 32);
  }
  std::size_t remaining() const { return size_ - (pos_ < size_ ? pos_ : size_); }

private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// Encoding used by the decoders below (MakeSeeds writes the same):
//   mode byte % 3 == 0: typical value, then a u32 fraction of [lo, hi]
//   mode byte % 3 == 1: special value, then a u8 index into the special table
//   mode byte % 3 == 2: raw bit pattern (u64 for double, u32 for float / int)
enum Mode : std::uint8_t { kTypical = 0, kSpecial = 1, kRaw = 2 };

inline double specialDouble(std::uint8_t index, double lo, double hi)
{
  const double table[] = { std::numeric_limits<double>::quiet_NaN(),
    -std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -HUGE_VAL, 0.0, -0.0,
    std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(), DBL_MIN,
    DBL_MAX, -DBL_MAX, 1e-300, 1e300, -1.0, 1.0, DBL_EPSILON, 1.0 + DBL_EPSILON,
    1.0 - DBL_EPSILON / 2, 1e-9, 1e-4, 1e-3, 1e3, 1e4, lo, hi, std::nextafter(lo, -HUGE_VAL),
    std::nextafter(hi, HUGE_VAL), std::nextafter(lo, HUGE_VAL), std::nextafter(hi, -HUGE_VAL),
    0.5 * (lo + hi) };
  return table[index % (sizeof table / sizeof table[0])];
}

// logScale: the typical value is log-uniform in [lo, hi] (lo > 0), for parameters that
// span decades (refractive index, threshold, step length).
inline double decodeDouble(Bytes& b, double lo, double hi, bool logScale = false)
{
  switch (b.u8() % 3) {
  case kTypical: {
    const double f = static_cast<double>(b.u32()) / 4294967295.0;
    if (logScale) {
      return std::fmin(
        hi, std::fmax(lo, std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * f)));
    }
    return lo + (hi - lo) * f;
  }
  case kSpecial:
    return specialDouble(b.u8(), lo, hi);
  default: {
    const std::uint64_t bits = b.u64();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  }
}

inline float decodeFloat(Bytes& b, float lo, float hi)
{
  switch (b.u8() % 3) {
  case kTypical:
    return lo + (hi - lo) * static_cast<float>(static_cast<double>(b.u32()) / 4294967295.0);
  case kSpecial: {
    const float table[] = { std::numeric_limits<float>::quiet_NaN(), HUGE_VALF, -HUGE_VALF, 0.0f,
      -0.0f, std::numeric_limits<float>::denorm_min(), FLT_MAX, -FLT_MAX, -1.0f, 1.0f,
      std::nextafter(1.0f, 2.0f), std::nextafter(0.0f, -1.0f), lo, hi };
    return table[b.u8() % (sizeof table / sizeof table[0])];
  }
  default: {
    const std::uint32_t bits = b.u32();
    float v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  }
}

inline int decodeInt(Bytes& b, int lo, int hi)
{
  switch (b.u8() % 3) {
  case kTypical: {
    const auto span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo) + 1;
    return static_cast<int>(lo + static_cast<std::int64_t>(b.u32() % span));
  }
  case kSpecial: {
    const int table[] = { INT_MIN, -1, 0, 1, 2, INT_MAX, lo, hi, lo - 1,
      hi == INT_MAX ? INT_MAX : hi + 1, 1 << 20, (1 << 20) + 1, 1 << 24, (1 << 24) + 1, 16384,
      16385, 1024, 1025 };
    return table[b.u8() % (sizeof table / sizeof table[0])];
  }
  default:
    return static_cast<int>(b.u32());
  }
}

// Bit patterns, so NaN == NaN with the same payload and 0.0 != -0.0.
template <typename T> bool sameBits(T a, T b)
{
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

inline bool sameSettings(
  const scatterer::GeneratorSettings& a, const scatterer::GeneratorSettings& b)
{
  return a.initialLights == b.initialLights && sameBits(a.threshold, b.threshold) &&
         a.templatesPerMaterial == b.templatesPerMaterial && a.seed == b.seed &&
         sameBits(a.stepLength, b.stepLength) && sameBits(a.latticeCell, b.latticeCell) &&
         a.maxPhotonsPerTemplate == b.maxPhotonsPerTemplate &&
         a.maxEventsPerTemplate == b.maxEventsPerTemplate;
}

inline bool sameMaterial(const scatterer::Material& a, const scatterer::Material& b)
{
  return a.name == b.name && sameBits(a.opacity, b.opacity) &&
         sameBits(a.refractiveIndex, b.refractiveIndex) && sameBits(a.diffuse.r, b.diffuse.r) &&
         sameBits(a.diffuse.g, b.diffuse.g) && sameBits(a.diffuse.b, b.diffuse.b) &&
         a.selector.kind == b.selector.kind && sameBits(a.selector.lo, b.selector.lo) &&
         sameBits(a.selector.hi, b.selector.hi) && a.selector.label == b.selector.label;
}

inline bool sameTemplate(const scatterer::Template& a, const scatterer::Template& b)
{
  const scatterer::EnergyLedger& x = a.ledger;
  const scatterer::EnergyLedger& y = b.ledger;
  if (a.capped != b.capped || a.events != b.events || a.photons.size() != b.photons.size() ||
      !sameBits(x.initial, y.initial) || !sameBits(x.stored, y.stored) ||
      !sameBits(x.lostInTransit, y.lostInTransit) || !sameBits(x.escaped, y.escaped) ||
      !sameBits(x.droppedBelowThreshold, y.droppedBelowThreshold) ||
      !sameBits(x.droppedAtCap, y.droppedAtCap)) {
    return false;
  }
  for (std::size_t i = 0; i < a.photons.size(); ++i) {
    const scatterer::Photon& p = a.photons[i];
    const scatterer::Photon& q = b.photons[i];
    if (!sameBits(p.position.x, q.position.x) || !sameBits(p.position.y, q.position.y) ||
        !sameBits(p.position.z, q.position.z) || !sameBits(p.intensity, q.intensity)) {
      return false;
    }
  }
  return true;
}

inline bool sameSet(const scatterer::TemplateSet& a, const scatterer::TemplateSet& b)
{
  if (!sameSettings(a.settings, b.settings) || a.materials.size() != b.materials.size()) {
    return false;
  }
  for (std::size_t m = 0; m < a.materials.size(); ++m) {
    const scatterer::MaterialTemplates& x = a.materials[m];
    const scatterer::MaterialTemplates& y = b.materials[m];
    if (!sameMaterial(x.material, y.material) || x.templates.size() != y.templates.size()) {
      return false;
    }
    for (std::size_t t = 0; t < x.templates.size(); ++t) {
      if (!sameTemplate(x.templates[t], y.templates[t])) {
        return false;
      }
    }
  }
  return true;
}

// FNV-1a 64, as the file format's trailing checksum (docs/model.md).
inline std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size)
{
  std::uint64_t hash = 0xCBF29CE484222325ull;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 0x100000001B3ull;
  }
  return hash;
}

} // namespace fuzz
