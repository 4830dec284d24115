// Command-line options of scatterer-render, parsed and validated in one place
// so bad arguments get one clear message and a non-zero exit.
#ifndef ScattererRenderOptions_h
#define ScattererRenderOptions_h

#include <string>

namespace scatterer_examples
{
struct RenderOptions
{
  std::string Input;                    // empty: the prepared CT head
  std::string Output = "ct-head.png";
  std::string Mode = "template";        // stock | phong | template
  std::string Scene = "auto";           // auto | ct-head (scene for --input volumes)
  int Width = 512;
  int Height = 512;
  int Frames = 1;
  bool Json = false;
  bool Help = false;
  bool Version = false;

  // Template illumination (--mode template); negative = the mapper's default.
  bool Shadows = true, Bleeding = true, Thin = true, Boundary = true, Blend = false;
  bool RequestedPaths = false; // --paths requested: every switched-on effect
  int Photons = -1, Templates = -1, Interval = -1, TransportScale = -1;
  std::string Illumination = "transport"; // transport | per-sample
  double Radius = -1, Threshold = -1, Strength = -1, LongRange = -1, MultipleScattering = -1;
};

/** Parses argv into @p options; false with @p error set on a bad argument. */
bool ParseRenderOptions(int argc, char* argv[], RenderOptions& options, std::string& error);

/**
 * Parses a window size "WxH", each 16..8192 (plain decimal integers, as every number
 * option); false with @p why saying what is wrong. scatterer-viewer uses it too.
 */
bool ParseSize(const std::string& text, int& width, int& height, std::string& why);

/** The --help text. */
std::string RenderUsage();

/** What --version prints: "<program> <ScattererTemplate version> (VTK <version>)". */
std::string VersionText(const std::string& program);

/** A number as messages show it (printf %g). */
std::string FormatNumber(double value);

/** Escapes a string for a JSON string literal. */
std::string JsonEscape(const std::string& text);
}

#endif
