// Transport mode: keeps the light transport volume (vtkScattererTransportVolume) up
// to date with the frame.
//
// Each frame it fills the transport volume's Inputs record from the plan (lights,
// materials, kernels), the ray caster's own volume texture, the mask, the clipping
// planes and cropping, then lets the transport volume decide whether to rebuild. The
// tables (medium, materials, kernels) cost milliseconds to tabulate, so they are
// rebuilt only when their change key (transfer functions, range, materials, templates,
// PhotonCap, radius; ScattererChangeKey.h) changes.
#ifndef ScattererTransportUpdate_h
#define ScattererTransportUpdate_h

#include "ScattererChangeKey.h"
#include "ScattererMaskTexture.h"
#include "vtkScattererLightExchange.h"
#include "vtkScattererTransportVolume.h"

#include "vtkMatrix4x4.h" // for vtkNew<vtkMatrix4x4>
#include "vtkNew.h"
#include "vtkVolumeTexture.h" // for vtkNew<vtkVolumeTexture>

#include <functional>
#include <string>
#include <vector>

class vtkColorTransferFunction;
class vtkImageData;
class vtkMatrix4x4;
class vtkPiecewiseFunction;
class vtkPlaneCollection;
class vtkRenderer;
class vtkVolume;
class vtkVolumeTexture;
class vtkWindow;

namespace scatterer_render
{
struct FramePlan;
struct IlluminationParameters;
class TemplateCache;
class WarnOnce;

/** Entries of the medium and material tables over the scalar range. */
constexpr int kMediumTableSize = 4096;

/**
 * One row of the medium over [lo, hi] (@p entries of 4 floats): albedo rgb
 * from @p color (white when none), and sigma_t per world unit from @p opacity in VTK's
 * convention with @p unit the ScalarOpacityUnitDistance.
 */
void TabulateMedium(float* row, vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity,
  double lo, double hi, double unit, int entries = kMediumTableSize);

/** What the transport reads of the mapper besides the plan (its public state). */
struct TransportSource
{
  vtkVolumeTexture* VolumeTexture = nullptr; ///< the ray caster's own, loaded (PreLoadData)
  /// A vtkMultiVolume: the ray caster's texture of each input, in its order (the plan's Parts).
  std::vector<vtkVolumeTexture*> PartTextures;
  vtkImageData* Mask = nullptr;
  float MaskBlend = 1.0f;
  vtkPlaneCollection* ClippingPlanes = nullptr;
  bool Cropping = false;
  int CropFlags = 0;
  const double* CroppingRegionPlanes = nullptr; ///< 6 values: x min, x max, y min, ...
  /// A piece of a distributed volume: the light the other pieces let through, or null.
  const vtkScattererLightExchange::Result* Exchange = nullptr;
  /// The transport stage's progress in [0, 1], or empty when nobody listens (each
  /// report makes the build wait for the GPU).
  std::function<void(double)> Progress;
};

/**
 * Owns the light transport volume and its mask texture, and fills the transport
 * volume's inputs from each frame (tables only when their key changes).
 */
class TransportUpdate
{
public:
  TransportUpdate();
  ~TransportUpdate();
  TransportUpdate(const TransportUpdate&) = delete;
  TransportUpdate& operator=(const TransportUpdate&) = delete;

  /**
   * Rebuilds the transport volume if anything it depends on changed. Returns "" or
   * why the volume renders as stock; @p error is set when that is an error to raise
   * (the build failed), rather than a warning said through @p warn.
   */
  std::string Update(vtkRenderer* renderer, vtkVolume* volume, const FramePlan& plan,
    const IlluminationParameters& parameters, const TemplateCache& templates,
    const TransportSource& source, WarnOnce& warn, std::string& error);

  vtkScattererTransportVolume* GetVolume() const { return this->Transport; }

  /** Dataset coordinates -> the light texture's, row-major (after an Update). */
  void DatasetToLightTexture(double rowMajor[16]) const;

  /** True when the last update lit a piece with the light exchange's maps. */
  bool UsesLightExchange() const
  {
    return !this->Inputs.Lights.empty() && this->Inputs.Lights.front().Entering;
  }

  /** For tests: false reads every kernel photon by photon (Inputs::GatherAtCentroid). */
  void SetGatherAtCentroid(bool atCentroid) { this->Inputs.GatherAtCentroid = atCentroid; }

  /** For tests: false diffuses on every coarse texel (Inputs::DiffuseOnTiles). */
  void SetDiffuseOnTiles(bool onTiles) { this->Inputs.DiffuseOnTiles = onTiles; }

  /** For tests: false sweeps every light on the fine grid (Inputs::CoarseDimLights). */
  void SetCoarseDimLights(bool coarse) { this->Inputs.CoarseDimLights = coarse; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /**
   * The texture the transport reads: the ray caster's own, or for a partitioned volume
   * the whole volume loaded into one (null, with @p why, if it does not fit).
   */
  vtkVolumeTexture* WholeVolumeTexture(vtkRenderer* renderer, vtkVolume* volume,
    const FramePlan& plan, vtkVolumeTexture* rayCaster, std::string& why);
  /** The volume texture, its scale and bias, components and mask; "" or why not. */
  std::string UpdateVolume(vtkRenderer* renderer, vtkVolume* volume, const FramePlan& plan,
    const TransportSource& source, WarnOnce& warn);
  /** A vtkMultiVolume: each input's texture and placement in the box around them; "" or
   * why not. */
  std::string UpdateParts(const FramePlan& plan, const TransportSource& source, WarnOnce& warn);
  /** Where the volume texture lies (texture -> dataset -> world). */
  void UpdateGeometry(vtkVolume* volume, const FramePlan& plan);
  /** The clipping planes and the cropping region (not of a vtkMultiVolume). */
  void UpdateClipping(
    const TransportSource& source, const IlluminationParameters& parameters, bool multiVolume);
  /** The key of the medium, material and kernel tables' inputs. */
  std::string TablesKey(vtkVolume* volume, const FramePlan& plan,
    const IlluminationParameters& parameters, const TemplateCache& templates) const;
  /** The plan's lights; with an exchange made for them, the depth in front of the piece. */
  void UpdateLights(const FramePlan& plan, const TransportSource& source, WarnOnce& warn);
  /** How the medium comes from the volume's components (the plan's rule). */
  void UpdateComponents(vtkVolume* volume, const FramePlan& plan);
  /** The medium, material and kernel tables, over the volume texture's scalar ranges. */
  void UpdateTables(vtkVolume* volume, const FramePlan& plan,
    const IlluminationParameters& parameters, const TemplateCache& templates);
  /** The medium rows (per rule) and the material table of one volume. */
  void UpdateVolumeTables(vtkVolume* volume, const FramePlan& plan);
  /** A vtkMultiVolume's medium rows and material table rows, one per input. */
  void UpdatePartTables(const FramePlan& plan);

  // The light transport volume (owns its textures and build key).
  vtkNew<vtkScattererTransportVolume> Transport;
  // The mask (binary or label map) as the transport volume reads it.
  scatterer_gpu::MaskTexture Mask;
  // A partitioned volume: the ray caster streams one block at a time through one
  // texture, so the transport reads the whole volume from a texture of its own, loaded
  // by VTK's own class (same scale, bias and ranges) when the data changes.
  vtkNew<vtkVolumeTexture> WholeVolume;
  ChangeKey WholeVolumeKey;
  // The texel -> dataset matrix of the texture the transport read (VTK's texture ->
  // dataset after its cell-to-point offset is undone); for a vtkMultiVolume the box's
  // texel -> world matrix (the ray caster's lookup starts from the world there).
  vtkNew<vtkMatrix4x4> VolumeTextureToDataset;
  // The texture the transport read (the tables span its scalar ranges), and a
  // vtkMultiVolume's, one per input.
  vtkVolumeTexture* ReadTexture = nullptr;
  std::vector<vtkVolumeTexture*> PartTextures;
  // What the transport volume is built from (kept between frames for the tables).
  vtkScattererTransportVolume::Inputs Inputs;
  ChangeKey Tables;
};
}

#endif
