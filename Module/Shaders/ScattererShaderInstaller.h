// Puts the illumination GLSL and its uniforms on a volume's shader property,
// and takes them off again, leaving nothing behind.
//
// The replacements live on the vtkVolume's shader property, not on the mapper:
// a volume later given to another mapper would keep them, so the mapper calls
// RemoveIllumination whenever a volume stops being illuminated. Replacements
// are added only when their text changes, because every
// AddFragmentShaderReplacement marks the property modified and makes the stock
// mapper rebuild its shader.
#ifndef ScattererShaderInstaller_h
#define ScattererShaderInstaller_h

#include "ScattererTemplateModule.h" // for export macro (used by the tests)

#include <string>
#include <vector>

class vtkVolume;

namespace scatterer_scene
{
struct LightSet;
}

namespace scatterer_shader
{
/** Values of the st_* uniforms for one frame. */
struct UniformValues
{
  int TemplatesPerMaterial = 8;
  int PhotonCount = 24;
  float PhotonThreshold = 0.002f;
  float OcclusionScale = 1.0f;
  float LongRange = 3.0f;
  int Interval = 4;
  float ToTex[3][3] = {};
  /// transport mode: dataset coordinates -> light texture coordinates (row-major)
  double DatasetToTransport[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  float IndexOrigin[3] = { 0, 0, 0 }; ///< extent index of the first voxel (template hash)
  const scatterer_scene::LightSet* Lights = nullptr;
  std::vector<float> MaterialRanges; ///< 2 per material
  std::vector<float> MaterialColors; ///< 3 per material
  std::vector<float> SpeedRatios;    ///< materials^2
  std::vector<float> OpacityRatios;  ///< materials^2
};

/** A texture the shader samples: its uniform name and GLSL sampler type. */
struct Sampler
{
  std::string Name;
  std::string Type; ///< "sampler2D", "sampler3D"
};

/**
 * Adds (or updates, if the text changed) the illumination replacements, and
 * retypes the @p samplers' int uniforms (vtkUniforms has no sampler type).
 */
void InstallIllumination(vtkVolume* volume, const std::string& declarations,
  const std::string& shadingInit, const std::string& shading, const std::string& shadingExit,
  const std::vector<Sampler>& samplers);

/**
 * Sets every st_* value uniform (values only, so no shader rebuild unless sizes
 * change) and removes the st_* uniforms that are neither set here nor one of the
 * @p samplers (whose texture units the caller sets).
 */
void SetIlluminationUniforms(
  vtkVolume* volume, const UniformValues& values, const std::vector<Sampler>& samplers);

/** Removes the replacements and every st_* uniform, if present. */
SCATTERERTEMPLATE_EXPORT void RemoveIllumination(vtkVolume* volume);

/** Number of illumination replacements and st_* uniforms on the volume's shader property. */
SCATTERERTEMPLATE_EXPORT int CountIlluminationLeftovers(vtkVolume* volume);
}

#endif
