// Template files: bit-identical round trip; every malformed input is refused with a
// std::runtime_error that says why, and never crashes.
#include <scatterer/Random.h>
#include <scatterer/TemplateIO.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace scatterer;

namespace {

TemplateSet exampleSet(int templatesPerMaterial)
{
  TemplateSet set;
  set.settings.templatesPerMaterial = templatesPerMaterial;
  const std::vector<Material> materials = exampleTissueMaterials();
  const auto templates = generateAllTemplates(materials, set.settings);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    set.materials.push_back({ materials[m], templates[m] });
  }
  return set;
}

std::vector<std::uint8_t> bytesOf(const TemplateSet& set)
{
  std::ostringstream out(std::ios::binary);
  writeTemplates(out, set);
  const std::string s = out.str();
  return std::vector<std::uint8_t>(s.begin(), s.end());
}

std::string tempPath(const char* name)
{
  return ::testing::TempDir() + name;
}

// Expects parse to fail with a runtime_error whose message contains `word`.
void expectRejected(const std::vector<std::uint8_t>& bytes, const char* word)
{
  try {
    parseTemplates(bytes.data(), bytes.size());
    ADD_FAILURE() << "accepted; expected an error mentioning '" << word << "'";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

void putU32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v)
{
  for (int i = 0; i < 4; ++i) {
    b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
  }
}

// Byte offsets of the version layout 1 (docs/model.md).
constexpr std::size_t kVersionAt = 8;
constexpr std::size_t kMaterialCountAt = 16 + 48;
constexpr std::size_t kFirstMaterialAt = kMaterialCountAt + 4;

bool sameBits(const TemplateSet& a, const TemplateSet& b)
{
  return bytesOf(a) == bytesOf(b);
}

// Builds template files byte by byte after docs/model.md, independently of the writer,
// so a test can make files the writer refuses to make. `at()` is the offset of the
// next field, for checking the byte offsets in error messages.
class FileBuilder {
public:
  std::vector<std::uint8_t> bytes;

  std::size_t at() const { return bytes.size(); }
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
  void f32(float v)
  {
    std::uint32_t b;
    std::memcpy(&b, &v, 4);
    u32(b);
  }
  void f64(double v)
  {
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    u64(b);
  }

  void header(const GeneratorSettings& s, std::uint32_t materialCount)
  {
    for (char c : { 'S', 'C', 'A', 'T', 'T', 'P', 'L' }) {
      u8(static_cast<std::uint8_t>(c));
    }
    u8(0x1A);
    u32(1); // version
    u32(0); // flags
    u32(static_cast<std::uint32_t>(s.initialLights));
    f64(s.threshold);
    u32(static_cast<std::uint32_t>(s.templatesPerMaterial));
    u64(s.seed);
    f64(s.stepLength);
    f64(s.latticeCell);
    u32(static_cast<std::uint32_t>(s.maxPhotonsPerTemplate));
    u32(static_cast<std::uint32_t>(s.maxEventsPerTemplate));
    u32(materialCount);
  }
  // A valid material (range selector) with this name; then its template count.
  void material(const std::string& name, std::uint32_t templateCount)
  {
    u8(static_cast<std::uint8_t>(name.size()));
    for (char c : name) {
      u8(static_cast<std::uint8_t>(c));
    }
    f64(0.5);  // opacity
    f64(1.4);  // refractiveIndex
    f32(0.9f); // diffuse
    f32(0.6f);
    f32(0.5f);
    u8(0); // scalar range
    f64(100.0);
    f64(300.0);
    u32(0); // label
    u32(templateCount);
  }
  // A valid template: `photons` photons of descending intensity whose sum is stored,
  // a ledger that closes, `events` events.
  void templateRecord(std::uint32_t photons, std::uint64_t events)
  {
    u32(photons);
    u8(0); // not capped
    u64(events);
    double stored = 0.0;
    for (std::uint32_t j = 0; j < photons; ++j) {
      stored += static_cast<double>(intensity(j));
    }
    f64(1.0);          // initial
    f64(stored);       // stored
    f64(1.0 - stored); // lostInTransit
    f64(0.0);          // escaped
    f64(0.0);          // droppedBelowThreshold
    f64(0.0);          // droppedAtCap
    for (std::uint32_t j = 0; j < photons; ++j) {
      f32(0.1f * static_cast<float>(j % 8));
      f32(-0.05f);
      f32(0.2f);
      f32(intensity(j));
    }
  }
  // Appends the FNV-1a 64 checksum of everything so far: the file is not corrupt, so
  // what the reader refuses is the content.
  std::vector<std::uint8_t> finish()
  {
    std::uint64_t hash = 0xCBF29CE484222325ull;
    for (std::uint8_t b : bytes) {
      hash ^= b;
      hash *= 0x100000001B3ull;
    }
    u64(hash);
    return bytes;
  }

private:
  static float intensity(std::uint32_t j) { return 0.25f / static_cast<float>(j + 1); }
};

GeneratorSettings smallSettings()
{
  GeneratorSettings s;
  s.templatesPerMaterial = 2;
  s.maxPhotonsPerTemplate = 3;
  s.maxEventsPerTemplate = 100;
  return s;
}

// Byte offset at which a FileBuilder places material 0's template count.
std::size_t templateCountAt(const std::string& name)
{
  return kFirstMaterialAt + 1 + name.size() + 49;
}

// Expects parse to fail with a message that contains `words` and names the byte `at`.
void expectRejectedAt(
  const std::vector<std::uint8_t>& bytes, const std::string& words, std::size_t at)
{
  try {
    parseTemplates(bytes.data(), bytes.size());
    ADD_FAILURE() << "accepted; expected an error mentioning '" << words << "'";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(words), std::string::npos) << what;
    EXPECT_NE(what.find("(at byte " + std::to_string(at) + ")"), std::string::npos)
      << what << "\n(expected byte " << at << ")";
  }
}

} // namespace

TEST(TemplateIO, FileRoundTripIsBitIdentical)
{
  const TemplateSet set = exampleSet(8);
  const std::string path = tempPath("roundtrip.sctpl");
  saveTemplates(path, set);
  const TemplateSet back = loadTemplates(path);
  std::remove(path.c_str());

  ASSERT_EQ(back.materials.size(), set.materials.size());
  EXPECT_EQ(back.settings.seed, set.settings.seed);
  EXPECT_EQ(back.settings.threshold, set.settings.threshold);
  for (std::size_t m = 0; m < set.materials.size(); ++m) {
    const MaterialTemplates& a = set.materials[m];
    const MaterialTemplates& b = back.materials[m];
    EXPECT_EQ(a.material.name, b.material.name);
    EXPECT_EQ(a.material.opacity, b.material.opacity);
    EXPECT_EQ(a.material.selector.hi, b.material.selector.hi);
    ASSERT_EQ(a.templates.size(), b.templates.size());
    for (std::size_t t = 0; t < a.templates.size(); ++t) {
      const Template& x = a.templates[t];
      const Template& y = b.templates[t];
      ASSERT_EQ(x.photons.size(), y.photons.size());
      EXPECT_EQ(
        std::memcmp(x.photons.data(), y.photons.data(), x.photons.size() * sizeof(Photon)), 0);
      EXPECT_EQ(std::memcmp(&x.ledger, &y.ledger, sizeof x.ledger), 0);
      EXPECT_EQ(x.capped, y.capped);
      EXPECT_EQ(x.events, y.events);
    }
  }
  EXPECT_TRUE(sameBits(set, back)); // and writing it again gives the same bytes
}

TEST(TemplateIO, StreamRoundTrip)
{
  const TemplateSet set = exampleSet(2);
  std::stringstream io(std::ios::in | std::ios::out | std::ios::binary);
  writeTemplates(io, set);
  EXPECT_TRUE(sameBits(readTemplates(io), set));
}

TEST(TemplateIO, MissingFileIsReported)
{
  try {
    loadTemplates("/nonexistent/dir/none.sctpl");
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/none.sctpl"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
  }
}

TEST(TemplateIO, EveryTruncationIsRejected)
{
  const std::vector<std::uint8_t> bytes = bytesOf(exampleSet(1));
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    const std::vector<std::uint8_t> prefix(bytes.begin(), bytes.begin() + size);
    EXPECT_THROW(parseTemplates(prefix.data(), prefix.size()), std::runtime_error) << size;
  }
  expectRejected(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 40), "truncated");
}

TEST(TemplateIO, EverySingleByteChangeIsRejected)
{
  const std::vector<std::uint8_t> bytes = bytesOf(exampleSet(1));
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    std::vector<std::uint8_t> changed = bytes;
    changed[at] ^= 0x5A;
    EXPECT_THROW(parseTemplates(changed.data(), changed.size()), std::runtime_error) << at;
  }
}

TEST(TemplateIO, GarbageIsRejected)
{
  Pcg32 rng = Pcg32::forStream(99, 0);
  for (std::size_t size : { 1u, 7u, 8u, 64u, 1000u, 100000u }) {
    std::vector<std::uint8_t> garbage(size);
    for (auto& b : garbage) {
      b = static_cast<std::uint8_t>(rng.next());
    }
    EXPECT_THROW(parseTemplates(garbage.data(), garbage.size()), std::runtime_error);
  }
  const std::string text = "x y z intensity\n0.1 0.2 0.3 0.5\n";
  expectRejected(std::vector<std::uint8_t>(text.begin(), text.end()), "bad magic");
  EXPECT_THROW(parseTemplates(nullptr, 0), std::runtime_error);
}

TEST(TemplateIO, HeaderProblemsAreNamed)
{
  const std::vector<std::uint8_t> good = bytesOf(exampleSet(1));
  std::vector<std::uint8_t> b = good;
  b[0] = 'X';
  expectRejected(b, "bad magic");

  b = good;
  putU32(b, kVersionAt, 7);
  expectRejected(b, "unsupported version 7");

  b = good;
  b.push_back(0);
  expectRejected(b, "trailing");
}

TEST(TemplateIO, AbsurdCountsAreRejectedBeforeAllocating)
{
  const std::vector<std::uint8_t> good = bytesOf(exampleSet(1));
  std::vector<std::uint8_t> b = good;
  putU32(b, kMaterialCountAt, 0xFFFFFFFFu);
  expectRejected(b, "absurd material count");

  b = good;
  putU32(b, kMaterialCountAt, 4000); // under the cap, but cannot fit in the file
  expectRejected(b, "material count 4000 does not fit");

  // First material: name length byte + name + 49 bytes of parameters, then its counts.
  const std::size_t nameLength = good[kFirstMaterialAt];
  const std::size_t templateCountAt = kFirstMaterialAt + 1 + nameLength + 49;
  b = good;
  putU32(b, templateCountAt, 0x7FFFFFFFu);
  expectRejected(b, "absurd template count");

  b = good;
  putU32(b, templateCountAt + 4, 0xFFFFFFF0u);
  expectRejected(b, "absurd photon count");

  b = good;
  putU32(b, templateCountAt + 4, 1u << 20); // allowed count, not in the file
  expectRejected(b, "photon count 1048576 does not fit");
}

TEST(TemplateIO, WriterRefusesWhatTheReaderWouldReject)
{
  TemplateSet set = exampleSet(1);
  std::swap(set.materials[0].templates[0].photons[0], set.materials[0].templates[0].photons[1]);
  std::ostringstream out;
  EXPECT_THROW(writeTemplates(out, set), std::invalid_argument);

  set = exampleSet(1);
  set.materials[0].templates[0].ledger.stored += 0.5;
  EXPECT_THROW(writeTemplates(out, set), std::invalid_argument);

  set = exampleSet(1);
  set.materials[0].material.opacity = -1.0;
  EXPECT_THROW(writeTemplates(out, set), std::invalid_argument);
}

// The FileBuilder the tests below use writes what the writer writes, and the reader
// accepts it: what they patch is the only thing wrong.
TEST(TemplateIO, FileBuilderMatchesTheWriter)
{
  const GeneratorSettings s = smallSettings();
  FileBuilder b;
  b.header(s, 1);
  b.material("skin", 2);
  b.templateRecord(3, 40);
  b.templateRecord(0, 1);
  const std::vector<std::uint8_t> bytes = b.finish();
  const TemplateSet set = parseTemplates(bytes.data(), bytes.size());
  ASSERT_EQ(set.materials.size(), 1u);
  EXPECT_EQ(set.materials[0].material.name, "skin");
  ASSERT_EQ(set.materials[0].templates.size(), 2u);
  EXPECT_EQ(set.materials[0].templates[0].photons.size(), 3u);
  EXPECT_EQ(set.materials[0].templates[0].events, 40u);
  EXPECT_EQ(bytesOf(set), bytes);
}

// Issue 13: settings that promise 2 templates per material over a file that holds 0
// loaded as a set without a single photon.
TEST(TemplateIO, TemplateCountThatDisagreesWithTheSettingsIsRejected)
{
  const GeneratorSettings s = smallSettings(); // 2 templates per material
  for (std::uint32_t held : { 0u, 1u, 3u }) {
    SCOPED_TRACE(std::to_string(held) + " templates held");
    FileBuilder b;
    b.header(s, 1);
    b.material("skin", held);
    for (std::uint32_t t = 0; t < held; ++t) {
      b.templateRecord(1, 10);
    }
    expectRejectedAt(b.finish(),
      "material 0 holds " + std::to_string(held) +
        " templates, but the settings' templatesPerMaterial is 2",
      templateCountAt("skin"));
  }

  // ... and the writer does not write such a file.
  TemplateSet set = exampleSet(2);
  set.materials[1].templates.pop_back();
  std::ostringstream out;
  EXPECT_THROW(writeTemplates(out, set), std::invalid_argument);
  set.materials[1].templates.clear();
  EXPECT_THROW(writeTemplates(out, set), std::invalid_argument);
}

TEST(TemplateIO, PhotonCountOverTheSettingsCapIsRejected)
{
  const GeneratorSettings s = smallSettings(); // at most 3 photons per template
  FileBuilder b;
  b.header(s, 1);
  b.material("skin", 2);
  b.templateRecord(3, 10); // at the cap: fine
  const std::size_t photonCountAt = b.at();
  b.templateRecord(4, 10);
  expectRejectedAt(
    b.finish(), "photon count 4 exceeds the settings' maxPhotonsPerTemplate 3", photonCountAt);

  TemplateSet set = exampleSet(1);
  set.settings.maxPhotonsPerTemplate =
    static_cast<int>(set.materials[0].templates[0].photons.size()) - 1;
  std::ostringstream out;
  EXPECT_THROW(writeTemplates(out, set), std::invalid_argument);
}

TEST(TemplateIO, EventCountOverTheSettingsCapIsRejected)
{
  const GeneratorSettings s = smallSettings(); // at most 100 events per template
  FileBuilder b;
  b.header(s, 1);
  b.material("skin", 2);
  b.templateRecord(1, 100); // at the cap: fine
  const std::size_t eventCountAt = b.at() + 4 + 1;
  b.templateRecord(1, 101);
  expectRejectedAt(
    b.finish(), "event count 101 exceeds the settings' maxEventsPerTemplate 100", eventCountAt);

  TemplateSet set = exampleSet(1);
  set.settings.maxEventsPerTemplate = static_cast<int>(set.materials[0].templates[0].events) - 1;
  std::ostringstream out;
  EXPECT_THROW(writeTemplates(out, set), std::invalid_argument);
}

// Issue 13: a NUL in a material name was accepted, and cut the name short wherever it
// became a C string (VTK).
TEST(TemplateIO, NulInMaterialNameIsRejected)
{
  const std::string name("sk\0in", 5);
  FileBuilder b;
  b.header(smallSettings(), 1);
  b.material(name, 2);
  b.templateRecord(1, 10);
  b.templateRecord(1, 10);
  // The offset is the NUL's own: after the name length byte and "sk".
  expectRejectedAt(
    b.finish(), "material 0: name has a NUL byte (name byte 2 of 5)", kFirstMaterialAt + 1 + 2);

  // The writer (and anything else that validates a material) refuses it too.
  TemplateSet set = exampleSet(1);
  set.materials[2].material.name = name;
  std::ostringstream out;
  EXPECT_THROW(writeTemplates(out, set), std::invalid_argument);
  EXPECT_THROW(set.materials[2].material.validate(), std::invalid_argument);
}

// A material count that disagrees with the records is named as such (it was reported as
// file corruption), in both directions, when the checksum shows the file is intact.
TEST(TemplateIO, MaterialCountThatDisagreesWithTheContentIsNamed)
{
  const GeneratorSettings s = smallSettings();
  FileBuilder more; // counts 2, holds 1
  more.header(s, 2);
  more.material("skin", 2);
  more.templateRecord(1, 10);
  more.templateRecord(1, 10);
  const std::size_t checksumAt = more.at();
  expectRejectedAt(
    more.finish(), "the header counts 2 materials, but the file holds 1", checksumAt);

  FileBuilder fewer; // counts 1, holds 2
  fewer.header(s, 1);
  fewer.material("skin", 2);
  fewer.templateRecord(1, 10);
  fewer.templateRecord(1, 10);
  const std::size_t secondAt = fewer.at();
  fewer.material("bone", 2);
  fewer.templateRecord(1, 10);
  fewer.templateRecord(1, 10);
  const std::size_t extra = fewer.at() - secondAt;
  expectRejectedAt(fewer.finish(),
    "the records of the header's material count 1 end " + std::to_string(extra) +
      " bytes before the checksum: a count disagrees with the content",
    secondAt);
}
