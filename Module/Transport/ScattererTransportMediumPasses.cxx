#include "ScattererTransportMediumPasses.h"

#include "ScattererTransportFramebuffer.h"
#include "ScattererTransportGrid.h"
#include "ScattererTransportPass.h"
#include "ScattererTransportPrograms.h"
#include "ScattererTransportProgress.h"
#include "ScattererTransportTables.h"
#include "ScattererTransportTextures.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <vector>

namespace scatterer_gpu
{
namespace
{
// Pass 0a: the fine texels' scattering coefficient and gather.
void DrawFineMedium(const TransportPass& pass)
{
  const vtkScattererTransportVolume::Inputs& in = pass.In;
  vtkShaderProgram* program = UseProgram(pass.Window, pass.Programs.Medium.get());
  SetCommonUniforms(program, pass.Grid, in);
  SetMaterialUniforms(program, in);
  float meanSize = 0.0f;
  for (int a = 0; a < 3; ++a)
  {
    meanSize += static_cast<float>(pass.Grid.TexelLength(a)) / 3.0f;
  }
  program->SetUniformf("st_fineSize", meanSize);
  const ExtinctionSampling sampling = ExtinctionSampling::For(in.Downsample);
  program->SetUniformi("st_meanPoints", sampling.MeanPoints);
  ScopedVolume volume(program, in);
  ScopedSampler medium(program, "st_medium", pass.Tables.Medium);
  ScopedSampler extinction(program, "st_extinction", pass.Tables.Extinction);
  ScopedSampler kernel(program, "st_kernel", pass.Tables.Kernel);
  ScopedSampler materials(program, "st_materialTable", pass.Tables.Materials);
  pass.Window->GetState()->vtkglViewport(0, 0, pass.Grid.Dims[0], pass.Grid.Dims[1]);
  if (sampling.UsesTexelMeans())
  {
    DrawLayers(pass.Framebuffer, pass.Programs.Medium.get(), program,
      { pass.Textures.FineScattering, pass.Textures.FineGather, pass.Textures.FineExtinction },
      pass.Grid.Dims[2]);
  }
  else
  {
    DrawLayers(pass.Framebuffer, pass.Programs.Medium.get(), program,
      { pass.Textures.FineScattering, pass.Textures.FineGather }, pass.Grid.Dims[2]);
  }
}

// Pass 0c: the gather variant each layer needs: the texels of each layer at or above
// each variant's least gather value (pass 0a's FineGather: -1 none, m, m + ST_MIXED),
// counted by occlusion queries.
std::vector<int> CountLayerGathers(const TransportPass& pass)
{
  const int layers = pass.Grid.Dims[2];
  vtkShaderProgram* program = UseProgram(pass.Window, pass.Programs.Count.get());
  float dims[3];
  pass.Grid.GetDims(dims);
  program->SetUniform3f("st_gridDims", dims);
  ScopedSampler fineGather(program, "st_fineGather", pass.Textures.FineGather);
  // A target of the grid's size to draw on, nothing written.
  vtkOpenGLState* state = pass.Window->GetState();
  vtkOpenGLState::ScopedglColorMask mask(state);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglViewport(0, 0, pass.Grid.Dims[0], pass.Grid.Dims[1]);
  // The least gather value of each variant above the first (ST_MIXED is
  // ST_MAX_MATERIALS, scatterer_scene::kMaxMaterials here).
  const float atLeast[] = { 0.0f, static_cast<float>(scatterer_scene::kMaxMaterials) };
  std::vector<GLuint> queries(2 * static_cast<size_t>(layers));
  glGenQueries(static_cast<GLsizei>(queries.size()), queries.data());
  AttachLayered(0, pass.Textures.Light);
  pass.Framebuffer->ActivateDrawBuffers(1);
  for (int v = 0; v < 2; ++v)
  {
    program->SetUniformf("st_atLeast", atLeast[v]);
    for (int z = 0; z < layers; ++z)
    {
      glBeginQuery(GL_SAMPLES_PASSED, queries[v * layers + z]);
      DrawInstances(pass.Programs.Count.get(), program, z, 1);
      glEndQuery(GL_SAMPLES_PASSED);
    }
  }
  DetachAll(pass.Framebuffer);
  std::vector<int> gathers(static_cast<size_t>(layers), GatherArriving);
  for (int v = 0; v < 2; ++v)
  {
    for (int z = 0; z < layers; ++z)
    {
      GLuint texels = 0;
      glGetQueryObjectuiv(queries[v * layers + z], GL_QUERY_RESULT, &texels);
      if (texels > 0)
      {
        gathers[z] = v + 1; // GatherTemplates, GatherAcrossMaterials
      }
    }
  }
  glDeleteQueries(static_cast<GLsizei>(queries.size()), queries.data());
  return gathers;
}

// Pass 0b: the coarse medium and the ambient occlusion.
void DrawCoarseMedium(const TransportPass& pass, const CoarseGrid& coarse)
{
  const CoarseUniforms u(pass.Grid, coarse);
  vtkShaderProgram* program = UseProgram(pass.Window, pass.Programs.Coarsen.get());
  SetCommonUniforms(program, pass.Grid, pass.In);
  program->SetUniform3f("st_coarseDims", u.Dims);
  program->SetUniform3f("st_coarseToGrid", u.ToGrid);
  program->SetUniform3f("st_h", u.H);
  program->SetUniformi("st_aoSteps", 2);
  program->SetUniform3f("st_blockSize", coarse.BlockSize().data());
  program->SetUniformi("st_subsamples", coarse.Subsamples);
  ScopedVolume volume(program, pass.In);
  ScopedSampler medium(program, "st_medium", pass.Tables.Medium);
  ScopedSampler extinction(program, "st_extinction", pass.Tables.Extinction);
  pass.Window->GetState()->vtkglViewport(0, 0, coarse.Dims[0], coarse.Dims[1]);
  DrawLayers(pass.Framebuffer, pass.Programs.Coarsen.get(), program,
    { pass.Textures.CoarseMedium, pass.Textures.CoarseOcclusion }, coarse.Dims[2]);
}

// Pass 0d: both fluence atlases start as no light, each coarse texel's extinction in alpha.
void DrawFluenceStart(const TransportPass& pass, const CoarseGrid& coarse, const int atlas[2])
{
  const CoarseUniforms u(pass.Grid, coarse);
  vtkOpenGLQuadHelper* quad = pass.Programs.FluenceStart.get();
  vtkShaderProgram* program = UseProgram(pass.Window, quad);
  program->SetUniform3f("st_coarseDims", u.Dims);
  program->SetUniformi("st_atlasColumns", u.AtlasColumns);
  ScopedSampler medium(program, "st_coarseMedium", pass.Textures.CoarseMedium);
  pass.Window->GetState()->vtkglViewport(0, 0, atlas[0], atlas[1]);
  for (vtkTextureObject* fluence : pass.Textures.Fluence)
  {
    Attach2D(0, fluence);
    pass.Framebuffer->ActivateDrawBuffers(1);
    quad->Render();
  }
  DetachAll(pass.Framebuffer);
}
}

bool BuildMediumTextures(const TransportPass& pass, std::string& why)
{
  const CoarseGrid coarse =
    CoarseGrid::Over(pass.Grid, pass.In.Downsample, pass.In.StillDownsample);
  int atlas[2];
  coarse.GetAtlasSize(atlas);
  if (!pass.Textures.AllocateCoarse(pass.Window, coarse.Dims, atlas, why))
  {
    return false;
  }
  if (!pass.Programs.CreateMedium(pass.Window, why))
  {
    return false;
  }
  pass.Window->GetState()->vtkglDisable(GL_BLEND);
  DrawFineMedium(pass);
  pass.Textures.LayerGathers = CountLayerGathers(pass);
  DrawCoarseMedium(pass, coarse);
  DrawFluenceStart(pass, coarse, atlas);
  pass.Textures.Tiles.Update(pass.Textures.CoarseMedium, pass.In.DiffuseOnTiles);
  pass.Progress.StepDone();
  return true;
}
}
