// The first stage of every illuminated frame: what this scene needs, or why it
// renders as the stock ray caster.
//
// FramePlanner checks that illumination applies (blend mode, input kind, scalars,
// mask, depth pass, transfer-function mode), collects the lights, derives the
// template radius and the materials, and chooses the shader's code paths and
// GLSL. It keeps between frames only what is expensive to redo when nothing
// changed: a label-map mask's visible opacity and the scan for unassigned voxels,
// each behind its change key (ScattererChangeKey.h).
#ifndef ScattererFramePlan_h
#define ScattererFramePlan_h

#include "ScattererChangeKey.h"
#include "ScattererSceneLights.h"
#include "ScattererSceneMaterials.h"
#include "ScattererShaderComposer.h"
#include "scatterer/IlluminationSettings.h"

#include "vtkNew.h"

#include <string>
#include <vector>

class vtkDataArray;
class vtkDataSet;
class vtkImageData;
class vtkRenderer;
class vtkVolume;
class vtkVolumeProperty;

namespace scatterer_render
{
struct IlluminationParameters;
class WarnOnce;

/** Everything one frame of illumination needs, decided before rendering. */
struct FramePlan
{
  scatterer_shader::Features Features;
  scatterer_scene::LightSet Lights;
  scatterer_scene::MaterialSet Materials;
  bool MaterialsBuilt = false; ///< Materials were derived this frame (even if none)
  /// materials x materials tables, built once with the materials: the Snell speed ratio
  /// and the opacity ratio between each pair (the transport tables and the per-sample
  /// uniforms both read them)
  std::vector<float> SpeedRatios, OpacityRatios;
  vtkImageData* Image = nullptr;
  vtkDataArray* Scalars = nullptr;
  int CellFlag = 0;
  /// The component whose scalar selects the materials (0 for one scalar; the opacity's
  /// component of dependent ones; the first shown of independent ones).
  int MaterialComponent = 0;
  /// A 2D transfer function (over the scalar and its gradient magnitude) gives colour and
  /// opacity, one ray step of SampleDistance at a time (ScattererTransfer2D.h).
  bool Transfer2D = false;
  /// One scalar with a 1D transfer function whose gradient opacity hides some matter: VTK's
  /// ray caster multiplies each step's opacity by the gradient opacity at the scalar's
  /// gradient magnitude, and the transport's medium takes it over (scalar, gradient
  /// magnitude) alike (ScattererTransfer2D.h), so that hidden matter casts no shadow.
  bool GradientOpacity = false;
  /// A vtkMultiVolume's inputs, in the ray caster's order (its input ports, ascending);
  /// empty for one volume. Image, Scalars and CellFlag above are the first one's.
  struct Part
  {
    vtkVolume* Volume = nullptr; ///< its placement and properties
    vtkImageData* Image = nullptr;
    vtkDataArray* Scalars = nullptr;
    int CellFlag = 0;
    int FirstMaterial = 0, MaterialCount = 0; ///< its materials in Materials
  };
  std::vector<Part> Parts;
  double SampleDistance = 1.0; ///< the ray caster's step, world units
  double Radius = 1.0;         ///< template radius, world units
  float ToTex[3][3] = {}; ///< per-sample mode: texture offset of one radius along world x, y, z
  std::string Declarations, ShadingInit, Shading, ShadingExit; ///< this frame's GLSL

  /** Identifies this frame's shader text (ScattererChangeKey.h). */
  std::string ShaderKey() const
  {
    return this->Declarations + this->ShadingInit + this->Shading + this->ShadingExit;
  }
};

/** What the mapper renders, as the planner reads it (the mapper's public state). */
struct VolumeSource
{
  vtkDataSet* Input = nullptr;
  vtkImageData* Mask = nullptr;
  bool LabelMapMask = false; ///< Mask is a label map (VTK's LabelMapMaskType)
  int BlendMode = 0;
  bool UseDepthPass = false;
  bool Clipped = false;        ///< clipping planes are set
  bool Cropped = false;        ///< cropping is on
  double SampleDistance = 1.0; ///< vtkVolumeMapper's SampleDistance (world units)
  /// The ray caster's step between samples on still frames, as VTK 9.1 picks it from
  /// SampleDistance, AutoAdjustSampleDistances and LockSampleDistanceToInputSpacing
  /// (world units; 0: unknown).
  double StillRayStep = 0.0;
  /// This frame's step may be longer than StillRayStep: a frame rendered while the user
  /// drags (the renderer's time below a second) with AutoAdjustSampleDistances on, whose
  /// step VTK divides by half its reduction factor, known only once the ray caster draws.
  bool RayStepMayGrow = false;
  /// A voxel's edges in the world (0: unknown).
  double VoxelEdges[3] = { 0.0, 0.0, 0.0 };
  int ScalarMode = 0, ArrayAccessMode = 0, ArrayId = -1;
  const char* ArrayName = nullptr;
  /// A vtkMultiVolume: each input port's data and volume, ports ascending (empty: one volume).
  struct Part
  {
    vtkDataSet* Input = nullptr;
    vtkVolume* Volume = nullptr;
  };
  std::vector<Part> Parts;
};

/** The materials the user asked for, and shader texts known not to compile here. */
struct PlanRequests
{
  const std::vector<scatterer_scene::RequestedMaterial>* Materials = nullptr;
  std::string ExtraGLSL; ///< for tests: appended to the declarations
  /// for tests: at most this many samples per light read (1: every sample reads it)
  int MaximumLightStride = scatterer::illumination::kMaximumLightReadStride;
  bool SurfaceDetail = true; ///< for tests: false leaves out the light inside a dense texel
  const KeySet* FailedShaders = nullptr;
};

/**
 * Decides each frame what the illumination needs (FramePlan) or why the volume renders
 * as stock; keeps only the label-union opacity and the unassigned-voxel scan between frames.
 */
class FramePlanner
{
public:
  FramePlanner();
  ~FramePlanner();
  FramePlanner(const FramePlanner&) = delete;
  FramePlanner& operator=(const FramePlanner&) = delete;

  /**
   * Fills @p plan for rendering @p source in @p volume with @p renderer; returns ""
   * when the frame can be illuminated, or why it renders as stock (warning once,
   * through @p warn, where the user asked for something that cannot be lit).
   */
  std::string Plan(vtkRenderer* renderer, vtkVolume* volume, const VolumeSource& source,
    const IlluminationParameters& parameters, const PlanRequests& requests, WarnOnce& warn,
    FramePlan& plan);

private:
  std::string PlanGeometry(
    vtkVolume* volume, const IlluminationParameters& parameters, WarnOnce& warn, FramePlan& plan);
  std::string PlanMaterials(vtkVolume* volume, const VolumeSource& source,
    const IlluminationParameters& parameters, const PlanRequests& requests, WarnOnce& warn,
    FramePlan& plan);
  /** The volume property materials are derived from (a label-map mask: the union of its
   * labels; independent components: the material component's functions). */
  vtkVolumeProperty* MaterialProperty(vtkVolumeProperty* property, bool labelMapMask,
    const double derivation[2], const FramePlan& plan);
  /** A vtkMultiVolume: each input's materials from its own transfer functions, together
   * at most the material limit. */
  std::string PlanPartMaterials(const IlluminationParameters& parameters,
    const PlanRequests& requests, WarnOnce& warn, FramePlan& plan);
  void WarnUnassigned(
    vtkVolumeProperty* property, const double range[2], WarnOnce& warn, const FramePlan& plan);
  std::string PlanFeatures(vtkVolume* volume, const VolumeSource& source,
    const IlluminationParameters& parameters, const PlanRequests& requests, FramePlan& plan);

  // A label-map mask: the opacity materials are derived from (the largest any label
  // gives a scalar), and what it was tabulated from.
  vtkNew<vtkVolumeProperty> LabelUnion;
  ChangeKey LabelUnionKey;
  // Independent components: the material component's functions as component 0's; a 2D
  // transfer function: what each scalar shows at its most visible gradient.
  vtkNew<vtkVolumeProperty> ComponentView;
  ChangeKey Transfer2DKey;
  // The data, transfer function and materials last scanned for unassigned voxels.
  ChangeKey UnassignedKey;
};
}

#endif
