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
// Where the sweeps read the texels' mean extinction (st_gridToMeansScale, ..._Offset,
// st_farMeanShift: scatterer_transport_sweep_common.glsl): on the dim lights' grid, the
// fine grid's means.
void SetMeansUniforms(vtkShaderProgram* program, const TransportPass& pass)
{
  const TransportGrid& means = pass.MeansGrid ? *pass.MeansGrid : pass.Grid;
  float scale[3], offset[3];
  pass.Grid.GetPositionsOn(means, scale, offset);
  for (int a = 0; a < 3; ++a) // position -> texture coordinate
  {
    scale[a] /= means.Dims[a];
    offset[a] = (offset[a] + 0.5f) / means.Dims[a];
  }
  program->SetUniform3f("st_gridToMeansScale", scale);
  program->SetUniform3f("st_gridToMeansOffset", offset);
  program->SetUniformf("st_farMeanShift", pass.MeansGrid ? 0.25f : 0.0f);
}

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
    , FineExtinction(program, "st_fineExtinction",
        pass.MeansTexture ? pass.MeansTexture : pass.Textures.FineExtinction.Get())
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
    program->SetUniformi(
      "st_stepSamples", ExtinctionSampling::For(pass.Grid.Downsample).StepSamples);
    SetMeansUniforms(program, pass);
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

// Texels of the arriving light (one more than the grid on each side) whose grid index
// along Axis lies in [Lo, Hi], the texture's border taken with the first and last grid
// slices; by default all of them.
struct ArrivingSlab
{
  int Axis = 2;
  int Lo = 0;
  int Hi = -1; // below Lo: every texel
};

// Draws @p quad (the light one light brings) into the arriving light, which has one
// texel more than the grid on each side: its texels of @p slab, a range of layers along
// z, of columns or rows (the scissor test) along x or y. The lights add up: the @p first
// replaces what the texture holds, the others blend on.
void DrawIntoArriving(const TransportPass& pass, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, bool first, const ArrivingSlab& slab = ArrivingSlab())
{
  vtkOpenGLState* state = pass.Window->GetState();
  const int* dims = pass.Grid.Dims;
  const int n = dims[slab.Axis];
  const bool whole = slab.Hi < slab.Lo;
  const int from = whole || slab.Lo == 0 ? 0 : slab.Lo + 1; // texel: grid index + 1
  const int to = whole || slab.Hi == n - 1 ? n + 1 : slab.Hi + 1;
  state->vtkglViewport(0, 0, dims[0] + 2, dims[1] + 2);
  if (first)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    BlendAdditively(state);
  }
  if (!whole && slab.Axis < 2)
  {
    state->vtkglEnable(GL_SCISSOR_TEST);
    if (slab.Axis == 0)
    {
      state->vtkglScissor(from, 0, to - from + 1, dims[1] + 2);
    }
    else
    {
      state->vtkglScissor(0, from, dims[0] + 2, to - from + 1);
    }
  }
  const int axis = slab.Axis;
  DrawLayersWhere(pass.Framebuffer, quad, program, { pass.Textures.Arriving }, dims[2] + 2,
    [axis, from, to](int z) { return axis < 2 || (z >= from && z <= to); });
  state->vtkglDisable(GL_SCISSOR_TEST);
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
// Lines by image store) go kLineSlices slices a draw, and the draw of the light their
// slices' texels hold (scatterer_transport_line_texels.glsl) follows every kTexelSlices of
// them, so that the lines' texture holds a ring of kTexelSlices + 1 slices (those and the
// slice before them) instead of the whole sweep. A texels' draw after every draw of lines (a ring
// of 17) held 0.4 MiB less on the CT head, but its many small draws cost a light kit's sweeps 10-18
// % on llvmpipe (every two: 8 %; docs/rendering.md, the lines' ring).
constexpr int kLineSlices = 16;
constexpr int kTexelSlices = 2 * kLineSlices;

int LineSlots(const int sweepDims[3])
{
  return std::min(sweepDims[2], kTexelSlices + 1);
}

// Both lines' ends as if no draw had left a line anywhere yet: step -1 matches no draw.
void ClearLineEnds(const TransportPass& pass, const LineRange& all)
{
  vtkOpenGLState* state = pass.Window->GetState();
  pass.Framebuffer->ActivateDrawBuffers(1);
  state->vtkglClearColor(1.0, -1.0, 0.0, 1.0);
  for (vtkTextureObject* ends : { pass.Textures.LineEnds[0], pass.Textures.LineEnds[1] })
  {
    Attach2D(0, ends);
    state->vtkglViewport(0, 0, all.Count[0], all.Count[1]);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
  }
}

// The lines' draw of steps [@p first, first + kLineSlices) of the sweep (away from the light),
// over the lines with a texel in the grid there; @p all: the lines of all the slices
// (LinesOf), the lines' ends allocated for them. It leaves each line's end in
// LineEnds[@p current] and takes it up from the other.
void DrawLineChunk(const TransportPass& pass, vtkShaderProgram* program, vtkOpenGLQuadHelper* lines,
  const vtkScattererTransportVolume::Light& light, const SweepPlan& plan, const int sweepDims[3],
  const LineRange& all, int first, int current)
{
  TransportTextures& textures = pass.Textures;
  const float origin[2] = { static_cast<float>(all.Lo[0]), static_cast<float>(all.Lo[1]) };
  program->SetUniform2f("st_lineOrigin", origin);
  program->SetUniformi("st_chunkSlices", kLineSlices);
  program->SetUniformi("st_lineSlots", LineSlots(sweepDims));
  program->SetUniformi("st_lines", 0); // image unit 0
  program->SetUniformi("st_chunkFirst", first);
  // The texels' draw before read the ring's slots that these stores overwrite.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindImageTexture(0, textures.Lines->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG16F);
  const LineRange drawn =
    LinesOf(pass.Grid, plan, light, first, std::min(first + kLineSlices, sweepDims[2]));
  pass.Framebuffer->ActivateDrawBuffers(1);
  Attach2D(0, textures.LineEnds[current]);
  pass.Window->GetState()->vtkglViewport(
    drawn.Lo[0] - all.Lo[0], drawn.Lo[1] - all.Lo[1], drawn.Count[0], drawn.Count[1]);
  ScopedSampler start(program, "st_lineStart", textures.LineEnds[1 - current]);
  lines->Render();
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG16F);
  // The texels' draw reads what these stored.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

// The light entering each texel (scatterer_transport_line_texels.glsl) of the sweep's slices @p lo
// to
// @p hi (texture slices, inclusive), the grid's indices along plan.Axis: into those
// layers of the transmittance texture (sweep order), or, @p arriving, added into the
// arriving light (grid order, one texel more a side: the first and last slices take
// the border beyond them), the lights after the @p firstLight blended on.
void DrawLineTexels(const TransportPass& pass, vtkOpenGLQuadHelper* texels,
  vtkShaderProgram* program, const SweepPlan& plan, const int sweepDims[3], int lo, int hi,
  bool arriving, bool firstLight)
{
  vtkOpenGLState* state = pass.Window->GetState();
  program->SetUniformi("st_lineSlots", LineSlots(sweepDims));
  if (!arriving)
  {
    state->vtkglViewport(0, 0, sweepDims[0], sweepDims[1]);
    DrawLayersWhere(pass.Framebuffer, texels, program, { pass.Textures.Transmittance },
      sweepDims[2], [lo, hi](int z) { return z >= lo && z <= hi; });
    return;
  }
  ArrivingSlab slab;
  slab.Axis = plan.Axis;
  slab.Lo = lo;
  slab.Hi = hi;
  DrawIntoArriving(pass, texels, program, firstLight, slab);
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
  vtkOpenGLQuadHelper* texels = nullptr;
  const bool arriving = output != SweepOutput::Transmittance;
  const bool oneSample = ExtinctionSampling::For(pass.Grid.Downsample).StepSamples == 1;
  if (!light.Positional && pass.SweepLinesInParallel &&
    pass.Programs.SweepLines(pass.Window, enteringKind, arriving, oneSample, lines, texels))
  {
    const LineRange range = LinesOf(pass.Grid, plan, light, 0, sweepDims[2]);
    const int ringDims[3] = { sweepDims[0], sweepDims[1], LineSlots(sweepDims) };
    if (!textures.AllocateLines(pass.Window, ringDims, range.Count, why) ||
      (!arriving && !textures.AllocateSweep(pass.Window, sweepDims, false, why)))
    {
      return false;
    }
    ClearLineEnds(pass, range);
    // Step i of the sweep is texture slice firstSlice + i * away (one run, away from the
    // light); the lines and their texels' draw go kTexelSlices steps at a time.
    const int firstSlice = plan.Runs.front().first;
    const int away = plan.Runs.front().second >= firstSlice ? 1 : -1;
    int current = 0;
    for (int first = 0; first < sweepDims[2]; first += kTexelSlices)
    {
      const int end = std::min(first + kTexelSlices, sweepDims[2]);
      {
        vtkShaderProgram* program = UseProgram(pass.Window, lines);
        SweepBindings bindings(program, pass, light, plan, sweepDims, enteringTexture, enteringMap);
        for (int chunk = first; chunk < end; chunk += kLineSlices)
        {
          DrawLineChunk(pass, program, lines, light, plan, sweepDims, range, chunk, current);
          current = 1 - current;
        }
      }
      const int last = end - 1;
      const int a = firstSlice + first * away, b = firstSlice + last * away;
      vtkShaderProgram* program = UseProgram(pass.Window, texels);
      SweepBindings bindings(program, pass, light, plan, sweepDims, enteringTexture, enteringMap);
      ScopedSampler carried(program, "st_lines", textures.Lines);
      if (arriving)
      {
        program->SetUniform3f("st_lightColor", light.Color);
      }
      DrawLineTexels(pass, texels, program, plan, sweepDims, std::min(a, b), std::max(a, b),
        arriving, output == SweepOutput::ArrivingFirst);
    }
    summed = arriving;
    pass.Progress.StepDone();
  }
  else
  {
    vtkOpenGLQuadHelper* quad =
      pass.Programs.Sweep(pass.Window, light.Positional, enteringKind, oneSample, why);
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

std::vector<bool> DimLightsOf(const vtkScattererTransportVolume::Inputs& in)
{
  std::vector<bool> dim(in.Lights.size(), false);
  if (!in.CoarseDimLights || in.Lights.size() < 2 || in.Downsample < 2)
  {
    return dim;
  }
  const auto irradiance = [](const vtkScattererTransportVolume::Light& light) {
    return std::max({ light.Color[0], light.Color[1], light.Color[2] });
  };
  float brightest = 0.0f;
  for (const auto& light : in.Lights)
  {
    brightest = std::max(brightest, irradiance(light));
  }
  for (size_t l = 0; l < in.Lights.size(); ++l)
  {
    dim[l] = irradiance(in.Lights[l]) < kDimLightFraction * brightest;
  }
  return dim;
}

bool AddDimLights(const TransportPass& pass, const TransportPass& dim, std::string& why)
{
  vtkOpenGLQuadHelper* quad = pass.Programs.DimLights(pass.Window, why);
  if (!quad)
  {
    return false;
  }
  vtkShaderProgram* program = UseProgram(pass.Window, quad);
  float gridDims[3], dimDims[3], scale[3], offset[3];
  pass.Grid.GetDims(gridDims);
  dim.Grid.GetDims(dimDims);
  pass.Grid.GetPositionsOn(dim.Grid, scale, offset);
  program->SetUniform3f("st_gridDims", gridDims);
  program->SetUniform3f("st_dimDims", dimDims);
  program->SetUniform3f("st_gridToDimScale", scale);
  program->SetUniform3f("st_gridToDimOffset", offset);
  ScopedSampler arriving(program, "st_dimArriving", dim.Textures.Arriving);
  DrawIntoArriving(pass, quad, program, false);
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

bool AddArrivingLight(const TransportPass& pass, const vtkScattererTransportVolume::Light& light,
  const SweepPlan& plan, bool first, std::string& why)
{
  const vtkScattererTransportVolume::Inputs& in = pass.In;
  vtkOpenGLQuadHelper* quad = pass.Programs.Arrive(pass.Window, why);
  if (!quad)
  {
    return false;
  }
  vtkShaderProgram* program = UseProgram(pass.Window, quad);
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
  DrawIntoArriving(pass, quad, program, first);
  return true;
}

bool GatherLight(
  const TransportPass& pass, const SweepPlan& plan, vtkTextureObject* fluence, std::string& why)
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
    vtkOpenGLQuadHelper* quad = pass.Programs.Gather(pass.Window, variant, why);
    if (!quad)
    {
      return false;
    }
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
  return true;
}
}
