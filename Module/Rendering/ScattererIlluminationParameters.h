// The mapper's illumination settings for one frame, as one plain record with no VTK.
//
// vtkScattererTemplateVolumeMapper keeps its settings as members (its setters clamp
// them and its subclasses may read them) and gathers them here once per frame; the
// helpers that plan, generate, feed and install the frame (ScattererFramePlan,
// ScattererTemplateCache, ScattererTransportUpdate, ScattererUniformInstaller) take
// this record by const reference instead of a pointer back into the mapper. Defaults
// are those of scatterer/IlluminationSettings.h, where each is written once.
#ifndef ScattererIlluminationParameters_h
#define ScattererIlluminationParameters_h

#include "scatterer/IlluminationSettings.h"

#include <algorithm>

namespace scatterer_render
{
namespace il = scatterer::illumination;

/** The mapper's settings for one frame, by value: what the stage helpers read. */
struct IlluminationParameters
{
  bool Enabled = il::Illumination.Default;
  bool Shadows = il::Shadows.Default;
  bool ColorBleeding = il::ColorBleeding.Default;
  bool ThinPartCheck = il::ThinPartCheck.Default;
  bool BoundaryRefraction = il::BoundaryRefraction.Default;
  bool TemplateBlending = il::TemplateBlending.Default;
  bool CroppedMatterCastsShadows = il::CroppedMatterCastsShadows.Default;
  int ShaderPathSelection = il::ShaderPathSelection.Default;
  int IlluminationMode = il::IlluminationMode.Default;
  int TransportScale = il::TransportScale.Default;
  int InteractiveTransportScale = il::InteractiveTransportScale.Default;
  int MaximumTransportVoxels = il::MaximumTransportVoxels.Default;
  /// A piece of a distributed volume: the whole volume's point dimensions (0: the input
  /// is the whole volume).
  int WholeDimensions[3] = { 0, 0, 0 };
  double MultipleScattering = il::MultipleScattering.Default;
  double TemplateRadius = il::TemplateRadius.Default;
  int TemplatesPerMaterial = il::TemplatesPerMaterial.Default;
  int PhotonCap = il::PhotonCap.Default;
  double OcclusionStrength = il::OcclusionStrength.Default;
  double LongRangeMultiple = il::LongRangeMultiple.Default;
  int IlluminationInterval = il::IlluminationInterval.Default;
  double PhotonThreshold = il::PhotonThreshold.Default;
  double GeneratorThreshold = il::GeneratorThreshold.Default;
  /// Scalar range materials are derived over; lo > hi: the input's data range.
  double MaterialDerivationRange[2] = { 1.0, 0.0 };

  bool Transport() const { return this->IlluminationMode == il::Transport; }

  /** The scale a transport volume is built at (MaximumTransportVoxels) for a volume of
   * @p dims points of @p spacing, or for the whole volume when it is a piece of one. */
  int TransportScaleFor(const int dims[3], const double spacing[3], bool interactive) const
  {
    // A piece is never larger than the whole it belongs to: a whole set too small
    // (a stale setting) still keeps the piece within the voxel budget.
    int whole[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      whole[axis] = std::max(this->WholeDimensions[axis], dims[axis]);
    }
    const int still =
      il::transportScaleFor(this->TransportScale, whole, spacing, this->MaximumTransportVoxels);
    return interactive ? il::interactiveTransportScaleFor(
                           this->TransportScale, this->InteractiveTransportScale, still)
                       : still;
  }
  bool Automatic() const { return this->ShaderPathSelection == il::Automatic; }
};

/**
 * OcclusionStrength as a shader reads it: the factor on the optical depth of occluders.
 *
 * Each illumination path integrates optical depth over distances in its own length
 * unit, so the factor is the strength times the world length of that unit, and a
 * strength of 1 is physical in both: the transport volume measures in world units
 * (unit 1; vtkScattererTransportVolume::Inputs::OcclusionScale), the per-sample
 * photon test in template radii (unit: the radius; the st_occlusionScale uniform,
 * scatterer_illumination_dec.glsl st_transmittance).
 */
inline float OcclusionScale(double occlusionStrength, double worldLengthOfUnit)
{
  return static_cast<float>(occlusionStrength * worldLengthOfUnit);
}
}

#endif
