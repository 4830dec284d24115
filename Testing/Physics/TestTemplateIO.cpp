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
      EXPECT_EQ(std::memcmp(x.photons.data(), y.photons.data(), x.photons.size() * sizeof(Photon)), 0);
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
