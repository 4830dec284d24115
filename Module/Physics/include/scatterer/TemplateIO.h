// Saving and loading templates in the small binary format of docs/model.md
// ("Template file format"): magic + version header, the generator settings, then per
// material its parameters and templates (ledger + photons x y z intensity), and a
// FNV-1a 64 checksum. All numbers little-endian; floats stored as IEEE bit patterns,
// so a round trip is bit-identical.
#pragma once

#include <scatterer/GeneratorSettings.h>
#include <scatterer/Material.h>
#include <scatterer/Template.h>

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace scatterer {

struct MaterialTemplates {
  Material material;
  std::vector<Template> templates;
};

// Everything needed to reproduce or inspect a set of templates.
struct TemplateSet {
  GeneratorSettings settings;
  std::vector<MaterialTemplates> materials;
};

constexpr std::uint32_t kTemplateFileVersion = 1;
// Readers refuse anything larger, so a hostile file cannot make them allocate much.
constexpr std::size_t kMaxTemplateFileBytes = std::size_t(256) << 20;
constexpr std::uint32_t kMaxFileMaterials = 4096;

// Throw std::invalid_argument if the set breaks an invariant the reader checks
// (invalid material/settings, a NUL in a material name, a material without exactly
// settings.templatesPerMaterial templates, a template over the settings' photon or event
// cap, unsorted or non-finite photons, a ledger that does not close), and
// std::runtime_error when the stream or file cannot be written.
void writeTemplates(std::ostream& out, const TemplateSet& set);
void saveTemplates(const std::string& path, const TemplateSet& set);

// Throw std::runtime_error with a message saying what is wrong and where (missing file,
// truncation, bad magic, unsupported version, absurd counts, counts that disagree with
// the settings or the content, a NUL in a name, invalid values, checksum mismatch,
// trailing bytes). Never allocates more than a small multiple of the input size.
TemplateSet parseTemplates(const std::uint8_t* data, std::size_t size);
TemplateSet readTemplates(std::istream& in);
TemplateSet loadTemplates(const std::string& path);

} // namespace scatterer
