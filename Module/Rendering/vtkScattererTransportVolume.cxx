#include "vtkScattererTransportVolume.h"

#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "scatterer_transport_coarsen.h"
#include "scatterer_transport_combine.h"
#include "scatterer_transport_common.h"
#include "scatterer_transport_diffuse.h"
#include "scatterer_transport_gather.h"
#include "scatterer_transport_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <utility>

vtkStandardNewMacro(vtkScattererTransportVolume);

namespace
{
// The scalar texture, and the mask when there is one, for a pass that reads the medium.
void BindVolume(vtkShaderProgram* program, const vtkScattererTransportVolume::Inputs& in)
{
  in.Volume->Activate();
  program->SetUniformi("st_volume", in.Volume->GetTextureUnit());
  if (in.Mask)
  {
    in.Mask->Activate();
    program->SetUniformi("st_mask", in.Mask->GetTextureUnit());
  }
  else
  {
    // Unused (st_masked 0), but a sampler keeps its unit between draws, and a
    // sampler3D left on a unit where a 2D texture is bound now makes the draw invalid
    // (GL_INVALID_OPERATION: nothing is drawn). The volume's unit is always 3D.
    program->SetUniformi("st_mask", in.Volume->GetTextureUnit());
  }
}

void UnbindVolume(const vtkScattererTransportVolume::Inputs& in)
{
  if (in.Mask)
  {
    in.Mask->Deactivate();
  }
  in.Volume->Deactivate();
}

// Progress reports per light sweep: a sweep is most of a build's GPU time.
constexpr int kSweepSteps = 4;

// The common declarations go where the pass has its tag.
std::string WithCommon(const char* pass)
{
  std::string text = pass;
  const std::string tag = "//VTK::Transport::Common";
  const auto at = text.find(tag);
  if (at != std::string::npos)
  {
    text.replace(at, tag.size(), scatterer_transport_common);
  }
  return text;
}

// How one light is swept: the grid axis the slices run along (the light's
// dominant axis in grid units), the other two in order, and where the light is.
struct SweepPlan
{
  int Axis = 2;
  int Row = 0, Column = 1;
  // Slices to sweep, each run starting with T = 1: (first, last) inclusive.
  std::vector<std::pair<int, int>> Runs;
};

// Attaches one layer of a 3D texture (or a 2D texture) to the bound draw framebuffer.
// Straight to GL: vtkOpenGLFramebufferObject keeps an attachment of the same texture
// as it is, whatever the layer, and its bookkeeping costs more than the draw.
void AttachLayer(unsigned int index, vtkTextureObject* texture, int layer)
{
  glFramebufferTextureLayer(
    GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + index, texture->GetHandle(), 0, layer);
}

void Attach2D(unsigned int index, vtkTextureObject* texture)
{
  glFramebufferTexture2D(
    GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + index, GL_TEXTURE_2D, texture->GetHandle(), 0);
}

// Leaves no texture attached (the textures are sampled by later passes and the ray caster).
void DetachAll(vtkOpenGLFramebufferObject* framebuffer)
{
  for (unsigned int index = 0; index < 2; ++index)
  {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + index, GL_TEXTURE_2D, 0, 0);
  }
  framebuffer->ActivateDrawBuffers(1);
}

// The GL state of the transport passes, and the caller's restored after them:
// no blending, depth or scissor test, our framebuffer bound.
class PassState
{
public:
  PassState(vtkOpenGLRenderWindow* window, vtkOpenGLFramebufferObject* framebuffer)
    : State(window->GetState())
    , Viewport(State)
    , Blend(State, GL_BLEND)
    , Depth(State, GL_DEPTH_TEST)
    , Scissor(State, GL_SCISSOR_TEST)
    , BlendFunc(State)
  {
    this->State->vtkglDisable(GL_BLEND);
    this->State->vtkglDisable(GL_DEPTH_TEST);
    this->State->vtkglDisable(GL_SCISSOR_TEST);
    this->State->PushFramebufferBindings();
    framebuffer->Bind();
  }
  ~PassState() { this->State->PopFramebufferBindings(); }

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable Depth;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
};

// Draws `quad` once per layer of the 3D `targets` (all of the same size), each layer
// attached as a colour attachment in order; `program` gets the layer as st_layer.
void DrawLayers(vtkOpenGLFramebufferObject* framebuffer, vtkOpenGLQuadHelper* quad,
  vtkShaderProgram* program, std::initializer_list<vtkTextureObject*> targets, int layers)
{
  for (int z = 0; z < layers; ++z)
  {
    unsigned int index = 0;
    for (vtkTextureObject* target : targets)
    {
      AttachLayer(index++, target, z);
    }
    if (z == 0)
    {
      framebuffer->ActivateDrawBuffers(index);
    }
    program->SetUniformf("st_layer", static_cast<float>(z));
    quad->Render();
  }
  DetachAll(framebuffer);
}

// a / b rounded toward minus infinity (b > 0): grids anchored to index 0 for pieces
// whose extents start below or above it.
int FloorDiv(int a, int b)
{
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

void Multiply3(const double m[9], const double v[3], double out[3])
{
  for (int r = 0; r < 3; ++r)
  {
    out[r] = m[3 * r] * v[0] + m[3 * r + 1] * v[1] + m[3 * r + 2] * v[2];
  }
}
}

struct vtkScattererTransportVolume::vtkInternals
{
  vtkSmartPointer<vtkTextureObject> LightTexture;  // RGBA16F, grid order
  vtkSmartPointer<vtkTextureObject> Transmittance; // R16F, sweep order
  vtkSmartPointer<vtkTextureObject> Slices[2];     // R16F, ping-pong
  vtkSmartPointer<vtkTextureObject> Medium;        // RGBA32F, N x 1: albedo, sigma_t
  vtkSmartPointer<vtkTextureObject> Source;        // RGBA16F, grid order: light scattered once
  vtkSmartPointer<vtkTextureObject> Fluence[2];    // RGBA16F, coarse grid: diffusion ping-pong
  vtkSmartPointer<vtkTextureObject> CoarseMedium;  // RGBA16F, coarse grid: albedo, sigma_t
  vtkSmartPointer<vtkTextureObject> CoarseSource;  // RGBA16F, coarse grid: light scattered once
  vtkSmartPointer<vtkTextureObject> Kernel;        // RGBA32F, photons x materials
  vtkSmartPointer<vtkTextureObject> Materials;     // R32F, material index over the scalar
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  std::function<void(double)> Progress; // SetProgressCallback
  bool Building = false;                // in Update (not ReadTransmittance's sweep)
  int StepsDone = 0, StepsTotal = 1;    // progress of the build under way
  /** One more stage of the build is queued: wait for it and report the fraction. */
  void StepDone()
  {
    ++this->StepsDone;
    if (this->Progress && this->Building)
    {
      glFinish();
      this->Progress(std::min(1.0, this->StepsDone / static_cast<double>(this->StepsTotal)));
    }
  }
  std::unique_ptr<vtkOpenGLQuadHelper> Sweep;
  std::unique_ptr<vtkOpenGLQuadHelper> Gather;
  std::unique_ptr<vtkOpenGLQuadHelper> Coarsen;
  std::unique_ptr<vtkOpenGLQuadHelper> Diffuse;
  std::unique_ptr<vtkOpenGLQuadHelper> Combine;
  vtkOpenGLRenderWindow* Context = nullptr;

  std::uint64_t Key = 0; // fingerprint of the inputs of the last build
  bool HasKey = false;
  int Dims[3] = { 0, 0, 0 };
  int TransmittanceDims[3] = { 0, 0, 0 };
  int SliceDims[2] = { 0, 0 };
  int FirstIndex[3] = { 0, 0, 0 }; // global index (in grid texels) of grid texel 0
  int CoarseDims[3] = { 0, 0, 0 };
  int CoarseToGrid[3] = { 0, 0, 0 }; // coarse texel c covers fine texels Block c + this, + [0, Block)
  int Block = 2;                     // fine texels per coarse texel along each axis
  float TexScale[3] = { 1, 1, 1 };
  float TexOffset[3] = { 0, 0, 0 };
  double LastMs = 0.0;
  int Builds = 0;

  // Derived per build.
  double GridToTex[3] = { 0, 0, 0 };
  double GridToTexOffset[3] = { 0.5, 0.5, 0.5 };
  double GridToWorld[9] = {};
  double WorldToGrid[9] = {};
  double GridOriginWorld[3] = { 0, 0, 0 };
  SweepPlan CurrentPlan; // of the light whose transmittance the texture holds
  Inputs Last;           // of the last build (ReadTransmittance sweeps again from it)

  void Release(vtkWindow* window)
  {
    for (auto* t : { &this->LightTexture, &this->Transmittance, &this->Slices[0], &this->Slices[1],
           &this->Medium, &this->Kernel, &this->Materials, &this->Source, &this->Fluence[0],
           &this->Fluence[1], &this->CoarseMedium, &this->CoarseSource })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(window);
        *t = nullptr;
      }
    }
    if (this->Sweep)
    {
      this->Sweep->ReleaseGraphicsResources(window);
      this->Sweep.reset();
    }
    for (auto* quad : { &this->Gather, &this->Coarsen, &this->Diffuse, &this->Combine })
    {
      if (*quad)
      {
        (*quad)->ReleaseGraphicsResources(window);
        quad->reset();
      }
    }
    this->Framebuffer->ReleaseGraphicsResources(window);
    this->Context = nullptr;
    this->HasKey = false;
    for (int& d : this->TransmittanceDims)
    {
      d = 0;
    }
    this->SliceDims[0] = this->SliceDims[1] = 0;
  }

  vtkSmartPointer<vtkTextureObject> NewTexture(bool linear, int wrap)
  {
    auto t = vtkSmartPointer<vtkTextureObject>::New();
    t->SetContext(this->Context);
    t->SetMinificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
    t->SetMagnificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
    t->SetWrapS(wrap);
    t->SetWrapT(wrap);
    t->SetWrapR(wrap);
    return t;
  }

  SweepPlan PlanSweep(const Light& light) const;
  /** World length of one grid texel along grid axis a. */
  double TexelLength(int a) const
  {
    const double* g = this->GridToWorld;
    return std::sqrt(g[a] * g[a] + g[3 + a] * g[3 + a] + g[6 + a] * g[6 + a]);
  }
  void SetCommonUniforms(vtkShaderProgram* program, const Inputs& in);
  bool SweepLight(const Inputs& in, const Light& light, std::string& why);
  void GatherLight(const Inputs& in, const Light& light, bool first);
  bool AddScatteredAndAmbientLight(const Inputs& in, std::string& why);
};

vtkScattererTransportVolume::vtkScattererTransportVolume()
  : Internals(new vtkInternals)
{
}

vtkScattererTransportVolume::~vtkScattererTransportVolume() = default;

vtkTextureObject* vtkScattererTransportVolume::GetLightTexture() const
{
  return this->Internals->LightTexture;
}

void vtkScattererTransportVolume::GetTextureTransform(float scale[3], float offset[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    scale[a] = this->Internals->TexScale[a];
    offset[a] = this->Internals->TexOffset[a];
  }
}

void vtkScattererTransportVolume::GetDimensions(int dims[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = this->Internals->Dims[a];
  }
}

double vtkScattererTransportVolume::GetLastBuildMilliseconds() const
{
  return this->Internals->LastMs;
}

int vtkScattererTransportVolume::GetBuildCount() const
{
  return this->Internals->Builds;
}

size_t vtkScattererTransportVolume::GetGPUBytes() const
{
  const vtkInternals& in = *this->Internals;
  const size_t light = static_cast<size_t>(in.Dims[0]) * in.Dims[1] * in.Dims[2] * 8; // RGBA16F
  const size_t transmittance = // R16F
    static_cast<size_t>(in.TransmittanceDims[0]) * in.TransmittanceDims[1] * in.TransmittanceDims[2] * 2;
  const size_t slices = 2 * static_cast<size_t>(in.SliceDims[0]) * in.SliceDims[1] * 2;
  const size_t coarse = // four RGBA16F coarse grids: two for the iteration, the medium, the source
    4 * static_cast<size_t>(in.CoarseDims[0]) * in.CoarseDims[1] * in.CoarseDims[2] * 8;
  return 2 * light + transmittance + slices + coarse; // light and source alike
}

void vtkScattererTransportVolume::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->Release(window);
}

SweepPlan vtkScattererTransportVolume::vtkInternals::PlanSweep(const Light& light) const
{
  SweepPlan plan;
  double toward[3];
  double lightGrid[3] = { 0, 0, 0 };
  if (light.Positional)
  {
    double rel[3];
    for (int a = 0; a < 3; ++a)
    {
      rel[a] = light.Position[a] - this->GridOriginWorld[a];
    }
    Multiply3(this->WorldToGrid, rel, lightGrid);
    for (int a = 0; a < 3; ++a)
    {
      toward[a] = lightGrid[a] - 0.5 * (this->Dims[a] - 1);
    }
  }
  else
  {
    const double w[3] = { light.Toward[0], light.Toward[1], light.Toward[2] };
    Multiply3(this->WorldToGrid, w, toward);
  }
  plan.Axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    if (std::abs(toward[a]) > std::abs(toward[plan.Axis]))
    {
      plan.Axis = a;
    }
  }
  plan.Row = plan.Axis == 0 ? 1 : 0;
  plan.Column = plan.Axis == 2 ? 1 : 2;
  const int n = this->Dims[plan.Axis];
  if (light.Positional)
  {
    // The radial variant: away from the light's own slice, on both sides.
    const double k = lightGrid[plan.Axis];
    const int below = static_cast<int>(std::floor(std::min(k, n - 1.0)));
    if (below >= 0)
    {
      plan.Runs.emplace_back(below, 0);
    }
    const int above = static_cast<int>(std::max(std::floor(k) + 1.0, 0.0));
    if (above <= n - 1)
    {
      plan.Runs.emplace_back(above, n - 1);
    }
  }
  else if (toward[plan.Axis] > 0.0)
  {
    plan.Runs.emplace_back(n - 1, 0);
  }
  else
  {
    plan.Runs.emplace_back(0, n - 1);
  }
  return plan;
}

void vtkScattererTransportVolume::vtkInternals::SetCommonUniforms(
  vtkShaderProgram* program, const Inputs& in)
{
  program->SetUniformf("st_scalarScale", in.ScalarScale);
  program->SetUniformf("st_scalarBias", in.ScalarBias);
  program->SetUniformf("st_extinctionScale", in.ExtinctionScale);
  const float dims[3] = { static_cast<float>(this->Dims[0]), static_cast<float>(this->Dims[1]),
    static_cast<float>(this->Dims[2]) };
  program->SetUniform3f("st_gridDims", dims);
  program->SetUniform3f("st_gridToTex", this->GridToTex);
  program->SetUniform3f("st_gridToTexOffset", this->GridToTexOffset);
  // vtkShaderProgram::SetUniformMatrix hands VTK's row-major elements to GL as
  // columns (GLSL sees the transpose; VTK's own shaders multiply v * M): transpose
  // here so that the GLSL reads M * v.
  vtkNew<vtkMatrix4x4> texToWorld, texToDataset;
  texToWorld->DeepCopy(in.TexToWorld);
  texToWorld->Transpose();
  texToDataset->DeepCopy(in.TexToDataset);
  texToDataset->Transpose();
  program->SetUniformMatrix("st_texToWorld", texToWorld);
  program->SetUniformMatrix("st_texToDataset", texToDataset);
  const int planes = static_cast<int>(std::min<size_t>(in.ClipPlanes.size() / 4, 6));
  float clip[6][4] = {};
  for (int p = 0; p < planes; ++p)
  {
    for (int c = 0; c < 4; ++c)
    {
      clip[p][c] = in.ClipPlanes[4 * p + c];
    }
  }
  program->SetUniform4fv("st_clipPlanes", 6, clip);
  program->SetUniformi("st_clipCount", planes);
  program->SetUniformi("st_masked", in.Mask && !in.LabelMask ? 1 : 0);
  program->SetUniformi("st_labelMasked", in.Mask && in.LabelMask ? 1 : 0);
  program->SetUniformf("st_maskBlend", in.MaskBlend);
  program->SetUniformf("st_mediumRows", static_cast<float>(std::max(1, in.MediumRows)));
  program->SetUniformi("st_cropping", in.Cropping ? 1 : 0);
  program->SetUniformi("st_cropFlags", in.CropFlags);
  program->SetUniform3f("st_cropMin", in.CropMin);
  program->SetUniform3f("st_cropMax", in.CropMax);
  vtkNew<vtkMatrix3x3> gridToWorld, worldToGrid;
  for (int i = 0; i < 9; ++i)
  {
    gridToWorld->SetElement(i % 3, i / 3, this->GridToWorld[i]); // transposed, as above
    worldToGrid->SetElement(i % 3, i / 3, this->WorldToGrid[i]);
  }
  program->SetUniformMatrix("st_worldToGrid", worldToGrid);
  program->SetUniformMatrix("st_gridToWorld", gridToWorld);
}

bool vtkScattererTransportVolume::vtkInternals::SweepLight(
  const Inputs& in, const Light& light, std::string& why)
{
  const SweepPlan plan = this->PlanSweep(light);
  const int w = this->Dims[plan.Row], h = this->Dims[plan.Column], d = this->Dims[plan.Axis];
  const float border[4] = { 1, 1, 1, 1 };
  if (!this->Transmittance || this->TransmittanceDims[0] != w ||
    this->TransmittanceDims[1] != h || this->TransmittanceDims[2] != d)
  {
    this->Transmittance = this->NewTexture(true, vtkTextureObject::ClampToBorder);
    this->Transmittance->SetBorderColor(const_cast<float*>(border));
    this->Transmittance->SetInternalFormat(GL_R16F);
    this->Transmittance->SetFormat(GL_RED);
    if (!this->Transmittance->Allocate3D(w, h, d, 1, VTK_FLOAT))
    {
      why = "the transmittance texture could not be allocated";
      return false;
    }
    this->TransmittanceDims[0] = w;
    this->TransmittanceDims[1] = h;
    this->TransmittanceDims[2] = d;
  }
  if (this->SliceDims[0] != w || this->SliceDims[1] != h)
  {
    for (auto& slice : this->Slices)
    {
      slice = this->NewTexture(true, vtkTextureObject::ClampToBorder);
      slice->SetBorderColor(const_cast<float*>(border));
      slice->SetInternalFormat(GL_R16F);
      slice->SetFormat(GL_RED);
      if (!slice->Allocate2D(w, h, 1, VTK_FLOAT))
      {
        why = "the slice textures could not be allocated";
        return false;
      }
    }
    this->SliceDims[0] = w;
    this->SliceDims[1] = h;
  }

  vtkShaderProgram* program = this->Sweep->Program;
  this->Context->GetShaderCache()->ReadyShaderProgram(program);
  this->SetCommonUniforms(program, in);
  // Grid -> sweep order: rows, columns, slices.
  vtkNew<vtkMatrix3x3> toSweep;
  toSweep->Zero();
  toSweep->SetElement(plan.Row, 0, 1.0); // transposed, as in SetCommonUniforms
  toSweep->SetElement(plan.Column, 1, 1.0);
  toSweep->SetElement(plan.Axis, 2, 1.0);
  program->SetUniformMatrix("st_toSweep", toSweep);
  const float sweepDims[3] = { static_cast<float>(w), static_cast<float>(h),
    static_cast<float>(d) };
  program->SetUniform3f("st_sweepDims", sweepDims);
  program->SetUniform3f("st_lightToward", light.Toward);
  program->SetUniform3f("st_lightPosition", light.Position);
  program->SetUniformi("st_lightPositional", light.Positional ? 1 : 0);
  program->SetUniformi("st_substeps", std::max(1, in.Downsample));
  BindVolume(program, in);
  this->Medium->Activate();
  program->SetUniformi("st_medium", this->Medium->GetTextureUnit());

  vtkOpenGLState* state = this->Context->GetState();
  state->vtkglViewport(0, 0, w, h);
  int current = 0;
  // Progress: kSweepSteps reports per sweep, the last one after the sweep (Update).
  int total = 0;
  for (const auto& run : plan.Runs)
  {
    total += std::abs(run.second - run.first) + 1;
  }
  const int chunk = std::max(1, (total + kSweepSteps - 1) / kSweepSteps);
  int swept = 0;
  for (const auto& run : plan.Runs)
  {
    const int step = run.second >= run.first ? 1 : -1;
    bool first = true;
    for (int k = run.first;; k += step)
    {
      Attach2D(0, this->Slices[current]);
      AttachLayer(1, this->Transmittance, k);
      if (first && run.first == plan.Runs.front().first)
      {
        this->Framebuffer->ActivateDrawBuffers(2);
      }
      vtkTextureObject* previous = this->Slices[1 - current];
      previous->Activate();
      program->SetUniformi("st_previous", previous->GetTextureUnit());
      program->SetUniformi("st_hasPrevious", first ? 0 : 1);
      program->SetUniformf("st_slice", static_cast<float>(k));
      this->Sweep->Render();
      previous->Deactivate();
      current = 1 - current;
      first = false;
      if (++swept % chunk == 0 && swept < total)
      {
        this->StepDone();
      }
      if (k == run.second)
      {
        break;
      }
    }
  }
  DetachAll(this->Framebuffer);
  this->Medium->Deactivate();
  UnbindVolume(in);
  this->CurrentPlan = plan;
  return true;
}

void vtkScattererTransportVolume::vtkInternals::GatherLight(
  const Inputs& in, const Light& light, bool first)
{
  vtkShaderProgram* program = this->Gather->Program;
  this->Context->GetShaderCache()->ReadyShaderProgram(program);
  this->SetCommonUniforms(program, in);
  vtkNew<vtkMatrix3x3> toSweep;
  toSweep->Zero();
  toSweep->SetElement(this->CurrentPlan.Row, 0, 1.0); // transposed, as in SetCommonUniforms
  toSweep->SetElement(this->CurrentPlan.Column, 1, 1.0);
  toSweep->SetElement(this->CurrentPlan.Axis, 2, 1.0);
  program->SetUniformMatrix("st_toSweep", toSweep);
  const int materials = static_cast<int>(in.MaterialColors.size() / 3);
  program->SetUniformi("st_materialCount", materials);
  float colors[8][3] = {}, speed[64] = {}, ratio[64] = {};
  for (int m = 0; m < materials && m < 8; ++m)
  {
    for (int c = 0; c < 3; ++c)
    {
      colors[m][c] = in.MaterialColors[3 * m + c];
    }
    for (int k = 0; k < materials && k < 8; ++k)
    {
      speed[8 * m + k] = in.SpeedRatios[materials * m + k];
      ratio[8 * m + k] = in.OpacityRatios[materials * m + k];
    }
  }
  program->SetUniform3fv("st_matColor", 8, colors);
  program->SetUniform1fv("st_speedRatio", 64, speed);
  program->SetUniform1fv("st_opacityRatio", 64, ratio);
  program->SetUniformi("st_kernelCount", in.KernelWidth);
  program->SetUniformi("st_bleed", in.Bleed ? 1 : 0);
  program->SetUniformi("st_boundary", in.Boundary ? 1 : 0);
  program->SetUniform3f("st_lightColor", light.Color);
  program->SetUniform3f("st_lightPosition", light.Position);
  program->SetUniform3f("st_lightFocalDirection", light.FocalDirection);
  program->SetUniformi("st_lightPositional", light.Positional ? 1 : 0);
  program->SetUniform3f("st_lightAttenuation", light.Attenuation);
  program->SetUniformf("st_lightConeCos", light.ConeCos);
  program->SetUniformf("st_lightExponent", light.Exponent);
  BindVolume(program, in);
  this->Medium->Activate();
  program->SetUniformi("st_medium", this->Medium->GetTextureUnit());
  this->Transmittance->Activate();
  program->SetUniformi("st_transmittance", this->Transmittance->GetTextureUnit());
  this->Kernel->Activate();
  program->SetUniformi("st_kernel", this->Kernel->GetTextureUnit());
  this->Materials->Activate();
  program->SetUniformi("st_materialTable", this->Materials->GetTextureUnit());

  vtkOpenGLState* state = this->Context->GetState();
  state->vtkglViewport(0, 0, this->Dims[0], this->Dims[1]);
  if (first)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  }
  DrawLayers(this->Framebuffer, this->Gather.get(), program, { this->LightTexture, this->Source },
    this->Dims[2]);
  this->Medium->Deactivate();
  this->Materials->Deactivate();
  this->Kernel->Deactivate();
  this->Transmittance->Deactivate();
  UnbindVolume(in);
}

bool vtkScattererTransportVolume::vtkInternals::AddScatteredAndAmbientLight(const Inputs& in, std::string& why)
{
  // The coarse grid: blocks of `block` fine texels, so that a coarse texel spans about
  // 4 volume voxels (the diffusion's reach per iteration then stays the same),
  // anchored like the fine grid (to multiples of `block` in global fine indices) so
  // pieces share it. At least 2: a coarse texel's medium is the mean of its fine
  // texels', and one point sample of the transfer function standing for a whole
  // block (transport scale 3 or more) let the diffusion pile the bone's colour up
  // into yellow-green blotches on the CT head; so from scale 3 on a coarse texel
  // spans 6 or more voxels.
  const int block = std::max(2, 4 / std::max(1, in.Downsample));
  this->Block = block;
  for (int a = 0; a < 3; ++a)
  {
    const int first = this->FirstIndex[a];
    const int coarseFirst = FloorDiv(first, block);
    this->CoarseToGrid[a] = block * coarseFirst - first;
    this->CoarseDims[a] = FloorDiv(first + this->Dims[a] - 1, block) - coarseFirst + 1;
  }
  if (!this->Fluence[0] || this->Fluence[0]->GetWidth() != static_cast<unsigned int>(this->CoarseDims[0]) ||
    this->Fluence[0]->GetHeight() != static_cast<unsigned int>(this->CoarseDims[1]) ||
    this->Fluence[0]->GetDepth() != static_cast<unsigned int>(this->CoarseDims[2]))
  {
    for (auto* grid : { &this->Fluence[0], &this->Fluence[1], &this->CoarseMedium,
           &this->CoarseSource })
    {
      *grid = this->NewTexture(true, vtkTextureObject::ClampToEdge);
      (*grid)->SetInternalFormat(GL_RGBA16F);
      (*grid)->SetFormat(GL_RGBA);
      if (!(*grid)->Allocate3D(this->CoarseDims[0], this->CoarseDims[1], this->CoarseDims[2], 4, VTK_FLOAT))
      {
        why = "the diffusion textures could not be allocated";
        return false;
      }
    }
  }
  const float coarseDims[3] = { static_cast<float>(this->CoarseDims[0]),
    static_cast<float>(this->CoarseDims[1]), static_cast<float>(this->CoarseDims[2]) };
  const float coarseToGrid[3] = { static_cast<float>(this->CoarseToGrid[0]),
    static_cast<float>(this->CoarseToGrid[1]), static_cast<float>(this->CoarseToGrid[2]) };
  float h[3];
  for (int a = 0; a < 3; ++a)
  {
    h[a] = static_cast<float>(block * this->TexelLength(a));
  }

  vtkOpenGLState* state = this->Context->GetState();
  state->vtkglDisable(GL_BLEND);
  state->vtkglViewport(0, 0, this->CoarseDims[0], this->CoarseDims[1]);
  {
    vtkShaderProgram* coarsen = this->Coarsen->Program;
    this->Context->GetShaderCache()->ReadyShaderProgram(coarsen);
    this->SetCommonUniforms(coarsen, in);
    coarsen->SetUniform3f("st_coarseDims", coarseDims);
    coarsen->SetUniform3f("st_coarseToGrid", coarseToGrid);
    coarsen->SetUniform3f("st_h", h);
    coarsen->SetUniformi("st_aoSteps", 2);
    coarsen->SetUniformi("st_block", block);
    BindVolume(coarsen, in);
    this->Medium->Activate();
    coarsen->SetUniformi("st_medium", this->Medium->GetTextureUnit());
    this->Source->Activate();
    coarsen->SetUniformi("st_source", this->Source->GetTextureUnit());
    DrawLayers(this->Framebuffer, this->Coarsen.get(), coarsen,
      { this->CoarseMedium, this->CoarseSource }, this->CoarseDims[2]);
    this->StepDone();
    this->Source->Deactivate();
    this->Medium->Deactivate();
    UnbindVolume(in);
  }

  vtkShaderProgram* program = this->Diffuse->Program;
  this->Context->GetShaderCache()->ReadyShaderProgram(program);
  program->SetUniform3f("st_coarseDims", coarseDims);
  program->SetUniform3f("st_h", h);
  this->CoarseMedium->Activate();
  program->SetUniformi("st_coarseMedium", this->CoarseMedium->GetTextureUnit());
  this->CoarseSource->Activate();
  program->SetUniformi("st_coarseSource", this->CoarseSource->GetTextureUnit());
  int current = 0;
  const int iterations = in.MultipleScattering > 0.0f ? std::max(1, in.DiffusionIterations) : 0;
  for (int i = 0; i < iterations; ++i)
  {
    vtkTextureObject* previous = this->Fluence[1 - current];
    previous->Activate();
    program->SetUniformi("st_previous", previous->GetTextureUnit());
    program->SetUniformi("st_first", i == 0 ? 1 : 0);
    DrawLayers(this->Framebuffer, this->Diffuse.get(), program, { this->Fluence[current] },
      this->CoarseDims[2]);
    previous->Deactivate();
    current = 1 - current;
    this->StepDone();
  }
  this->CoarseSource->Deactivate();
  this->CoarseMedium->Deactivate();

  // Add the fluence to the light each fine texel receives.
  vtkShaderProgram* combine = this->Combine->Program;
  this->Context->GetShaderCache()->ReadyShaderProgram(combine);
  vtkTextureObject* fluence = this->Fluence[1 - current];
  fluence->Activate();
  combine->SetUniformi("st_fluence", fluence->GetTextureUnit());
  this->CoarseSource->Activate();
  combine->SetUniformi("st_occlusion", this->CoarseSource->GetTextureUnit());
  float ambient[3] = { 0, 0, 0 };
  for (const auto& light : in.Lights)
  {
    for (int c = 0; c < 3; ++c)
    {
      ambient[c] += light.Ambient[c];
    }
  }
  combine->SetUniform3f("st_ambient", ambient);
  const float dims[3] = { static_cast<float>(this->Dims[0]), static_cast<float>(this->Dims[1]),
    static_cast<float>(this->Dims[2]) };
  combine->SetUniform3f("st_gridDims", dims);
  combine->SetUniform3f("st_coarseDims", coarseDims);
  combine->SetUniform3f("st_coarseToGrid", coarseToGrid);
  combine->SetUniformf("st_block", static_cast<float>(block));
  combine->SetUniformf("st_strength", in.MultipleScattering);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  state->vtkglViewport(0, 0, this->Dims[0], this->Dims[1]);
  DrawLayers(this->Framebuffer, this->Combine.get(), combine, { this->LightTexture },
    this->Dims[2]);
  this->CoarseSource->Deactivate();
  fluence->Deactivate();
  state->vtkglDisable(GL_BLEND);
  return true;
}

namespace
{
// A fingerprint of everything a build depends on: FNV-1a over the inputs' bytes (the
// tables by their version). Cheap enough for every frame, unlike formatting as text.
class Fingerprint
{
public:
  template <typename T>
  void Add(const T* values, size_t count)
  {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values);
    for (size_t i = 0; i < count * sizeof(T); ++i)
    {
      this->Hash = (this->Hash ^ bytes[i]) * 1099511628211ull;
    }
  }
  template <typename T>
  void Add(const T& value)
  {
    this->Add(&value, 1);
  }
  template <typename T>
  void Add(const std::vector<T>& values)
  {
    this->Add(values.size());
    this->Add(values.data(), values.size());
  }
  std::uint64_t Value() const { return this->Hash; }

private:
  std::uint64_t Hash = 14695981039346656037ull;
};

std::uint64_t KeyOf(const vtkScattererTransportVolume::Inputs& in)
{
  Fingerprint f;
  f.Add(in.Volume);
  f.Add(in.VolumeUploadTime);
  f.Add(in.Mask);
  f.Add(in.MaskUploadTime);
  f.Add(in.LabelMask);
  f.Add(in.MaskBlend);
  f.Add(in.MediumRows);
  f.Add(in.ScalarScale);
  f.Add(in.ScalarBias);
  f.Add(in.ExtinctionScale);
  f.Add(in.Downsample);
  f.Add(in.IndexOrigin, 3);
  f.Add(in.Cropping);
  f.Add(in.CropFlags);
  f.Add(in.CropMin, 3);
  f.Add(in.CropMax, 3);
  f.Add(in.Bleed);
  f.Add(in.Boundary);
  f.Add(in.MultipleScattering);
  f.Add(in.DiffusionIterations);
  f.Add(in.TablesVersion);
  f.Add(in.TexToWorld, 16);
  f.Add(in.TexToDataset, 16);
  f.Add(in.ClipPlanes);
  for (const auto& l : in.Lights)
  {
    f.Add(l.Toward, 3);
    f.Add(l.Position, 3);
    f.Add(l.Positional);
    f.Add(l.Color, 3);
    f.Add(l.Ambient, 3);
    f.Add(l.FocalDirection, 3);
    f.Add(l.Attenuation, 3);
    f.Add(l.ConeCos);
    f.Add(l.Exponent);
  }
  return f.Value();
}
}

bool vtkScattererTransportVolume::IsCurrent(vtkOpenGLRenderWindow* window, const Inputs& in) const
{
  const vtkInternals& s = *this->Internals;
  return s.HasKey && s.Context == window && s.LightTexture && KeyOf(in) == s.Key;
}

bool vtkScattererTransportVolume::Update(
  vtkOpenGLRenderWindow* window, const Inputs& in, std::string& why)
{
  vtkInternals& s = *this->Internals;
  if (!window || !in.Volume || in.Lights.empty() || in.Medium.size() < 4)
  {
    why = "no volume texture, light or transfer function to build it from";
    return false;
  }
  if (s.Context && s.Context != window)
  {
    s.Release(s.Context);
  }
  const std::uint64_t key = KeyOf(in);
  if (this->IsCurrent(window, in))
  {
    s.LastMs = 0.0;
    return true;
  }
  const auto start = std::chrono::steady_clock::now();
  s.Context = window;
  s.Last = in;

  // The grid: every Downsample-th structured index, anchored to index 0 (not to this
  // image's first voxel), so that a piece of a split volume (ParaView with MPI) puts
  // its transport voxels where the whole volume does; one more at each end covers
  // the texture's edges.
  const int volumeDims[3] = { static_cast<int>(in.Volume->GetWidth()),
    static_cast<int>(in.Volume->GetHeight()), static_cast<int>(in.Volume->GetDepth()) };
  const int ds = std::max(1, in.Downsample);
  double gridToWorld[9];
  for (int a = 0; a < 3; ++a)
  {
    const int n = std::max(1, volumeDims[a]);
    const int e0 = in.IndexOrigin[a];
    const int first = FloorDiv(e0, ds), last = FloorDiv(e0 + n - 1 + ds - 1, ds);
    s.Dims[a] = n < 2 ? 1 : last - first + 1;
    s.FirstIndex[a] = first;
    const int m = s.Dims[a];
    // Texel j sits at index first * ds + j * ds, texture coordinate (index - e0 + 0.5) / n.
    s.GridToTex[a] = m > 1 ? static_cast<double>(ds) / n : 0.0;
    s.GridToTexOffset[a] = m > 1 ? (first * ds - e0 + 0.5) / n : 0.5;
    // Light texture coordinate = (j + 0.5) / M with j = (t - offset) / scale.
    if (m > 1)
    {
      s.TexScale[a] = static_cast<float>(1.0 / (s.GridToTex[a] * m));
      s.TexOffset[a] = static_cast<float>((0.5 - s.GridToTexOffset[a] / s.GridToTex[a]) / m);
    }
    else
    {
      s.TexScale[a] = 0.0f;
      s.TexOffset[a] = 0.5f;
    }
    // A flat axis still needs a direction scale: one voxel.
    const double scale = m > 1 ? s.GridToTex[a] : 1.0 / n;
    for (int r = 0; r < 3; ++r)
    {
      gridToWorld[3 * r + a] = in.TexToWorld[4 * r + a] * scale;
    }
  }
  for (int r = 0; r < 3; ++r)
  {
    s.GridOriginWorld[r] = in.TexToWorld[4 * r + 3];
    for (int a = 0; a < 3; ++a)
    {
      s.GridOriginWorld[r] += in.TexToWorld[4 * r + a] * s.GridToTexOffset[a];
    }
  }
  std::copy(gridToWorld, gridToWorld + 9, s.GridToWorld);
  vtkNew<vtkMatrix3x3> inverse;
  for (int i = 0; i < 9; ++i)
  {
    inverse->SetElement(i / 3, i % 3, gridToWorld[i]);
  }
  if (inverse->Determinant() == 0.0 || !std::isfinite(inverse->Determinant()))
  {
    why = "the volume's placement is degenerate (zero spacing or a singular matrix)";
    return false;
  }
  inverse->Invert();
  for (int i = 0; i < 9; ++i)
  {
    s.WorldToGrid[i] = inverse->GetElement(i / 3, i % 3);
  }

  // Shaders, small tables, the light texture.
  if (!s.Sweep)
  {
    const std::string vs = vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader();
    s.Sweep.reset(new vtkOpenGLQuadHelper(
      window, vs.c_str(), WithCommon(scatterer_transport_sweep).c_str(), ""));
    s.Gather.reset(new vtkOpenGLQuadHelper(
      window, vs.c_str(), WithCommon(scatterer_transport_gather).c_str(), ""));
    s.Coarsen.reset(new vtkOpenGLQuadHelper(
      window, vs.c_str(), WithCommon(scatterer_transport_coarsen).c_str(), ""));
    s.Diffuse.reset(new vtkOpenGLQuadHelper(window, vs.c_str(), scatterer_transport_diffuse, ""));
    s.Combine.reset(new vtkOpenGLQuadHelper(window, vs.c_str(), scatterer_transport_combine, ""));
    if (!s.Sweep->Program || !s.Gather->Program || !s.Coarsen->Program || !s.Diffuse->Program ||
      !s.Combine->Program)
    {
      why = "the transport shaders failed to compile on this OpenGL implementation";
      for (auto* quad : { &s.Sweep, &s.Gather, &s.Coarsen, &s.Diffuse, &s.Combine })
      {
        quad->reset();
      }
      return false;
    }
    s.Framebuffer->SetContext(window);
  }
  s.Medium = s.NewTexture(true, vtkTextureObject::ClampToEdge);
  const int rows = std::max(1, in.MediumRows);
  s.Medium->Create2DFromRaw(static_cast<unsigned int>(in.Medium.size() / (4 * rows)),
    static_cast<unsigned int>(rows), 4, VTK_FLOAT, const_cast<float*>(in.Medium.data()));
  const int materials = std::max<int>(1, static_cast<int>(in.MaterialColors.size() / 3));
  std::vector<float> table(in.MaterialTable);
  if (table.empty())
  {
    table.push_back(-1.0f);
  }
  s.Materials = s.NewTexture(false, vtkTextureObject::ClampToEdge);
  s.Materials->Create2DFromRaw(static_cast<unsigned int>(table.size()), 1, 1, VTK_FLOAT, table.data());
  std::vector<float> kernel(in.Kernels);
  const int width = std::max(1, in.KernelWidth);
  kernel.resize(static_cast<size_t>(4 * width * materials), 0.0f);
  s.Kernel = s.NewTexture(false, vtkTextureObject::ClampToEdge);
  s.Kernel->Create2DFromRaw(width, materials, 4, VTK_FLOAT, kernel.data());
  if (!s.LightTexture || s.LightTexture->GetWidth() != static_cast<unsigned int>(s.Dims[0]) ||
    s.LightTexture->GetHeight() != static_cast<unsigned int>(s.Dims[1]) ||
    s.LightTexture->GetDepth() != static_cast<unsigned int>(s.Dims[2]))
  {
    for (auto* texture : { &s.LightTexture, &s.Source })
    {
      *texture = s.NewTexture(true, vtkTextureObject::ClampToEdge);
      (*texture)->SetInternalFormat(GL_RGBA16F);
      (*texture)->SetFormat(GL_RGBA);
      if (!(*texture)->Allocate3D(s.Dims[0], s.Dims[1], s.Dims[2], 4, VTK_FLOAT))
      {
        why = "the light texture could not be allocated";
        return false;
      }
    }
  }

  PassState passes(window, s.Framebuffer);
  // Progress stages: per light its sweep (kSweepSteps) and gather; then the coarsening,
  // the diffusion iterations and the combine.
  const int iterations = in.MultipleScattering > 0.0f ? std::max(1, in.DiffusionIterations) : 0;
  s.StepsDone = 0;
  s.StepsTotal = static_cast<int>(in.Lights.size()) * (kSweepSteps + 1) + 2 + iterations;
  s.Building = true;
  bool ok = true;
  for (size_t l = 0; l < in.Lights.size() && ok; ++l)
  {
    window->GetState()->vtkglDisable(GL_BLEND);
    ok = s.SweepLight(in, in.Lights[l], why);
    if (ok)
    {
      s.StepsDone = static_cast<int>(l) * (kSweepSteps + 1) + kSweepSteps - 1;
      s.StepDone();
      s.GatherLight(in, in.Lights[l], l == 0);
      s.StepDone();
    }
  }
  if (ok)
  {
    ok = s.AddScatteredAndAmbientLight(in, why);
  }
  if (ok)
  {
    s.StepsDone = s.StepsTotal - 1;
    s.StepDone(); // the combine: 1
  }
  s.Building = false;

  if (!ok)
  {
    s.HasKey = false;
    return false;
  }
  if (this->SynchronousTiming)
  {
    glFinish();
  }
  s.Key = key;
  s.HasKey = true;
  ++s.Builds;
  s.LastMs =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return true;
}

namespace
{
std::vector<float> Download(vtkTextureObject* texture, int components)
{
  std::vector<float> data(static_cast<size_t>(texture->GetWidth()) * texture->GetHeight() *
    texture->GetDepth() * components);
  texture->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, components == 1 ? GL_RED : GL_RGBA, GL_FLOAT, data.data());
  texture->Deactivate();
  return data;
}
}

void vtkScattererTransportVolume::SetProgressCallback(std::function<void(double)> callback)
{
  this->Internals->Progress = std::move(callback);
}

std::vector<float> vtkScattererTransportVolume::ReadTransmittance(
  vtkOpenGLRenderWindow* window, int light)
{
  vtkInternals& s = *this->Internals;
  if (!window || s.Context != window || light < 0 ||
    light >= static_cast<int>(s.Last.Lights.size()))
  {
    return {};
  }
  window->MakeCurrent();
  std::string why;
  bool ok = false;
  {
    PassState passes(window, s.Framebuffer);
    ok = s.SweepLight(s.Last, s.Last.Lights[static_cast<size_t>(light)], why);
  }
  s.HasKey = false; // the transmittance texture now holds this light alone
  if (!ok)
  {
    return {};
  }
  const std::vector<float> sweep = Download(s.Transmittance, 1);
  const SweepPlan& p = s.CurrentPlan;
  const int w = s.Dims[p.Row], h = s.Dims[p.Column];
  std::vector<float> grid(sweep.size());
  for (int z = 0; z < s.Dims[2]; ++z)
  {
    for (int y = 0; y < s.Dims[1]; ++y)
    {
      for (int x = 0; x < s.Dims[0]; ++x)
      {
        const int j[3] = { x, y, z };
        const size_t from =
          static_cast<size_t>(j[p.Row]) + static_cast<size_t>(w) * (j[p.Column] + static_cast<size_t>(h) * j[p.Axis]);
        grid[x + static_cast<size_t>(s.Dims[0]) * (y + static_cast<size_t>(s.Dims[1]) * z)] = sweep[from];
      }
    }
  }
  return grid;
}

std::vector<float> vtkScattererTransportVolume::ReadLight(vtkOpenGLRenderWindow* window)
{
  vtkInternals& s = *this->Internals;
  if (!window || s.Context != window || !s.LightTexture)
  {
    return {};
  }
  window->MakeCurrent();
  const std::vector<float> rgba = Download(s.LightTexture, 4);
  std::vector<float> rgb;
  rgb.reserve(rgba.size() / 4 * 3);
  for (size_t i = 0; i < rgba.size(); i += 4)
  {
    rgb.insert(rgb.end(), { rgba[i], rgba[i + 1], rgba[i + 2] });
  }
  return rgb;
}

void vtkScattererTransportVolume::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const vtkInternals& s = *this->Internals;
  os << indent << "Dimensions: " << s.Dims[0] << " x " << s.Dims[1] << " x " << s.Dims[2] << "\n";
  os << indent << "Builds: " << s.Builds << "\n";
  os << indent << "LastBuildMilliseconds: " << s.LastMs << "\n";
  os << indent << "GPUBytes: " << this->GetGPUBytes() << "\n";
  os << indent << "SynchronousTiming: " << (this->SynchronousTiming ? "On" : "Off") << "\n";
}
