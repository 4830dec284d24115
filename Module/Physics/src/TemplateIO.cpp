// Binary template files; the byte layout is specified in docs/model.md.
#include <scatterer/TemplateIO.h>

#include "ByteStream.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace scatterer {

namespace {

using detail::fnv1a;
using detail::load64;
using detail::Reader;
using detail::Writer;

constexpr unsigned char kMagic[8] = { 'S', 'C', 'A', 'T', 'T', 'P', 'L', 0x1A };
// Smallest possible records, used to reject counts the remaining bytes cannot hold
// before anything is allocated for them.
constexpr std::size_t kMinMaterialBytes = 1 + 8 + 8 + 3 * 4 + 1 + 8 + 8 + 4 + 4;
constexpr std::size_t kTemplateHeaderBytes = 4 + 1 + 8 + 6 * 8;
constexpr std::size_t kPhotonBytes = 4 * 4;
constexpr double kPositionSlack = 1e-5; // float rounding of positions just inside |p| < 1

// What the reader accepts is exactly what the writer may write: one check for both.
std::string templateProblem(const Template& t)
{
  const EnergyLedger& l = t.ledger;
  const double fields[6] = { l.initial, l.stored, l.lostInTransit, l.escaped,
    l.droppedBelowThreshold, l.droppedAtCap };
  for (double f : fields) {
    if (!std::isfinite(f) || f < 0.0) {
      return "energy ledger has a negative or non-finite entry";
    }
  }
  if (std::fabs(l.residual()) > 1e-6 * std::fmax(1.0, l.initial)) {
    return "energy ledger does not close (residual " + std::to_string(l.residual()) + ")";
  }
  for (std::size_t j = 0; j < t.photons.size(); ++j) {
    const Photon& p = t.photons[j];
    const glm::vec3& x = p.position;
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z) ||
        !std::isfinite(p.intensity)) {
      return "photon " + std::to_string(j) + " has a non-finite value";
    }
    if (!(p.intensity > 0.0f)) {
      return "photon " + std::to_string(j) + " has intensity <= 0";
    }
    const double r2 = double(x.x) * x.x + double(x.y) * x.y + double(x.z) * x.z;
    if (r2 > (1.0 + kPositionSlack) * (1.0 + kPositionSlack)) {
      return "photon " + std::to_string(j) + " lies outside the unit template sphere";
    }
    if (j > 0 && p.intensity > t.photons[j - 1].intensity) {
      return "photons are not sorted by descending intensity (at " + std::to_string(j) + ")";
    }
  }
  return {};
}

void writeSettings(Writer& w, const GeneratorSettings& s)
{
  w.u32(static_cast<std::uint32_t>(s.initialLights));
  w.f64(s.threshold);
  w.u32(static_cast<std::uint32_t>(s.templatesPerMaterial));
  w.u64(s.seed);
  w.f64(s.stepLength);
  w.f64(s.latticeCell);
  w.u32(static_cast<std::uint32_t>(s.maxPhotonsPerTemplate));
  w.u32(static_cast<std::uint32_t>(s.maxEventsPerTemplate));
}

// Settings ints are stored as u32; values above INT_MAX fail validate() as negatives.
GeneratorSettings readSettings(Reader& r)
{
  GeneratorSettings s;
  s.initialLights = static_cast<int>(r.u32("initialLights"));
  s.threshold = r.f64("threshold");
  s.templatesPerMaterial = static_cast<int>(r.u32("templatesPerMaterial"));
  s.seed = r.u64("seed");
  s.stepLength = r.f64("stepLength");
  s.latticeCell = r.f64("latticeCell");
  s.maxPhotonsPerTemplate = static_cast<int>(r.u32("maxPhotonsPerTemplate"));
  s.maxEventsPerTemplate = static_cast<int>(r.u32("maxEventsPerTemplate"));
  try {
    s.validate();
  } catch (const std::invalid_argument& e) {
    r.fail(std::string("invalid settings: ") + e.what());
  }
  return s;
}

void writeMaterial(Writer& w, const Material& m)
{
  w.u8(static_cast<std::uint8_t>(m.name.size()));
  for (char c : m.name) {
    w.u8(static_cast<std::uint8_t>(c));
  }
  w.f64(m.opacity);
  w.f64(m.refractiveIndex);
  w.f32(m.diffuse.r);
  w.f32(m.diffuse.g);
  w.f32(m.diffuse.b);
  w.u8(m.selector.kind == Selector::Kind::Label ? 1 : 0);
  w.f64(m.selector.lo);
  w.f64(m.selector.hi);
  w.u32(static_cast<std::uint32_t>(m.selector.label));
}

Material readMaterial(Reader& r, std::uint32_t index)
{
  Material m;
  const std::uint8_t nameLength = r.u8("material name length");
  const std::size_t nameAt = r.position();
  const std::uint8_t* name = r.take(nameLength, "material name");
  // A NUL would cut the name short wherever it is used as a C string (VTK, messages).
  if (const void* nul = std::memchr(name, 0, nameLength)) {
    const auto i = static_cast<std::size_t>(static_cast<const std::uint8_t*>(nul) - name);
    r.failAt(nameAt + i, "material " + std::to_string(index) + ": name has a NUL byte (name byte " +
                           std::to_string(i) + " of " + std::to_string(nameLength) + ")");
  }
  m.name.assign(reinterpret_cast<const char*>(name), nameLength);
  m.opacity = r.f64("opacity");
  m.refractiveIndex = r.f64("refractiveIndex");
  m.diffuse.r = r.f32("diffuse.r");
  m.diffuse.g = r.f32("diffuse.g");
  m.diffuse.b = r.f32("diffuse.b");
  const std::uint8_t kind = r.u8("selector kind");
  if (kind > 1) {
    r.fail("selector kind must be 0 (range) or 1 (label), got " + std::to_string(kind));
  }
  m.selector.kind = kind == 1 ? Selector::Kind::Label : Selector::Kind::ScalarRange;
  m.selector.lo = r.f64("selector lo");
  m.selector.hi = r.f64("selector hi");
  m.selector.label = static_cast<std::int32_t>(r.u32("selector label"));
  try {
    m.validate();
  } catch (const std::invalid_argument& e) {
    r.fail(std::string("invalid material: ") + e.what());
  }
  return m;
}

void writeTemplate(Writer& w, const Template& t)
{
  w.u32(static_cast<std::uint32_t>(t.photons.size()));
  w.u8(t.capped ? 1 : 0);
  w.u64(t.events);
  const EnergyLedger& l = t.ledger;
  for (double f :
    { l.initial, l.stored, l.lostInTransit, l.escaped, l.droppedBelowThreshold, l.droppedAtCap }) {
    w.f64(f);
  }
  for (const Photon& p : t.photons) {
    w.f32(p.position.x);
    w.f32(p.position.y);
    w.f32(p.position.z);
    w.f32(p.intensity);
  }
}

// The settings' caps bound every template the generator makes; a file whose templates
// exceed them did not come from those settings.
Template readTemplate(Reader& r, const GeneratorSettings& s)
{
  Template t;
  const std::size_t photonsAt = r.position();
  const std::uint32_t photons =
    r.count("photon count", static_cast<std::uint32_t>(kMaxPhotonsCap), kPhotonBytes);
  if (photons > static_cast<std::uint32_t>(s.maxPhotonsPerTemplate)) {
    r.failAt(photonsAt, "photon count " + std::to_string(photons) +
                          " exceeds the settings' maxPhotonsPerTemplate " +
                          std::to_string(s.maxPhotonsPerTemplate));
  }
  const std::uint8_t capped = r.u8("capped flag");
  if (capped > 1) {
    r.fail("capped flag must be 0 or 1, got " + std::to_string(capped));
  }
  t.capped = capped == 1;
  const std::size_t eventsAt = r.position();
  t.events = r.u64("event count");
  if (t.events > static_cast<std::uint64_t>(s.maxEventsPerTemplate)) {
    r.failAt(eventsAt, "event count " + std::to_string(t.events) +
                         " exceeds the settings' maxEventsPerTemplate " +
                         std::to_string(s.maxEventsPerTemplate));
  }
  EnergyLedger& l = t.ledger;
  l.initial = r.f64("ledger.initial");
  l.stored = r.f64("ledger.stored");
  l.lostInTransit = r.f64("ledger.lostInTransit");
  l.escaped = r.f64("ledger.escaped");
  l.droppedBelowThreshold = r.f64("ledger.droppedBelowThreshold");
  l.droppedAtCap = r.f64("ledger.droppedAtCap");
  t.photons.resize(photons); // bounded: count() checked the bytes are there
  for (Photon& p : t.photons) {
    p.position.x = r.f32("photon x");
    p.position.y = r.f32("photon y");
    p.position.z = r.f32("photon z");
    p.intensity = r.f32("photon intensity");
  }
  const std::string problem = templateProblem(t);
  if (!problem.empty()) {
    r.fail("invalid template: " + problem);
  }
  return t;
}

std::vector<std::uint8_t> serialize(const TemplateSet& set)
{
  set.settings.validate();
  if (set.materials.size() > kMaxFileMaterials) {
    throw std::invalid_argument("writeTemplates: at most " + std::to_string(kMaxFileMaterials) +
                                " materials per file, got " + std::to_string(set.materials.size()));
  }
  Writer w;
  w.bytes.insert(w.bytes.end(), kMagic, kMagic + 8);
  w.u32(kTemplateFileVersion);
  w.u32(0); // flags, reserved
  writeSettings(w, set.settings);
  w.u32(static_cast<std::uint32_t>(set.materials.size()));
  for (std::size_t m = 0; m < set.materials.size(); ++m) {
    const MaterialTemplates& mt = set.materials[m];
    mt.material.validate();
    if (mt.templates.size() != static_cast<std::size_t>(set.settings.templatesPerMaterial)) {
      throw std::invalid_argument("writeTemplates: material " + std::to_string(m) + " has " +
                                  std::to_string(mt.templates.size()) +
                                  " templates, but settings.templatesPerMaterial is " +
                                  std::to_string(set.settings.templatesPerMaterial));
    }
    writeMaterial(w, mt.material);
    w.u32(static_cast<std::uint32_t>(mt.templates.size()));
    for (std::size_t t = 0; t < mt.templates.size(); ++t) {
      const Template& tpl = mt.templates[t];
      std::string problem = templateProblem(tpl);
      if (tpl.photons.size() > static_cast<std::size_t>(set.settings.maxPhotonsPerTemplate)) {
        problem = std::to_string(tpl.photons.size()) +
                  " photons exceed settings.maxPhotonsPerTemplate " +
                  std::to_string(set.settings.maxPhotonsPerTemplate);
      } else if (tpl.events > static_cast<std::uint64_t>(set.settings.maxEventsPerTemplate)) {
        problem = std::to_string(tpl.events) + " events exceed settings.maxEventsPerTemplate " +
                  std::to_string(set.settings.maxEventsPerTemplate);
      }
      if (!problem.empty()) {
        throw std::invalid_argument("writeTemplates: material " + std::to_string(m) + " template " +
                                    std::to_string(t) + ": " + problem);
      }
      writeTemplate(w, tpl);
    }
  }
  if (w.bytes.size() + 8 > kMaxTemplateFileBytes) {
    throw std::invalid_argument("writeTemplates: the set needs more than " +
                                std::to_string(kMaxTemplateFileBytes) + " bytes");
  }
  w.u64(fnv1a(w.bytes.data(), w.bytes.size()));
  return w.bytes;
}

TemplateSet parse(const std::uint8_t* data, std::size_t size, const std::string& source)
{
  if (size > kMaxTemplateFileBytes) {
    throw std::runtime_error(
      source + ": larger than the " + std::to_string(kMaxTemplateFileBytes) + "-byte limit");
  }
  Reader r(data, size, source);
  const std::uint8_t* magic = r.take(8, "magic");
  if (std::memcmp(magic, kMagic, 8) != 0) {
    r.fail("not a scatterer template file (bad magic)");
  }
  const std::uint32_t version = r.u32("version");
  if (version != kTemplateFileVersion) {
    r.fail("unsupported version " + std::to_string(version) + " (this reader knows " +
           std::to_string(kTemplateFileVersion) + ")");
  }
  if (r.u32("flags") != 0) {
    r.fail("unknown flags set");
  }
  TemplateSet set;
  set.settings = readSettings(r);
  const std::uint32_t materials = r.count("material count", kMaxFileMaterials, kMinMaterialBytes);
  // Whether the last 8 bytes are the checksum of the rest: then a count that disagrees
  // with the records is named as such rather than as corruption.
  const bool intact = size >= 8 && fnv1a(data, size - 8) == load64(data + size - 8);
  set.materials.reserve(materials);
  for (std::uint32_t m = 0; m < materials; ++m) {
    if (r.remaining() == 8 && intact) { // only the checksum is left
      r.fail("the header counts " + std::to_string(materials) + " materials, but the file " +
             "holds " + std::to_string(m));
    }
    MaterialTemplates mt;
    mt.material = readMaterial(r, m);
    // The settings promise templatesPerMaterial templates for every material; a file
    // holding fewer (0 loads as a set without photons) or more did not come from them.
    const std::size_t templatesAt = r.position();
    const std::uint32_t templates = r.count(
      "template count", static_cast<std::uint32_t>(kMaxTemplatesPerMaterial), kTemplateHeaderBytes);
    if (templates != static_cast<std::uint32_t>(set.settings.templatesPerMaterial)) {
      r.failAt(templatesAt, "material " + std::to_string(m) + " holds " +
                              std::to_string(templates) +
                              " templates, but the settings' templatesPerMaterial is " +
                              std::to_string(set.settings.templatesPerMaterial));
    }
    mt.templates.reserve(templates);
    for (std::uint32_t t = 0; t < templates; ++t) {
      mt.templates.push_back(readTemplate(r, set.settings));
    }
    set.materials.push_back(std::move(mt));
  }
  const std::size_t payload = r.position();
  const std::uint64_t stored = r.u64("checksum");
  const bool checksumMatches = r.remaining() == 0 ? intact : stored == fnv1a(data, payload);
  if (!checksumMatches) {
    if (r.remaining() > 0 && intact) {
      // Not corrupted: the counted records end before the checksum.
      r.failAt(payload, "the records of the header's material count " + std::to_string(materials) +
                          " end " + std::to_string(size - 8 - payload) +
                          " bytes before the checksum: a count disagrees with the content");
    }
    r.fail("checksum mismatch (file corrupted)");
  }
  if (r.remaining() != 0) {
    r.fail(std::to_string(r.remaining()) + " unexpected trailing bytes");
  }
  return set;
}

// Reads at most limit + 1 bytes, so an endless or huge stream is refused, not buffered.
std::vector<std::uint8_t> readAll(std::istream& in, const std::string& source)
{
  std::vector<std::uint8_t> bytes;
  char buffer[65536];
  while (in) {
    in.read(buffer, sizeof buffer);
    const auto got = static_cast<std::size_t>(in.gcount());
    bytes.insert(bytes.end(), buffer, buffer + got);
    if (bytes.size() > kMaxTemplateFileBytes) {
      throw std::runtime_error(
        source + ": larger than the " + std::to_string(kMaxTemplateFileBytes) + "-byte limit");
    }
  }
  if (in.bad()) {
    throw std::runtime_error(source + ": read error");
  }
  return bytes;
}

} // namespace

void writeTemplates(std::ostream& out, const TemplateSet& set)
{
  const std::vector<std::uint8_t> bytes = serialize(set);
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    throw std::runtime_error("writeTemplates: write failed");
  }
}

void saveTemplates(const std::string& path, const TemplateSet& set)
{
  const std::vector<std::uint8_t> bytes = serialize(set); // fail before touching the file
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) {
    throw std::runtime_error("template file '" + path + "': cannot open for writing");
  }
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    throw std::runtime_error("template file '" + path + "': write failed");
  }
}

TemplateSet parseTemplates(const std::uint8_t* data, std::size_t size)
{
  if (data == nullptr && size != 0) {
    throw std::runtime_error("template data: null pointer");
  }
  return parse(data, size, "template data");
}

TemplateSet readTemplates(std::istream& in)
{
  const std::vector<std::uint8_t> bytes = readAll(in, "template stream");
  return parse(bytes.data(), bytes.size(), "template stream");
}

TemplateSet loadTemplates(const std::string& path)
{
  const std::string source = "template file '" + path + "'";
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw std::runtime_error(source + ": cannot open (missing or unreadable)");
  }
  const std::vector<std::uint8_t> bytes = readAll(in, source);
  return parse(bytes.data(), bytes.size(), source);
}

} // namespace scatterer
