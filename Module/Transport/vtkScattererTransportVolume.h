/**
 * @class   vtkScattererTransportVolume
 * @brief   The light transport volume: global shadows and template in-scattering,
 *          built on the GPU from the ray caster's own volume texture.
 *
 * For every light, a transmittance volume T_l (the fraction of the light's energy
 * that reaches each point through the whole volume) is swept slice by slice along
 * the light's dominant axis (Beer-Lambert, O(N) per light). The light all of them
 * bring, sum_l E_l a_l T_l, is gathered once through each material's scatterer
 * templates (single scattering, colour bleeding, Snell rescaling) into one RGB
 * texture: the light each point receives. The light scattered once is then spread by a diffusion
 * solve on a coarser grid (multiple scattering) and added. The ray caster reads
 * that texture once per 4, 2 or 1 samples (the most whose span fits in one of its
 * texels) and interpolates the samples between two reads. The equations are in
 * scatterer_transport_*.glsl beside it and docs/model.md.
 *
 * Both passes are fragment passes into textures (vtkOpenGLFramebufferObject,
 * vtkOpenGLQuadHelper) that read the mapper's scalar texture directly: there is no
 * host copy of the volume. Extinction follows VTK's opacity convention and the
 * transfer function the scene really uses; cropping and clipping planes remove
 * material from the transport (it neither shows nor casts shadow); the placement
 * is the ray caster's own (dataset matrix, image direction, the volume's matrix).
 *
 * The class owns its textures and a change key. Update() rebuilds only when the
 * inputs differ from the last build (volume upload, transfer function, lights,
 * geometry, materials, settings). It has no pointer back into the mapper: the
 * mapper fills a Inputs record each frame.
 *
 * @sa vtkScattererTemplateVolumeMapper
 */
#ifndef vtkScattererTransportVolume_h
#define vtkScattererTransportVolume_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkObject.h"

#include <functional> // for the progress callback
#include <memory>     // for Internals and Light::Entering
#include <string>     // for Inputs
#include <vector>     // for Inputs

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class SCATTERERTEMPLATE_EXPORT vtkScattererTransportVolume : public vtkObject
{
public:
  static vtkScattererTransportVolume* New();
  vtkTypeMacro(vtkScattererTransportVolume, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * A piece of a distributed volume: the optical depth between a light and everything
   * this piece holds (its voxels and ghost layers) that the other pieces hold, as a
   * light-space map (scatterer/LightSpace.h, filled by vtkScattererLightExchange) over
   * the whole volume's structured indices.
   */
  struct EnteringDepth
  {
    bool Positional = false;
    float Light[3] = { 0, 0, 0 };                 ///< positional: the light (index space)
    float U[3] = { 1, 0, 0 }, V[3] = { 0, 1, 0 }; ///< directional: the map plane's basis
    float Lo[2] = { 0, 0 };                       ///< directional: the map's corner on the plane
    float Side = 1;                               ///< directional: the map's side (index units)
    int Size = 0;                                 ///< texels per side
    std::vector<float> Depth;                     ///< Size x Size optical depths, row by row
  };

  /** One light as the transport sees it (world coordinates). */
  struct Light
  {
    float Toward[3] = { 0, 0, 1 };   ///< directional: unit vector toward the light
    float Position[3] = { 0, 0, 0 }; ///< positional: position
    bool Positional = false;
    float Color[3] = { 1, 1, 1 };           ///< irradiance: kd x diffuse colour x intensity
    float Ambient[3] = { 0, 0, 0 };         ///< VTK's ambient term: ka x ambient colour x intensity
    float FocalDirection[3] = { 0, 0, -1 }; ///< positional: unit vector light -> focal point
    float Attenuation[3] = { 1, 0, 0 };     ///< positional: 1 / (a0 + a1 d + a2 d^2)
    float ConeCos = -2.0f;                  ///< positional spot: cos(cone angle); < -1: none
    float Exponent = 1.0f;                  ///< positional spot exponent
    /// A piece of a distributed volume: what the other pieces take of this light before
    /// it enters this one (none: nothing does). Shared, not copied, frame to frame; a
    /// new map is a new object.
    std::shared_ptr<const EnteringDepth> Entering;
  };

  /** Everything one build needs; filled by the mapper every frame. */
  struct Inputs
  {
    vtkTextureObject* Volume = nullptr; ///< the ray caster's scalar texture (3D)
    /// texel -> normalised scalar, per component (the ray caster's in_volume_scale, _bias)
    float ScalarScale[4] = { 1, 1, 1, 1 }, ScalarBias[4] = { 0, 0, 0, 0 };
    /// How the medium comes from the components, as VTK's ray caster composites them
    /// (the values of ST_ONE_SCALAR ... in scatterer_transport_common.glsl):
    /// - OneScalar: row 0 of Medium (or a label's row) at the scalar;
    /// - Independent: row c at component c, mixed by ComponentWeights;
    /// - LuminanceAlpha: albedo from row 0 at component 0, sigma_t from row 1 at component 1;
    /// - RGBA: albedo = the rgb components, sigma_t from row 0 at component 3;
    /// - Transfer2D: Medium is a 2D table over (scalar, gradient magnitude), the
    ///   magnitude as VTK's ray caster computes it (VoxelStep, GradientAspect);
    /// - MultiInput: the inputs of a vtkMultiVolume (Parts), row k of Medium at part k's
    ///   scalar, their extinctions summed.
    enum ComponentRule
    {
      OneScalar = 0,
      Independent = 1,
      LuminanceAlpha = 2,
      RGBA = 3,
      Transfer2D = 4,
      MultiInput = 5
    };
    int ComponentMode = OneScalar;
    int Components = 1;                         ///< components of the volume texture (1-4)
    int MaterialComponent = 0;                  ///< the component MaterialTable is over
    float ComponentWeights[4] = { 1, 1, 1, 1 }; ///< vtkVolumeProperty's component weights
    float VoxelStep[3] = { 0, 0, 0 };           ///< one texel of the volume texture (Transfer2D)
    float GradientAspect[3] = { 1, 1, 1 }; ///< spacing * 2 / mean spacing, per axis (Transfer2D)
    unsigned long VolumeUploadTime = 0;    ///< changes when the texture's content does
    /// The texture's filter (vtkTextureObject's Nearest or Linear, the property's
    /// interpolation type): the passes sample the medium through it, and VTK changes it in
    /// place, without an upload.
    int VolumeFilter = 0;
    /// One input of a vtkMultiVolume, read through its own placement.
    struct Part
    {
      vtkTextureObject* Volume = nullptr; ///< the ray caster's texture of this input (1 component)
      float ScalarScale = 1, ScalarBias = 0; ///< texel -> normalised scalar
      double BoxToTexture[16] = {};          ///< box texture coordinates -> Volume's (row-major)
      unsigned long UploadTime = 0;
      int Filter = 0; ///< as VolumeFilter, this input's
    };
    /// A vtkMultiVolume (MultiInput; at most kMaxParts): VTK 9.1 composites its inputs one
    /// after the other at each ray step, so their extinctions add up. The transport is
    /// then placed on a box that holds all of them: "volume texture coordinates" below
    /// are the box's, BoxTexels its texels (Volume is part 0's texture, read by nothing).
    std::vector<Part> Parts;
    int BoxTexels[3] = { 0, 0, 0 };
    static constexpr int kMaxParts = 4;
    /// A binary mask on the volume's grid (R, nearest; VTK's convention: a voxel whose
    /// mask value is 0 is masked out), or none. Masked-out matter neither shows (the ray
    /// caster's own mask) nor casts shadow or scatters light (here).
    vtkTextureObject* Mask = nullptr;
    unsigned long MaskUploadTime = 0; ///< changes when the mask texture's content does
    /// The mask is a label map (VTK's LabelMapMaskType) rather than binary: a voxel's
    /// medium is row `label` of Medium (0: the volume's own transfer functions), mixed
    /// with row 0 by MaskBlend as VTK mixes the colours.
    bool LabelMask = false;
    float MaskBlend = 1;
    double TexToWorld[16] = {};   ///< volume texture coordinates -> world (row-major)
    double TexToDataset[16] = {}; ///< volume texture coordinates -> dataset (row-major)
    double TexToIndex[16] = {};   ///< volume texture coordinates -> structured index (row-major)
    /// Over the normalised scalar [0, 1], 4 per entry: albedo rgb (the colour transfer
    /// function) and sigma_t per world unit (the opacity transfer function); MediumRows
    /// rows of equal length (a label-map mask: one per label value, 0..255; a 2D transfer
    /// function: one per gradient-magnitude bin).
    std::vector<float> Medium;
    int MediumRows = 1;
    float OcclusionScale = 1;      ///< OcclusionStrength
    std::vector<float> ClipPlanes; ///< 4 per plane (world): kept where n.p + d >= 0
    bool Cropping = false;
    int CropFlags = 0;
    float CropMin[3] = { 0, 0, 0 }, CropMax[3] = { 0, 0, 0 }; ///< dataset coordinates
    /// The transport scale: volume voxels per transport voxel along each axis, fewer
    /// along an axis of long voxels (scatterer::illumination::transportStridesFor; the
    /// voxels' lengths from TexToWorld: scatterer_gpu::VoxelLengths)
    int Downsample = 2;
    /// A still frame's Downsample, which the diffusion's grid follows also when this
    /// build is coarser (a frame rendered while the user drags); 0: Downsample.
    int StillDownsample = 0;
    int IndexOrigin[3] = { 0, 0,
      0 }; ///< structured index of the texture's first texel (extent start)
    std::vector<Light> Lights;
    /// Changes whenever Medium, MaterialTable, MaterialColors, SpeedRatios,
    /// OpacityRatios, Kernels or KernelWidth change: the change key reads it instead of
    /// those tables, which would cost every frame.
    unsigned long TablesVersion = 0;
    // Materials (at most 8): a table of material indices over the normalised scalar
    // (-1: none), colours, albedos, ratio tables (materials^2, row = the sample's
    // material) and each one's kernel.
    std::vector<float> MaterialTable;
    int MaterialRows = 1;              ///< rows of MaterialTable (MultiInput: one per part)
    std::vector<float> MaterialColors; ///< 3 per material
    std::vector<float> SpeedRatios;
    std::vector<float> OpacityRatios;
    std::vector<float> Kernels; ///< per material KernelWidth x (offset xyz, weight)
    int KernelWidth = 0;
    bool Bleed = true;
    bool Boundary = true;
    /// A texel inside its material reads a kernel that spreads little at its centroid
    /// alone (scatterer::readsAtCentroid); false (tests only): photon by photon.
    bool GatherAtCentroid = true;
    /// The diffusion draws only the coarse texels that hold a medium
    /// (ScattererTransportTiles.h); false (tests only): every coarse texel.
    bool DiffuseOnTiles = true;
    /// Lights dimmer than half the brightest are swept on a grid twice as coarse
    /// (DimLightsOf, ScattererTransportLightPasses.h); false (tests only): every light on
    /// the fine grid.
    bool CoarseDimLights = true;
    float MultipleScattering = 1; ///< strength of the multiple-scattering term (0: none)
    int DiffusionIterations = 8;  ///< Jacobi iterations of the diffusion solve

    /** The points the grid lies on: the volume texture's, or (a vtkMultiVolume) the
     * box's that holds the parts. */
    void GetGridSourceDims(int dims[3]) const;
  };

  /**
   * Rebuilds the transport volume if @p inputs differ from the last build, in
   * the current OpenGL context of @p window. Returns false with @p why set when
   * it cannot (no volume texture, a framebuffer the driver refuses, ...).
   */
  bool Update(vtkOpenGLRenderWindow* window, const Inputs& inputs, std::string& why);

  /** True when Update(@p window, @p inputs) would keep the last build as it is. */
  bool IsCurrent(vtkOpenGLRenderWindow* window, const Inputs& inputs) const;

  /** The received-light texture (RGB, world irradiance summed over the lights). */
  vtkTextureObject* GetLightTexture() const;

  /** Volume texture coordinates -> light texture coordinates: t * scale + offset. */
  void GetTextureTransform(float scale[3], float offset[3]) const;

  /** Transport grid dimensions of the last build. */
  void GetDimensions(int dims[3]) const;

  /** Milliseconds the last rebuild took, GPU work included (0: the frame reused it). */
  double GetLastBuildMilliseconds() const;

  /** Where a rebuild's time goes, in milliseconds per stage. */
  struct StageMilliseconds
  {
    double Medium = 0.0; ///< what no light changes (only when the medium changed)
    double Sweeps = 0.0; ///< the lights' transmittance sweeps (pass 1)
    /// the light that lights swept slice by slice bring (pass 2a; a directional light
    /// swept in parallel adds its own in its sweep)
    double Arriving = 0.0;
    double Gather = 0.0;    ///< the template in-scattering (pass 2b)
    double Diffusion = 0.0; ///< multiple scattering and the ambient term (passes 3a-4)
  };

  /**
   * The stages of the last rebuild (all 0: the frame reused it). With SynchronousTiming,
   * or with a progress callback (SetProgressCallback, which waits for each stage
   * anyway), each stage waits for the GPU (glFinish) and its time is its GPU work;
   * otherwise it is the time to issue its passes.
   */
  StageMilliseconds GetLastBuildStageMilliseconds() const;

  /** Rebuilds so far (for tests and benchmarks). */
  int GetBuildCount() const;

  /** Builds so far that drew what no light changes again (for tests and benchmarks):
   * the medium's passes run when the volume, its transfer functions or placement,
   * clipping, cropping, the materials or the grid change, not when a light moves. */
  int GetMediumBuildCount() const;

  /** True while the medium's programs are held (for tests): they are compiled for the
   * medium's passes and kept only while the medium changes build after build (a transfer
   * function dragged), so that an orbit holds none (on llvmpipe a compiled program is
   * host memory). */
  bool GetHoldsMediumPrograms() const;

  /** GPU bytes held: the light and source textures, the transmittance, the slices, a
   * directional light's lines, the diffusion grids. */
  size_t GetGPUBytes() const;

  /**
   * For tests: the transmittance of light @p light of the last build (the light
   * entering each texel, scatterer_transport_sweep.glsl), in grid order
   * (x fastest), rebuilt for that light alone. Empty if none.
   */
  std::vector<float> ReadTransmittance(vtkOpenGLRenderWindow* window, int light);

  /** For tests: the received light read back, RGB per grid texel (what the texture
   * holds divided by the texel's weight in the ray's read). */
  std::vector<float> ReadLight(vtkOpenGLRenderWindow* window);

  /** For tests: each grid texel's weight in the ray's read of the light (1, or less for
   * a dense interior texel: scatterer_transport_gather.glsl). */
  std::vector<float> ReadLightWeights(vtkOpenGLRenderWindow* window);

  /** For tests: the diffusion's coarse grid of the last build, read back from its
   * textures; each array RGBA per coarse texel in grid order (x fastest). */
  struct DiffusionReadBack
  {
    int Dims[3] = { 0, 0, 0 };
    /// coarse texel c covers fine texels Block c + ToGrid + [0, Block)
    int ToGrid[3] = { 0, 0, 0 };
    int Block[3] = { 1, 1, 1 };
    float H[3] = { 0, 0, 0 };     ///< coarse texel size along each axis, world units
    std::vector<float> Medium;    ///< albedo, sigma_t
    std::vector<float> Occlusion; ///< one value a texel: the ambient light's transmittance
    std::vector<float> Source;    ///< the light scattered once
    /// the fluence of the Jacobi iteration before the last (rgb; alpha the texel's sigma_t)
    std::vector<float> Before;
    /// the fluence of the last iteration, as the gather read it (rgb; alpha its sigma_t)
    std::vector<float> Fluence;
  };

  /** For tests: see DiffusionReadBack; arrays empty if no build solved a diffusion. */
  DiffusionReadBack ReadDiffusion(vtkOpenGLRenderWindow* window);

  void ReleaseGraphicsResources(vtkWindow* window);

  /**
   * Called during a rebuild with the fraction of its passes done, (0, 1]: after the
   * medium's passes (when the medium changed), each light's sweep (twice for a
   * directional light swept line by line, SweepLinesInParallel on, the default; four
   * times, a quarter of its slices each, for a light swept slice by slice, as
   * positional lights are), the light each brings, the source, each diffusion
   * iteration and the gather (which adds the diffused and the ambient light). One
   * directional light and 8 iterations: 13 calls, 14 when the medium changed; one
   * positional light: 15 and 16. The fraction counts every sweep as 4 calls. The
   * passes run on the GPU asynchronously, so with a callback set the build waits for
   * each stage (glFinish) before reporting it: the fraction then says what the GPU has
   * done, not what was queued. Unset (the default), nothing waits. The mapper forwards it as its
   * ProgressEvent.
   */
  void SetProgressCallback(std::function<void(double)> callback);

  ///@{
  /**
   * Wait for the GPU to finish a build, and each of its stages, before timing it
   * (glFinish), so that GetLastBuildMilliseconds and GetLastBuildStageMilliseconds
   * include the GPU work. For benchmarks; default off (off, they are the time to issue
   * the passes).
   */
  vtkSetMacro(SynchronousTiming, bool);
  vtkGetMacro(SynchronousTiming, bool);
  ///@}

  ///@{
  /**
   * Sweep a directional light's lines in parallel, 16 slices a draw, then one draw for
   * the texels' mean (image load/store; scatterer_transport_lines.glsl), rather than one
   * draw per slice
   * (scatterer_transport_sweep.glsl). Both compute the same transmittance; the slice
   * sweep serves positional lights, and directional ones where the OpenGL implementation
   * has no image load/store (before 4.2, as on macOS). Default on; off for tests and A/B
   * measurements. A change applies at the next rebuild.
   */
  vtkSetMacro(SweepLinesInParallel, bool);
  vtkGetMacro(SweepLinesInParallel, bool);
  vtkBooleanMacro(SweepLinesInParallel, bool);
  ///@}

  ///@{
  /**
   * For tests: raise an OpenGL error as the next rebuild starts, as an OpenGL
   * implementation that refuses one of its passes would. Update then fails, saying so,
   * and the same inputs are not built again in this context.
   */
  vtkSetMacro(RaiseOpenGLErrorForTesting, bool);
  ///@}

protected:
  vtkScattererTransportVolume();
  ~vtkScattererTransportVolume() override;

  bool SynchronousTiming = false;
  bool SweepLinesInParallel = true;
  bool RaiseOpenGLErrorForTesting = false;

private:
  vtkScattererTransportVolume(const vtkScattererTransportVolume&) = delete;
  void operator=(const vtkScattererTransportVolume&) = delete;

  // The light texture read back as it holds it: RGB times the weight, and the weight.
  std::vector<float> ReadWeightedLight(vtkOpenGLRenderWindow* window);

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
