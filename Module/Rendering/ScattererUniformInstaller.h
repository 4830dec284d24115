// The last stage before the ray caster renders an illuminated frame: the frame's GLSL,
// its st_* uniform values and the texture its shader samples, put on the volume.
//
// The shader text and uniforms live on the volume's shader property
// (Shaders/ScattererShaderInstaller.h installs them, only when they change); this
// gathers their values from the plan and the settings, and binds the sampled texture
// (the light transport volume, or the packed templates per sample) around the render.
#ifndef ScattererUniformInstaller_h
#define ScattererUniformInstaller_h

#include "ScattererShaderInstaller.h"

#include <vector>

class vtkTextureObject;
class vtkVolume;

namespace scatterer_render
{
struct FramePlan;
struct IlluminationParameters;

/** The textures of a frame's shader. */
struct FrameTextures
{
  /// Transport mode: the received-light texture, and dataset -> light texture
  /// coordinates (row-major).
  vtkTextureObject* TransportLight = nullptr;
  double DatasetToTransport[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  /// Per-sample mode: the packed templates.
  vtkTextureObject* Templates = nullptr;
  /// Texels per row of the packed templates (the most photons any template keeps).
  int PackedWidth = 0;
};

/**
 * Installs a frame's GLSL and st_* uniforms on the volume and binds the texture its
 * shader samples around the ray caster's render.
 */
class UniformInstaller
{
public:
  /** Puts the frame's GLSL, uniforms and sampler declarations on @p volume. */
  void Install(vtkVolume* volume, const FramePlan& plan, const IlluminationParameters& parameters,
    const FrameTextures& textures);

  /** Just before the ray caster renders: activates the textures, sets their samplers' units. */
  void BindTextures(vtkVolume* volume);

  /** Just after. */
  void UnbindTextures();

private:
  std::vector<scatterer_shader::Sampler> Samplers;
  std::vector<vtkTextureObject*> Textures; // one per sampler
};
}

#endif
