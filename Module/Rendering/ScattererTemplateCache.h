// The scatterer templates of the frame's materials, kept between frames.
//
// Generating templates (a photon simulation per material, scatterer/Template.h) is
// the expensive CPU step of a frame, so it is redone only when what they are made
// from changes: the materials' opacities and refractive indices, TemplatesPerMaterial
// and GeneratorThreshold. PhotonCap only decides how many photons of each template
// the shader reads, so changing it repacks the kept templates (and re-uploads them)
// without regenerating. Each stage follows its own change key (ScattererChangeKey.h).
#ifndef ScattererTemplateCache_h
#define ScattererTemplateCache_h

#include "ScattererChangeKey.h"

#include "vtkSmartPointer.h"

#include <scatterer/Pack.h>
#include <scatterer/Template.h>

#include <functional>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace scatterer_scene
{
struct SceneMaterial;
}

namespace scatterer_render
{
struct IlluminationParameters;
class WarnOnce;

/**
 * The templates of the frame's materials: generated when the materials or generator
 * settings change, repacked when PhotonCap changes, uploaded per context when repacked.
 */
class TemplateCache
{
public:
  TemplateCache();
  ~TemplateCache();
  TemplateCache(const TemplateCache&) = delete;
  TemplateCache& operator=(const TemplateCache&) = delete;

  /**
   * Regenerates the templates of @p materials if they or the generator settings
   * changed, and repacks them if that or PhotonCap changed. @p progress hears 0
   * before a regeneration and 1 after it. Returns "" or, when the generator fails
   * (warned once through @p warn), why the volume renders as stock.
   */
  std::string Update(const std::vector<scatterer_scene::SceneMaterial>& materials,
    const IlluminationParameters& parameters, const std::function<void(double)>& progress,
    WarnOnce& warn);

  /** Per-sample mode: the packed templates as a texture of @p window, uploaded when repacked. */
  vtkTextureObject* GetTexture(vtkOpenGLRenderWindow* window);

  /** The packed templates (photons normalised to the unit sphere, at most PhotonCap per row). */
  const scatterer::PackedTemplates& GetPacked() const { return this->Packed; }

  /** Each material's templates as generated (photons in template radii), for the transport kernels.
   */
  const std::vector<std::vector<scatterer::Template>>& GetRawTemplates() const
  {
    return this->RawTemplates;
  }

  /** What the kept templates were generated from (changes exactly when they are regenerated). */
  const std::string& GetGenerationKey() const { return this->Generated.Get(); }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::vector<std::vector<scatterer::Template>> RawTemplates;
  std::vector<std::vector<scatterer::Template>> Templates; // normalised to the unit sphere
  scatterer::PackedTemplates Packed;
  vtkSmartPointer<vtkTextureObject> Texture;
  ChangeKey Generated; // materials and generator settings
  ChangeKey Packing;   // Generated and PhotonCap
  ChangeKey Uploaded;  // the Packing uploaded into Texture
};
}

#endif
