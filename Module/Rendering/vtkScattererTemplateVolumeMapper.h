/**
 * @class   vtkScattererTemplateVolumeMapper
 * @brief   GPU ray-cast volume mapper with scatterer-template global illumination.
 *
 * A drop-in replacement for vtkOpenGLGPUVolumeRayCastMapper that lights
 * volumes physically: global shadows through the whole volume, light scattered
 * inside materials (the scatterer templates of Lee, Kwon and Shin 2016 used as
 * the in-scattering kernel), colour bleeding between materials and multiple
 * scattering into shadowed regions.
 *
 * Default (IlluminationMode Transport): a light transport volume is built on the
 * GPU from the ray caster's own volume texture whenever the data, transfer
 * function, lights or settings change (vtkScattererTransportVolume: a
 * Beer-Lambert sweep per light, then one template gather of them all), and the
 * rays read it once per 4, 2 or 1 samples (light-stride: the most whose span fits in
 * one transport texel, so 4 on the benchmark scene and 2 at VTK's automatic step of
 * one voxel, as in ParaView; a vtkMultiVolume reads at every sample); the samples
 * between two reads take the light interpolated between them (docs/rendering.md,
 * "Fewer light reads").
 * PerSample: the paper's local photon test in the shader every IlluminationInterval
 * (4) samples (occluders within the template radius only).
 *
 * The work is injected into the stock ray caster as GLSL replacements on the
 * volume's shader property (Module/Shaders), so blend modes, cropping,
 * clipping planes, opaque geometry and several volumes keep working; removed
 * (cropped or clipped) material neither shows nor casts shadow.
 * With IlluminationEnabled off the mapper renders pixel-identically to
 * vtkOpenGLGPUVolumeRayCastMapper (tested).
 *
 * What the shader carries is chosen from the scene each frame (see
 * GetLastShaderFeatures); an effect switched off has no code at all
 * (ShaderPathSelection Automatic). The shader is rebuilt only when that GLSL
 * text changes.
 *
 * Illumination applies to composite blending of single-component scalars
 * (intensities or label maps), with or without a mask in transport mode: a binary
 * mask's masked-out matter neither shows nor casts shadow; with a label-map mask
 * each label's colour and opacity functions (vtkVolumeProperty SetLabelColor /
 * SetLabelScalarOpacity, labels 1..255) colour the picture and carry the light. The
 * transport mode also lights multi-component scalars, 2D transfer functions, a
 * vtkMultiVolume (up to 4 inputs), clipping planes, cropping and partitioned volumes
 * whose whole fits one 3D texture. These render as the stock mapper does, with one
 * warning per reason if illumination was asked for: other blend modes, rectilinear
 * grids, the depth pass; in per-sample mode multi-component scalars, 2D transfer
 * functions, a mask, clipping planes, cropping (unless CroppedMatterCastsShadows),
 * gradient opacity (a function not 1 everywhere) and a vtkMultiVolume; in transport mode a
 * partitioned volume whose whole does not fit one 3D texture, a label-map mask with
 * several components, a 2D transfer function or gradient opacity, a 2D transfer
 * function or gradient opacity on several components, and a vtkMultiVolume of
 * more than 4 inputs or with an input that has several components, a 2D transfer
 * function or gradient opacity (docs/rendering.md, "When the mapper renders as the
 * stock mapper").
 *
 * Parameters that only feed shader uniforms or the transport volume do not
 * call Modified(): the stock mapper rebuilds its shader whenever the mapper's
 * MTime moves, and a slider drag must not recompile. They bump
 * GetIlluminationMTime() instead and take effect on the next render. NaN values
 * are rejected with an error; values outside a parameter's range are clamped
 * with a warning.
 *
 * Progress (vtkCommand::ProgressEvent): a frame that rebuilds the illumination
 * reports 0 when the templates are regenerated, 0.1 when they are done, then the
 * light transport volume's GPU stages up to 0.95 (the medium's passes when the
 * medium changed; each light's sweep, in 2 reports for a directional light swept
 * line by line (vtkScattererTransportVolume SweepLinesInParallel, the default) and
 * in 4 for a light swept slice by slice (positional lights); the light it brings;
 * the source; each diffusion iteration (8); the gather: 13 reports for one
 * directional light, 14 when the medium changed, 15 and 16 for one positional light;
 * only while an observer is present, because each report waits for the GPU), and 1
 * after the image, with the progress text "Scatterer illumination" (the mapper's
 * executive also reports 0 and 1, untitled, when its pipeline runs).
 * Frames that rebuild nothing report nothing.
 *
 * @sa vtkOpenGLGPUVolumeRayCastMapper
 */
#ifndef vtkScattererTemplateVolumeMapper_h
#define vtkScattererTemplateVolumeMapper_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkTimeStamp.h" // for IlluminationTime

#include "scatterer/IlluminationSettings.h" // for the settings' defaults and ranges

#include <memory> // for Internals
#include <string> // for GetLastShaderFeatures

// The setting macros keep their hand layout (one-line accessor bodies).
// clang-format off
/**
 * Like vtkSetClampMacro, but without Modified() (see the class comment),
 * rejecting NaN with an error and warning when it clamps, naming the parameter.
 */
#define vtkScattererSetClampMacro(name, type, min, max)                                            \
  virtual void Set##name(type _arg)                                                                \
  {                                                                                                \
    if (_arg != _arg)                                                                              \
    {                                                                                              \
      vtkErrorMacro(<< "Set" #name ": NaN is not a valid value; keeping " << this->name << ".");  \
      return;                                                                                      \
    }                                                                                              \
    const type clamped = (_arg < min ? min : (_arg > max ? max : _arg));                           \
    if (clamped != _arg)                                                                           \
    {                                                                                              \
      vtkWarningMacro(<< "Set" #name ": " << _arg << " is outside [" << min << ", " << max        \
                      << "]; using " << clamped << ".");                                           \
    }                                                                                              \
    if (this->name != clamped)                                                                     \
    {                                                                                              \
      this->name = clamped;                                                                        \
      this->IlluminationTime.Modified();                                                           \
    }                                                                                              \
  }                                                                                                \
  virtual type Get##name##MinValue() { return min; }                                               \
  virtual type Get##name##MaxValue() { return max; }

/**
 * vtkScattererSetClampMacro with the range of the setting of the same name in
 * scatterer/IlluminationSettings.h, where every default and range is written once.
 */
#define vtkScattererSetSettingMacro(name, type)                                                    \
  vtkScattererSetClampMacro(name, type, scatterer::illumination::name.Minimum,                     \
    scatterer::illumination::name.Maximum)

/** A boolean switch without Modified() (see the class comment). */
#define vtkScattererSetSwitchMacro(name)                                                           \
  virtual void Set##name(bool _arg)                                                                \
  {                                                                                                \
    if (this->name != _arg)                                                                        \
    {                                                                                              \
      this->name = _arg;                                                                           \
      this->IlluminationTime.Modified();                                                           \
    }                                                                                              \
  }                                                                                                \
  vtkGetMacro(name, bool);                                                                         \
  vtkBooleanMacro(name, bool)
// clang-format on

class vtkScattererLightExchange;
class vtkScattererTransportVolume;
namespace scatterer_render
{
struct FramePlan;
struct IlluminationParameters;
}

class SCATTERERTEMPLATE_EXPORT vtkScattererTemplateVolumeMapper
  : public vtkOpenGLGPUVolumeRayCastMapper
{
public:
  static vtkScattererTemplateVolumeMapper* New();
  vtkTypeMacro(vtkScattererTemplateVolumeMapper, vtkOpenGLGPUVolumeRayCastMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Master switch. Off: exactly the stock mapper. Default: on. */
  vtkScattererSetSwitchMacro(IlluminationEnabled);
  ///@}

  ///@{
  /** Effect switches (default on, template blending off). */
  /** Occlusion: shadows (per sample: at each photon; transport: along every light path). */
  vtkScattererSetSwitchMacro(ShadowsEnabled);
  /** Photons in another material carry that material's colour. */
  vtkScattererSetSwitchMacro(ColorBleedingEnabled);
  /** Per sample: the longer check along photon directions, so thin parts do not glow. */
  vtkScattererSetSwitchMacro(ThinPartCheckEnabled);
  /** Snell's-law rescaling of photon offsets across materials. */
  vtkScattererSetSwitchMacro(BoundaryRefractionEnabled);
  /** Per sample: average two templates per sample (smoother, about twice the photon work). */
  vtkScattererSetSwitchMacro(TemplateBlendingEnabled);
  ///@}

  enum IlluminationModeType
  {
    TRANSPORT = scatterer::illumination::Transport, ///< light transport volume built on the GPU,
                                                    ///< read by every sample (default)
    PER_SAMPLE = scatterer::illumination::PerSample ///< the paper's local photon test in the
                                                    ///< fragment shader at every ray sample
  };
  ///@{
  /**
   * Transport (default): global shadows, template in-scattering and multiple
   * scattering from a light transport volume rebuilt on the GPU only when the
   * volume, transfer function, lights or settings change; each ray sample then
   * costs one extra texture read. PerSample: the paper's photon loop in the
   * shader at every sample, with its early exit on ray transmittance x photon
   * intensity; it sees occluders within the template radius only (times
   * LongRangeMultiple along the thin-part check).
   */
  vtkScattererSetSettingMacro(IlluminationMode, int);
  vtkGetMacro(IlluminationMode, int);
  void SetIlluminationModeToTransport() { this->SetIlluminationMode(TRANSPORT); }
  void SetIlluminationModeToPerSample() { this->SetIlluminationMode(PER_SAMPLE); }
  ///@}

  ///@{
  /**
   * Transport mode: volume voxels per transport-volume voxel along each axis
   * for still frames (default 2: 1/8 of the voxels), and for interactive frames
   * (the volume's allocated render time below 1 s, as VTK's interactor asks
   * while the user drags; default 4) that must rebuild the volume: when nothing it
   * depends on changed (orbiting under a scene light), interactive frames keep the
   * still frames' volume. Interactive frames keep the still frames' multiple scattering
   * grid, so their colours stay the still frames'. Smaller is sharper and slower. A
   * volume larger than MaximumTransportVoxels allows is built coarser. An axis whose
   * voxels are at least twice as long as the shortest axis's takes fewer per transport
   * voxel, so that the texels stay about as long along it (2, 2, 1 on an MRI's 1 x 1 x 3
   * mm; scatterer::illumination::transportStridesFor).
   */
  vtkScattererSetSettingMacro(TransportScale, int);
  vtkGetMacro(TransportScale, int);
  vtkScattererSetSettingMacro(InteractiveTransportScale, int);
  vtkGetMacro(InteractiveTransportScale, int);
  ///@}

  ///@{
  /**
   * Transport mode: the most voxels a still frame's transport volume holds (default
   * 1048576; 0: no limit). A volume that would hold more at TransportScale is built at
   * the smallest coarser scale that fits, and its dragging frames as much coarser
   * again as InteractiveTransportScale asks: the light is then stored as finely in the
   * object whatever the volume's resolution, so a resampled volume is lit as the
   * original, and a rebuild costs about the same at every size. The CT head
   * (256x256x108) keeps scale 2; 511x511x215 takes 4.
   */
  vtkScattererSetSettingMacro(MaximumTransportVoxels, int);
  vtkGetMacro(MaximumTransportVoxels, int);
  ///@}

  ///@{
  /**
   * A piece of a distributed volume: the point dimensions of the whole volume (the
   * ParaView plugin sets them from the pipeline's whole extent), so that every piece
   * builds its transport volume at the scale the whole volume takes (the pieces'
   * light must match). Default 0 0 0: the input is the whole volume.
   */
  void SetWholeDimensions(int nx, int ny, int nz);
  const int* GetWholeDimensions() const VTK_SIZEHINT(3) { return this->WholeDimensions; }
  ///@}

  /**
   * Transport mode: the scale (volume voxels per transport voxel; fewer along an axis
   * whose voxels are at least twice as long as the shortest axis's) the transport volume
   * of a volume of @p dims points of @p spacing (or of the whole volume,
   * SetWholeDimensions) is built at, for still frames or for frames the user drags
   * (@p interactive).
   */
  int GetEffectiveTransportScale(
    const int dims[3], const double spacing[3], bool interactive) const;

  ///@{
  /**
   * Transport mode: strength of the multiple-scattering term (light scattered
   * more than once, which reaches shadowed regions; docs/model.md). 0 leaves
   * single scattering only. Default 1.
   */
  vtkScattererSetSettingMacro(MultipleScattering, double);
  vtkGetMacro(MultipleScattering, double);
  ///@}

  ///@{
  /**
   * Off (default): cropped and clipped-away material neither shows nor casts
   * shadow. On: cropping only hides voxels from view, and they still carry light
   * (clipping planes keep removing matter). For a piece of a split volume, whose
   * ghost layers are hidden by cropping yet lie between the light and the piece's
   * own voxels; the ParaView plugin switches it on when it crops to the owned part.
   */
  vtkScattererSetSwitchMacro(CroppedMatterCastsShadows);
  ///@}

  /** Transport mode: milliseconds the last rebuild took (0 if the frame reused it). */
  double GetLastTransportBuildMilliseconds() const;

  /** Transport mode: the transport volume (its size, GPU bytes, build count, timing switch). */
  vtkScattererTransportVolume* GetTransportVolume() const;

  ///@{
  /**
   * A piece of a distributed volume: the exchange that carries each light in from the
   * other pieces (vtkScattererLightExchange; the ParaView plugin sets it). Its maps are
   * used when they were made for this frame's lights; otherwise the piece is lit
   * through its own voxels and ghost layers only. Default: none.
   */
  void SetLightExchange(vtkScattererLightExchange* exchange);
  vtkScattererLightExchange* GetLightExchange() const;
  /** True when the last transport build used the exchange's maps. */
  bool GetLightExchangeUsed() const;
  ///@}

  /**
   * How far, in the volume's data units, the illumination of a sample reads the
   * volume locally (0 with IlluminationEnabled off). Per sample: the template radius
   * (TemplateRadius, or 10 x the mean of `spacing` when that is 0), times
   * LongRangeMultiple with shadows and the thin-part check on. Transport: the largest
   * of the template radius (the kernel), two diffusion voxels (the ambient occlusion)
   * and, with MultipleScattering above 0, one diffusion voxel per diffusion iteration
   * (8); plus one transport voxel. A diffusion voxel is max(4, 2 x the still frames'
   * scale) x the finest spacing; a transport voxel is the larger of the still and
   * dragging frames' scales x the finest spacing (both grids count voxels, as many along
   * every axis or fewer along an axis of long voxels, so the reach over the finest spacing
   * is the ghost layers a piece needs; scales from
   * GetEffectiveTransportScale for the whole dimensions; TransportScale and
   * InteractiveTransportScale when they are not set). Defaults at spacing 1:
   * max(10, 8, 8 x 4) + 4 = 36; 14 with MultipleScattering 0; 52 at TransportScale 3
   * (diffusion voxel 6). Ghost layers this wide give a piece of a distributed volume the
   * in-scattering, multiple scattering and ambient light of the whole volume; shadows
   * cast from farther away (other pieces) come in through the light exchange
   * (SetLightExchange; docs/paraview.md).
   * Assumes an unscaled volume matrix.
   */
  double GetIlluminationReach(const double spacing[3]) const;

  enum ShaderPathSelectionType
  {
    AUTOMATIC =
      scatterer::illumination::Automatic, ///< only the code paths the scene needs (default)
    AS_REQUESTED =
      scatterer::illumination::AsRequested ///< every switched-on effect that can act, needed or not
  };
  ///@{
  /**
   * Automatic: the shader carries only what the scene needs (one material: no
   * boundary or bleeding code; a long-range multiple of 1: no thin-part code;
   * no positional light: no positional code). AsRequested: every effect that is
   * switched on and can act, for users who want to compare or who change scenes
   * often: boundary still needs 2 or more materials, bleeding is left out for
   * dependent components, the thin-part check (with shadows) and template blending
   * are per-sample only.
   */
  vtkScattererSetSettingMacro(ShaderPathSelection, int);
  vtkGetMacro(ShaderPathSelection, int);
  void SetShaderPathSelectionToAutomatic() { this->SetShaderPathSelection(AUTOMATIC); }
  void SetShaderPathSelectionToAsRequested() { this->SetShaderPathSelection(AS_REQUESTED); }
  ///@}

  ///@{
  /**
   * Template radius in world units. 0 (default): 10 times the mean voxel
   * spacing. Per sample: the reach of the photon test (larger radii see
   * occluders farther away). Transport: the largest in-scattering kernel (a
   * material's photons sit at its own mean free paths, up to this radius). Visible
   * matter's mean free paths are far shorter than any radius a user sets, so in
   * transport mode this changes nothing visible in practice (the CT head: the same
   * pixels at 1e-6 and 40 mm) and rebuilds nothing unless a kernel changes.
   */
  vtkScattererSetSettingMacro(TemplateRadius, double);
  vtkGetMacro(TemplateRadius, double);
  ///@}

  ///@{
  /**
   * Templates per material (default 8). Per sample: more templates mean finer
   * grain. Transport: a material's kernel is the mean of its templates.
   */
  vtkScattererSetSettingMacro(TemplatesPerMaterial, int);
  vtkGetMacro(TemplatesPerMaterial, int);
  ///@}

  ///@{
  /**
   * Per sample: most photons tested per template and sample. Transport: photons
   * in a material's in-scattering kernel (the most intense of all its templates'
   * photons). Default 24.
   */
  vtkScattererSetSettingMacro(PhotonCap, int);
  vtkGetMacro(PhotonCap, int);
  ///@}

  ///@{
  /**
   * Scales the optical depth of occluders (default 1, physical; 0 switches
   * occlusion off without changing the shader): at photon positions (per
   * sample), or along every light path of the transport volume.
   */
  vtkScattererSetSettingMacro(OcclusionStrength, double);
  vtkGetMacro(OcclusionStrength, double);
  ///@}

  ///@{
  /**
   * Per sample: ray samples between two photon evaluations (default 4; 1 =
   * every sample). Illumination varies on the scale of the template radius, so
   * a ray reuses it for a few samples (always re-evaluated when the material
   * changes). The transport mode reads its light once per 4, 2 or 1 samples (the
   * most whose span fits in one transport texel) and interpolates between the reads.
   */
  vtkScattererSetSettingMacro(IlluminationInterval, int);
  vtkGetMacro(IlluminationInterval, int);
  ///@}

  ///@{
  /**
   * Per sample: how far the thin-part check looks, in multiples of the photon
   * offset (default 3). The transport volume sees the whole volume.
   */
  vtkScattererSetSettingMacro(LongRangeMultiple, double);
  vtkGetMacro(LongRangeMultiple, double);
  ///@}

  ///@{
  /**
   * Per sample: the photon loop stops once ray transmittance x photon intensity
   * falls below this (default 0.002). 0 tests every photon up to PhotonCap.
   */
  vtkScattererSetSettingMacro(PhotonThreshold, double);
  vtkGetMacro(PhotonThreshold, double);
  ///@}

  ///@{
  /** Energy threshold of template generation (paper: 0.01; default 0.01). */
  vtkScattererSetSettingMacro(GeneratorThreshold, double);
  vtkGetMacro(GeneratorThreshold, double);
  ///@}

  ///@{
  /**
   * Materials. Without any, materials are derived from the scalar opacity
   * transfer function (one per interval where it is above zero). A scalar
   * range or a label id of a label map, with a refractive index and a diffuse
   * colour; the opacity comes from the transfer function. Up to 8.
   * AddMaterialsFromLabelTransferFunctions adds one per label of the volume
   * property's label maps (vtkVolumeProperty::GetLabelMapLabels), coloured by
   * the label's colour transfer function.
   */
  void AddScalarRangeMaterial(
    double lo, double hi, double refractiveIndex, double r, double g, double b);
  void AddLabelMaterial(int label, double refractiveIndex, double r, double g, double b);
  void AddMaterialsFromLabelTransferFunctions(vtkVolumeProperty* property);
  void RemoveAllMaterials();
  int GetNumberOfRequestedMaterials() const;

  /**
   * Scalar range over which materials are derived from the opacity transfer
   * function when none are given. Default (lo > hi, or after
   * ClearMaterialDerivationRange): the input's data range. A piece of a split
   * volume should get the whole volume's range, so that every piece derives the
   * same materials and templates as the whole volume (the ParaView plugin sets
   * it). Non-finite values are rejected with an error.
   */
  void SetMaterialDerivationRange(double lo, double hi);
  void ClearMaterialDerivationRange() { this->SetMaterialDerivationRange(1.0, 0.0); }
  const double* GetMaterialDerivationRange() const VTK_SIZEHINT(2)
  {
    return this->MaterialDerivationRange;
  }
  ///@}

  /**
   * Time of the last change to an illumination parameter (any setter above, or the
   * requested materials), for users and pipelines that watch the settings. The
   * mapper itself does not rebuild by it: what it keeps between frames (templates,
   * transport tables, shader texts) follows keys of the values it was made from, so a
   * setting that only feeds a uniform rebuilds nothing.
   */
  vtkMTimeType GetIlluminationMTime() const { return this->IlluminationTime.GetMTime(); }

  /**
   * What the last frame did: "stock: <reason>" or the feature list of the
   * illumination shader (e.g. "lights=1 materials=2 shadow thin bleed boundary").
   */
  const std::string& GetLastShaderFeatures() const;

  /** Materials used in the last frame (derived or requested). */
  int GetNumberOfActiveMaterials() const;

  /** Bytes of the template texture used in the last frame. */
  size_t GetTemplateTextureBytes() const;

  /** Releases the template texture and the transport volume with the stock mapper's resources. */
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * For tests: GLSL appended to the illumination declarations (e.g. a syntax
   * error, to check the fallback when a shader fails to compile).
   */
  void SetExtraShaderCodeForTesting(const std::string& glsl);

  /**
   * For tests: at most this many ray samples share a read of the light transport volume
   * (1: every sample reads it; by default as many as lightReadStride allows).
   */
  void SetMaximumLightReadStrideForTesting(int stride);

  /**
   * For tests: false leaves out the light inside a dense texel (on by default where the
   * scene allows it: scatterer_illumination_dec.glsl, st_surfaceChange), as a
   * vtkMultiVolume has none.
   */
  void SetSurfaceDetailForTesting(bool surfaceDetail);

  /**
   * For tests: false gathers every material's in-scattering kernel photon by photon,
   * also where it spreads little enough to be read at its centroid alone (the default,
   * scatterer::readsAtCentroid).
   */
  void SetGatherAtCentroidForTesting(bool atCentroid);

  /**
   * For tests: false draws the multiple-scattering solve on every texel of its coarse
   * grid, not only on the tiles that hold a medium (the default; the same light).
   */
  void SetDiffuseOnTilesForTesting(bool onTiles);

  /**
   * For tests: false sweeps every light on the transport volume's own grid, the dim ones
   * too (by default a light dimmer than half the brightest is swept on a grid twice as
   * coarse: a light kit's fill, head and back lights).
   */
  void SetCoarseDimLightsForTesting(bool coarse);

protected:
  vtkScattererTemplateVolumeMapper();
  ~vtkScattererTemplateVolumeMapper() override;

  /**
   * The injection point: decides what the scene needs, installs or removes
   * the GLSL replacements and uniforms on the volume's shader property, binds
   * the template texture, then lets the stock ray caster render.
   */
  void GPURender(vtkRenderer* ren, vtkVolume* vol) override;

  bool IlluminationEnabled = scatterer::illumination::Illumination.Default;
  bool ShadowsEnabled = scatterer::illumination::Shadows.Default;
  bool ColorBleedingEnabled = scatterer::illumination::ColorBleeding.Default;
  bool ThinPartCheckEnabled = scatterer::illumination::ThinPartCheck.Default;
  bool BoundaryRefractionEnabled = scatterer::illumination::BoundaryRefraction.Default;
  bool TemplateBlendingEnabled = scatterer::illumination::TemplateBlending.Default;
  int ShaderPathSelection = scatterer::illumination::ShaderPathSelection.Default;
  bool CroppedMatterCastsShadows = scatterer::illumination::CroppedMatterCastsShadows.Default;
  int IlluminationMode = scatterer::illumination::IlluminationMode.Default;
  int TransportScale = scatterer::illumination::TransportScale.Default;
  int InteractiveTransportScale = scatterer::illumination::InteractiveTransportScale.Default;
  int MaximumTransportVoxels = scatterer::illumination::MaximumTransportVoxels.Default;
  int WholeDimensions[3] = { 0, 0, 0 };
  double MultipleScattering = scatterer::illumination::MultipleScattering.Default;
  double TemplateRadius = scatterer::illumination::TemplateRadius.Default;
  int TemplatesPerMaterial = scatterer::illumination::TemplatesPerMaterial.Default;
  int PhotonCap = scatterer::illumination::PhotonCap.Default;
  double OcclusionStrength = scatterer::illumination::OcclusionStrength.Default;
  double LongRangeMultiple = scatterer::illumination::LongRangeMultiple.Default;
  int IlluminationInterval = scatterer::illumination::IlluminationInterval.Default;
  double PhotonThreshold = scatterer::illumination::PhotonThreshold.Default;
  double GeneratorThreshold = scatterer::illumination::GeneratorThreshold.Default;
  double MaterialDerivationRange[2] = { 1.0, 0.0 };
  vtkTimeStamp IlluminationTime;

private:
  /** UpdateProgress, and remember to report 1 at the end of the frame. */
  void ReportProgress(double fraction);
  /** Releases the graphics resources when an input's scalars have other components than
   * at the last frame (VTK 9.1's ray caster crashed on more of them). */
  void ReleaseOnNewComponents(vtkRenderer* ren);

  vtkScattererTemplateVolumeMapper(const vtkScattererTemplateVolumeMapper&) = delete;
  void operator=(const vtkScattererTemplateVolumeMapper&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  // The stages of GPURender, in order; each hands its work to a helper that gets the
  // settings as one VTK-free record (Module/Rendering/Scatterer*.h).
  /** The settings, gathered for the helpers of one frame. */
  scatterer_render::IlluminationParameters GatherParameters() const;
  /** The ray caster's step on still frames and a voxel's edges, in world units
   * (VolumeSource::StillRayStep, VolumeSource::VoxelEdges; 0 if unknown). */
  void StillSampling(vtkVolume* vol, double& rayStep, double voxelEdges[3]);
  /** What this frame needs, or why this volume renders as stock ("" if it can be lit). */
  std::string PlanFrame(vtkRenderer* ren, vtkVolume* vol,
    const scatterer_render::IlluminationParameters& parameters, scatterer_render::FramePlan& plan);
  /** Loads the ray caster's own textures before this frame makes any of its own. */
  std::string LoadVolume(vtkRenderer* ren, vtkVolume* vol, const scatterer_render::FramePlan& plan);
  /** Rebuilds the light transport volume if its inputs changed (transport mode). */
  std::string UpdateTransport(vtkRenderer* ren, vtkVolume* vol,
    const scatterer_render::IlluminationParameters& parameters,
    const scatterer_render::FramePlan& plan);
  /** Installs the GLSL and uniforms, then lets the stock ray caster render. */
  std::string RenderIlluminated(vtkRenderer* ren, vtkVolume* vol,
    const scatterer_render::IlluminationParameters& parameters,
    const scatterer_render::FramePlan& plan);
  /** Renders as the stock mapper, recording why. */
  void RenderStock(vtkRenderer* ren, vtkVolume* vol, const std::string& reason);
  /** The stock ray caster's GPURender, with the box's winding right for an image whose
   * direction matrix mirrors (ScattererMirroredWinding.h). */
  void RenderRayCaster(vtkRenderer* ren, vtkVolume* vol);
};

#endif
