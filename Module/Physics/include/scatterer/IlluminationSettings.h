// The illumination's settings: one record of each quantity's name, default and valid
// range, with no VTK. vtkScattererTemplateVolumeMapper takes its member defaults and its
// setters' clamps from here, the example programs their option ranges and help text,
// and a test holds the ParaView representation's XML defaults to it. A default or a
// range is written here and nowhere else.
#ifndef scatterer_IlluminationSettings_h
#define scatterer_IlluminationSettings_h

#include <cmath>
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
// (2: 1/8 of the voxels) and for interactive frames that must rebuild; fewer along an axis
// of long voxels (transportStridesFor).
inline constexpr Setting<int> TransportScale{ "TransportScale", 2, 1, 8 };
inline constexpr Setting<int> InteractiveTransportScale{ "InteractiveTransportScale", 4, 1, 8 };
// Transport mode: the most voxels a still frame's transport volume holds (0: no limit).
// A volume that would have more at TransportScale is built coarser (transportScaleFor),
// so that its light is stored as finely in the object as a smaller volume's of the same
// object: the CT head's 256x256x108 voxels (915 k transport voxels at scale 2) keep
// scale 2, its resamples to 383x383x161 and 511x511x215 take 3 and 4 and the same 915 k
// voxels, and are lit as it is instead of by a finer diffusion; a rebuild then costs
// the same at every size (docs/rendering.md).
inline constexpr Setting<int> MaximumTransportVoxels{ "MaximumTransportVoxels", 1 << 20, 0,
  std::numeric_limits<int>::max() };

// Transport mode: how the transport grid's strides follow voxels that are not cubic. An
// axis whose voxels are at least kLongVoxel times as long as the shortest axis's takes
// fewer volume voxels per transport voxel, so that its texels stay about as long as along
// the shortest axis. A 1 x 1 x 3 mm ball at scale 2 had texels 6 mm deep and diffusion
// texels 12 mm deep: its light showed rings 6 mm apart and turned red (the diffusion's
// texels, averaging skin and air over 12 mm, scattered too often), 5.1 levels from the
// same ball sampled at 1 mm on average and up to 112, where stock Phong differs by 0.2
// (MapperBehaviour.NonCubicVoxelsAreLitAsTheSameObjectInCubicOnes; docs/model.md, "Its grid").
// Below kLongVoxel the grid keeps `scale` along every axis: at the CT head's 1.57 (0.96 x 0.96
// x 1.5 mm), texels of 2 x 2 x 1 voxels took the crown's rings away, but doubled the build under a
// moving light (orbiting 1.40x -> 1.55-1.61x stock on llvmpipe) and measured a little
// farther from the Monte Carlo reference (docs/accuracy.md, "Bands on the crown").
inline constexpr double kLongVoxel = 2.0;

// Each axis's voxel length in voxels of the shortest axis, or 1 where that is below
// kLongVoxel (`spacing`: the volume's voxel lengths; any unit, signs ignored; a length
// that is not positive and finite counts as 1).
inline void relativeVoxelLengths(const double spacing[3], double relative[3])
{
  double shortest = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double l = spacing[a] < 0.0 ? -spacing[a] : spacing[a];
    if (l > 0.0 && l < 1e300 && (shortest == 0.0 || l < shortest)) {
      shortest = l;
    }
  }
  for (int a = 0; a < 3; ++a) {
    const double l = spacing[a] < 0.0 ? -spacing[a] : spacing[a];
    const double r = shortest > 0.0 && l > 0.0 && l < 1e300 ? l / shortest : 1.0;
    relative[a] = r >= kLongVoxel ? r : 1.0;
  }
}

// Volume voxels per transport voxel along each axis at transport scale `scale`: `scale`,
// and along an axis of long voxels (relativeVoxelLengths) as many as keep the texel about
// `scale` voxels of the shortest axis long, at least 1.
inline void transportStridesFor(int scale, const double spacing[3], int strides[3])
{
  const int s = scale > 1 ? scale : 1;
  double relative[3];
  relativeVoxelLengths(spacing, relative);
  for (int a = 0; a < 3; ++a) {
    const long long n = static_cast<long long>(s / relative[a] + 0.5);
    strides[a] = n < 1 ? 1 : static_cast<int>(n);
  }
}

// The transport voxels of a volume of `dims` points per axis at `strides` volume voxels
// per transport voxel: every stride-th point from the first, and the last one covered.
inline long long transportVoxelsAt(const int dims[3], const int strides[3])
{
  long long voxels = 1;
  for (int a = 0; a < 3; ++a) {
    const int n = dims[a] > 1 ? dims[a] : 1;
    const int d = strides[a] > 1 ? strides[a] : 1;
    voxels *= n < 2 ? 1 : (n - 1 + d - 1) / d + 1;
  }
  return voxels;
}

// The scale a still frame's transport volume is built at, for a volume of `dims` points
// of `spacing`: TransportScale, raised until the volume holds at most
// MaximumTransportVoxels.
inline int transportScaleFor(
  int scale, const int dims[3], const double spacing[3], int maximumVoxels)
{
  int s = scale > 1 ? scale : 1;
  const int longest = dims[0] > dims[1] ? (dims[0] > dims[2] ? dims[0] : dims[2])
                                        : (dims[1] > dims[2] ? dims[1] : dims[2]);
  int strides[3];
  transportStridesFor(s, spacing, strides);
  while (maximumVoxels > 0 && s < longest && transportVoxelsAt(dims, strides) > maximumVoxels) {
    ++s;
    transportStridesFor(s, spacing, strides);
  }
  return s;
}

// The scale of a frame the user drags, when the still frames' is `stillScale`: as much
// coarser than a still frame's as InteractiveTransportScale is than TransportScale.
inline int interactiveTransportScaleFor(int scale, int interactiveScale, int stillScale)
{
  const int s = scale > 1 ? scale : 1;
  const int raised = (interactiveScale * stillScale + s - 1) / s;
  return interactiveScale > raised ? interactiveScale : raised;
}
// Volume voxels a texel of the diffusion's grid spans along each axis, when a still
// frame's transport scale is `stillScale`: about 4 (the diffusion's reach per iteration
// then stays the same) and at least 2 transport voxels. Frames built coarser while the
// user drags keep it (CoarseGrid::Over, Module/Transport).
inline int diffusionVoxelsFor(int stillScale)
{
  const int s = stillScale > 1 ? stillScale : 1;
  return 2 * s > 4 ? 2 * s : 4;
}
// Fine transport voxels per diffusion texel along each axis, for fine `strides` and a still
// frame's scale `stillScale`: diffusionVoxelsFor(stillScale) voxels of the shortest axis
// long, at least one fine voxel (along an axis of long voxels, relativeVoxelLengths, as
// many fine voxels as fit in that length). A frame built coarser while the user drags
// keeps a still frame's diffusion texels where its fine voxels divide them.
inline void diffusionBlocksFor(
  int stillScale, const int strides[3], const double spacing[3], int blocks[3])
{
  double relative[3];
  relativeVoxelLengths(spacing, relative);
  for (int a = 0; a < 3; ++a) {
    const double fine = (strides[a] > 1 ? strides[a] : 1) * relative[a];
    const long long n = static_cast<long long>(diffusionVoxelsFor(stillScale) / fine + 1e-9);
    blocks[a] = n < 1 ? 1 : static_cast<int>(n);
  }
}
// Transport mode: how many ray samples share one read of the light transport volume.
// The stored light is trilinear over texels of `texelSize` (world units, the geometric
// mean of a still frame's texel edges), so along a ray it has no detail finer than a
// texel: the ray reads it every `stride` samples of `rayStep` as long as that span fits
// in one texel, and the samples between two reads take the light interpolated between
// them (scatterer_shading_impl.glsl). 4 at most: each shared read costs a copy of the
// composite step in the shader (docs/rendering.md, "Fewer light reads"). 1: every
// sample reads the light (also for steps or texels that are not positive and finite).
inline constexpr int kMaximumLightReadStride = 4;
// A transport texel's size in the world: the geometric mean of its edges, at transport
// scale `scale` for voxels `voxelEdges` long (transportStridesFor); 0 for edges that are
// not positive.
inline double transportTexelSize(int scale, const double voxelEdges[3])
{
  int strides[3];
  transportStridesFor(scale, voxelEdges, strides);
  const double volume =
    strides[0] * voxelEdges[0] * strides[1] * voxelEdges[1] * strides[2] * voxelEdges[2];
  return volume > 0.0 ? std::cbrt(volume) : 0.0;
}
inline int lightReadStride(double rayStep, double texelSize)
{
  if (!(rayStep > 0.0) || !(texelSize > 0.0) || !(texelSize < 1e300) || !(rayStep < 1e300)) {
    return 1;
  }
  // "Fits" within a relative 1e-5: the ray step arrives rounded to single precision, and a
  // span of exactly one texel must not depend on the data's unit (0.5 mm steps over 2 mm
  // texels gave 4, the same in metres 2).
  int stride = kMaximumLightReadStride;
  while (stride > 1 && stride * rayStep > texelSize * (1.0 + 1e-5)) {
    stride /= 2;
  }
  return stride;
}
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
