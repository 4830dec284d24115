#include "ScattererTransportDiffusionPasses.h"

#include "ScattererTransportFramebuffer.h"
#include "ScattererTransportGrid.h"
#include "ScattererTransportLightPasses.h"
#include "ScattererTransportPass.h"
#include "ScattererTransportPrograms.h"
#include "ScattererTransportProgress.h"
#include "ScattererTransportTextures.h"
#include "ScattererTransportTiles.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

namespace scatterer_gpu
{
namespace
{
// Pass 3a: the multiple-scattering source on the coarse grid (mean light scattered
// once), from the fine scattering coefficient of pass 0a and the lights' arriving light,
// and in alpha each texel's escape at free faces (from the coarse medium); on the tiles
// that hold a medium, the only texels whose source the diffusion reads.
void DrawSource(const TransportPass& pass, const SweepPlan& plan, const CoarseGrid& coarse,
  const CoarseUniforms& u)
{
  vtkShaderProgram* program = UseProgram(pass.Window, pass.Programs.Source.get());
  SetCommonUniforms(program, pass.Grid, pass.In);
  program->SetUniform3f("st_coarseDims", u.Dims);
  program->SetUniform3f("st_coarseToGrid", u.ToGrid);
  program->SetUniform3f("st_blockSize", coarse.BlockSize().data());
  program->SetUniformi("st_atlasColumns", u.AtlasColumns);
  program->SetUniform3f("st_h", u.H);
  ScopedSampler fineScattering(program, "st_fineScattering", pass.Textures.FineScattering);
  ScopedSampler medium(program, "st_coarseMedium", pass.Textures.CoarseMedium);
  ScopedArrivingLight arriving(program, pass, plan);
  DrawTiles(pass.Framebuffer, program, pass.Textures.CoarseSource, pass.Textures.Tiles);
  pass.Progress.StepDone();
}

// Pass 3b: Jacobi iterations of the diffusion equation, ping-pong between the two fluence
// grids, on the tiles that hold a medium (the texels left out stay 0). Returns the grid
// holding the last iteration's phi.
vtkTextureObject* Diffuse(const TransportPass& pass, const CoarseUniforms& u, int iterations)
{
  TransportTextures& textures = pass.Textures;
  vtkShaderProgram* program = UseProgram(pass.Window, pass.Programs.Diffuse.get());
  program->SetUniform3f("st_coarseDims", u.Dims);
  program->SetUniform3f("st_h", u.H);
  program->SetUniformi("st_atlasColumns", u.AtlasColumns);
  ScopedSampler medium(program, "st_coarseMedium", textures.CoarseMedium);
  ScopedSampler source(program, "st_coarseSource", textures.CoarseSource);
  // rgb alone: alpha keeps the extinction the atlases start with (pass 0d).
  // The caller's mask is restored on return, whatever it was.
  vtkOpenGLState* state = pass.Window->GetState();
  vtkOpenGLState::ScopedglColorMask mask(state);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  int current = 0;
  for (int i = 0; i < iterations; ++i)
  {
    {
      ScopedSampler previous(program, "st_previous", textures.Fluence[1 - current]);
      program->SetUniformi("st_first", i == 0 ? 1 : 0);
      DrawTiles(pass.Framebuffer, program, textures.Fluence[current], textures.Tiles);
    }
    current = 1 - current;
    pass.Progress.StepDone();
  }
  return textures.Fluence[1 - current];
}

}

int DiffusionIterations(const vtkScattererTransportVolume::Inputs& in)
{
  return in.MultipleScattering > 0.0f ? std::max(1, in.DiffusionIterations) : 0;
}

bool SolveMultipleScattering(
  const TransportPass& pass, const SweepPlan& plan, vtkTextureObject*& fluence, std::string& why)
{
  const CoarseGrid coarse =
    CoarseGrid::Over(pass.Grid, pass.In.Downsample, pass.In.StillDownsample);
  int atlas[2];
  coarse.GetAtlasSize(atlas);
  if (!pass.Textures.AllocateCoarse(pass.Window, coarse.Dims, atlas, why))
  {
    return false;
  }
  const CoarseUniforms uniforms(pass.Grid, coarse);
  vtkOpenGLState* state = pass.Window->GetState();
  state->vtkglDisable(GL_BLEND);
  state->vtkglViewport(0, 0, atlas[0], atlas[1]);
  DrawSource(pass, plan, coarse, uniforms);
  fluence = Diffuse(pass, uniforms, DiffusionIterations(pass.In));
  return true;
}

ScopedScatteredLight::ScopedScatteredLight(
  vtkShaderProgram* program, const TransportPass& pass, vtkTextureObject* fluence)
  : Fluence(program, "st_fluence", fluence)
  , Occlusion(program, "st_occlusion", pass.Textures.CoarseOcclusion)
{
  const CoarseGrid coarse =
    CoarseGrid::Over(pass.Grid, pass.In.Downsample, pass.In.StillDownsample);
  const CoarseUniforms u(pass.Grid, coarse);
  float ambient[3] = { 0, 0, 0 };
  for (const auto& light : pass.In.Lights)
  {
    for (int c = 0; c < 3; ++c)
    {
      ambient[c] += light.Ambient[c];
    }
  }
  program->SetUniform3f("st_ambient", ambient);
  program->SetUniform3f("st_coarseDims", u.Dims);
  program->SetUniform3f("st_coarseToGrid", u.ToGrid);
  program->SetUniform3f("st_blockSize", coarse.BlockSize().data());
  program->SetUniformf("st_strength", pass.In.MultipleScattering);
  program->SetUniformi("st_atlasColumns", u.AtlasColumns);
}
}
