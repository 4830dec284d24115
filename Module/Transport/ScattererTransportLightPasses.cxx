#include "ScattererTransportLightPasses.h"

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
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdlib>

namespace scatterer_gpu
{
bool SweepTransmittance(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  SweepPlan& swept, std::string& why)
{
  const vtkScattererTransportVolume::Inputs& in = pass.In;
  TransportTextures& textures = pass.Textures;
  const SweepPlan plan = PlanSweep(pass.Grid, light);
  int sweepDims[3];
  plan.GetSweepDims(pass.Grid, sweepDims);
  if (!textures.AllocateSweep(pass.Window, sweepDims, why))
  {
    return false;
  }

  // A piece of a distributed volume: the depth in front of it (1 texel of zeros when
  // none, so the sampler is always bound).
  const vtkScattererTransportVolume::EnteringDepth* entering = light.Entering.get();
  const bool hasEntering = entering && entering->Size > 0 &&
    entering->Depth.size() == static_cast<size_t>(entering->Size) * entering->Size;
  vtkOpenGLQuadHelper* quad = pass.Programs.Sweep(
    pass.Window, light.Positional, hasEntering ? (entering->Positional ? 2 : 1) : 0, why);
  if (!quad)
  {
    return false;
  }
  vtkShaderProgram* program = UseProgram(pass.Window, quad);
  SetCommonUniforms(program, pass.Grid, in);
  SetSweepOrder(program, plan);
  const float sweepDimsF[3] = { static_cast<float>(sweepDims[0]), static_cast<float>(sweepDims[1]),
    static_cast<float>(sweepDims[2]) };
  program->SetUniform3f("st_sweepDims", sweepDimsF);
  program->SetUniform3f("st_lightToward", light.Toward);
  program->SetUniform3f("st_lightPosition", light.Position);
  program->SetUniformi("st_substeps", std::max(1, in.Downsample));
  program->SetUniformf("st_sliceOrigin", static_cast<float>(pass.Grid.FirstIndex[plan.Axis]));
  SetIndexUniforms(program, in);
  vtkSmartPointer<vtkTextureObject> enteringTexture =
    NewTransportTexture(pass.Window, true, vtkTextureObject::ClampToEdge);
  float none = 0.0f;
  enteringTexture->Create2DFromRaw(hasEntering ? entering->Size : 1,
    hasEntering ? entering->Size : 1, 1, VTK_FLOAT,
    hasEntering ? const_cast<float*>(entering->Depth.data()) : &none);
  if (hasEntering)
  {
    program->SetUniform3f("st_enteringLight", entering->Light);
    program->SetUniform3f("st_enteringU", entering->U);
    program->SetUniform3f("st_enteringV", entering->V);
    program->SetUniform2f("st_enteringLo", entering->Lo);
    program->SetUniformf("st_enteringSide", entering->Side);
  }
  ScopedVolume volume(program, in);
  ScopedSampler medium(program, "st_medium", pass.Tables.Medium);
  ScopedSampler depthInFront(program, "st_enteringDepth", enteringTexture);

  pass.Window->GetState()->vtkglViewport(0, 0, sweepDims[0], sweepDims[1]);
  // Progress: kSweepSteps reports per sweep, the last one after the sweep
  // (TransportProgress::SweepDone).
  int total = 0;
  for (const auto& run : plan.Runs)
  {
    total += std::abs(run.second - run.first) + 1;
  }
  const int chunk = std::max(1, (total + kSweepSteps - 1) / kSweepSteps);
  int slicesDone = 0;
  // Each slice is drawn into one slice texture, reading the other (the slice before
  // it), and copied into its layer of the transmittance texture (a second output).
  int current = 0;
  for (const auto& run : plan.Runs)
  {
    const int step = run.second >= run.first ? 1 : -1;
    bool first = true;
    for (int k = run.first;; k += step)
    {
      Attach2D(0, textures.Slices[current]);
      AttachLayer(1, textures.Transmittance, k);
      if (first && run.first == plan.Runs.front().first)
      {
        pass.Framebuffer->ActivateDrawBuffers(2);
      }
      {
        ScopedSampler previous(program, "st_previous", textures.Slices[1 - current]);
        program->SetUniformi("st_hasPrevious", first ? 0 : 1);
        program->SetUniformf("st_slice", static_cast<float>(k));
        quad->Render();
      }
      current = 1 - current;
      first = false;
      if (++slicesDone % chunk == 0 && slicesDone < total)
      {
        pass.Progress.StepDone();
      }
      if (k == run.second)
      {
        break;
      }
    }
  }
  DetachAll(pass.Framebuffer);
  swept = plan;
  return true;
}

int DirectLight(const vtkScattererTransportVolume::Inputs& in)
{
  for (int l = static_cast<int>(in.Lights.size()) - 1; l >= 0; --l)
  {
    if (!in.Lights[static_cast<size_t>(l)].Positional)
    {
      return l;
    }
  }
  return -1;
}

bool HasArrivingLights(const vtkScattererTransportVolume::Inputs& in)
{
  return in.Lights.size() > (DirectLight(in) >= 0 ? 1u : 0u);
}

ScopedArrivingLight::ScopedArrivingLight(
  vtkShaderProgram* program, const TransportPass& pass, const SweepPlan& plan)
  : Transmittance(program, "st_transmittance", pass.Textures.Transmittance)
{
  if (pass.Textures.Arriving)
  {
    this->Arriving.reset(new ScopedSampler(program, "st_arriving", pass.Textures.Arriving));
  }
  const int direct = DirectLight(pass.In);
  if (direct >= 0)
  {
    SetSweepOrder(program, plan);
    program->SetUniform3f("st_directColor", pass.In.Lights[static_cast<size_t>(direct)].Color);
  }
}

void AddArrivingLight(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  const SweepPlan& plan, bool first)
{
  const vtkScattererTransportVolume::Inputs& in = pass.In;
  vtkShaderProgram* program = UseProgram(pass.Window, pass.Programs.Arrive.get());
  SetCommonUniforms(program, pass.Grid, in);
  SetSweepOrder(program, plan);
  program->SetUniform3f("st_lightColor", light.Color);
  program->SetUniform3f("st_lightPosition", light.Position);
  program->SetUniform3f("st_lightFocalDirection", light.FocalDirection);
  program->SetUniformi("st_lightPositional", light.Positional ? 1 : 0);
  program->SetUniform3f("st_lightAttenuation", light.Attenuation);
  program->SetUniformf("st_lightConeCos", light.ConeCos);
  program->SetUniformf("st_lightExponent", light.Exponent);
  ScopedSampler transmittance(program, "st_transmittance", pass.Textures.Transmittance);

  // The texture has one texel more than the grid on each side (arrive.glsl).
  vtkOpenGLState* state = pass.Window->GetState();
  state->vtkglViewport(0, 0, pass.Grid.Dims[0] + 2, pass.Grid.Dims[1] + 2);
  // The lights add up: the first replaces, the others blend on.
  if (first)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    BlendAdditively(state);
  }
  DrawLayers(pass.Framebuffer, pass.Programs.Arrive.get(), program, { pass.Textures.Arriving },
    pass.Grid.Dims[2] + 2);
  state->vtkglDisable(GL_BLEND);
}

void GatherLight(const TransportPass& pass, const SweepPlan& plan)
{
  const vtkScattererTransportVolume::Inputs& in = pass.In;
  const std::vector<int>& layerGathers = pass.Textures.LayerGathers;
  vtkOpenGLState* state = pass.Window->GetState();
  state->vtkglViewport(0, 0, pass.Grid.Dims[0], pass.Grid.Dims[1]);
  state->vtkglDisable(GL_BLEND);
  // Each layer by the cheapest variant that serves all its texels (pass 0c).
  for (int variant = 0; variant < GatherVariants; ++variant)
  {
    if (std::find(layerGathers.begin(), layerGathers.end(), variant) == layerGathers.end())
    {
      continue;
    }
    const auto drawn = [&](int z)
    { return z < static_cast<int>(layerGathers.size()) && layerGathers[z] == variant; };
    vtkOpenGLQuadHelper* quad = pass.Programs.Gather[variant].get();
    vtkShaderProgram* program = UseProgram(pass.Window, quad);
    SetCommonUniforms(program, pass.Grid, in);
    SetMaterialUniforms(program, in);
    ScopedArrivingLight arriving(program, pass, plan);
    ScopedSampler fineMedium(program, "st_fineMedium", pass.Textures.FineMedium);
    ScopedVolume volume(program, in);
    ScopedSampler medium(program, "st_medium", pass.Tables.Medium);
    ScopedSampler kernel(program, "st_kernel", pass.Tables.Kernel);
    ScopedSampler materials(program, "st_materialTable", pass.Tables.Materials);
    DrawLayersWhere(
      pass.Framebuffer, quad, program, { pass.Textures.Light }, pass.Grid.Dims[2], drawn);
  }
  pass.Progress.StepDone();
}
}
