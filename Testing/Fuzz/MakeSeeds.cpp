// Writes the seed corpora committed under Testing/Fuzz/corpus/ (a few hundred bytes each):
//   fuzz_make_seeds <corpus folder>
// template_generator/: encoded GeneratorInputs (typical, transparent, opaque with total
//   internal reflection at the caps, invalid values); each is decoded back and checked.
// template_reader/: small valid template files (from the generator with tiny caps), an
//   empty set and a truncated file.
// volume_headers/: small MetaImage, NRRD and NIfTI files in the layouts of
//   VolumeHeaderInput.h (each valid kind, plus the bad headers of issue 13).
#include "GeneratorInput.h"
#include "ScattererVolumeBytes.h"
#include "VolumeHeaderInput.h"

#include <scatterer/Template.h>
#include <scatterer/TemplateIO.h>

#include <cstdio>
#include <cstring>
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
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
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
              fuzz::sameSettings(back.settings, in.settings) &&
              back.templateIndex == in.templateIndex && back.packCap == in.packCap &&
              back.halfFormat == in.halfFormat && b.remaining() == 0;
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

// 16-bit little-endian voxels n * 37 - 400, so that no two neighbours are equal.
int seedValue(int n)
{
  return n * 37 - 400;
}

std::string shorts(int count)
{
  return scatterer_testing::ShortBytes(count, seedValue);
}

std::string asciiShorts(int count)
{
  return scatterer_testing::AsciiValues(count, 10, seedValue) + "\n";
}

// A little-endian NIfTI-1 header for a 4x3x2 volume of the given type, data at vox_offset.
std::string nifti1(std::int16_t datatype, std::int16_t bitpix)
{
  scatterer_testing::Nifti1Fields fields;
  fields.Dim = { 4, 3, 2 };
  fields.Datatype = datatype;
  fields.Bitpix = bitpix;
  fields.Pixdim = { 0.8f, 0.8f, 2.5f };
  return scatterer_testing::Nifti1Header(fields);
}

void writeVolumeSeed(const std::string& path, fuzz::VolumeFormat format, const std::string& header,
  const std::string& data = std::string())
{
  const std::string bytes = fuzz::encodeVolumeInput(format, header, data);
  write(path, std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
}

void writeVolumeSeeds(const std::string& dir)
{
  using namespace fuzz;
  // A 4x3x2 MET_SHORT header with a spacing and an origin; extra fields go before the
  // ElementDataFile that ends it.
  auto meta = [](const std::string& extra, const std::string& dataFile) {
    return scatterer_testing::MetaImageHeader(
      "4 3 2", "ElementSpacing = 0.5 0.5 1.5\nOffset = -10 5 0\n" + extra, dataFile);
  };
  writeVolumeSeed(dir + "mha-local", kMetaImageLocal, meta("", "LOCAL") + shorts(24));
  writeVolumeSeed(dir + "mhd-float-2-channels", kMetaImageDetached,
    "NDims = 3\nDimSize = 3 2 2\nElementType = MET_FLOAT\nElementNumberOfChannels = 2\n"
    "ElementDataFile = data.raw\n",
    shorts(48));
  writeVolumeSeed(dir + "mha-zlib", kMetaImageLocal,
    meta("CompressedData = True\nCompressedDataSize = 59\n", "LOCAL") +
      scatterer_testing::ZlibStored(shorts(24)));
  writeVolumeSeed(
    dir + "mha-ascii", kMetaImageLocal, meta("BinaryData = False\n", "LOCAL") + asciiShorts(24));
  writeVolumeSeed(dir + "mhd-header-size-minus-1", kMetaImageDetached,
    meta("HeaderSize = -1\n", "data.raw"), "0123456789abcdef" + shorts(24));
  writeVolumeSeed(dir + "issue-mha-negative-channels", kMetaImageLocal,
    meta("ElementNumberOfChannels = -3\n", "LOCAL") + shorts(24));
  writeVolumeSeed(dir + "issue-mha-compressed-raw", kMetaImageLocal,
    meta("CompressedData = True\n", "LOCAL") + shorts(24));

  const std::string nrrd = "type: short\ndimension: 3\nspace: left-posterior-superior\n"
                           "sizes: 10 2 2\nspace directions: (0.5,0,0) (0,0.5,0) (0,0,2)\n"
                           "space origin: (-5,0,3)\nendian: little\n";
  writeVolumeSeed(dir + "nrrd-raw", kNrrdAttached,
    scatterer_testing::NrrdHeader("seed", nrrd + "encoding: raw\n") + shorts(40));
  writeVolumeSeed(dir + "nrrd-gzip", kNrrdAttached,
    scatterer_testing::NrrdHeader("seed", nrrd + "encoding: gzip\n") +
      scatterer_testing::GzipStored(shorts(40)));
  writeVolumeSeed(dir + "nrrd-rgb", kNrrdAttached,
    "NRRD0005\ntype: uchar\ndimension: 4\nsizes: 3 10 2 2\nkinds: RGB-color domain domain domain\n"
    "spacings: nan 1 1 1\nencoding: raw\n\n" +
      std::string(120, '\x7f'));
  writeVolumeSeed(dir + "nhdr-ascii", kNrrdDetached,
    "NRRD0004\ntype: short\ndimension: 3\nsizes: 10 2 2\nencoding: ascii\ndata file: data.raw\n",
    asciiShorts(40));
  writeVolumeSeed(dir + "nhdr-raw-float", kNrrdDetached,
    "NRRD0004\ntype: float\ndimension: 2\nsizes: 10 4\nspacings: 0.1 0.2\nencoding: raw\n"
    "endian: little\ndatafile: data.raw\n",
    shorts(80));
  writeVolumeSeed(dir + "issue-nrrd-dimension-5", kNrrdAttached,
    "NRRD0004\ntype: short\ndimension: 5\nsizes: 10 2 2\nencoding: raw\n\n" + shorts(40));

  writeVolumeSeed(dir + "nii", kNifti, nifti1(4, 16) + shorts(24));
  writeVolumeSeed(dir + "nii-rgb", kNifti, nifti1(128, 24) + std::string(72, '\x40'));
  writeVolumeSeed(dir + "nii2", kNifti,
    scatterer_testing::Nifti2Header({ 4, 3, 2 }, { 0.8, 0.8, 2.5 }) + shorts(24));
  writeVolumeSeed(dir + "nii-gz", kNiftiGzipped, nifti1(16, 32) + shorts(48));
  writeVolumeSeed(
    dir + "nii-gz-raw", kNiftiGzipRaw, scatterer_testing::GzipStored(nifti1(4, 16) + shorts(24)));
  writeVolumeSeed(dir + "issue-nii-datatype-999", kNifti, nifti1(999, 16) + shorts(24));
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
  one.materials.push_back(
    { material("skin", 0.5, 1.4), generateTemplates(material("skin", 0.5, 1.4), s) });
  const std::vector<std::uint8_t> oneBytes = serialize(one);
  write(rd + "one-material", oneBytes);

  GeneratorSettings s2 = s;
  s2.templatesPerMaterial = 1;
  s2.initialLights = 2;
  s2.maxPhotonsPerTemplate = 3;
  TemplateSet two;
  two.settings = s2;
  two.materials.push_back(
    { material("air", 0.0, 1.0), generateTemplates(material("air", 0.0, 1.0), s2) });
  Material bone = material("bone", 1.0, 1.55);
  bone.selector = Selector::labelId(7);
  two.materials.push_back({ bone, generateTemplates(bone, s2) });
  write(rd + "two-materials", serialize(two));

  TemplateSet empty;
  empty.settings = s;
  write(rd + "empty-set", serialize(empty));

  write(rd + "truncated", std::vector<std::uint8_t>(oneBytes.begin(), oneBytes.begin() + 100));

  writeVolumeSeeds(root + "/volume_headers/");
  return 0;
}
