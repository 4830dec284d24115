// The illumination's settings: one record of each quantity's name, default and valid
// range, with no VTK. vtkScattererTemplateVolumeMapper takes its member defaults and its
// setters' clamps from here, the example programs their option ranges and help text,
// and a test holds the ParaView representation's XML defaults to it. A default or a
// range is written here and nowhere else.
#ifndef scatterer_IlluminationSettings_h
#define scatterer_IlluminationSettings_h

#include <limits>

namespace scatterer {
namespace illumination {
/** A number the user sets: its name (as in the mapper's Set<Name>), default and range. */
template <typename T> struct Setting {
  const char* Name;
  T Default;
  T Minimum;
  T Maximum;
};

/** An effect or behaviour switched on or off. */
struct Switch {
  const char* Name;
  bool Default;
};

/** How the light a sample receives is found. */
enum Mode {
  Transport = 0, ///< the light transport volume (scatterer/Transport.h), read once per sample
  PerSample = 1  ///< the paper's local photon test at every sample
};

/** Which shader paths are compiled. */
enum PathSelection {
  Automatic = 0,  ///< what the scene needs (an effect with nothing to act on is left out)
  AsRequested = 1 ///< every effect switched on
};

inline constexpr Switch Illumination{ "IlluminationEnabled", true };
inline constexpr Switch Shadows{ "ShadowsEnabled", true };
inline constexpr Switch ColorBleeding{ "ColorBleedingEnabled", true };
inline constexpr Switch ThinPartCheck{ "ThinPartCheckEnabled", true };
inline constexpr Switch BoundaryRefraction{ "BoundaryRefractionEnabled", true };
inline constexpr Switch TemplateBlending{ "TemplateBlendingEnabled", false };
inline constexpr Switch CroppedMatterCastsShadows{ "CroppedMatterCastsShadows", false };

inline constexpr Setting<int> IlluminationMode{ "IlluminationMode", Transport, Transport,
  PerSample };
inline constexpr Setting<int> ShaderPathSelection{ "ShaderPathSelection", Automatic, Automatic,
  AsRequested };

// Transport mode: volume voxels per transport voxel along each axis, for still frames
// (2: 1/8 of the voxels) and for interactive frames that must rebuild.
inline constexpr Setting<int> TransportScale{ "TransportScale", 2, 1, 8 };
inline constexpr Setting<int> InteractiveTransportScale{ "InteractiveTransportScale", 4, 1, 8 };
// Transport mode: strength of the diffusion term (1 physical, 0 single scattering only).
inline constexpr Setting<double> MultipleScattering{ "MultipleScattering", 1.0, 0.0, 16.0 };

// Templates (Lee, Kwon, Shin 2016, section 3.1): radius in world units (0: ten times
// the mean spacing), templates per material, photons kept per template.
inline constexpr Setting<double> TemplateRadius{ "TemplateRadius", 0.0, 0.0,
  std::numeric_limits<double>::max() };
// The template radius a TemplateRadius setting means for a volume whose mean voxel
// spacing (world units) is meanSpacing: the setting itself, or 0 for ten voxels.
inline double templateRadiusFor(double setting, double meanSpacing)
{
  return setting > 0.0 ? setting : 10.0 * meanSpacing;
}
inline constexpr Setting<int> TemplatesPerMaterial{ "TemplatesPerMaterial", 8, 1, 64 };
inline constexpr Setting<int> PhotonCap{ "PhotonCap", 24, 1, 1024 };
// Scales the extinction along light paths only (1 physical, 0 no shadows).
inline constexpr Setting<double> OcclusionStrength{ "OcclusionStrength", 1.0, 0.0, 100.0 };

// Per-sample mode: ray samples between photon evaluations, the thin-part check's reach
// in photon offsets, the photon loop's cut-off on transmittance x intensity, and the
// template generator's cut-off on a photon's absorbed intensity.
inline constexpr Setting<int> IlluminationInterval{ "IlluminationInterval", 4, 1, 64 };
inline constexpr Setting<double> LongRangeMultiple{ "LongRangeMultiple", 3.0, 1.0, 64.0 };
inline constexpr Setting<double> PhotonThreshold{ "PhotonThreshold", 0.002, 0.0, 1.0 };
inline constexpr Setting<double> GeneratorThreshold{ "GeneratorThreshold", 0.01, 1e-6, 0.5 };
} // namespace illumination
} // namespace scatterer

#endif
