#include "ScattererUniformInstaller.h"

#include "ScattererFramePlan.h"
#include "ScattererIlluminationParameters.h"

#include "vtkImageData.h"
#include "vtkShaderProperty.h"
#include "vtkTextureObject.h"
#include "vtkUniforms.h"
#include "vtkVolume.h"

#include <algorithm>

namespace scatterer_render
{
void UniformInstaller::Install(vtkVolume* vol, const FramePlan& plan,
  const IlluminationParameters& parameters, const FrameTextures& textures)
{
  this->Samplers.clear();
  this->Textures.clear();
  scatterer_shader::UniformValues u;
  if (plan.Features.Transport)
  {
    this->Samplers.push_back({ "st_transport", "sampler3D" });
    this->Textures.push_back(textures.TransportLight);
    std::copy(textures.DatasetToTransport, textures.DatasetToTransport + 16, u.DatasetToTransport);
  }
  else
  {
    this->Samplers.push_back({ "st_templates", "sampler2D" });
    this->Textures.push_back(textures.Templates);
  }
  scatterer_shader::InstallIllumination(
    vol, plan.Declarations, plan.ShadingInit, plan.Shading, plan.ShadingExit, this->Samplers);

  u.TemplatesPerMaterial = parameters.TemplatesPerMaterial;
  u.PhotonCount = std::min(parameters.PhotonCap, textures.PackedWidth);
  u.PhotonThreshold = static_cast<float>(parameters.PhotonThreshold);
  // The per-sample photon test measures distances in template radii; the transport mode's
  // ray, marching toward the light inside a dense texel (st_surfaceChange), in world units.
  u.OcclusionScale =
    OcclusionScale(parameters.OcclusionStrength, plan.Features.Transport ? 1.0 : plan.Radius);
  u.LongRange = static_cast<float>(parameters.LongRangeMultiple);
  u.Interval = parameters.IlluminationInterval;
  int extent[6];
  plan.Image->GetExtent(extent);
  for (int c = 0; c < 3; ++c)
  {
    u.IndexOrigin[c] = static_cast<float>(extent[2 * c]);
    for (int a = 0; a < 3; ++a)
    {
      u.ToTex[c][a] = plan.ToTex[c][a];
    }
  }
  u.Lights = &plan.Lights;
  for (const auto& m : plan.Materials.Materials)
  {
    u.MaterialRanges.push_back(m.Range[0]);
    u.MaterialRanges.push_back(m.Range[1]);
    for (int c = 0; c < 3; ++c)
    {
      u.MaterialColors.push_back(m.Physics.diffuse[c]);
    }
  }
  u.SpeedRatios = plan.SpeedRatios;
  u.OpacityRatios = plan.OpacityRatios;
  scatterer_shader::SetIlluminationUniforms(vol, u, this->Samplers);
}

void UniformInstaller::BindTextures(vtkVolume* vol)
{
  vtkUniforms* fragmentUniforms = vol->GetShaderProperty()->GetFragmentCustomUniforms();
  for (size_t t = 0; t < this->Textures.size(); ++t)
  {
    this->Textures[t]->Activate();
    fragmentUniforms->SetUniformi(
      this->Samplers[t].Name.c_str(), this->Textures[t]->GetTextureUnit());
  }
}

void UniformInstaller::UnbindTextures()
{
  for (auto* texture : this->Textures)
  {
    texture->Deactivate();
  }
}
}
