// libFuzzer target: the template generator's parameters (docs/fuzzing.md).
//
// The input decodes (GeneratorInput.h) to 1-2 materials, GeneratorSettings, a template
// index, a pack cap and a texel format, any of them NaN, infinite, negative or huge.
// Properties checked (a violation traps, which libFuzzer reports as a crash):
//  - validate(), meanFreePath(), generateTemplate(s)/generateAllTemplates and
//    packTemplates throw std::invalid_argument exactly when an input is invalid; any
//    other exception escapes and is reported too;
//  - a generated template's ledger closes (|residual| <= 1e-6 * initial) with finite,
//    non-negative entries; photons are finite, inside the unit sphere, have finite
//    positive intensity, are sorted by descending intensity and sum to ledger.stored;
//    caps hold; generation is deterministic;
//  - the generated set writes to the template file format and reads back bit-identically;
//  - the packed texture has the documented layout (zeros after photonCount, no NaN).
// Time: valid settings get their caps clamped (kFuzzMax*) so one input takes a few ms.
#include "GeneratorInput.h"

#include <scatterer/Pack.h>
#include <scatterer/Template.h>
#include <scatterer/TemplateIO.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace scatterer;

namespace {

constexpr int kFuzzMaxEvents = 2048;
constexpr int kFuzzMaxPhotons = 1024;
constexpr int kFuzzMaxTemplates = 2;

template <typename F> bool throwsInvalidArgument(F&& f)
{
  try {
    f();
  } catch (const std::invalid_argument& e) {
    FUZZ_CHECK(e.what()[0] != '\0', "empty invalid_argument message");
    return true;
  }
  return false;
}

void checkTemplate(const Template& t, const GeneratorSettings& s)
{
  const EnergyLedger& l = t.ledger;
  FUZZ_CHECK(l.initial == 1.0, "ledger.initial %.17g", l.initial);
  const double fields[] = { l.stored, l.lostInTransit, l.escaped, l.droppedBelowThreshold,
    l.droppedAtCap };
  for (double f : fields) {
    FUZZ_CHECK(std::isfinite(f) && f >= 0.0, "ledger entry %.17g", f);
  }
  FUZZ_CHECK(std::fabs(l.residual()) <= 1e-6 * l.initial, "ledger residual %.17g", l.residual());
  FUZZ_CHECK(t.events <= static_cast<std::uint64_t>(s.maxEventsPerTemplate), "events %llu > cap",
    static_cast<unsigned long long>(t.events));
  FUZZ_CHECK(t.photons.size() <= static_cast<std::size_t>(s.maxPhotonsPerTemplate),
    "%zu photons > cap", t.photons.size());
  FUZZ_CHECK(t.capped || l.droppedAtCap == 0.0, "droppedAtCap %.17g without a cap", l.droppedAtCap);

  double sum = 0.0;
  for (std::size_t j = 0; j < t.photons.size(); ++j) {
    const Photon& p = t.photons[j];
    FUZZ_CHECK(
      std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z),
      "photon %zu position not finite", j);
    FUZZ_CHECK(std::isfinite(p.intensity) && p.intensity > 0.0f, "photon %zu intensity %.9g", j,
      static_cast<double>(p.intensity));
    const double r2 = double(p.position.x) * p.position.x + double(p.position.y) * p.position.y +
                      double(p.position.z) * p.position.z;
    FUZZ_CHECK(
      r2 <= (1.0 + 1e-5) * (1.0 + 1e-5), "photon %zu outside the sphere (r^2 %.17g)", j, r2);
    FUZZ_CHECK(j == 0 || p.intensity <= t.photons[j - 1].intensity, "photons unsorted at %zu", j);
    sum += p.intensity;
  }
  // Photon intensities are the float-rounded per-cell sums that make up ledger.stored.
  FUZZ_CHECK(std::fabs(sum - l.stored) <= 1e-6 * l.stored + 1e-30,
    "photons sum %.17g, stored %.17g", sum, l.stored);
}

void checkPacked(const PackedTemplates& packed, const std::vector<std::vector<Template>>& all,
  int cap, TexelFormat format)
{
  std::size_t rows = 0;
  std::size_t width = 0;
  for (const auto& templates : all) {
    rows += templates.size();
    for (const Template& t : templates) {
      width = std::max(width, std::min(t.photons.size(), static_cast<std::size_t>(cap)));
    }
  }
  if (rows > 0) {
    width = std::max<std::size_t>(width, 1);
  }
  FUZZ_CHECK(packed.format == format, "format");
  FUZZ_CHECK(
    static_cast<std::size_t>(packed.height) == rows, "height %d, rows %zu", packed.height, rows);
  FUZZ_CHECK(
    static_cast<std::size_t>(packed.width) == width, "width %d, expected %zu", packed.width, width);
  FUZZ_CHECK(packed.rgba.size() == width * rows * 4, "rgba size %zu", packed.rgba.size());
  FUZZ_CHECK(format == TexelFormat::RGBA32F ? packed.rgbaHalf.empty()
                                            : packed.rgbaHalf.size() == packed.rgba.size(),
    "rgbaHalf size %zu", packed.rgbaHalf.size());
  FUZZ_CHECK(packed.photonCount.size() == rows && packed.truncatedIntensity.size() == rows,
    "per-row arrays");
  FUZZ_CHECK(
    packed.materialFirstRow.size() == all.size() && packed.materialRowCount.size() == all.size(),
    "per-material arrays");
  FUZZ_CHECK(
    packed.byteCount() == width * rows * (format == TexelFormat::RGBA16F ? 8 : 16), "byteCount");

  std::size_t row = 0;
  for (std::size_t m = 0; m < all.size(); ++m) {
    FUZZ_CHECK(packed.materialFirstRow[m] == static_cast<int>(row), "materialFirstRow[%zu]", m);
    FUZZ_CHECK(packed.materialRowCount[m] == static_cast<int>(all[m].size()), "materialRowCount");
    for (const Template& t : all[m]) {
      const int count = packed.photonCount[row];
      const std::size_t kept = std::min(t.photons.size(), static_cast<std::size_t>(cap));
      FUZZ_CHECK(
        count >= 0 && static_cast<std::size_t>(count) <= kept, "row %zu count %d", row, count);
      const double truncated = packed.truncatedIntensity[row];
      FUZZ_CHECK(std::isfinite(truncated) && truncated >= 0.0, "truncated %.17g", truncated);
      double packedSum = 0.0;
      for (std::size_t j = 0; j < width; ++j) {
        const float* texel = &packed.rgba[(row * width + j) * 4];
        if (j < static_cast<std::size_t>(count)) {
          for (int c = 0; c < 4; ++c) {
            FUZZ_CHECK(std::isfinite(texel[c]), "row %zu texel %zu not finite", row, j);
          }
          FUZZ_CHECK(texel[3] > 0.0f, "row %zu texel %zu has w <= 0 before photonCount", row, j);
          if (format == TexelFormat::RGBA32F) {
            const Photon& p = t.photons[j];
            FUZZ_CHECK(
              fuzz::sameBits(texel[0], p.position.x) && fuzz::sameBits(texel[1], p.position.y) &&
                fuzz::sameBits(texel[2], p.position.z) && fuzz::sameBits(texel[3], p.intensity),
              "row %zu texel %zu differs from the photon", row, j);
          }
          packedSum += texel[3];
        } else {
          for (int c = 0; c < 4; ++c) {
            FUZZ_CHECK(texel[c] == 0.0f, "row %zu texel %zu not zero after photonCount", row, j);
          }
        }
      }
      if (format == TexelFormat::RGBA32F) {
        // Every photon has intensity > 0, so in float format only the cap truncates.
        FUZZ_CHECK(
          static_cast<std::size_t>(count) == kept, "row %zu count %d, kept %zu", row, count, kept);
        double total = 0.0;
        for (const Photon& p : t.photons) {
          total += p.intensity;
        }
        FUZZ_CHECK(std::fabs(packedSum + truncated - total) <= 1e-9 * total + 1e-30,
          "row %zu packed %.17g + truncated %.17g != %.17g", row, packedSum, truncated, total);
      }
      ++row;
    }
  }
}

void checkFileRoundTrip(const GeneratorSettings& s, const std::vector<Material>& materials,
  const std::vector<std::vector<Template>>& all)
{
  TemplateSet set;
  set.settings = s;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    set.materials.push_back({ materials[m], all[m] });
  }
  std::ostringstream out;
  try {
    writeTemplates(out, set);
  } catch (const std::exception& e) {
    FUZZ_CHECK(false, "writeTemplates refused generated templates: %s", e.what());
  }
  const std::string bytes = out.str();
  TemplateSet back;
  try {
    back = parseTemplates(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  } catch (const std::exception& e) {
    FUZZ_CHECK(false, "parseTemplates refused what writeTemplates wrote: %s", e.what());
  }
  FUZZ_CHECK(fuzz::sameSet(set, back), "file round trip is not bit-identical");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  fuzz::Bytes bytes(data, size);
  fuzz::GeneratorInput in = fuzz::decodeGeneratorInput(bytes);
  GeneratorSettings& s = in.settings;

  bool materialsValid = true;
  for (const Material& m : in.materials) {
    const bool invalid = throwsInvalidArgument([&] { m.validate(); });
    materialsValid = materialsValid && !invalid;
    double lambda = 0.0;
    FUZZ_CHECK(throwsInvalidArgument([&] { lambda = meanFreePath(m); }) == invalid,
      "meanFreePath and validate disagree");
    if (!invalid) {
      // +inf for opacity 0, and for subnormal opacities whose 1 / (sqrt(2) opacity)
      // overflows (the generator then treats them as transparent, which they are to
      // within double precision).
      FUZZ_CHECK(lambda > 0.0 && (std::isfinite(lambda) || m.opacity < 1e-300),
        "meanFreePath %.17g for opacity %.17g", lambda, m.opacity);
    }
  }
  const bool settingsValid = !throwsInvalidArgument([&] { s.validate(); });
  if (settingsValid) {
    // Bound the time per input; the unclamped values were validated above.
    s.maxEventsPerTemplate = std::min(s.maxEventsPerTemplate, kFuzzMaxEvents);
    s.maxPhotonsPerTemplate = std::min(s.maxPhotonsPerTemplate, kFuzzMaxPhotons);
    s.templatesPerMaterial = std::min(s.templatesPerMaterial, kFuzzMaxTemplates);
    s.validate(); // still valid
  }
  const Material& first = in.materials.front();
  const bool firstValid = !throwsInvalidArgument([&] { first.validate(); });

  // One template by index (negative indices must be refused).
  const bool singleValid = firstValid && settingsValid && in.templateIndex >= 0;
  Template single;
  FUZZ_CHECK(throwsInvalidArgument(
               [&] { single = generateTemplate(first, s, in.templateIndex); }) == !singleValid,
    "generateTemplate: invalid_argument iff invalid input (material %d settings %d index %d)",
    firstValid, settingsValid, in.templateIndex);
  if (singleValid) {
    checkTemplate(single, s);
  }

  // All templates of all materials.
  const bool allValid = materialsValid && settingsValid;
  std::vector<std::vector<Template>> all;
  FUZZ_CHECK(
    throwsInvalidArgument([&] { all = generateAllTemplates(in.materials, s); }) == !allValid,
    "generateAllTemplates: invalid_argument iff invalid input");
  if (!allValid) {
    return 0;
  }
  FUZZ_CHECK(all.size() == in.materials.size(), "one template list per material");
  for (const auto& templates : all) {
    FUZZ_CHECK(
      templates.size() == static_cast<std::size_t>(s.templatesPerMaterial), "templatesPerMaterial");
    for (const Template& t : templates) {
      checkTemplate(t, s);
    }
  }
  // Determinism: material 0 of generateAllTemplates uses materialSeed(seed, 0).
  if (in.templateIndex >= 0 && in.templateIndex < s.templatesPerMaterial) {
    GeneratorSettings s0 = s;
    s0.seed = materialSeed(s.seed, 0);
    FUZZ_CHECK(fuzz::sameTemplate(generateTemplate(first, s0, in.templateIndex),
                 all[0][static_cast<std::size_t>(in.templateIndex)]),
      "generation is not deterministic");
  }

  checkFileRoundTrip(s, in.materials, all);

  const TexelFormat format = in.halfFormat ? TexelFormat::RGBA16F : TexelFormat::RGBA32F;
  const bool capValid = in.packCap >= 1 && in.packCap <= kMaxPackWidth;
  PackedTemplates packed;
  FUZZ_CHECK(
    throwsInvalidArgument([&] { packed = packTemplates(all, in.packCap, format); }) == !capValid,
    "packTemplates: invalid_argument iff the cap %d is invalid", in.packCap);
  if (capValid) {
    checkPacked(packed, all, in.packCap, format);
  }
  return 0;
}
