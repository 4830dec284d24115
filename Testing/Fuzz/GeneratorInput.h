// How FuzzTemplateGenerator decodes its input (MakeSeeds encodes seeds with the same
// order). Every field may come out NaN, infinite, negative, huge or otherwise invalid.
#pragma once

#include "FuzzCommon.h"

#include <scatterer/GeneratorSettings.h>
#include <scatterer/Material.h>

#include <vector>

namespace fuzz {

struct GeneratorInput {
  std::vector<scatterer::Material> materials; // 1 or 2
  scatterer::GeneratorSettings settings;
  int templateIndex = 0;
  int packCap = 1;
  bool halfFormat = false;
};

// Order: u8 materialCount-1 (low bit), then per material: u8 name code, name bytes,
// opacity, refractiveIndex, diffuse r g b, u8 selector kind, lo, hi, label; then settings
// in declaration order (seed as raw u64); then templateIndex, packCap, u8 format.
inline scatterer::Material decodeMaterial(Bytes& b)
{
  scatterer::Material m;
  const std::uint8_t nameCode = b.u8();
  // High bit: a long name around the 255-byte limit; otherwise up to 15 bytes.
  const std::size_t nameLength = (nameCode & 0x80) ? 250 + (nameCode & 0x0F) : (nameCode & 0x0F);
  m.name.clear();
  for (std::size_t i = 0; i < nameLength; ++i) {
    m.name.push_back(static_cast<char>(b.u8()));
  }
  m.opacity = decodeDouble(b, 0.0, 1.0);
  m.refractiveIndex = decodeDouble(b, 1e-4, 1e4, /*logScale=*/true);
  m.diffuse.r = decodeFloat(b, 0.0f, 1.0f);
  m.diffuse.g = decodeFloat(b, 0.0f, 1.0f);
  m.diffuse.b = decodeFloat(b, 0.0f, 1.0f);
  // 0: scalar range, 1: label, 2: an enumerator value that is neither (validate rejects it).
  m.selector.kind = static_cast<scatterer::Selector::Kind>(b.u8() % 3);
  m.selector.lo = decodeDouble(b, -1000.0, 3000.0);
  m.selector.hi = decodeDouble(b, -1000.0, 3000.0);
  m.selector.label = decodeInt(b, 0, 255);
  return m;
}

inline GeneratorInput decodeGeneratorInput(Bytes& b)
{
  GeneratorInput in;
  const int materials = 1 + (b.u8() & 1);
  for (int i = 0; i < materials; ++i) {
    in.materials.push_back(decodeMaterial(b));
  }
  scatterer::GeneratorSettings& s = in.settings;
  s.initialLights = decodeInt(b, 1, 64);
  s.threshold = decodeDouble(b, 1e-9, 1.0, true);
  s.templatesPerMaterial = decodeInt(b, 1, 4);
  s.seed = b.u64();
  s.stepLength = decodeDouble(b, 1e-6, 1.0, true);
  s.latticeCell = decodeDouble(b, 1e-4, 1.0, true);
  s.maxPhotonsPerTemplate = decodeInt(b, 1, 4096);
  s.maxEventsPerTemplate = decodeInt(b, 1, 4096);
  in.templateIndex = decodeInt(b, 0, 16);
  in.packCap = decodeInt(b, 1, 64);
  in.halfFormat = (b.u8() & 1) != 0;
  return in;
}

} // namespace fuzz
