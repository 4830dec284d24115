// GPU packing: all templates of all materials in one texture-ready buffer.
//
// Layout: one template per row, row = materialFirstRow[m] + t (= m * templatesPerMaterial
// + t when every material has the same count). Texel j of a row is photon j:
// xyz = position in template radii, w = intensity. Photons are sorted by descending
// intensity and unused texels are exactly 0, so a shader may stop at the first texel
// whose w is 0 (or after photonCount[row] texels).
#pragma once

#include <scatterer/Template.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace scatterer {

enum class TexelFormat {
  RGBA32F, // 16 bytes per photon
  RGBA16F  // 8 bytes per photon (half floats; positions to ~5e-4 of a radius)
};

struct PackedTemplates {
  TexelFormat format = TexelFormat::RGBA32F;
  int width = 0;  // texels per row = largest packed photon count (at least 1 if height > 0)
  int height = 0; // rows = templates over all materials
  // width * height * 4 floats, row-major. For RGBA16F these are the half-rounded values,
  // so the CPU sees exactly what the GPU samples.
  std::vector<float> rgba;
  std::vector<std::uint16_t> rgbaHalf; // RGBA16F only: the half-float bits of rgba
  std::vector<int> photonCount;        // per row: texels with intensity > 0
  std::vector<double>
    truncatedIntensity; // per row: intensity of photons left out (cap, half underflow)
  std::vector<int> materialFirstRow;
  std::vector<int> materialRowCount;

  // Size of the texture payload in bytes (the upload size), by format.
  std::size_t byteCount() const;
};

// Largest accepted photon cap (a common GL_MAX_TEXTURE_SIZE lower bound).
constexpr int kMaxPackWidth = 16384;

// Packs the first maxPhotonsPerTemplate photons of every template (the brightest, since
// photons are sorted). Throws std::invalid_argument for a cap outside [1, kMaxPackWidth]
// or more than 16384 rows.
PackedTemplates packTemplates(const std::vector<std::vector<Template>>& perMaterial,
  int maxPhotonsPerTemplate, TexelFormat format = TexelFormat::RGBA32F);

} // namespace scatterer
