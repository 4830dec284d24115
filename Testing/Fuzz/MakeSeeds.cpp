// Writes the seed corpora committed under Testing/Fuzz/corpus/ (a few hundred bytes each):
//   fuzz_make_seeds <corpus folder>
// template_generator/: encoded GeneratorInputs (typical, transparent, opaque with total
//   internal reflection at the caps, invalid values); each is decoded back and checked.
// template_reader/: small valid template files (from the generator with tiny caps), an
//   empty set and a truncated file.
#include "GeneratorInput.h"

#include <scatterer/Template.h>
#include <scatterer/TemplateIO.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace scatterer;

namespace {

// Mirrors GeneratorInput.h with exact values: raw bit patterns (mode 2).
class Encoder {
public:
  std::vector<std::uint8_t> bytes;

  void u8(std::uint8_t v) { bytes.push_back(v); }
  void u32(std::uint32_t v)
  {
    for (int i = 0; i < 4; ++i) {
      u8(static_cast<std::uint8_t>(v >> (8 * i)));
    }
  }
  void u64(std::uint64_t v)
  {
    u32(static_cast<std::uint32_t>(v));
    u32(static_cast<std::uint32_t>(v >> 32));
  }
  void f64(double v)
  {
    u8(fuzz::kRaw);
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    u64(b);
  }
  void f32(float v)
  {
    u8(fuzz::kRaw);
    std::uint32_t b;
    std::memcpy(&b, &v, 4);
    u32(b);
  }
  void i32(int v)
  {
    u8(fuzz::kRaw);
    u32(static_cast<std::uint32_t>(v));
  }

  void material(const Material& m, std::uint8_t kind)
  {
    if (m.name.size() >= 250) {
      u8(static_cast<std::uint8_t>(0x80 | (m.name.size() - 250)));
    } else {
      u8(static_cast<std::uint8_t>(m.name.size()));
    }
    for (char c : m.name) {
      u8(static_cast<std::uint8_t>(c));
    }
    f64(m.opacity);
    f64(m.refractiveIndex);
    f32(m.diffuse.r);
    f32(m.diffuse.g);
    f32(m.diffuse.b);
    u8(kind);
    f64(m.selector.lo);
    f64(m.selector.hi);
    i32(m.selector.label);
  }

  void input(const fuzz::GeneratorInput& in)
  {
    u8(static_cast<std::uint8_t>(in.materials.size() - 1));
    for (const Material& m : in.materials) {
      material(m, m.selector.kind == Selector::Kind::Label ? 1 : 0);
    }
    const GeneratorSettings& s = in.settings;
    i32(s.initialLights);
    f64(s.threshold);
    i32(s.templatesPerMaterial);
    u64(s.seed);
    f64(s.stepLength);
    f64(s.latticeCell);
    i32(s.maxPhotonsPerTemplate);
    i32(s.maxEventsPerTemplate);
    i32(in.templateIndex);
    i32(in.packCap);
    u8(in.halfFormat ? 1 : 0);
  }
};

void write(const std::string& path, const std::vector<std::uint8_t>& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    std::exit(1);
  }
  std::printf("%s: %zu bytes\n", path.c_str(), bytes.size());
}

void writeGeneratorSeed(const std::string& path, const fuzz::GeneratorInput& in)
{
  Encoder e;
  e.input(in);
  fuzz::Bytes b(e.bytes.data(), e.bytes.size());
  const fuzz::GeneratorInput back = fuzz::decodeGeneratorInput(b);
  bool same = back.materials.size() == in.materials.size() &&
    fuzz::sameSettings(back.settings, in.settings) && back.templateIndex == in.templateIndex &&
    back.packCap == in.packCap && back.halfFormat == in.halfFormat && b.remaining() == 0;
  for (std::size_t m = 0; same && m < in.materials.size(); ++m) {
    same = fuzz::sameMaterial(back.materials[m], in.materials[m]);
  }
  if (!same) {
    std::fprintf(stderr, "%s: encoder and GeneratorInput.h disagree\n", path.c_str());
    std::exit(1);
  }
  write(path, e.bytes);
}

std::vector<std::uint8_t> serialize(const TemplateSet& set)
{
  std::ostringstream out;
  writeTemplates(out, set);
  const std::string s = out.str();
  return std::vector<std::uint8_t>(s.begin(), s.end());
}

Material material(const char* name, double opacity, double n)
{
  Material m;
  m.name = name;
  m.opacity = opacity;
  m.refractiveIndex = n;
  m.diffuse = { 0.9f, 0.6f, 0.5f };
  m.selector = Selector::range(100.0, 300.0);
  return m;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <corpus folder>\n", argv[0]);
    return 2;
  }
  const std::string root = argv[1];
  const double nan = std::numeric_limits<double>::quiet_NaN();

  // Generator inputs.
  const std::string gen = root + "/template_generator/";
  fuzz::GeneratorInput typical;
  typical.materials = { material("skin", 0.5, 1.4) };
  typical.settings.maxEventsPerTemplate = 2048;
  typical.settings.templatesPerMaterial = 2;
  typical.templateIndex = 1;
  typical.packCap = 64;
  writeGeneratorSeed(gen + "typical", typical);

  fuzz::GeneratorInput transparent = typical;
  transparent.materials = { material("", 0.0, 1.0), material("bone", 0.9, 1.55) };
  transparent.materials[1].selector = Selector::labelId(3);
  transparent.settings.initialLights = 1;
  transparent.halfFormat = true;
  writeGeneratorSeed(gen + "transparent-and-label", transparent);

  fuzz::GeneratorInput opaque = typical;
  opaque.materials = { material("tir", 1.0, 1e3) };
  opaque.settings.threshold = 1e-9;
  opaque.settings.stepLength = 1e-6;
  opaque.settings.latticeCell = 1e-4;
  opaque.settings.maxPhotonsPerTemplate = 16;
  opaque.packCap = 8;
  writeGeneratorSeed(gen + "opaque-tiny-step-caps", opaque);

  fuzz::GeneratorInput invalid = typical;
  invalid.materials[0].refractiveIndex = 1e-5;
  invalid.settings.threshold = nan;
  invalid.settings.maxEventsPerTemplate = (1 << 24) + 1;
  invalid.templateIndex = -1;
  invalid.packCap = 0;
  writeGeneratorSeed(gen + "invalid-nan-threshold", invalid);

  // The first finding (docs/fuzzing.md): an opacity so small that every absorbed amount
  // underflows float left ledger.stored slightly negative.
  fuzz::GeneratorInput underflow = typical;
  underflow.materials = { material("", 7.6154311270414583e-298, 1e4) };
  underflow.settings.initialLights = 64;
  underflow.settings.threshold = 1.0;
  underflow.settings.maxEventsPerTemplate = 3;
  writeGeneratorSeed(gen + "regression-underflowing-opacity", underflow);

  // Template files.
  const std::string rd = root + "/template_reader/";
  GeneratorSettings s;
  s.templatesPerMaterial = 2;
  s.maxPhotonsPerTemplate = 5;
  s.maxEventsPerTemplate = 256;
  TemplateSet one;
  one.settings = s;
  one.materials.push_back({ material("skin", 0.5, 1.4), generateTemplates(material("skin", 0.5, 1.4), s) });
  const std::vector<std::uint8_t> oneBytes = serialize(one);
  write(rd + "one-material", oneBytes);

  GeneratorSettings s2 = s;
  s2.templatesPerMaterial = 1;
  s2.initialLights = 2;
  s2.maxPhotonsPerTemplate = 3;
  TemplateSet two;
  two.settings = s2;
  two.materials.push_back({ material("air", 0.0, 1.0), generateTemplates(material("air", 0.0, 1.0), s2) });
  Material bone = material("bone", 1.0, 1.55);
  bone.selector = Selector::labelId(7);
  two.materials.push_back({ bone, generateTemplates(bone, s2) });
  write(rd + "two-materials", serialize(two));

  TemplateSet empty;
  empty.settings = s;
  write(rd + "empty-set", serialize(empty));

  write(rd + "truncated", std::vector<std::uint8_t>(oneBytes.begin(), oneBytes.begin() + 100));
  return 0;
}
