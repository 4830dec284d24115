// libFuzzer target: the template file reader (docs/fuzzing.md).
//
// Any bytes must give either std::runtime_error or a TemplateSet; any other exception,
// crash, sanitizer report, or allocation beyond -rss_limit_mb is a finding. An accepted set
// must re-serialize to exactly the input bytes (the format has one encoding per set) and
// re-parse to a bit-identical set, through both parseTemplates and readTemplates.
//
// Each input is tried twice: as is, and with its last 8 bytes replaced by the right
// FNV-1a 64 checksum of the bytes before them, so mutations get past the checksum and
// reach the record parsing behind it.
#include "FuzzCommon.h"

#include <scatterer/TemplateIO.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace scatterer;

namespace {

void checkInput(const std::uint8_t* data, std::size_t size)
{
  TemplateSet set;
  try {
    set = parseTemplates(data, size);
  } catch (const std::runtime_error& e) {
    FUZZ_CHECK(std::string(e.what()).rfind("template data: ", 0) == 0,
      "error message does not name its source: %s", e.what());
    // The stream reader must refuse the same bytes.
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    bool refused = false;
    try {
      readTemplates(in);
    } catch (const std::runtime_error&) {
      refused = true;
    }
    FUZZ_CHECK(refused, "readTemplates accepted what parseTemplates refused (%s)", e.what());
    return;
  }

  std::ostringstream out;
  try {
    writeTemplates(out, set);
  } catch (const std::exception& e) {
    FUZZ_CHECK(false, "writeTemplates refused a set the reader accepted: %s", e.what());
  }
  const std::string bytes = out.str();
  FUZZ_CHECK(bytes.size() == size && std::memcmp(bytes.data(), data, size) == 0,
    "re-serialized set differs from the input (%zu vs %zu bytes)", bytes.size(), size);

  const TemplateSet again =
    parseTemplates(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  FUZZ_CHECK(fuzz::sameSet(set, again), "re-parsed set differs");
  std::istringstream in(bytes);
  FUZZ_CHECK(fuzz::sameSet(set, readTemplates(in)), "readTemplates differs from parseTemplates");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  checkInput(data, size);
  if (size >= 8) {
    std::vector<std::uint8_t> fixed(data, data + size);
    const std::uint64_t sum = fuzz::fnv1a(fixed.data(), size - 8);
    for (int i = 0; i < 8; ++i) {
      fixed[size - 8 + i] = static_cast<std::uint8_t>(sum >> (8 * i));
    }
    checkInput(fixed.data(), fixed.size());
  }
  return 0;
}
