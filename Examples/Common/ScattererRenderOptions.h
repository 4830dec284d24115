// Command-line options of scatterer-render, parsed and validated in one place
// (CLI11, through ScattererCommandLine; why CLI11 is said there) so bad arguments
// get one clear message and exit status 2.
#ifndef ScattererRenderOptions_h
#define ScattererRenderOptions_h

#include "ScattererNumbers.h" // ParseSize, FormatNumber: used with these options

#include "scatterer/IlluminationSettings.h"

#include <string>

namespace scatterer_examples
{
struct RenderOptions
{
  std::string Input; // empty: the prepared CT head
  std::string Output = "ct-head.png";
  std::string Mode = "template"; // stock | phong | template
  std::string Scene = "auto";    // auto | ct-head (scene for --input volumes)
  int Width = 512;
  int Height = 512;
  int Frames = 1;
  bool Json = false;

  // Template illumination (--mode template); negative = the mapper's default.
  bool Shadows = scatterer::illumination::Shadows.Default;
  bool Bleeding = scatterer::illumination::ColorBleeding.Default;
  bool Thin = scatterer::illumination::ThinPartCheck.Default;
  bool Boundary = scatterer::illumination::BoundaryRefraction.Default;
  bool Blend = scatterer::illumination::TemplateBlending.Default;
  bool RequestedPaths = false; // --paths requested: every switched-on effect
  int Photons = -1, Templates = -1, Interval = -1, TransportScale = -1, MaxTransportVoxels = -1;
  std::string Illumination = "transport"; // transport | per-sample
  double Radius = -1, Threshold = -1, Strength = -1, LongRange = -1, MultipleScattering = -1;
};

/**
 * Parses argv into @p options. Returns ContinueRun (ScattererCommandLine.h) to go on,
 * otherwise the exit status once --help, --version or a usage error has been printed.
 */
int ParseRenderOptions(int argc, char* argv[], RenderOptions& options);

/** What --version prints: "<program> <ScattererTemplate version> (VTK <version>)". */
std::string VersionText(const std::string& program);

/** Escapes a string for a JSON string literal. */
std::string JsonEscape(const std::string& text);
}

#endif
