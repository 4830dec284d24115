#include "vtkScattererTransportVolume.h"

// The build in stages, each in its own file (namespace scatterer_gpu):
//   ScattererTransportKey              whether the inputs changed since the last build
//   ScattererTransportGrid             where the grid lies, how a light is swept (CPU only)
//   ScattererTransportPrograms         the pass programs and the uniforms they share
//   ScattererTransportTables           the medium and material tables, uploaded with the medium
//   ScattererTransportTextures         the render targets and their allocation
//   ScattererTransportMediumPasses     what no light changes, when the medium does
//   ScattererTransportLightPasses      per light its sweep and arriving light; one gather
//   ScattererTransportDiffusionPasses  multiple scattering and ambient light
//   ScattererTransportFramebuffer      the GL state and layered draws of every pass
//   ScattererTransportProgress         the fraction of the build done (ProgressEvent)
#include "ScattererTransportDiffusionPasses.h"
#include "ScattererTransportFramebuffer.h"
#include "ScattererTransportGrid.h"
#include "ScattererTransportKey.h"
#include "ScattererTransportLightPasses.h"
#include "ScattererTransportMediumPasses.h"
#include "ScattererTransportPass.h"
#include "ScattererTransportPrograms.h"
#include "ScattererTransportProgress.h"
#include "ScattererTransportTables.h"
#include "ScattererTransportTextures.h"
#include "ScattererTransportUnits.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <utility>

vtkStandardNewMacro(vtkScattererTransportVolume);

namespace
{
// The OpenGL errors raised since the last call, taken off the context: the first of
// them, or GL_NO_ERROR. At most a few are taken (glGetError reports one flag at a time,
// and without a current context some implementations report one for ever).
GLenum TakeOpenGLErrors()
{
  GLenum first = GL_NO_ERROR;
  for (int i = 0; i < 16; ++i)
  {
    const GLenum e = glGetError();
    if (e == GL_NO_ERROR)
    {
      break;
    }
    first = first == GL_NO_ERROR ? e : first;
  }
  return first;
}
}

struct vtkScattererTransportVolume::vtkInternals
{
  scatterer_gpu::TransportGrid Grid;
  scatterer_gpu::TransportPrograms Programs;
  scatterer_gpu::TransportTables Tables;
  scatterer_gpu::TransportTextures Textures;
  // The dim lights' grid, twice as coarse as Grid, and what their sweeps draw into (its
  // lines and arriving light; the texel means are Textures'): empty without dim lights.
  scatterer_gpu::TransportGrid DimGrid;
  scatterer_gpu::TransportTextures DimTextures;
  scatterer_gpu::TransportProgress Progress;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkOpenGLRenderWindow* Context = nullptr;

  std::uint64_t Key = 0; // scatterer_gpu::TransportKey of the inputs of the last build
  bool HasKey = false;
  // The inputs of a build the OpenGL implementation refused (programs that do not
  // compile, textures not made, an error raised by its passes), and why: the same inputs
  // are not built again in this context.
  std::uint64_t RefusedKey = 0;
  std::string Refused;
  // scatterer_gpu::MediumKey of what the medium passes' textures hold, and
  // Textures.MediumAllocations when they were drawn
  std::uint64_t MediumKey = 0;
  int MediumAllocations = 0;
  bool HasMedium = false;
  int MediumBuilds = 0;
  bool MediumChangedLastBuild = false; ///< the last build ran the medium's passes
  double LastMs = 0.0;
  StageMilliseconds LastStages;
  int Builds = 0;
  scatterer_gpu::SweepPlan CurrentPlan; // of the light whose transmittance the texture holds
  vtkTextureObject* Fluence = nullptr;  // of the Textures' fluence atlases, the one last solved
  Inputs Last;                      // of the last build (ReadTransmittance sweeps again from it)
  bool SweepLinesInParallel = true; // the object's, at the last Update or ReadTransmittance

  bool IsCurrent(vtkOpenGLRenderWindow* window, std::uint64_t key) const
  {
    return this->HasKey && this->Context == window && this->Textures.Light && key == this->Key;
  }

  scatterer_gpu::TransportPass Pass(const Inputs& in)
  {
    return { this->Context, this->Framebuffer, this->Programs, in, this->Grid, this->Tables,
      this->Textures, this->Progress, this->SweepLinesInParallel };
  }

  /** The passes of the dim lights (DimLightsOf): on DimGrid, into DimTextures, reading
   * the fine grid's texel means. */
  scatterer_gpu::TransportPass DimPass(const Inputs& in)
  {
    scatterer_gpu::TransportPass pass{ this->Context, this->Framebuffer, this->Programs, in,
      this->DimGrid, this->Tables, this->DimTextures, this->Progress, this->SweepLinesInParallel };
    pass.MeansGrid = &this->Grid;
    pass.MeansTexture = this->Textures.FineExtinction;
    return pass;
  }

  /** Runs the passes of a build, timing its stages into LastStages (each waiting for
   * the GPU if @p synchronous). */
  bool RunPasses(const Inputs& in, bool synchronous, std::string& why);
  void Release(vtkWindow* window);
};

// The passes of one build: the medium's when it changed, per light its sweep and the
// light it brings (the direct light, alone, read by the gather from its transmittance),
// then the template gather of them all, then the diffusion.
bool vtkScattererTransportVolume::vtkInternals::RunPasses(
  const Inputs& in, bool synchronous, std::string& why)
{
  this->LastStages = StageMilliseconds();
  auto lapStart = std::chrono::steady_clock::now();
  // Adds the time since the last lap to @p stage. A build that reports progress waits
  // for each stage anyway: then the stage's time is its GPU work too.
  const auto lap = [&](double& stage)
  {
    if (synchronous || this->Progress.Waits())
    {
      glFinish();
    }
    const auto now = std::chrono::steady_clock::now();
    stage += std::chrono::duration<double, std::milli>(now - lapStart).count();
    lapStart = now;
  };
  scatterer_gpu::TransportPassState state(this->Context, this->Framebuffer);
  const scatterer_gpu::TransportPass pass = this->Pass(in);
  const int lights = static_cast<int>(in.Lights.size());
  const std::uint64_t mediumKey = scatterer_gpu::MediumKey(in);
  const bool mediumChanged = !this->HasMedium || mediumKey != this->MediumKey ||
    this->Textures.MediumAllocations != this->MediumAllocations;
  this->Progress.BeginBuild(lights, scatterer_gpu::DiffusionIterations(in), mediumChanged);
  const int direct = scatterer_gpu::DirectLight(in);
  bool ok = true;
  if (mediumChanged)
  {
    // The tables depend on what the medium key covers (TablesVersion): uploaded with the
    // medium's passes, not on every light change.
    this->HasMedium = false;
    this->Tables.Upload(this->Context, in);
    ok = scatterer_gpu::BuildMediumTextures(pass, why);
    ++this->MediumBuilds;
    this->HasMedium = ok;
    this->MediumKey = mediumKey;
    this->MediumAllocations = this->Textures.MediumAllocations;
    lap(this->LastStages.Medium);
  }
  // The medium's programs are kept while the medium changes build after build (a transfer
  // function or a clipping plane dragged), and released otherwise, before the light's
  // passes compile theirs (TransportPrograms::Medium).
  if (!mediumChanged || !this->MediumChangedLastBuild)
  {
    this->Programs.ReleaseMedium(this->Context);
  }
  this->MediumChangedLastBuild = mediumChanged;
  // The lights of pass 2a need their texture; one directional light alone does not.
  if (ok && scatterer_gpu::HasArrivingLights(in))
  {
    ok = this->Textures.AllocateArriving(this->Context, this->Grid.Dims, why);
  }
  else if (ok)
  {
    this->Textures.ReleaseArriving(this->Context);
  }
  // The dim lights go first, on their own grid, then the others on the fine grid, the
  // direct light last (its plan is the one the passes after read), then the dim lights'
  // light is added to the fine grid's.
  const std::vector<bool> dim = scatterer_gpu::DimLightsOf(in);
  const bool hasDim = std::find(dim.begin(), dim.end(), true) != dim.end();
  int volumeDims[3];
  in.GetGridSourceDims(volumeDims);
  if (ok && hasDim &&
    (!this->DimGrid.Place(volumeDims, in.IndexOrigin,
       scatterer_gpu::kDimLightCoarsening * in.Downsample, in.TexToWorld) ||
      !this->DimTextures.AllocateArriving(this->Context, this->DimGrid.Dims, why)))
  {
    why = why.empty() ? "the dim lights' grid is degenerate" : why;
    ok = false;
  }
  if (!hasDim && this->DimTextures.Arriving)
  {
    // The dim lights' textures are allocated together, the arriving light first.
    this->DimTextures.ReleaseGraphicsResources(this->Context);
  }
  const scatterer_gpu::TransportPass dimPass = this->DimPass(in);
  int swept = 0, sweptDim = 0;
  const auto sweep = [&](int l)
  {
    this->Context->GetState()->vtkglDisable(GL_BLEND);
    using scatterer_gpu::SweepOutput;
    const bool isDim = dim[static_cast<size_t>(l)];
    int& before = isDim ? sweptDim : swept; // the lights before it on its grid
    const scatterer_gpu::TransportPass& on = isDim ? dimPass : pass;
    const SweepOutput output = l == direct ? SweepOutput::Transmittance
      : before == 0                        ? SweepOutput::ArrivingFirst
                                           : SweepOutput::ArrivingAdded;
    bool summed = false;
    scatterer_gpu::SweepPlan plan;
    ok = scatterer_gpu::SweepTransmittance(
      on, in.Lights[static_cast<size_t>(l)], output, plan, summed, why);
    lap(this->LastStages.Sweeps);
    if (ok)
    {
      this->Progress.SweepDone(swept + sweptDim);
      if (l != direct && !summed)
      {
        ok = scatterer_gpu::AddArrivingLight(
          on, in.Lights[static_cast<size_t>(l)], plan, before == 0, why);
        lap(this->LastStages.Arriving);
      }
      if (!isDim)
      {
        this->CurrentPlan = plan;
      }
      this->Progress.StepDone();
      ++before;
    }
  };
  for (int pick = 0; pick < 2; ++pick) // the dim lights, then the others
  {
    for (int l = 0; l < lights && ok; ++l)
    {
      if (l != direct && dim[static_cast<size_t>(l)] == (pick == 0))
      {
        sweep(l);
      }
    }
  }
  if (ok && direct >= 0)
  {
    sweep(direct);
  }
  if (ok && hasDim)
  {
    ok = scatterer_gpu::AddDimLights(pass, dimPass, why);
    lap(this->LastStages.Arriving);
  }
  // The diffusion needs only the arriving light, so it runs first and the gather writes
  // the whole light in one pass.
  vtkTextureObject* fluence = nullptr;
  ok = ok && scatterer_gpu::SolveMultipleScattering(pass, this->CurrentPlan, fluence, why);
  if (ok)
  {
    lap(this->LastStages.Diffusion);
    this->Fluence = fluence;
    ok = scatterer_gpu::GatherLight(pass, this->CurrentPlan, fluence, why);
    lap(this->LastStages.Gather);
  }
  if (ok)
  {
    this->Progress.BuildDone();
  }
  this->Progress.EndBuild();
  return ok;
}

void vtkScattererTransportVolume::vtkInternals::Release(vtkWindow* window)
{
  this->Textures.ReleaseGraphicsResources(window);
  this->DimTextures.ReleaseGraphicsResources(window);
  this->Tables.ReleaseGraphicsResources(window);
  this->Programs.ReleaseGraphicsResources(window);
  this->Framebuffer->ReleaseGraphicsResources(window);
  this->Context = nullptr;
  this->HasKey = false;
  this->HasMedium = false;
  this->Fluence = nullptr;
  this->Refused.clear();
}

vtkScattererTransportVolume::vtkScattererTransportVolume()
  : Internals(new vtkInternals)
{
}

vtkScattererTransportVolume::~vtkScattererTransportVolume() = default;

bool vtkScattererTransportVolume::IsCurrent(vtkOpenGLRenderWindow* window, const Inputs& in) const
{
  return this->Internals->IsCurrent(window, scatterer_gpu::TransportKey(in));
}

void vtkScattererTransportVolume::Inputs::GetGridSourceDims(int dims[3]) const
{
  const bool box = !this->Parts.empty();
  dims[0] = box ? this->BoxTexels[0] : static_cast<int>(this->Volume->GetWidth());
  dims[1] = box ? this->BoxTexels[1] : static_cast<int>(this->Volume->GetHeight());
  dims[2] = box ? this->BoxTexels[2] : static_cast<int>(this->Volume->GetDepth());
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
  const std::uint64_t key = scatterer_gpu::TransportKey(in);
  if (s.IsCurrent(window, key))
  {
    s.LastMs = 0.0;
    s.LastStages = StageMilliseconds();
    return true;
  }
  if (!s.Refused.empty() && s.Context == window && key == s.RefusedKey)
  {
    why = s.Refused;
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  s.Context = window;
  s.SweepLinesInParallel = this->SweepLinesInParallel;
  s.Last = in;
  // From here every length in the transport's own unit (ScattererTransportUnits.h).
  scatterer_gpu::ToTransportUnits(s.Last, scatterer_gpu::TransportLengthUnit(in));
  const Inputs& built = s.Last;

  // The stages: place the grid, compile the programs (once), allocate the light
  // texture, run the passes (the tables are uploaded with the medium's).
  // The grid lies on the volume texture, or on the box that holds a vtkMultiVolume's parts.
  int volumeDims[3];
  built.GetGridSourceDims(volumeDims);
  if (!s.Grid.Place(volumeDims, built.IndexOrigin, built.Downsample, built.TexToWorld))
  {
    why = "the volume's placement is degenerate (zero spacing or a singular matrix)";
    return false;
  }
  // A build the OpenGL implementation refuses (its programs do not compile, its textures
  // are not made, or it raises an error as the passes draw) is not tried again for the
  // same inputs in this context: every frame would compile or draw again, to fail again.
  const auto refuse = [&s, key, &why]()
  {
    s.HasKey = false;
    s.RefusedKey = key;
    s.Refused = why;
    return false;
  };
  const std::string variant = scatterer_gpu::TransportPrograms::Variant(built);
  if (!s.Programs.IsCreated(variant))
  {
    if (!s.Programs.Create(window, variant, why))
    {
      return refuse();
    }
    s.Framebuffer->SetContext(window);
  }
  if (!s.Textures.AllocateFine(window, s.Grid.Dims,
        scatterer_gpu::ExtinctionSampling::For(built.Downsample).UsesTexelMeans(), why))
  {
    return refuse();
  }
  // A pass the OpenGL implementation refuses (an error raised as it draws: a format, a
  // layered target or a program state it does not take) leaves the light texture as it
  // was, black at a first build: the volume then renders as stock, not black. The errors
  // raised before the build are not its own, so they are taken off first.
  TakeOpenGLErrors();
  if (this->RaiseOpenGLErrorForTesting)
  {
    glEnable(GL_INVALID_ENUM); // not a capability: raises GL_INVALID_ENUM
    this->RaiseOpenGLErrorForTesting = false;
  }
  if (!s.RunPasses(built, this->SynchronousTiming, why))
  {
    TakeOpenGLErrors();
    return refuse();
  }
  const GLenum error = TakeOpenGLErrors();
  if (error != GL_NO_ERROR)
  {
    char code[16];
    std::snprintf(code, sizeof(code), "0x%04X", static_cast<unsigned>(error));
    why = std::string("OpenGL reported error ") + code +
      " while its passes drew on this OpenGL implementation";
    return refuse();
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
  s.SweepLinesInParallel = this->SweepLinesInParallel;
  {
    scatterer_gpu::TransportPassState state(window, s.Framebuffer);
    bool summed = false;
    ok =
      scatterer_gpu::SweepTransmittance(s.Pass(s.Last), s.Last.Lights[static_cast<size_t>(light)],
        scatterer_gpu::SweepOutput::Transmittance, s.CurrentPlan, summed, why);
  }
  s.HasKey = false; // the transmittance texture now holds this light alone
  if (!ok)
  {
    return {};
  }
  return scatterer_gpu::SweepOrderToGridOrder(
    s.Grid, s.CurrentPlan, scatterer_gpu::DownloadTexture3D(s.Textures.Transmittance, 1));
}

std::vector<float> vtkScattererTransportVolume::ReadLight(vtkOpenGLRenderWindow* window)
{
  const std::vector<float> rgba = this->ReadWeightedLight(window);
  std::vector<float> rgb;
  rgb.reserve(rgba.size() / 4 * 3);
  for (size_t i = 0; i < rgba.size(); i += 4)
  {
    const float weight = rgba[i + 3];
    rgb.insert(rgb.end(), { rgba[i] / weight, rgba[i + 1] / weight, rgba[i + 2] / weight });
  }
  return rgb;
}

std::vector<float> vtkScattererTransportVolume::ReadLightWeights(vtkOpenGLRenderWindow* window)
{
  const std::vector<float> rgba = this->ReadWeightedLight(window);
  std::vector<float> weights;
  weights.reserve(rgba.size() / 4);
  for (size_t i = 3; i < rgba.size(); i += 4)
  {
    weights.push_back(rgba[i]);
  }
  return weights;
}

std::vector<float> vtkScattererTransportVolume::ReadWeightedLight(vtkOpenGLRenderWindow* window)
{
  vtkInternals& s = *this->Internals;
  if (!window || s.Context != window || !s.Textures.Light)
  {
    return {};
  }
  window->MakeCurrent();
  return scatterer_gpu::DownloadTexture3D(s.Textures.Light, 4);
}

vtkScattererTransportVolume::DiffusionReadBack vtkScattererTransportVolume::ReadDiffusion(
  vtkOpenGLRenderWindow* window)
{
  vtkInternals& s = *this->Internals;
  DiffusionReadBack back;
  scatterer_gpu::TransportTextures& t = s.Textures;
  if (!window || s.Context != window || !s.Fluence ||
    !(s.Fluence == t.Fluence[0] || s.Fluence == t.Fluence[1]) || !t.CoarseMedium)
  {
    return back;
  }
  window->MakeCurrent();
  const scatterer_gpu::CoarseGrid coarse =
    scatterer_gpu::CoarseGrid::Over(s.Grid, s.Last.Downsample, s.Last.StillDownsample);
  const scatterer_gpu::CoarseUniforms uniforms(s.Grid, coarse);
  for (int a = 0; a < 3; ++a)
  {
    back.Dims[a] = coarse.Dims[a];
    back.ToGrid[a] = coarse.ToGrid[a];
    back.H[a] = uniforms.H[a];
  }
  std::copy(coarse.Block, coarse.Block + 3, back.Block);
  back.Medium = scatterer_gpu::DownloadTexture3D(t.CoarseMedium, 4);
  back.Occlusion = scatterer_gpu::DownloadTexture3D(t.CoarseOcclusion, 1);
  back.Source = scatterer_gpu::DownloadAtlas(t.CoarseSource, coarse.Dims, coarse.AtlasColumns);
  back.Fluence = scatterer_gpu::DownloadAtlas(s.Fluence, coarse.Dims, coarse.AtlasColumns);
  back.Before = scatterer_gpu::DownloadAtlas(
    s.Fluence == t.Fluence[0] ? t.Fluence[1] : t.Fluence[0], coarse.Dims, coarse.AtlasColumns);
  return back;
}

vtkTextureObject* vtkScattererTransportVolume::GetLightTexture() const
{
  return this->Internals->Textures.Light;
}

void vtkScattererTransportVolume::GetTextureTransform(float scale[3], float offset[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    scale[a] = this->Internals->Grid.TexScale[a];
    offset[a] = this->Internals->Grid.TexOffset[a];
  }
}

void vtkScattererTransportVolume::GetDimensions(int dims[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = this->Internals->Grid.Dims[a];
  }
}

double vtkScattererTransportVolume::GetLastBuildMilliseconds() const
{
  return this->Internals->LastMs;
}

vtkScattererTransportVolume::StageMilliseconds
vtkScattererTransportVolume::GetLastBuildStageMilliseconds() const
{
  return this->Internals->LastStages;
}

int vtkScattererTransportVolume::GetBuildCount() const
{
  return this->Internals->Builds;
}

int vtkScattererTransportVolume::GetMediumBuildCount() const
{
  return this->Internals->MediumBuilds;
}

bool vtkScattererTransportVolume::GetHoldsMediumPrograms() const
{
  return this->Internals->Programs.Medium != nullptr;
}

size_t vtkScattererTransportVolume::GetGPUBytes() const
{
  return this->Internals->Textures.GetGPUBytes() + this->Internals->DimTextures.GetGPUBytes();
}

void vtkScattererTransportVolume::SetProgressCallback(std::function<void(double)> callback)
{
  this->Internals->Progress.SetCallback(std::move(callback));
}

void vtkScattererTransportVolume::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->Release(window);
}

void vtkScattererTransportVolume::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const vtkInternals& s = *this->Internals;
  os << indent << "Dimensions: " << s.Grid.Dims[0] << " x " << s.Grid.Dims[1] << " x "
     << s.Grid.Dims[2] << "\n";
  if (s.DimTextures.Arriving)
  {
    os << indent << "DimLightDimensions: " << s.DimGrid.Dims[0] << " x " << s.DimGrid.Dims[1]
       << " x " << s.DimGrid.Dims[2] << "\n";
  }
  os << indent << "Builds: " << s.Builds << "\n";
  if (!s.Refused.empty())
  {
    os << indent << "Refused: " << s.Refused << "\n";
  }
  os << indent << "MediumBuilds: " << s.MediumBuilds << "\n";
  os << indent << "HoldsMediumPrograms: " << (s.Programs.Medium ? "yes" : "no") << "\n";
  os << indent << "LastBuildMilliseconds: " << s.LastMs << "\n";
  const StageMilliseconds& t = s.LastStages;
  os << indent << "LastBuildStageMilliseconds: medium " << t.Medium << ", sweeps " << t.Sweeps
     << ", arriving " << t.Arriving << ", gather " << t.Gather << ", diffusion " << t.Diffusion
     << "\n";
  os << indent << "GPUBytes: " << this->GetGPUBytes() << "\n";
  os << indent << "SynchronousTiming: " << (this->SynchronousTiming ? "On" : "Off") << "\n";
  os << indent << "SweepLinesInParallel: " << (this->SweepLinesInParallel ? "On" : "Off") << "\n";
}
