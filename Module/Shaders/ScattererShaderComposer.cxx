#include "ScattererShaderComposer.h"

#include "ScattererSceneLights.h"
#include "ScattererSceneMaterials.h"

#include "scatterer_illumination_dec.h"
#include "scatterer_shading_exit.h"
#include "scatterer_shading_impl.h"
#include "scatterer_shading_init.h"
#include "scatterer_shading_part.h"

#include <sstream>
#include <stdexcept>
#include <vector>

namespace scatterer_shader
{
namespace
{
// Transport on one volume with samples that share a light read: the composite step is
// written out LightStride times (scatterer_shading_impl.glsl).
bool Grouped(const Features& f)
{
  return f.Transport && f.Parts == 0 && f.LightStride > 1;
}
}

bool Features::operator==(const Features& o) const
{
  return this->Lights == o.Lights && this->Materials == o.Materials && this->Shadow == o.Shadow &&
    this->Thin == o.Thin && this->Bleed == o.Bleed && this->Boundary == o.Boundary &&
    this->Positional == o.Positional && this->Blend2 == o.Blend2 && this->Phong == o.Phong &&
    this->Transport == o.Transport && this->LabelMask == o.LabelMask &&
    this->Components == o.Components && this->Parts == o.Parts &&
    this->LightStride == o.LightStride && this->SurfaceDetail == o.SurfaceDetail;
}

std::string Features::Describe() const
{
  std::ostringstream out;
  out << (this->Transport ? "transport" : "per-sample") << " lights=" << this->Lights
      << " materials=" << this->Materials;
  const std::pair<bool, const char*> names[] = { { this->Shadow, "shadow" }, { this->Thin, "thin" },
    { this->Bleed, "bleed" }, { this->Boundary, "boundary" }, { this->Positional, "positional" },
    { this->Blend2, "blend2" }, { this->Phong, "phong" }, { this->LabelMask, "labelmask" },
    { this->Components == Scalars::Independent, "independent" },
    { this->Components == Scalars::Dependent, "dependent" }, { this->SurfaceDetail, "surface" } };
  for (const auto& n : names)
  {
    if (n.first)
    {
      out << " " << n.second;
    }
  }
  if (this->Parts > 0)
  {
    out << " parts=" << this->Parts;
  }
  if (Grouped(*this))
  {
    out << " light-stride=" << this->LightStride;
  }
  return out.str();
}

std::string Preprocess(const std::string& text, const std::map<std::string, bool>& flags,
  const std::map<std::string, std::string>& values)
{
  // Stack of (this block is kept, the enclosing blocks are kept).
  std::vector<std::pair<bool, bool>> stack;
  auto keeping = [&]() { return stack.empty() || (stack.back().first && stack.back().second); };
  std::istringstream in(text);
  std::string out;
  std::string line;
  int number = 0;
  while (std::getline(in, line))
  {
    ++number;
    const auto first = line.find_first_not_of(" \t");
    const std::string trimmed = first == std::string::npos ? "" : line.substr(first);
    if (trimmed.rfind("//ST::IF ", 0) == 0)
    {
      const std::string name = trimmed.substr(9);
      const auto flag = flags.find(name);
      const bool enclosing = keeping();
      stack.emplace_back(flag != flags.end() && flag->second, enclosing);
      continue;
    }
    if (trimmed == "//ST::ELSE" || trimmed == "//ST::ENDIF")
    {
      if (stack.empty())
      {
        throw std::runtime_error(
          "shader template line " + std::to_string(number) + ": " + trimmed + " without //ST::IF");
      }
      if (trimmed == "//ST::ELSE")
      {
        stack.back().first = !stack.back().first;
      }
      else
      {
        stack.pop_back();
      }
      continue;
    }
    if (!keeping())
    {
      continue;
    }
    for (const auto& v : values)
    {
      const std::string key = "@" + v.first + "@";
      for (auto pos = line.find(key); pos != std::string::npos; pos = line.find(key, pos))
      {
        line.replace(pos, key.size(), v.second);
        pos += v.second.size();
      }
    }
    out += line;
    out += '\n';
  }
  if (!stack.empty())
  {
    throw std::runtime_error("shader template: an //ST::IF is not closed by //ST::ENDIF");
  }
  return out;
}

namespace
{
std::map<std::string, bool> Flags(const Features& f)
{
  return { { "SHADOW", f.Shadow }, { "THIN", f.Shadow && f.Thin }, { "BLEED", f.Bleed },
    { "BOUNDARY", f.Boundary && f.Materials > 1 }, { "POSITIONAL", f.Positional },
    { "BLEND2", f.Blend2 }, { "PHONG", f.Phong },
    { "FETCH", f.Shadow || f.Bleed || (f.Boundary && f.Materials > 1) },
    { "TRANSPORT", f.Transport }, { "GROUPED", Grouped(f) }, { "PERSAMPLE", !f.Transport },
    { "LABELMASK", f.LabelMask }, { "INDEPENDENT", f.Components == Features::Scalars::Independent },
    { "DEPENDENT", f.Components == Features::Scalars::Dependent }, { "MULTI", f.Parts > 0 },
    { "SURFACE", f.SurfaceDetail } };
}

// Limits, not the scene's counts, except the light slots (scatterer_illumination_dec.glsl).
std::map<std::string, std::string> Values(const Features& f)
{
  return { { "LIGHT_SLOTS", std::to_string(LightSlots(f)) },
    { "LIGHT_STRIDE", std::to_string(f.LightStride) },
    { "MAX_MATERIALS", std::to_string(scatterer_scene::kMaxMaterials) } };
}
}

int LightSlots(const Features& f)
{
  if (f.Transport)
  {
    return scatterer_scene::kMaxLights; // the transport shading has no per-light arrays
  }
  for (int slots : { 1, 2, 4 })
  {
    if (f.Lights <= slots)
    {
      return slots;
    }
  }
  return scatterer_scene::kMaxLights;
}

std::string IlluminationDeclarations(const Features& features)
{
  return std::string(kProgramMarker) + "\n" +
    Preprocess(scatterer_illumination_dec, Flags(features), Values(features));
}

std::string ShadingInitialization(const Features& features)
{
  return Preprocess(scatterer_shading_init, Flags(features), Values(features));
}

std::string ShadingExit(const Features& features)
{
  return Preprocess(scatterer_shading_exit, Flags(features), Values(features));
}

std::string ShadingImplementation(const Features& features)
{
  if (features.Parts <= 0 && !Grouped(features))
  {
    return Preprocess(scatterer_shading_impl, Flags(features), Values(features));
  }
  if (features.Parts <= 0)
  {
    // One pass of VTK's ray loop composites LightStride samples, the first reading the
    // light for all of them; the others carry VTK's per-sample tags, which VTK then
    // fills in as it fills in its loop's own.
    std::string text;
    auto flags = Flags(features);
    auto values = Values(features);
    for (int k = 0; k < features.LightStride; ++k)
    {
      flags["GROUP_START"] = k == 0;
      flags["GROUP_END"] = k == features.LightStride - 1;
      values["K"] = std::to_string(k);
      text += Preprocess(scatterer_shading_impl, flags, values);
    }
    return text;
  }
  // A vtkMultiVolume: VTK 9.1 numbers its inputs' samplers and transfer functions from 0
  // and their matrices from 1 (entry 0 is the box around them all).
  std::string text =
    "    // Composite step of a vtkMultiVolume with scatterer-template illumination.\n"
    "    if (!g_skip)\n"
    "      {\n"
    "      vec3 texPos;\n";
  const auto flags = Flags(features);
  for (int part = 0; part < features.Parts; ++part)
  {
    auto values = Values(features);
    values["PART"] = std::to_string(part);
    values["MATRIX"] = std::to_string(part + 1);
    text += Preprocess(scatterer_shading_part, flags, values);
  }
  return text + "      }\n";
}
}
