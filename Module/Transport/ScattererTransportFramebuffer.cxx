#include "ScattererTransportFramebuffer.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace scatterer_gpu
{
TransportPassState::TransportPassState(
  vtkOpenGLRenderWindow* window, vtkOpenGLFramebufferObject* framebuffer)
  : State(window->GetState())
  , Viewport(State)
  , Blend(State, GL_BLEND)
  , Depth(State, GL_DEPTH_TEST)
  , Scissor(State, GL_SCISSOR_TEST)
  , ScissorBox(State)
  , BlendFunc(State)
{
  this->State->vtkglDisable(GL_BLEND);
  this->State->vtkglDisable(GL_DEPTH_TEST);
  this->State->vtkglDisable(GL_SCISSOR_TEST);
  this->State->PushFramebufferBindings();
  framebuffer->Bind();
}

TransportPassState::~TransportPassState()
{
  this->State->PopFramebufferBindings();
}

// Attachments go straight to GL: vtkOpenGLFramebufferObject keeps an attachment of the
// same texture as it is, whatever the layer, and its bookkeeping costs more than the draw.
void AttachLayer(unsigned int index, vtkTextureObject* texture, int layer)
{
  glFramebufferTextureLayer(
    GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + index, texture->GetHandle(), 0, layer);
}

void AttachLayered(unsigned int index, vtkTextureObject* texture)
{
  glFramebufferTexture(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + index, texture->GetHandle(), 0);
}

// vtkOpenGLQuadHelper::Render draws its quad as a 4-vertex triangle strip; this draws
// @p count instances of it, which the layered geometry shader sends to consecutive
// layers.
void DrawInstances(vtkOpenGLQuadHelper* quad, vtkShaderProgram* program, int first, int count)
{
  program->SetUniformi("st_firstLayer", first);
  quad->VAO->Bind();
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
  quad->VAO->Release();
}

void AttachLayeredTargets(
  vtkOpenGLFramebufferObject* framebuffer, std::initializer_list<vtkTextureObject*> targets)
{
  unsigned int index = 0;
  for (vtkTextureObject* target : targets)
  {
    AttachLayered(index++, target);
  }
  framebuffer->ActivateDrawBuffers(index);
}

void Attach2D(unsigned int index, vtkTextureObject* texture)
{
  glFramebufferTexture2D(
    GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + index, GL_TEXTURE_2D, texture->GetHandle(), 0);
}

void DetachAll(vtkOpenGLFramebufferObject* framebuffer)
{
  // The passes use at most three attachments (pass 0a).
  for (unsigned int index = 0; index < 3; ++index)
  {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + index, GL_TEXTURE_2D, 0, 0);
  }
  framebuffer->ActivateDrawBuffers(1);
}

void DrawLayers(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, std::initializer_list<vtkTextureObject*> targets, int layers)
{
  DrawLayersWhere(framebuffer, quad, program, targets, layers, [](int) { return true; });
}

void DrawLayersWhere(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, std::initializer_list<vtkTextureObject*> targets, int layers,
  const std::function<bool(int)>& draw)
{
  AttachLayeredTargets(framebuffer, targets);
  for (int z = 0; z < layers;)
  {
    if (!draw(z))
    {
      ++z;
      continue;
    }
    int end = z + 1;
    while (end < layers && draw(end))
    {
      ++end;
    }
    DrawInstances(quad, program, z, end - z);
    z = end;
  }
  DetachAll(framebuffer);
}

void BlendAdditively(vtkOpenGLState* state)
{
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
}
}
