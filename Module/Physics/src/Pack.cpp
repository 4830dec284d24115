#include <scatterer/Half.h>
#include <scatterer/Pack.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace scatterer {

std::size_t PackedTemplates::byteCount() const
{
  const std::size_t texelBytes = format == TexelFormat::RGBA16F ? 8 : 16;
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * texelBytes;
}

PackedTemplates packTemplates(const std::vector<std::vector<Template>>& perMaterial,
  int maxPhotonsPerTemplate, TexelFormat format)
{
  if (maxPhotonsPerTemplate < 1 || maxPhotonsPerTemplate > kMaxPackWidth) {
    throw std::invalid_argument("packTemplates: maxPhotonsPerTemplate must be in [1, " +
                                std::to_string(kMaxPackWidth) + "], got " +
                                std::to_string(maxPhotonsPerTemplate));
  }
  std::size_t rows = 0;
  for (const auto& templates : perMaterial) {
    rows += templates.size();
  }
  if (rows > static_cast<std::size_t>(kMaxPackWidth)) {
    throw std::invalid_argument("packTemplates: at most " + std::to_string(kMaxPackWidth) +
                                " templates fit in one texture, got " + std::to_string(rows));
  }

  PackedTemplates packed;
  packed.format = format;
  packed.height = static_cast<int>(rows);
  const auto cap = static_cast<std::size_t>(maxPhotonsPerTemplate);
  std::size_t width = rows > 0 ? 1 : 0;
  for (const auto& templates : perMaterial) {
    for (const Template& t : templates) {
      width = std::max(width, std::min(t.photons.size(), cap));
    }
  }
  packed.width = static_cast<int>(width);
  packed.rgba.assign(width * rows * 4, 0.0f);
  if (format == TexelFormat::RGBA16F) {
    packed.rgbaHalf.assign(width * rows * 4, 0);
  }

  // Half: round each value once and keep the rounded float, so rgba == what the GPU
  // reads. Float: copy as is.
  const auto store = [&packed, format](std::size_t at, float value) {
    if (format == TexelFormat::RGBA16F) {
      packed.rgbaHalf[at] = floatToHalf(value);
      packed.rgba[at] = halfToFloat(packed.rgbaHalf[at]);
    } else {
      packed.rgba[at] = value;
    }
  };

  std::size_t row = 0;
  for (const auto& templates : perMaterial) {
    packed.materialFirstRow.push_back(static_cast<int>(row));
    packed.materialRowCount.push_back(static_cast<int>(templates.size()));
    for (const Template& t : templates) {
      double truncated = 0.0;
      int count = 0;
      for (std::size_t j = 0; j < t.photons.size(); ++j) {
        const Photon& p = t.photons[j];
        const bool fits = j < cap && (format == TexelFormat::RGBA32F
                                         ? p.intensity > 0.0f
                                         : halfToFloat(floatToHalf(p.intensity)) > 0.0f);
        if (!fits || count != static_cast<int>(j)) {
          truncated += p.intensity; // a 0 ends the row on the GPU: nothing after it counts
          continue;
        }
        const std::size_t at = (row * width + j) * 4;
        store(at + 0, p.position.x);
        store(at + 1, p.position.y);
        store(at + 2, p.position.z);
        store(at + 3, p.intensity);
        ++count;
      }
      packed.photonCount.push_back(count);
      packed.truncatedIntensity.push_back(truncated);
      ++row;
    }
  }
  return packed;
}

} // namespace scatterer
