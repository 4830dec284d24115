#include "ScattererTransportLightPasses.h"

#include "ScattererTransportDiffusionPasses.h"
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
namespace
{
// The uniforms and samplers every sweep program reads
// (scatterer_transport_sweep_common.glsl), for the bound program's lifetime.
class SweepBindings
{
public:
  SweepBindings(vtkShaderProgram* program, const TransportPass& pass,
    const vtkScattererTransportVolume::Light& light, const SweepPlan& plan, const int sweepDims[3],
    vtkTextureObject* enteringTexture, const vtkScattererTransportVolume::EnteringDepth* entering)
    : Volume(program, pass.In)
    , Medium(program, "st_medium", pass.Tables.Medium)
    , Extinction(program, "st_extinction", pass.Tables.Extinction)
    , FineExtinction(program, "st_fineExtinction", pass.Textures.FineExtinction)
    , DepthInFront(program, "st_enteringDepth", enteringTexture)
  {
    const vtkScattererTransportVolume::Inputs& in = pass.In;
    SetCommonUniforms(program, pass.Grid, in);
    SetSweepOrder(program, plan);
    const float sweepDimsF[3] = { static_cast<float>(sweepDims[0]),
      static_cast<float>(sweepDims[1]), static_cast<float>(sweepDims[2]) };
    program->SetUniform3f("st_sweepDims", sweepDimsF);
    if (light.Positional)
    {
      program->SetUniform3f("st_lightPosition", light.Position);
    }
    else
    {
      const LightStep step = StepTowardLight(pass.Grid, plan, light);
      const float stepSweep[3] = { static_cast<float>(step.Sweep[0]),
        static_cast<float>(step.Sweep[1]), static_cast<float>(step.Sweep[2]) };
      const float stepGrid[3] = { static_cast<float>(step.Grid[0]),
        static_cast<float>(step.Grid[1]), static_cast<float>(step.Grid[2]) };
      program->SetUniform3f("st_stepSweep", stepSweep);
      program->SetUniform3f("st_stepGrid", stepGrid);
      program->SetUniformf("st_stepLength", static_cast<float>(step.Length));
    }
    program->SetUniformi("st_stepSamples", ExtinctionSampling::For(in.Downsample).StepSamples);
    program->SetUniformf("st_sliceOrigin", static_cast<float>(pass.Grid.FirstIndex[plan.Axis]));
    program->SetUniformf("st_firstSlice", static_cast<float>(plan.Runs.front().first));
    SetIndexUniforms(program, in);
    if (entering)
    {
      program->SetUniform3f("st_enteringLight", entering->Light);
      program->SetUniform3f("st_enteringU", entering->U);
      program->SetUniform3f("st_enteringV", entering->V);
      program->SetUniform2f("st_enteringLo", entering->Lo);
      program->SetUniformf("st_enteringSide", entering->Side);
    }
  }

private:
  ScopedVolume Volume;
  ScopedSampler Medium;
  ScopedSampler Extinction;
  ScopedSampler FineExtinction;
  ScopedSampler DepthInFront;
};

// Draws @p quad (the light one light brings) into every layer of the arriving light,
// which has one texel more than the grid on each side. The lights add up: the @p first
// replaces what the texture holds, the others blend on.
void DrawIntoArriving(
  const TransportPass& pass, vtkOpenGLQuadHelper* quad, vtkShaderProgram* program, bool first)
{
  vtkOpenGLState* state = pass.Window->GetState();
  state->vtkglViewport(0, 0, pass.Grid.Dims[0] + 2, pass.Grid.Dims[1] + 2);
  if (first)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    BlendAdditively(state);
  }
  DrawLayers(pass.Framebuffer, quad, program, { pass.Textures.Arriving }, pass.Grid.Dims[2] + 2);
  state->vtkglDisable(GL_BLEND);
}

// The sweep one slice per draw (scatterer_transport_sweep.glsl): each slice is drawn
// into one slice texture, reading the other (the slice before it), and copied into its
// layer of the transmittance texture (a second output).
void DrawSlices(const TransportPass& pass, vtkOpenGLQuadHelper* quad, vtkShaderProgram* program,
  const SweepPlan& plan, const int sweepDims[3])
{
  TransportTextures& textures = pass.Textures;
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
}

// A directional light's lines swept in parallel (scatterer_transport_lines.glsl, into
// Lines by image store), kLineSlices slices a draw, each draw over the lines with a
// texel in the grid in its slices.
// @p all: the lines of all the slices (LinesOf), the lines' textures allocated for them.
void DrawLines(const TransportPass& pass, vtkShaderProgram* program, vtkOpenGLQuadHelper* lines,
  const vtkScattererTransportVolume::Light& light, const SweepPlan& plan, const int sweepDims[3],
  const LineRange& all)
{
  constexpr int kLineSlices = 16;
  TransportTextures& textures = pass.Textures;
  vtkOpenGLState* state = pass.Window->GetState();
  const float origin[2] = { static_cast<float>(all.Lo[0]), static_cast<float>(all.Lo[1]) };
  program->SetUniform2f("st_lineOrigin", origin);
  program->SetUniformi("st_chunkSlices", kLineSlices);
  program->SetUniformi("st_lines", 0); // image unit 0
  // The mean's draw of the light before read Lines: its reads come before these stores.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindImageTexture(0, textures.Lines->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG16F);
  pass.Framebuffer->ActivateDrawBuffers(1);
  // No line was left anywhere yet: step -1 matches no draw.
  state->vtkglClearColor(1.0, -1.0, 0.0, 1.0);
  for (vtkTextureObject* ends : { textures.LineEnds[0], textures.LineEnds[1] })
  {
    Attach2D(0, ends);
    state->vtkglViewport(0, 0, all.Count[0], all.Count[1]);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
  }
  int current = 0;
  for (int first = 0; first < sweepDims[2]; first += kLineSlices)
  {
    const LineRange drawn =
      LinesOf(pass.Grid, plan, light, first, std::min(first + kLineSlices, sweepDims[2]));
    Attach2D(0, textures.LineEnds[current]);
    state->vtkglViewport(
      drawn.Lo[0] - all.Lo[0], drawn.Lo[1] - all.Lo[1], drawn.Count[0], drawn.Count[1]);
    ScopedSampler start(program, "st_lineStart", textures.LineEnds[1 - current]);
    program->SetUniformi("st_chunkFirst", first);
    lines->Render();
    current = 1 - current;
  }
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG16F);
  // The mean's draw reads what these stored.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}
}

bool SweepTransmittance(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  SweepOutput output, SweepPlan& swept, bool& summed, std::string& why)
{
  summed = false;
  TransportTextures& textures = pass.Textures;
  const SweepPlan plan = PlanSweep(pass.Grid, light);
  int sweepDims[3];
  plan.GetSweepDims(pass.Grid, sweepDims);

  // A piece of a distributed volume: the depth in front of it (1 texel of zeros when
  // none, so the sampler is always bound).
  const vtkScattererTransportVolume::EnteringDepth* entering = light.Entering.get();
  const bool hasEntering = entering && entering->Size > 0 &&
    entering->Depth.size() == static_cast<size_t>(entering->Size) * entering->Size;
  const int enteringKind = hasEntering ? (entering->Positional ? 2 : 1) : 0;
  vtkSmartPointer<vtkTextureObject> enteringTexture =
    NewTransportTexture(pass.Window, true, vtkTextureObject::ClampToEdge);
  float none = 0.0f;
  enteringTexture->Create2DFromRaw(hasEntering ? entering->Size : 1,
    hasEntering ? entering->Size : 1, 1, VTK_FLOAT,
    hasEntering ? const_cast<float*>(entering->Depth.data()) : &none);
  const auto* enteringMap = hasEntering ? entering : nullptr;

  // A directional light's lines in parallel where the implementation can; otherwise
  // (and for positional lights, whose lines diverge) slice by slice.
  vtkOpenGLQuadHelper* lines = nullptr;
  vtkOpenGLQuadHelper* mean = nullptr;
  const bool arriving = output != SweepOutput::Transmittance;
  if (!light.Positional && pass.SweepLinesInParallel &&
    pass.Programs.SweepLines(pass.Window, enteringKind, arriving, lines, mean))
  {
    const LineRange range = LinesOf(pass.Grid, plan, light, 0, sweepDims[2]);
    if (!textures.AllocateLines(pass.Window, sweepDims, range.Count, why) ||
      (!arriving && !textures.AllocateSweep(pass.Window, sweepDims, false, why)))
    {
      return false;
    }
    {
      vtkShaderProgram* program = UseProgram(pass.Window, lines);
      SweepBindings bindings(program, pass, light, plan, sweepDims, enteringTexture, enteringMap);
      DrawLines(pass, program, lines, light, plan, sweepDims, range);
    }
    vtkShaderProgram* program = UseProgram(pass.Window, mean);
    SweepBindings bindings(program, pass, light, plan, sweepDims, enteringTexture, enteringMap);
    ScopedSampler carried(program, "st_lines", textures.Lines);
    if (arriving)
    {
      program->SetUniform3f("st_lightColor", light.Color);
      DrawIntoArriving(pass, mean, program, output == SweepOutput::ArrivingFirst);
      summed = true;
    }
    else
    {
      pass.Window->GetState()->vtkglViewport(0, 0, sweepDims[0], sweepDims[1]);
      DrawLayers(pass.Framebuffer, mean, program, { textures.Transmittance }, sweepDims[2]);
    }
    pass.Progress.StepDone();
  }
  else
  {
    vtkOpenGLQuadHelper* quad =
      pass.Programs.Sweep(pass.Window, light.Positional, enteringKind, why);
    if (!quad || !textures.AllocateSweep(pass.Window, sweepDims, true, why))
    {
      return false;
    }
    vtkShaderProgram* program = UseProgram(pass.Window, quad);
    SweepBindings bindings(program, pass, light, plan, sweepDims, enteringTexture, enteringMap);
    DrawSlices(pass, quad, program, plan, sweepDims);
  }
  DetachAll(pass.Framebuffer);
  swept = plan;
  return true;
}

int DirectLight(const vtkScattererTransportVolume::Inputs& in)
{
  return in.Lights.size() == 1 && !in.Lights.front().Positional ? 0 : -1;
}

bool HasArrivingLights(const vtkScattererTransportVolume::Inputs& in)
{
  return in.Lights.size() > (DirectLight(in) >= 0 ? 1u : 0u);
}

ScopedArrivingLight::ScopedArrivingLight(
  vtkShaderProgram* program, const TransportPass& pass, const SweepPlan& plan)
{
  if (pass.Textures.Arriving)
  {
    this->Arriving.reset(new ScopedSampler(program, "st_arriving", pass.Textures.Arriving));
  }
  const int direct = DirectLight(pass.In);
  if (direct >= 0)
  {
    this->Transmittance.reset(
      new ScopedSampler(program, "st_transmittance", pass.Textures.Transmittance));
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
  DrawIntoArriving(pass, pass.Programs.Arrive.get(), program, first);
}

void GatherLight(const TransportPass& pass, const SweepPlan& plan, vtkTextureObject* fluence)
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
    SetKernelReadUniforms(program, pass.Grid, in);
    ScopedArrivingLight arriving(program, pass, plan);
    ScopedSampler fineGather(program, "st_fineGather", pass.Textures.FineGather);
    ScopedVolume volume(program, in);
    ScopedSampler medium(program, "st_medium", pass.Tables.Medium);
    ScopedSampler kernel(program, "st_kernel", pass.Tables.Kernel);
    ScopedSampler materials(program, "st_materialTable", pass.Tables.Materials);
    ScopedScatteredLight scattered(program, pass, fluence);
    DrawLayersWhere(
      pass.Framebuffer, quad, program, { pass.Textures.Light }, pass.Grid.Dims[2], drawn);
  }
}
}
