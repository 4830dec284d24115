// The framebuffer side of the light transport passes: the GL state they run in, and
// drawing a full-screen quad into each layer of 3D textures (a fragment pass renders
// one 2D layer per draw).
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
 * test, @p framebuffer bound), and the caller's restored after them. */
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
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
};

/** Attaches layer @p layer of 3D @p texture as colour attachment @p index of the bound
 * draw framebuffer. */
void AttachLayer(unsigned int index, vtkTextureObject* texture, int layer);

/** Attaches 2D @p texture as colour attachment @p index of the bound draw framebuffer. */
void Attach2D(unsigned int index, vtkTextureObject* texture);

/** Leaves no texture attached to @p framebuffer (the textures are sampled by later
 * passes and the ray caster). */
void DetachAll(vtkOpenGLFramebufferObject* framebuffer);

/** Draws @p quad once per layer of the 3D @p targets (all of the same size), each
 * layer attached as a colour attachment in order; @p program gets the layer as
 * st_layer. Detaches them after. */
void DrawLayers(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, std::initializer_list<vtkTextureObject*> targets, int layers);

/** DrawLayers, for the layers @p z for which @p draw(z) holds. */
void DrawLayersWhere(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, std::initializer_list<vtkTextureObject*> targets, int layers,
  const std::function<bool(int)>& draw);

/** Sums what the following draws write into what the targets hold (additive blending). */
void BlendAdditively(vtkOpenGLState* state);
}

#endif
