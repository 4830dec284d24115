// The shader programs of the light transport passes (full-screen quads whose fragment
// shaders are scatterer_transport_*.glsl beside it) and what binding them takes: the
// uniforms every medium-reading pass shares, and scoped texture bindings.
#ifndef ScattererTransportPrograms_h
#define ScattererTransportPrograms_h

#include "vtkScattererTransportVolume.h" // for Inputs

#include <array>  // for All
#include <memory> // for std::unique_ptr
#include <string>
#include <vector> // for ScopedVolume::Parts

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace scatterer_gpu
{
struct SweepPlan;
struct TransportGrid;

/** The gather's variants (ST_GATHER in scatterer_transport_gather.glsl), cheapest
 * first: a layer is drawn by the first that serves all its texels. */
enum GatherVariant
{
  GatherArriving = 0,        ///< no texel in a material: the light arriving
  GatherTemplates = 1,       ///< the templates, no photon in another material
  GatherAcrossMaterials = 2, ///< photons in other materials: tint and rescale
  GatherVariants = 3
};

/** The pass programs for a context and component rule: the diffusion's compiled by Create,
 * the light passes' when first used, the medium's for its passes (CreateMedium). */
struct TransportPrograms
{
  // The medium's passes run when the medium changes (a transfer function edited, a
  // clipping plane moved), not when a light moves, as under the headlight in an orbit.
  // Their programs are compiled for those passes and released after them, OpenGL objects
  // included; when the medium changed in the build before too (a drag) they are kept
  // until a build whose medium does not change. On llvmpipe a compiled program is host
  // memory, about 2.6 MiB for these four at 511x511x215 (docs/rendering.md, the memory
  // target). Null when released.
  std::unique_ptr<vtkOpenGLQuadHelper> Medium;  ///< pass 0a: what no light changes, fine grid
  std::unique_ptr<vtkOpenGLQuadHelper> Coarsen; ///< pass 0b: medium and occlusion, coarse grid
  std::unique_ptr<vtkOpenGLQuadHelper> Count;   ///< pass 0c: which gather each layer needs
  /// pass 0d: the fluence atlases' start, each coarse texel's extinction in alpha
  std::unique_ptr<vtkOpenGLQuadHelper> FluenceStart;
  std::unique_ptr<vtkOpenGLQuadHelper> Source;  ///< pass 3a: light scattered once, coarse grid
  std::unique_ptr<vtkOpenGLQuadHelper> Diffuse; ///< pass 3b: one Jacobi iteration
  std::string CreatedVariant;                   ///< the defines they were compiled with

  /// The kinds of sweep program (ST_SWEEP_POSITIONAL, ST_SWEEP_ENTERING,
  /// ST_SWEEP_ONE_SAMPLE in scatterer_transport_sweep.glsl): a positional light, or a
  /// directional one with one extinction sample a step or more, times no depth in front,
  /// a directional map of it or a positional one.
  static constexpr int kSweepKinds = 9;

  TransportPrograms();
  ~TransportPrograms();

  /** The defines that specialise the passes to @p inputs' component rule. */
  static std::string Variant(const vtkScattererTransportVolume::Inputs& inputs);

  /** True when the programs exist for @p variant. */
  bool IsCreated(const std::string& variant) const
  {
    return this->Source != nullptr && this->CreatedVariant == variant;
  }

  /**
   * Pass 1's program for a light that is @p positional, with the depth in front of a
   * piece @p entering (0 none, 1 a directional map, 2 a positional one), for steps of
   * @p oneSample extinction sample (a directional light's; ExtinctionSampling), compiled
   * the first time one is asked for; null with @p why set if the OpenGL implementation
   * refuses it.
   */
  vtkOpenGLQuadHelper* Sweep(
    vtkOpenGLRenderWindow* window, bool positional, int entering, bool oneSample, std::string& why);

  /**
   * A directional light's pass 1 in a few draws instead of one per slice: its lines
   * swept in parallel (scatterer_transport_lines.glsl, image load/store) and the
   * light entering each texel after them (scatterer_transport_line_texels.glsl), with the depth
   * in front of a piece @p entering (0 none, 1 a directional map), into the
   * transmittance texture or, @p arriving, into the arriving light, for steps of
   * @p oneSample extinction sample (ExtinctionSampling). Compiled the first
   * time they are asked for; false when the OpenGL implementation has no image
   * load/store (OpenGL < 4.2 without ARB_shader_image_load_store, as on macOS) or
   * refuses them: the slice sweep (Sweep) serves then, with the same result.
   */
  bool SweepLines(vtkOpenGLRenderWindow* window, int entering, bool arriving, bool oneSample,
    vtkOpenGLQuadHelper*& lines, vtkOpenGLQuadHelper*& texels);

  /** Pass 2a, a light's arriving light (scatterer_transport_arrive.glsl), compiled when
   * first used (a build of one directional light never uses it); null with @p why set if
   * the OpenGL implementation refuses it. */
  vtkOpenGLQuadHelper* Arrive(vtkOpenGLRenderWindow* window, std::string& why);

  /** Passes 2b and 4, after 3a and 3b (scatterer_transport_gather.glsl): template
   * in-scattering plus the multiply scattered and ambient light, the light each texel
   * receives, in @p variant (a GatherVariant), compiled when a layer first needs it (no
   * layer of the CT head needs GatherAcrossMaterials); null with @p why set if refused. */
  vtkOpenGLQuadHelper* Gather(vtkOpenGLRenderWindow* window, int variant, std::string& why);

  /**
   * The draw that adds the dim lights' arriving light, from their coarser grid, to the
   * fine grid's (scatterer_transport_dim_lights.glsl), compiled the first time a build
   * has dim lights (a build under the headlight alone never compiles it); null with
   * @p why set if the OpenGL implementation refuses it.
   */
  vtkOpenGLQuadHelper* DimLights(vtkOpenGLRenderWindow* window, std::string& why);

  /** Compiles the diffusion's programs for @p variant in @p window (releasing any others);
   * false with @p why set (and none kept) if the OpenGL implementation refuses one. */
  bool Create(vtkOpenGLRenderWindow* window, const std::string& variant, std::string& why);
  /** Compiles the medium's programs (Medium, Coarsen, Count, FluenceStart) for the variant
   * created, unless they are; false with @p why set (and none kept) if the OpenGL
   * implementation refuses one. */
  bool CreateMedium(vtkOpenGLRenderWindow* window, std::string& why);
  /** Releases the medium's programs, their OpenGL programs too. */
  void ReleaseMedium(vtkWindow* window);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::array<std::unique_ptr<vtkOpenGLQuadHelper>*, 4> MediumQuads();
  std::unique_ptr<vtkOpenGLQuadHelper> Sweeps[kSweepKinds]; ///< pass 1, per kind, when first used
  std::unique_ptr<vtkOpenGLQuadHelper> Lines;               ///< SweepLines' first draw
  /// its second, per one sample x entering x arriving
  std::unique_ptr<vtkOpenGLQuadHelper> LineTexels[8];
  bool LinesRefused = false; ///< no image load/store here: the slice sweep serves
  // Compiled when first used: each compiled program holds llvmpipe's JIT code in host
  // memory (docs/rendering.md, the memory target).
  std::unique_ptr<vtkOpenGLQuadHelper> ArriveQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> GatherQuads[GatherVariants];
  std::unique_ptr<vtkOpenGLQuadHelper> DimLightsQuad;
};

/** Makes @p quad's program current in @p window and returns it. */
vtkShaderProgram* UseProgram(vtkOpenGLRenderWindow* window, vtkOpenGLQuadHelper* quad);

/** The uniforms of scatterer_transport_common.glsl: how to read the medium at a grid
 * texel (scalar mapping, clipping, cropping, mask) and where the grid lies. */
void SetCommonUniforms(vtkShaderProgram* program, const TransportGrid& grid,
  const vtkScattererTransportVolume::Inputs& inputs);

/** st_toSweep: grid order -> @p plan's sweep order (rows, columns, slices). */
void SetSweepOrder(vtkShaderProgram* program, const SweepPlan& plan);

/** The sweep's texture -> structured index matrix (where it reads the depth in front). */
void SetIndexUniforms(vtkShaderProgram* program, const vtkScattererTransportVolume::Inputs& in);

/** Binds a texture to a sampler of a program for this object's lifetime. */
class ScopedSampler
{
public:
  ScopedSampler(vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture);
  ~ScopedSampler();
  ScopedSampler(const ScopedSampler&) = delete;
  ScopedSampler& operator=(const ScopedSampler&) = delete;

private:
  vtkTextureObject* Texture;
};

/** Binds the scalar texture, the mask when there is one and a vtkMultiVolume's parts to
 * a pass that reads the medium (st_volume, st_mask, st_parts), for this object's
 * lifetime. */
class ScopedVolume
{
public:
  ScopedVolume(vtkShaderProgram* program, const vtkScattererTransportVolume::Inputs& inputs);
  ~ScopedVolume();
  ScopedVolume(const ScopedVolume&) = delete;
  ScopedVolume& operator=(const ScopedVolume&) = delete;

private:
  vtkTextureObject* Volume;
  vtkTextureObject* Mask;
  std::vector<vtkTextureObject*> Parts;
};
}

#endif
