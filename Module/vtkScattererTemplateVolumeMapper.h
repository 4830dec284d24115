/**
 * @class   vtkScattererTemplateVolumeMapper
 * @brief   GPU ray-cast volume mapper with scatterer-template global illumination.
 *
 * A drop-in replacement for vtkOpenGLGPUVolumeRayCastMapper that lights
 * volumes with soft shadows, ambient occlusion, colour bleeding between
 * materials and light that stops at thin parts, after Lee, Kwon and Shin (2016):
 * per material a few precomputed photon templates (see Module/Physics) are
 * tested for occlusion at every composite sample.
 *
 * The work is injected into the stock ray caster as GLSL replacements on the
 * volume's shader property (Module/Shaders), so blend modes, cropping,
 * clipping planes, opaque geometry and several volumes keep working.
 * With IlluminationEnabled off the mapper renders pixel-identically to
 * vtkOpenGLGPUVolumeRayCastMapper (tested).
 *
 * What the shader carries is chosen from the scene each frame: one material
 * means no boundary code, no switched-on light means no illumination code, an
 * effect switched off has no code at all (ShaderPathSelection Automatic). The
 * shader is rebuilt only when that GLSL text changes.
 *
 * Illumination applies to composite blending of single-component scalars
 * (intensities or label maps). Other blend modes, multi-component data, masks,
 * multi-volumes, rectilinear grids, depth-pass and 2D transfer functions render
 * as the stock mapper does, with one warning if illumination was asked for.
 *
 * Parameters that only feed shader uniforms or the template texture
 * (everything below except materials) do not call Modified(): the stock mapper
 * rebuilds its shader whenever the mapper's MTime moves, and a slider drag must
 * not recompile. They bump GetIlluminationMTime() instead and take effect on
 * the next render. NaN values are rejected with an error; values outside a
 * parameter's range are clamped with a warning.
 *
 * @sa vtkOpenGLGPUVolumeRayCastMapper
 */
#ifndef vtkScattererTemplateVolumeMapper_h
#define vtkScattererTemplateVolumeMapper_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkTimeStamp.h" // for IlluminationTime

#include <memory> // for Internals
#include <string> // for GetLastShaderFeatures

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
  /** Occlusion test at each photon: shadows and ambient occlusion. */
  vtkScattererSetSwitchMacro(ShadowsEnabled);
  /** Photons in another material carry that material's colour. */
  vtkScattererSetSwitchMacro(ColorBleedingEnabled);
  /** The longer check along photon directions, so thin parts do not glow. */
  vtkScattererSetSwitchMacro(ThinPartCheckEnabled);
  /** Snell's-law rescaling of photon offsets across materials. */
  vtkScattererSetSwitchMacro(BoundaryRefractionEnabled);
  /** Average two templates per sample (smoother, about twice the photon work). */
  vtkScattererSetSwitchMacro(TemplateBlendingEnabled);
  ///@}

  enum IlluminationModeType
  {
    CACHED = 0,    ///< photon test on the CPU at a coarse grid, read by every sample (default)
    PER_SAMPLE = 1 ///< photon test in the fragment shader at every ray sample (the paper's loop)
  };
  ///@{
  /**
   * Cached (default): the photon test runs on the CPU (all cores) at the
   * voxels of a grid CacheScale times coarser than the volume, only when the
   * volume, transfer function, lights or settings change; each ray sample then
   * costs one extra texture read, so orbiting the camera under scene lights is
   * nearly free. PerSample: the photon loop runs in the shader at every
   * sample, with the paper's early exit on ray transmittance x photon
   * intensity; exact at every sample, but the loop runs every frame.
   */
  vtkScattererSetClampMacro(IlluminationMode, int, CACHED, PER_SAMPLE);
  vtkGetMacro(IlluminationMode, int);
  void SetIlluminationModeToCached() { this->SetIlluminationMode(CACHED); }
  void SetIlluminationModeToPerSample() { this->SetIlluminationMode(PER_SAMPLE); }
  ///@}

  ///@{
  /** Cached mode: cache voxels per volume voxel along each axis (default 2). */
  vtkScattererSetClampMacro(CacheScale, int, 1, 8);
  vtkGetMacro(CacheScale, int);
  ///@}

  ///@{
  /**
   * Cached mode: distinct templates averaged per cache voxel (default 4;
   * TemplateBlendingEnabled averages all of the material's templates). More
   * templates mean less grain and a proportionally longer cache update.
   */
  vtkScattererSetClampMacro(CacheTemplatesPerVoxel, int, 1, 64);
  vtkGetMacro(CacheTemplatesPerVoxel, int);
  ///@}

  /** Cached mode: milliseconds the last cache update took (0 if none was needed). */
  double GetLastCacheUpdateMilliseconds() const;

  /**
   * How far, in the volume's data units, the illumination of a sample reads the
   * volume: the template radius (TemplateRadius, or 10 x the mean of `spacing`
   * when that is 0) times LongRangeMultiple when the thin-part check is on, plus
   * one cache voxel (CacheScale x the largest spacing) in cached mode. A piece of a
   * distributed volume with ghost layers at least this wide is lit exactly as the
   * same voxels of the whole volume (the ParaView plugin requests them).
   * Assumes an unscaled volume matrix.
   */
  double GetIlluminationReach(const double spacing[3]) const;

  enum ShaderPathSelectionType
  {
    AUTOMATIC = 0, ///< only the code paths the scene needs (default)
    AS_REQUESTED = 1 ///< every switched-on effect, needed or not
  };
  ///@{
  /**
   * Automatic: the shader carries only what the scene needs (one material: no
   * boundary or bleeding code; a long-range multiple of 1: no thin-part code;
   * no positional light: no positional code). AsRequested: every effect that is
   * switched on, for users who want to compare or who change scenes often.
   */
  vtkScattererSetClampMacro(ShaderPathSelection, int, AUTOMATIC, AS_REQUESTED);
  vtkGetMacro(ShaderPathSelection, int);
  void SetShaderPathSelectionToAutomatic() { this->SetShaderPathSelection(AUTOMATIC); }
  void SetShaderPathSelectionToAsRequested() { this->SetShaderPathSelection(AS_REQUESTED); }
  ///@}

  ///@{
  /**
   * Template radius in world units. 0 (default): 10 times the mean voxel
   * spacing. Larger radii see occluders farther away (softer, longer shadows).
   */
  vtkScattererSetClampMacro(TemplateRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TemplateRadius, double);
  ///@}

  ///@{
  /** Templates per material (default 8); more templates mean finer grain. */
  vtkScattererSetClampMacro(TemplatesPerMaterial, int, 1, 64);
  vtkGetMacro(TemplatesPerMaterial, int);
  ///@}

  ///@{
  /** Most photons tested per template and sample (default 24). */
  vtkScattererSetClampMacro(PhotonCap, int, 1, 1024);
  vtkGetMacro(PhotonCap, int);
  ///@}

  ///@{
  /**
   * Scales the optical depth of occluders at photon positions (default 1;
   * 0 switches occlusion off without changing the shader).
   */
  vtkScattererSetClampMacro(OcclusionStrength, double, 0.0, 100.0);
  vtkGetMacro(OcclusionStrength, double);
  ///@}

  ///@{
  /**
   * Ray samples between two photon evaluations (default 4; 1 = every sample).
   * Illumination varies on the scale of the template radius, so a ray reuses
   * it for a few samples (always re-evaluated when the material changes).
   */
  vtkScattererSetClampMacro(IlluminationInterval, int, 1, 64);
  vtkGetMacro(IlluminationInterval, int);
  ///@}

  ///@{
  /** How far the thin-part check looks, in multiples of the photon offset (default 3). */
  vtkScattererSetClampMacro(LongRangeMultiple, double, 1.0, 64.0);
  vtkGetMacro(LongRangeMultiple, double);
  ///@}

  ///@{
  /**
   * The photon loop stops once ray transmittance x photon intensity falls
   * below this (default 0.002). 0 tests every photon up to PhotonCap.
   */
  vtkScattererSetClampMacro(PhotonThreshold, double, 0.0, 1.0);
  vtkGetMacro(PhotonThreshold, double);
  ///@}

  ///@{
  /** Energy threshold of template generation (paper: 0.01; default 0.01). */
  vtkScattererSetClampMacro(GeneratorThreshold, double, 1e-6, 0.5);
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
  void AddScalarRangeMaterial(double lo, double hi, double refractiveIndex, double r, double g,
    double b);
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
  const double* GetMaterialDerivationRange() const { return this->MaterialDerivationRange; }
  ///@}

  /** Time of the last change to an illumination parameter. */
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

  /** Releases the template texture with the stock mapper's resources. */
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * For tests: GLSL appended to the illumination declarations (e.g. a syntax
   * error, to check the fallback when a shader fails to compile).
   */
  void SetExtraShaderCodeForTesting(const std::string& glsl);

protected:
  vtkScattererTemplateVolumeMapper();
  ~vtkScattererTemplateVolumeMapper() override;

  /**
   * The injection point: decides what the scene needs, installs or removes
   * the GLSL replacements and uniforms on the volume's shader property, binds
   * the template texture, then lets the stock ray caster render.
   */
  void GPURender(vtkRenderer* ren, vtkVolume* vol) override;

  bool IlluminationEnabled = true;
  bool ShadowsEnabled = true;
  bool ColorBleedingEnabled = true;
  bool ThinPartCheckEnabled = true;
  bool BoundaryRefractionEnabled = true;
  bool TemplateBlendingEnabled = false;
  int ShaderPathSelection = AUTOMATIC;
  int IlluminationMode = CACHED;
  int CacheScale = 2;
  int CacheTemplatesPerVoxel = 4;
  double TemplateRadius = 0.0;
  int TemplatesPerMaterial = 8;
  int PhotonCap = 24;
  double OcclusionStrength = 1.0;
  double LongRangeMultiple = 3.0;
  int IlluminationInterval = 4;
  double PhotonThreshold = 0.002;
  double GeneratorThreshold = 0.01;
  double MaterialDerivationRange[2] = { 1.0, 0.0 };
  vtkTimeStamp IlluminationTime;

private:
  vtkScattererTemplateVolumeMapper(const vtkScattererTemplateVolumeMapper&) = delete;
  void operator=(const vtkScattererTemplateVolumeMapper&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
