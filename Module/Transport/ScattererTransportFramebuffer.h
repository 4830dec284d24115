// The framebuffer side of the light transport passes: the GL state they run in, and
// drawing a full-screen quad into the layers of 3D textures: all the layers of a pass
// in one instanced draw (layered rendering, scatterer_transport_layers_gs.glsl), except
// the sweep, which draws one slice after another.
#ifndef ScattererTransportFramebuffer_h
#define ScattererTransportFramebuffer_h

#include "vtkOpenGLState.h" // for the scoped state

#include <functional>
#include <initializer_list>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

namespace scatterer_gpu
{
/** The GL state of the transport passes for its lifetime (no blending, depth or scissor
 * test, @p framebuffer bound), and the caller's restored after them (its scissor box
 * too: the renderer's viewport keeps to it). */
class TransportPassState
{
public:
  TransportPassState(vtkOpenGLRenderWindow* window, vtkOpenGLFramebufferObject* framebuffer);
  ~TransportPassState();
  TransportPassState(const TransportPassState&) = delete;
  TransportPassState& operator=(const TransportPassState&) = delete;

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable Depth;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  vtkOpenGLState::ScopedglScissor ScissorBox; // a directional light's mean draws a part
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
};

/** Attaches layer @p layer of 3D @p texture as colour attachment @p index of the bound
 * draw framebuffer. */
void AttachLayer(unsigned int index, vtkTextureObject* texture, int layer);

/** Attaches all the layers of 3D @p texture as colour attachment @p index of the bound
 * draw framebuffer (layered: a draw's gl_Layer chooses the layer). */
void AttachLayered(unsigned int index, vtkTextureObject* texture);

/** Attaches all the layers of each of the 3D @p targets, in order, as colour attachments
 * 0, 1, ... of @p framebuffer (bound as the draw framebuffer) and draws into them all. */
void AttachLayeredTargets(
  vtkOpenGLFramebufferObject* framebuffer, std::initializer_list<vtkTextureObject*> targets);

/** Draws @p quad (a program with the layered geometry shader) into layers
 * [@p first, @p first + @p count) of the layered attachments: one draw call. */
void DrawInstances(vtkOpenGLQuadHelper* quad, vtkShaderProgram* program, int first, int count);

/** Attaches 2D @p texture as colour attachment @p index of the bound draw framebuffer. */
void Attach2D(unsigned int index, vtkTextureObject* texture);

/** Leaves no texture attached to @p framebuffer (the textures are sampled by later
 * passes and the ray caster). */
void DetachAll(vtkOpenGLFramebufferObject* framebuffer);

/** Draws @p quad into every layer of the 3D @p targets (all of the same size, attached
 * layered as colour attachments in order) in one draw call; @p program gets the layer
 * as st_layer. Detaches them after. */
void DrawLayers(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, std::initializer_list<vtkTextureObject*> targets, int layers);

/** DrawLayers, for the layers @p z for which @p draw(z) holds: one draw call per run of
 * consecutive such layers. */
void DrawLayersWhere(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, std::initializer_list<vtkTextureObject*> targets, int layers,
  const std::function<bool(int)>& draw);

/** Sums what the following draws write into what the targets hold (additive blending). */
void BlendAdditively(vtkOpenGLState* state);
}

#endif
