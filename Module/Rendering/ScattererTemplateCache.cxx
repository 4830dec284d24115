#include "ScattererTemplateCache.h"

#include "ScattererIlluminationParameters.h"
#include "ScattererSceneMaterials.h"
#include "ScattererWarnOnce.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <scatterer/Material.h>

#include <algorithm>
#include <cmath>

namespace scatterer_render
{
namespace
{
// The generator's photons stay well inside the unit sphere (packets fall
// below the threshold long before they escape). Scale all templates by one
// factor so the farthest photon of any material lies at radius 1: the template
// radius is then the reach of the occlusion test, and the relative spread of
// dense and clear materials is kept.
void NormalizeExtent(std::vector<std::vector<scatterer::Template>>& templates)
{
  float reach = 0.0f;
  for (const auto& material : templates)
  {
    for (const auto& t : material)
    {
      for (const auto& p : t.photons)
      {
        reach = std::max(reach,
          std::sqrt(p.position.x * p.position.x + p.position.y * p.position.y +
            p.position.z * p.position.z));
      }
    }
  }
  if (reach > 0.0f)
  {
    for (auto& material : templates)
    {
      for (auto& t : material)
      {
        for (auto& p : t.photons)
        {
          p.position /= reach;
        }
      }
    }
  }
}
}

TemplateCache::TemplateCache() = default;
TemplateCache::~TemplateCache() = default;

std::string TemplateCache::Update(const std::vector<scatterer_scene::SceneMaterial>& materials,
  const IlluminationParameters& parameters, const std::function<void(double)>& progress,
  WarnOnce& warn)
{
  KeyWriter generation;
  generation << parameters.TemplatesPerMaterial << '|' << parameters.GeneratorThreshold;
  for (const auto& m : materials)
  {
    generation << '|' << m.Physics.opacity << ',' << m.Physics.refractiveIndex;
  }
  KeyWriter packing;
  packing << generation.Key() << '|' << parameters.PhotonCap;
  const bool regenerate = this->Generated.Differs(generation.Key());
  if (!regenerate && !this->Packing.Differs(packing.Key()))
  {
    return "";
  }
  if (regenerate)
  {
    progress(0.0);
  }
  try
  {
    if (regenerate)
    {
      std::vector<scatterer::Material> physics;
      for (const auto& m : materials)
      {
        physics.push_back(m.Physics);
      }
      scatterer::GeneratorSettings settings;
      settings.templatesPerMaterial = parameters.TemplatesPerMaterial;
      settings.threshold = parameters.GeneratorThreshold;
      this->RawTemplates = scatterer::generateAllTemplates(physics, settings);
      this->Templates = this->RawTemplates;
      NormalizeExtent(this->Templates);
      this->Generated.Record(generation.Key());
    }
    this->Packed = scatterer::packTemplates(this->Templates, parameters.PhotonCap);
  }
  catch (const std::exception& e)
  {
    warn(std::string("Scatterer templates could not be generated (") + e.what() +
      "); this volume renders as vtkOpenGLGPUVolumeRayCastMapper would.");
    // The keys still describe what is kept (a stage that threw kept its old result):
    // the next frame tries again.
    return "template generation failed";
  }
  if (regenerate)
  {
    progress(1.0);
  }
  this->Packing.Record(packing.Key());
  return "";
}

vtkTextureObject* TemplateCache::GetTexture(vtkOpenGLRenderWindow* window)
{
  const bool otherContext = !this->Texture || this->Texture->GetContext() != window;
  if (otherContext || this->Uploaded.Differs(this->Packing.Get()))
  {
    if (otherContext)
    {
      this->Texture = vtkSmartPointer<vtkTextureObject>::New();
      this->Texture->SetContext(window);
    }
    this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Texture->Create2DFromRaw(this->Packed.width, this->Packed.height, 4, VTK_FLOAT,
      const_cast<float*>(this->Packed.rgba.data()));
    this->Uploaded.Record(this->Packing.Get());
  }
  return this->Texture;
}

void TemplateCache::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
    this->Texture = nullptr;
  }
  this->Uploaded.Clear();
}
}
