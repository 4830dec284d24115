#include "ScattererTransportPrograms.h"

#include "ScattererSceneMaterials.h"
#include "ScattererTransportGrid.h"
#include "ScattererTransportLightPasses.h"

#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "scatterer_transport_arrive.h"
#include "scatterer_transport_dim_lights.h"
#include "scatterer_transport_arriving.h"
#include "scatterer_transport_atlas.h"
#include "scatterer_transport_coarsen.h"
#include "scatterer_transport_common.h"
#include "scatterer_transport_count.h"
#include "scatterer_transport_diffuse.h"
#include "scatterer_transport_fluence_start.h"
#include "scatterer_transport_gather.h"
#include "scatterer_transport_layers_gs.h"
#include "scatterer_transport_layers_vs.h"
#include "scatterer_transport_line_texels.h"
#include "scatterer_transport_lines.h"
#include "scatterer_transport_materials.h"
#include "scatterer_transport_medium.h"
#include "scatterer_transport_scattered.h"
#include "scatterer_transport_source.h"
#include "scatterer_transport_stored_gather.h"
#include "scatterer_transport_sweep.h"
#include "scatterer_transport_sweep_common.h"
#include "scatterer_transport_tiles_vs.h"

#include <algorithm>
#include <initializer_list>
#include <utility>

namespace scatterer_gpu
{
namespace
{
// What Create and Sweep report when the OpenGL implementation refuses a program.
const char* const kCompileFailed =
  "the transport shaders failed to compile on this OpenGL implementation";

// The common declarations, after the variant's defines, the materials', the sweeps', the
// arriving light's, the scattered light's, the coarse atlas's and the stored gather's
// functions go where the pass has their tags.
std::string WithCommon(const char* pass, const std::string& variant)
{
  std::string text = pass;
  const std::pair<std::string, std::string> chunks[] = { { "//VTK::Transport::Common",
                                                           variant + scatterer_transport_common },
    { "//VTK::Transport::Materials", scatterer_transport_materials },
    { "//VTK::Transport::Sweep", scatterer_transport_sweep_common },
    { "//VTK::Transport::Arriving", scatterer_transport_arriving },
    { "//VTK::Transport::Scattered", scatterer_transport_scattered },
    { "//VTK::Transport::Atlas", scatterer_transport_atlas },
    { "//VTK::Transport::StoredGather", scatterer_transport_stored_gather } };
  for (const auto& chunk : chunks)
  {
    const auto at = text.find(chunk.first);
    if (at != std::string::npos)
    {
      text.replace(at, chunk.first.size(), chunk.second);
    }
  }
  return text;
}

// A full-screen quad whose draws go to every layer of a 3D target
// (scatterer_transport_layers_vs.glsl, ..._gs.glsl), with fragment shader @p fs.
vtkOpenGLQuadHelper* NewLayeredQuad(vtkOpenGLRenderWindow* window, const std::string& fs)
{
  return new vtkOpenGLQuadHelper(
    window, scatterer_transport_layers_vs, fs.c_str(), scatterer_transport_layers_gs);
}

// Releases @p quad; VTK's shader cache keeps its program, compiled, until the window goes.
void Release(vtkWindow* window, std::unique_ptr<vtkOpenGLQuadHelper>& quad)
{
  if (quad)
  {
    quad->ReleaseGraphicsResources(window);
    quad.reset();
  }
}

// Releases @p quad and its program's OpenGL objects, which the release of a quad alone
// leaves to VTK's shader cache until the window goes; the cache compiles the program again
// when a quad asks for it next.
void ReleaseWithProgram(vtkWindow* window, std::unique_ptr<vtkOpenGLQuadHelper>& quad)
{
  if (quad && quad->Program)
  {
    quad->Program->ReleaseGraphicsResources(window);
  }
  Release(window, quad);
}

// @p quad, made by @p make the first time; null with @p why set if it does not compile.
template <typename Make>
vtkOpenGLQuadHelper* CompiledWhenFirstUsed(
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, Make make, std::string& why)
{
  if (!quad)
  {
    quad.reset(make());
  }
  if (!quad->Program)
  {
    why = kCompileFailed;
    quad.reset();
    return nullptr;
  }
  return quad.get();
}
}

std::string TransportPrograms::Variant(const vtkScattererTransportVolume::Inputs& in)
{
  // How the medium is read (scatterer_transport_common.glsl) and which arriving light the
  // passes read (scatterer_transport_arriving.glsl).
  const int mask =
    !in.Mask ? 0 : (in.LabelMask ? 2 : 1); // ST_NO_MASK, ST_BINARY_MASK, ST_LABEL_MASK
  return "#define ST_COMPONENT_MODE " + std::to_string(in.ComponentMode) +
    "\n#define ST_MATERIAL_COMPONENT " + std::to_string(in.MaterialComponent) +
    "\n#define ST_MAX_MATERIALS " + std::to_string(scatterer_scene::kMaxMaterials) +
    "\n#define ST_MASK " + std::to_string(mask) + "\n#define ST_CROPPING " +
    std::to_string(in.Cropping ? 1 : 0) + "\n#define ST_CLIPPING " +
    std::to_string(in.ClipPlanes.size() >= 4 ? 1 : 0) + "\n#define ST_PARTS " +
    std::to_string(std::max<size_t>(1, in.Parts.size())) + "\n#define ST_DIRECT_LIGHT " +
    std::to_string(DirectLight(in) >= 0 ? 1 : 0) + "\n#define ST_ARRIVING " +
    std::to_string(HasArrivingLights(in) ? 1 : 0) + "\n";
}

TransportPrograms::TransportPrograms() = default;
TransportPrograms::~TransportPrograms() = default;

bool TransportPrograms::Create(
  vtkOpenGLRenderWindow* window, const std::string& variant, std::string& why)
{
  this->ReleaseGraphicsResources(window);
  this->CreatedVariant = variant;
  // The diffusion's passes draw the coarse texels that hold a medium
  // (ScattererTransportTiles.h) into the coarse grid's atlas: 2D targets, no layers.
  const std::string tilesVertex = WithCommon(scatterer_transport_tiles_vs, "");
  this->Source = std::unique_ptr<vtkOpenGLQuadHelper>(new vtkOpenGLQuadHelper(
    window, tilesVertex.c_str(), WithCommon(scatterer_transport_source, variant).c_str(), ""));
  this->Diffuse = std::unique_ptr<vtkOpenGLQuadHelper>(new vtkOpenGLQuadHelper(
    window, tilesVertex.c_str(), WithCommon(scatterer_transport_diffuse, "").c_str(), ""));
  if (!this->Source->Program || !this->Diffuse->Program)
  {
    why = kCompileFailed;
    this->Source.reset();
    this->Diffuse.reset();
    return false;
  }
  return true;
}

bool TransportPrograms::CreateMedium(vtkOpenGLRenderWindow* window, std::string& why)
{
  if (this->Medium)
  {
    return true;
  }
  // Every pass but the sweep draws whole 3D textures, all their layers in one draw.
  this->Medium.reset(
    NewLayeredQuad(window, WithCommon(scatterer_transport_medium, this->CreatedVariant)));
  this->Coarsen.reset(
    NewLayeredQuad(window, WithCommon(scatterer_transport_coarsen, this->CreatedVariant)));
  this->Count.reset(
    NewLayeredQuad(window, WithCommon(scatterer_transport_count, this->CreatedVariant)));
  // A 2D target: VTK's full-screen quad.
  this->FluenceStart.reset(new vtkOpenGLQuadHelper(
    window, nullptr, WithCommon(scatterer_transport_fluence_start, "").c_str(), ""));
  for (auto* quad : this->MediumQuads())
  {
    if (!(*quad)->Program)
    {
      why = kCompileFailed;
      this->ReleaseMedium(window);
      return false;
    }
  }
  return true;
}

void TransportPrograms::ReleaseMedium(vtkWindow* window)
{
  for (auto* quad : this->MediumQuads())
  {
    ReleaseWithProgram(window, *quad);
  }
}

std::array<std::unique_ptr<vtkOpenGLQuadHelper>*, 4> TransportPrograms::MediumQuads()
{
  return { &this->Medium, &this->Coarsen, &this->Count, &this->FluenceStart };
}

vtkOpenGLQuadHelper* TransportPrograms::Arrive(vtkOpenGLRenderWindow* window, std::string& why)
{
  return CompiledWhenFirstUsed(
    this->ArriveQuad,
    [&] {
      return NewLayeredQuad(window, WithCommon(scatterer_transport_arrive, this->CreatedVariant));
    },
    why);
}

vtkOpenGLQuadHelper* TransportPrograms::Gather(
  vtkOpenGLRenderWindow* window, int variant, std::string& why)
{
  return CompiledWhenFirstUsed(
    this->GatherQuads[variant],
    [&]
    {
      return NewLayeredQuad(window,
        WithCommon(scatterer_transport_gather,
          this->CreatedVariant + "#define ST_GATHER " + std::to_string(variant) + "\n"));
    },
    why);
}

vtkOpenGLQuadHelper* TransportPrograms::Sweep(
  vtkOpenGLRenderWindow* window, bool positional, int entering, bool oneSample, std::string& why)
{
  oneSample = oneSample && !positional; // a positional light's sweep has no lines' points
  return CompiledWhenFirstUsed(
    this->Sweeps[(positional ? 3 : (oneSample ? 6 : 0)) + entering],
    [&]
    {
      const std::string defines = "#define ST_SWEEP_POSITIONAL " +
        std::to_string(positional ? 1 : 0) + "\n#define ST_SWEEP_ENTERING " +
        std::to_string(entering) + "\n#define ST_SWEEP_ONE_SAMPLE " + (oneSample ? "1" : "0") +
        "\n";
      return new vtkOpenGLQuadHelper(window,
        vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
        WithCommon(scatterer_transport_sweep, this->CreatedVariant + defines).c_str(), "");
    },
    why);
}

vtkOpenGLQuadHelper* TransportPrograms::DimLights(vtkOpenGLRenderWindow* window, std::string& why)
{
  return CompiledWhenFirstUsed(
    this->DimLightsQuad, [&] { return NewLayeredQuad(window, scatterer_transport_dim_lights); },
    why);
}

bool TransportPrograms::SweepLines(vtkOpenGLRenderWindow* window, int entering, bool arriving,
  bool oneSample, vtkOpenGLQuadHelper*& lines, vtkOpenGLQuadHelper*& texels)
{
  if (this->LinesRefused || entering < 0 || entering > 1)
  {
    return false;
  }
  // Asked before compiling, so that an implementation without it is not shown the
  // programs' compile errors; glew's entry points are null where it lacks them.
  int major = 0, minor = 0;
  window->GetOpenGLVersion(major, minor);
  const bool imageLoadStore =
    major > 4 || (major == 4 && minor >= 2) || glewIsSupported("GL_ARB_shader_image_load_store");
  if (!imageLoadStore || !glBindImageTexture || !glMemoryBarrier)
  {
    this->LinesRefused = true;
    return false;
  }
  // The lines' draw is the same for every kind (ST_SWEEP_ONE_SAMPLE tells how the texels'
  // draw takes the light entering a texel).
  const auto defines = [this](int e, bool one)
  {
    return this->CreatedVariant + "#define ST_SWEEP_ENTERING " + std::to_string(e) +
      "\n#define ST_SWEEP_ONE_SAMPLE " + (one ? "1" : "0") + "\n";
  };
  if (!this->Lines)
  {
    this->Lines.reset(new vtkOpenGLQuadHelper(window,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
      WithCommon(scatterer_transport_lines, defines(0, false)).c_str(), ""));
  }
  std::unique_ptr<vtkOpenGLQuadHelper>& lineTexels =
    this->LineTexels[4 * (oneSample ? 1 : 0) + 2 * entering + (arriving ? 1 : 0)];
  if (!lineTexels)
  {
    const std::string texelDefines = defines(entering, oneSample) +
      "#define ST_LINE_TEXELS_ARRIVING " + (arriving ? "1\n" : "0\n");
    lineTexels.reset(new vtkOpenGLQuadHelper(window, scatterer_transport_layers_vs,
      WithCommon(scatterer_transport_line_texels, texelDefines).c_str(),
      scatterer_transport_layers_gs));
  }
  if (!this->Lines->Program || !lineTexels->Program)
  {
    this->LinesRefused = true;
    this->Lines.reset();
    lineTexels.reset();
    return false;
  }
  lines = this->Lines.get();
  texels = lineTexels.get();
  return true;
}

void TransportPrograms::ReleaseGraphicsResources(vtkWindow* window)
{
  this->ReleaseMedium(window);
  Release(window, this->Source);
  Release(window, this->Diffuse);
  for (auto& sweep : this->Sweeps)
  {
    Release(window, sweep);
  }
  Release(window, this->Lines);
  Release(window, this->ArriveQuad);
  for (auto& gather : this->GatherQuads)
  {
    Release(window, gather);
  }
  Release(window, this->DimLightsQuad);
  for (auto& texels : this->LineTexels)
  {
    Release(window, texels);
  }
  this->LinesRefused = false;
}

vtkShaderProgram* UseProgram(vtkOpenGLRenderWindow* window, vtkOpenGLQuadHelper* quad)
{
  window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  return quad->Program;
}

void SetCommonUniforms(vtkShaderProgram* program, const TransportGrid& grid,
  const vtkScattererTransportVolume::Inputs& in)
{
  program->SetUniform4f("st_scalarScale", in.ScalarScale);
  program->SetUniform4f("st_scalarBias", in.ScalarBias);
  program->SetUniformi("st_components", in.Components);
  program->SetUniform4f("st_componentWeights", in.ComponentWeights);
  program->SetUniform3f("st_voxelStep", in.VoxelStep);
  program->SetUniform3f("st_gradientAspect", in.GradientAspect);
  program->SetUniformf("st_occlusionScale", in.OcclusionScale);
  float dims[3];
  grid.GetDims(dims);
  program->SetUniform3f("st_gridDims", dims);
  program->SetUniform3f("st_gridToTex", grid.GridToTex);
  program->SetUniform3f("st_gridToTexOffset", grid.GridToTexOffset);
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
  // At most 6 planes, as VTK's ray caster.
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
  program->SetUniformf("st_maskBlend", in.MaskBlend);
  program->SetUniformf("st_mediumRows", static_cast<float>(std::max(1, in.MediumRows)));
  program->SetUniformi("st_cropFlags", in.CropFlags);
  program->SetUniform3f("st_cropMin", in.CropMin);
  program->SetUniform3f("st_cropMax", in.CropMax);
  // A vtkMultiVolume: each part's placement in the box and its scalar scale and bias.
  const int parts = static_cast<int>(in.Parts.size());
  if (parts > 0)
  {
    std::vector<float> boxToPart(16 * parts);
    std::vector<float> scaleBias(2 * parts);
    for (int k = 0; k < parts; ++k)
    {
      for (int i = 0; i < 16; ++i)
      {
        // GLSL reads the array as columns: element (row, column) at column * 4 + row.
        boxToPart[16 * k + 4 * (i % 4) + i / 4] = static_cast<float>(in.Parts[k].BoxToTexture[i]);
      }
      scaleBias[2 * k] = in.Parts[k].ScalarScale;
      scaleBias[2 * k + 1] = in.Parts[k].ScalarBias;
    }
    program->SetUniformMatrix4x4v("st_boxToPart", parts, boxToPart.data());
    program->SetUniform2fv("st_partScaleBias", parts, scaleBias.data());
  }
  vtkNew<vtkMatrix3x3> gridToWorld, worldToGrid;
  for (int i = 0; i < 9; ++i)
  {
    gridToWorld->SetElement(i % 3, i / 3, grid.GridToWorld[i]); // transposed, as above
    worldToGrid->SetElement(i % 3, i / 3, grid.WorldToGrid[i]);
  }
  program->SetUniformMatrix("st_worldToGrid", worldToGrid);
  program->SetUniformMatrix("st_gridToWorld", gridToWorld);
}

void SetSweepOrder(vtkShaderProgram* program, const SweepPlan& plan)
{
  vtkNew<vtkMatrix3x3> toSweep;
  toSweep->Zero();
  toSweep->SetElement(plan.Row, 0, 1.0); // transposed, as in SetCommonUniforms
  toSweep->SetElement(plan.Column, 1, 1.0);
  toSweep->SetElement(plan.Axis, 2, 1.0);
  program->SetUniformMatrix("st_toSweep", toSweep);
}

void SetIndexUniforms(vtkShaderProgram* program, const vtkScattererTransportVolume::Inputs& in)
{
  vtkNew<vtkMatrix4x4> texToIndex;
  texToIndex->DeepCopy(in.TexToIndex);
  texToIndex->Transpose(); // as in SetCommonUniforms
  program->SetUniformMatrix("st_texToIndex", texToIndex);
}

ScopedSampler::ScopedSampler(
  vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture)
  : Texture(texture)
{
  texture->Activate();
  program->SetUniformi(sampler, texture->GetTextureUnit());
}

ScopedSampler::~ScopedSampler()
{
  this->Texture->Deactivate();
}

ScopedVolume::ScopedVolume(vtkShaderProgram* program, const vtkScattererTransportVolume::Inputs& in)
  : Volume(in.Volume)
  , Mask(in.Mask)
{
  this->Volume->Activate();
  program->SetUniformi("st_volume", this->Volume->GetTextureUnit());
  if (this->Mask)
  {
    this->Mask->Activate();
    program->SetUniformi("st_mask", this->Mask->GetTextureUnit());
  }
  else
  {
    // Unused (ST_NO_MASK), but a sampler keeps its unit between draws, and a
    // sampler3D left on a unit where a 2D texture is bound now makes the draw invalid
    // (GL_INVALID_OPERATION: nothing is drawn). The volume's unit is always 3D.
    program->SetUniformi("st_mask", this->Volume->GetTextureUnit());
  }
  for (size_t k = 0; k < in.Parts.size(); ++k)
  {
    vtkTextureObject* part = in.Parts[k].Volume;
    // Part 0's texture is the volume's, active already.
    if (part != this->Volume)
    {
      part->Activate();
      this->Parts.push_back(part);
    }
    const std::string name = "st_parts[" + std::to_string(k) + "]";
    program->SetUniformi(name.c_str(), part->GetTextureUnit());
  }
}

ScopedVolume::~ScopedVolume()
{
  for (vtkTextureObject* part : this->Parts)
  {
    part->Deactivate();
  }
  if (this->Mask)
  {
    this->Mask->Deactivate();
  }
  this->Volume->Deactivate();
}
}
