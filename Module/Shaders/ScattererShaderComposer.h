// Builds the GLSL of the scatterer-template illumination for one set of
// features, from the templates in Shaders/ (embedded at build time).
//
// The composer is what makes the mapper "simulate only what the scene calls
// for": every effect that is off has no code in the result, so the driver
// never compiles, and the GPU never branches over, work the scene does not
// need. Plain C++ (no VTK, no OpenGL) so the unit tests can read the text.
#ifndef ScattererShaderComposer_h
#define ScattererShaderComposer_h

#include "ScattererTemplateModule.h" // for export macro (used by the tests)

#include <map>
#include <string>

namespace scatterer_shader
{
/** The code paths one shader carries. */
struct SCATTERERTEMPLATE_EXPORT Features
{
  int Lights = 1;          ///< lights switched on (1..6, VTK's limit)
  int Materials = 1;       ///< materials the photon test distinguishes
  bool Shadow = true;      ///< occlusion test at each photon
  bool Thin = true;        ///< the longer check along the photon direction (needs Shadow)
  bool Bleed = true;       ///< photons in another material carry its colour
  bool Boundary = true;    ///< Snell rescaling across materials (needs Materials > 1)
  bool Positional = false; ///< some light is positional
  bool Blend2 = false;     ///< average two templates per sample
  bool Phong = false;      ///< keep VTK's gradient shading, darkened by the visibility
  bool Transport = true;  ///< read the light transport volume instead of the per-sample photon loop
  bool LabelMask = false; ///< colour from VTK's label-map mask (its per-label transfer functions)
  /// How the volume's components give colour and opacity, as VTK composites them: one
  /// scalar, independent components (each with its own transfer functions, mixed by the
  /// component weights), or dependent ones (luminance + alpha, RGBA).
  enum class Scalars
  {
    One,
    Independent,
    Dependent
  };
  Scalars Components = Scalars::One;
  /// A vtkMultiVolume: its inputs (0: one volume), each composited as VTK does.
  int Parts = 0;
  /// Transport, one volume: ray samples per read of the light transport volume (1, 2 or
  /// 4; scatterer::illumination::lightReadStride). Above 1 the composite step is written
  /// out that many times per pass of VTK's ray loop.
  int LightStride = 1;
  /// Transport, one volume, without gradient shading: the ray's first dense samples take
  /// the light inside their texel along the brightest light, after the ray loop
  /// (scatterer_illumination_dec.glsl, st_surfaceChange).
  bool SurfaceDetail = false;

  bool operator==(const Features& o) const;
  bool operator!=(const Features& o) const { return !(*this == o); }
  /** e.g. "lights=1 materials=2 shadow thin bleed boundary". */
  std::string Describe() const;
};

/**
 * Keeps or drops `//ST::IF NAME` ... `//ST::ELSE` ... `//ST::ENDIF` blocks by
 * @p flags (a missing name counts as false) and replaces `@NAME@` by
 * @p values. Throws std::runtime_error on unbalanced markers.
 */
SCATTERERTEMPLATE_EXPORT std::string Preprocess(const std::string& text,
  const std::map<std::string, bool>& flags, const std::map<std::string, std::string>& values);

/**
 * Light slots of the per-sample shader: the light count rounded up to 1, 2, 4 or
 * the limit (6); fixed in transport mode. With the material limit, the only count
 * the illumination text depends on, so that few texts (compiled programs) exist.
 */
SCATTERERTEMPLATE_EXPORT int LightSlots(const Features& features);

/** First line of IlluminationDeclarations: how an illumination program is recognized. */
constexpr const char* kProgramMarker = "// scatterer-template illumination program";

/** Functions inserted after VTK's `//VTK::ComputeRayDirection::Dec` text. */
SCATTERERTEMPLATE_EXPORT std::string IlluminationDeclarations(const Features& features);

/** Per-ray variables, inserted at `//VTK::Shading::Init` (VTK's text kept). */
SCATTERERTEMPLATE_EXPORT std::string ShadingInitialization(const Features& features);

/** The per-sample composite code that replaces `//VTK::Shading::Impl` (a vtkMultiVolume:
 * one block per input, in VTK's order). */
SCATTERERTEMPLATE_EXPORT std::string ShadingImplementation(const Features& features);

/** After the ray loop, inserted at `//VTK::Shading::Exit` (VTK's text kept; empty when
 * no feature needs it). */
SCATTERERTEMPLATE_EXPORT std::string ShadingExit(const Features& features);
}

#endif
