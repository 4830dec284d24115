#include "ScattererShaderInstaller.h"

#include "ScattererSceneLights.h"
#include "ScattererSceneMaterials.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkShader.h"
#include "vtkUniforms.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <vector>

namespace scatterer_shader
{
namespace
{
const char* const kDecTag = "//VTK::ComputeRayDirection::Dec";
const char* const kImplTag = "//VTK::Shading::Impl";
const char* const kInitTag = "//VTK::Shading::Init";
const char* const kExitTag = "//VTK::Shading::Exit";
// vtkUniforms has no sampler type: samplers are declared as int and retyped
// after VTK's own replacements have inserted the declaration.
const char* const kSamplerPrefix = "uniform int st_";

vtkOpenGLShaderProperty* Property(vtkVolume* volume)
{
  return volume ? vtkOpenGLShaderProperty::SafeDownCast(volume->GetShaderProperty()) : nullptr;
}

// The replacement for (tag, first), or nullptr.
const vtkShader::ReplacementValue* Find(vtkOpenGLShaderProperty* sp, const char* tag, bool first)
{
  for (const auto& r : sp->GetAllShaderReplacements())
  {
    if (r.first.ShaderType == vtkShader::Fragment && r.first.OriginalValue == tag &&
      r.first.ReplaceFirst == first)
    {
      return &r.second;
    }
  }
  return nullptr;
}

void Ensure(vtkOpenGLShaderProperty* sp, const char* tag, bool first, const std::string& text)
{
  const vtkShader::ReplacementValue* current = Find(sp, tag, first);
  if (!current || current->Replacement != text || current->ReplaceAll)
  {
    sp->AddFragmentShaderReplacement(tag, first, text, false);
  }
}

std::vector<std::string> IlluminationUniformNames(vtkUniforms* uniforms)
{
  std::vector<std::string> names;
  for (int i = 0; i < uniforms->GetNumberOfUniforms(); ++i)
  {
    const char* name = uniforms->GetNthUniformName(i);
    if (name && std::strncmp(name, "st_", 3) == 0)
    {
      names.emplace_back(name);
    }
  }
  return names;
}

void Set3(vtkUniforms* u, const char* name, const float* values, int count)
{
  u->SetUniform3fv(name, count, reinterpret_cast<const float(*)[3]>(values));
}
}

// Post-replacements that retype our sampler uniforms.
std::vector<std::string> SamplerReplacements(vtkOpenGLShaderProperty* sp)
{
  std::vector<std::string> found;
  for (const auto& r : sp->GetAllShaderReplacements())
  {
    if (r.first.ShaderType == vtkShader::Fragment && !r.first.ReplaceFirst &&
      r.first.OriginalValue.rfind(kSamplerPrefix, 0) == 0)
    {
      found.push_back(r.first.OriginalValue);
    }
  }
  return found;
}

void InstallIllumination(vtkVolume* volume, const std::string& declarations,
  const std::string& shadingInit, const std::string& shading, const std::string& shadingExit,
  const std::vector<Sampler>& samplers)
{
  vtkOpenGLShaderProperty* sp = Property(volume);
  if (!sp)
  {
    return;
  }
  // Starting with VTK's own tag keeps VTK's text, so our functions come after
  // computeOpacity, computeColor and in_volume[] are declared.
  Ensure(sp, kDecTag, true, std::string(kDecTag) + "\n" + declarations);
  Ensure(sp, kInitTag, true, shadingInit);
  Ensure(sp, kImplTag, true, shading);
  // After the ray loop: VTK's own exit code first (kept by its tag), then ours.
  if (shadingExit.empty())
  {
    if (Find(sp, kExitTag, true))
    {
      sp->ClearFragmentShaderReplacement(kExitTag, true);
    }
  }
  else
  {
    Ensure(sp, kExitTag, true, std::string(kExitTag) + "\n" + shadingExit);
  }
  std::vector<std::string> wanted;
  for (const auto& sampler : samplers)
  {
    wanted.push_back("uniform int " + sampler.Name + ";");
    Ensure(sp, wanted.back().c_str(), false, "uniform " + sampler.Type + " " + sampler.Name + ";");
  }
  for (const auto& existing : SamplerReplacements(sp))
  {
    if (std::find(wanted.begin(), wanted.end(), existing) == wanted.end())
    {
      sp->ClearFragmentShaderReplacement(existing, false);
    }
  }
}

void SetIlluminationUniforms(
  vtkVolume* volume, const UniformValues& v, const std::vector<Sampler>& samplers)
{
  vtkOpenGLShaderProperty* sp = Property(volume);
  if (!sp || !v.Lights)
  {
    return;
  }
  vtkUniforms* u = sp->GetFragmentCustomUniforms();
  // Every st_* uniform this frame uses: the names set below and the samplers.
  std::vector<std::string> used;
  for (const auto& sampler : samplers)
  {
    used.push_back(sampler.Name);
  }
  auto name = [&used](const char* uniform)
  {
    used.emplace_back(uniform);
    return uniform;
  };
  u->SetUniformi(name("st_templatesPerMaterial"), v.TemplatesPerMaterial);
  u->SetUniformi(name("st_photonCount"), v.PhotonCount);
  u->SetUniformf(name("st_photonThreshold"), v.PhotonThreshold);
  u->SetUniformf(name("st_occlusionScale"), v.OcclusionScale);
  u->SetUniformf(name("st_longRange"), v.LongRange);
  u->SetUniformi(name("st_interval"), v.Interval);
  u->SetUniform3f(name("st_toTexX"), v.ToTex[0]);
  u->SetUniform3f(name("st_toTexY"), v.ToTex[1]);
  u->SetUniform3f(name("st_toTexZ"), v.ToTex[2]);
  // GL takes the elements as columns: transposed, so that the GLSL reads M * v.
  vtkNew<vtkMatrix4x4> datasetToTransport;
  datasetToTransport->DeepCopy(v.DatasetToTransport);
  datasetToTransport->Transpose();
  u->SetUniformMatrix(name("st_datasetToTransport"), datasetToTransport);
  u->SetUniform3f(name("st_indexOrigin"), v.IndexOrigin);
  // Arrays always hold the limits' worth of entries (unused ones zero): VTK declares a
  // uniform array with the size it is given, so sizing them by the scene's counts
  // would make a new shader text, and a new compiled program, per count
  // (scatterer_illumination_dec.glsl).
  const scatterer_scene::LightSet& lights = *v.Lights;
  const int nl = lights.Count();
  constexpr int ml = scatterer_scene::kMaxLights;
  auto padded = [](const auto& values, size_t size)
  {
    std::vector<typename std::decay_t<decltype(values)>::value_type> out(size);
    std::copy_n(values.begin(), std::min(size, values.size()), out.begin());
    return out;
  };
  u->SetUniformi(name("st_lightCount"), nl);
  Set3(u, name("st_lightDir"), padded(lights.Direction, 3 * ml).data(), ml);
  Set3(u, name("st_lightPos"), padded(lights.Position, 3 * ml).data(), ml);
  Set3(u, name("st_lightColor"), padded(lights.Color, 3 * ml).data(), ml);
  u->SetUniform1iv(name("st_lightPositional"), ml, padded(lights.Positional, ml).data());
  u->SetUniform3f(name("st_ambient"), lights.Ambient);
  const scatterer_scene::BrightestLight brightest = scatterer_scene::FindBrightestLight(lights);
  u->SetUniformi(name("st_surfaceLight"), brightest.Index);
  u->SetUniformf(name("st_surfaceShare"), brightest.Share);
  // Brightness of an unoccluded white sample, to normalize the visibility
  // that darkens VTK's own (Phong) shading.
  float unlit = (lights.Ambient[0] + lights.Ambient[1] + lights.Ambient[2]) / 3.0f;
  for (int l = 0; l < nl; ++l)
  {
    unlit += (lights.Color[3 * l] + lights.Color[3 * l + 1] + lights.Color[3 * l + 2]) / 3.0f;
  }
  u->SetUniformf(name("st_unlitNorm"), unlit > 0.0f ? 1.0f / unlit : 1.0f);
  const int nm = static_cast<int>(v.MaterialRanges.size() / 2);
  constexpr int mm = scatterer_scene::kMaxMaterials;
  u->SetUniformi(name("st_materialCount"), nm);
  u->SetUniform2fv(name("st_matRange"), mm,
    reinterpret_cast<const float(*)[2]>(padded(v.MaterialRanges, 2 * mm).data()));
  Set3(u, name("st_matColor"), padded(v.MaterialColors, 3 * mm).data(), mm);
  // The n x n ratio tables go into mm x mm ones (row stride ST_MAX_MATERIALS).
  std::vector<float> speed(mm * mm, 1.0f), opacity(mm * mm, 1.0f);
  for (int a = 0; a < nm; ++a)
  {
    for (int b = 0; b < nm; ++b)
    {
      speed[a * mm + b] = v.SpeedRatios[a * nm + b];
      opacity[a * mm + b] = v.OpacityRatios[a * nm + b];
    }
  }
  u->SetUniform1fv(name("st_speedRatio"), mm * mm, speed.data());
  u->SetUniform1fv(name("st_opacityRatio"), mm * mm, opacity.data());
  // Drop the rest (e.g. the other mode's samplers, which would stay declared as
  // plain ints). Removing only what is unused keeps the uniform list, and so the
  // shader, unchanged from frame to frame.
  for (const auto& existing : IlluminationUniformNames(u))
  {
    if (std::find(used.begin(), used.end(), existing) == used.end())
    {
      u->RemoveUniform(existing.c_str());
    }
  }
}

void RemoveIllumination(vtkVolume* volume)
{
  vtkOpenGLShaderProperty* sp = Property(volume);
  if (!sp)
  {
    return;
  }
  if (Find(sp, kDecTag, true))
  {
    sp->ClearFragmentShaderReplacement(kDecTag, true);
  }
  if (Find(sp, kImplTag, true))
  {
    sp->ClearFragmentShaderReplacement(kImplTag, true);
  }
  if (Find(sp, kInitTag, true))
  {
    sp->ClearFragmentShaderReplacement(kInitTag, true);
  }
  if (Find(sp, kExitTag, true))
  {
    sp->ClearFragmentShaderReplacement(kExitTag, true);
  }
  for (const auto& sampler : SamplerReplacements(sp))
  {
    sp->ClearFragmentShaderReplacement(sampler, false);
  }
  vtkUniforms* u = sp->GetFragmentCustomUniforms();
  for (const auto& name : IlluminationUniformNames(u))
  {
    u->RemoveUniform(name.c_str());
  }
}

int CountIlluminationLeftovers(vtkVolume* volume)
{
  vtkOpenGLShaderProperty* sp = Property(volume);
  if (!sp)
  {
    return 0;
  }
  int count = 0;
  count += Find(sp, kDecTag, true) ? 1 : 0;
  count += Find(sp, kImplTag, true) ? 1 : 0;
  count += Find(sp, kInitTag, true) ? 1 : 0;
  count += Find(sp, kExitTag, true) ? 1 : 0;
  count += static_cast<int>(SamplerReplacements(sp).size());
  count += static_cast<int>(IlluminationUniformNames(sp->GetFragmentCustomUniforms()).size());
  return count;
}
}
