#include "ScattererRenderOptions.h"

#include "vtkScattererTemplateVersion.h"
#include "vtkVersion.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace scatterer_examples
{
std::string VersionText(const std::string& program)
{
  return program + " " + vtkScattererTemplateVersion::GetVersion() + " (VTK " +
    vtkVersion::GetVTKVersion() + ")\n";
}

std::string FormatNumber(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}

namespace
{

/**
 * Why @p text is not a plain decimal number (an integer when @p integer), or "" if
 * it is one. strtod and strtol alone would take " 5" (leading space), "0x10"
 * (hexadecimal; strtod even reads hexadecimal fractions), "inf" and "nan", and a
 * user who typed them most likely meant something else.
 */
std::string DecimalSyntaxProblem(const std::string& text, bool integer)
{
  if (text.empty())
  {
    return "empty; a number is needed";
  }
  if (std::isspace(static_cast<unsigned char>(text.front())) ||
    std::isspace(static_cast<unsigned char>(text.back())))
  {
    return "has spaces around it; write the number alone";
  }
  size_t i = text[0] == '+' || text[0] == '-' ? 1 : 0;
  std::string rest = text.substr(i);
  std::transform(rest.begin(), rest.end(), rest.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (rest.rfind("inf", 0) == 0 || rest.rfind("nan", 0) == 0)
  {
    return "not a finite number (inf and nan are refused)";
  }
  if (rest.rfind("0x", 0) == 0)
  {
    return "hexadecimal is not accepted; write the number in decimal";
  }
  // [+-] digits [. digits] [e [+-] digits], or [+-] . digits [e ...].
  const auto digits = [&]() {
    const size_t from = i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])))
    {
      ++i;
    }
    return i - from;
  };
  size_t mantissa = digits();
  bool fraction = false;
  if (i < text.size() && text[i] == '.')
  {
    ++i;
    fraction = true;
    mantissa += digits();
  }
  bool exponent = false;
  if (mantissa > 0 && i < text.size() && (text[i] == 'e' || text[i] == 'E'))
  {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-'))
    {
      ++i;
    }
    exponent = true;
    if (digits() == 0)
    {
      mantissa = 0; // "1e" or "1e+": no exponent digits
    }
  }
  if (mantissa == 0 || i != text.size())
  {
    return integer ? "not a decimal integer" : "not a decimal number";
  }
  if (integer && (fraction || exponent))
  {
    return "not an integer";
  }
  return std::string();
}

bool ParseInt(const std::string& text, int lo, int hi, int& value, std::string& why)
{
  why = DecimalSyntaxProblem(text, true);
  if (!why.empty())
  {
    return false;
  }
  errno = 0;
  const long long v = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE || v < lo || v > hi)
  {
    why = "out of range; must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

bool ParseDouble(const std::string& text, double lo, double hi, double& value, std::string& why)
{
  why = DecimalSyntaxProblem(text, false);
  if (!why.empty())
  {
    return false;
  }
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && std::fabs(v) > 1.0)
  {
    why = "too large to represent (beyond " + FormatNumber(DBL_MAX) + ", the largest double)";
    return false;
  }
  // Underflow: strtod returns a denormal or 0 with ERANGE. Refused rather than
  // rounded: the value the user wrote is not the value the program would use.
  if ((errno == ERANGE && std::fabs(v) < 1.0) || (v != 0.0 && std::fabs(v) < DBL_MIN))
  {
    why = "too small to represent: its magnitude is below " + FormatNumber(DBL_MIN) +
      ", the smallest normal double (it would be kept as a denormal or as 0); write 0 for zero";
    return false;
  }
  if (!(v >= lo && v <= hi))
  {
    why = "out of range; must be a number in [" + FormatNumber(lo) + ", " + FormatNumber(hi) + "]";
    return false;
  }
  value = v;
  return true;
}

bool ParseOnOff(const std::string& text, bool& value)
{
  if (text == "on")
  {
    value = true;
    return true;
  }
  if (text == "off")
  {
    value = false;
    return true;
  }
  return false;
}
}

bool ParseSize(const std::string& text, int& width, int& height, std::string& why)
{
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos)
  {
    why = "not WxH (two integers joined by x, e.g. 512x512)";
    return false;
  }
  std::string problem;
  if (!ParseInt(text.substr(0, x), 16, 8192, width, problem))
  {
    why = "width " + problem;
    return false;
  }
  if (!ParseInt(text.substr(x + 1), 16, 8192, height, problem))
  {
    why = "height " + problem;
    return false;
  }
  return true;
}

std::string RenderUsage()
{
  return "Usage: scatterer-render [options]\n"
         "Renders a volume to a PNG and prints frame times.\n"
         "Default: the real CT head scene (shared/scenes/ct-head.json), 512x512.\n"
         "\n"
         "  --input PATH      volume: .mhd/.mha, .nii/.nii.gz, .vti, .nrrd/.nhdr or a DICOM\n"
         "                    folder (default: the prepared CT head, see scripts/prepare-data.sh)\n"
         "  --output FILE.png image to write (default ct-head.png)\n"
         "  --size WxH        window size, 16..8192 each (default 512x512)\n"
         "  --frames N        timed frames after one warm-up frame, 1..10000 (default 1)\n"
         "  --mode MODE       stock    : vtkOpenGLGPUVolumeRayCastMapper, no shading\n"
         "                    phong    : the stock mapper with VTK's gradient (Phong) shading\n"
         "                    template : vtkScattererTemplateVolumeMapper with template\n"
         "                               illumination (default)\n"
         "  --scene SCENE     for --input volumes: auto (fit camera, ramp transfer function)\n"
         "                    or ct-head (the benchmark scene's camera, light and transfer\n"
         "                    functions; for CT data in HU)\n"
         "  --json            print one JSON object: settings, frame times (ms), output path\n"
         "Template illumination (--mode template):\n"
         "  --shadows on|off  occlusion: shadows (default on)\n"
         "  --bleeding on|off colour bleeding between materials (default on)\n"
         "  --thin on|off     per-sample: thin-part check toward the light (default on)\n"
         "  --boundary on|off Snell rescaling across material boundaries (default on)\n"
         "  --blend on|off    per-sample: average two templates per sample (default off)\n"
         "  --paths auto|requested  shader code for what the scene needs (auto, default)\n"
         "                    or for every effect switched on\n"
         "  --illumination transport|per-sample  light transport volume built on the GPU and\n"
         "                    read by every sample (transport, default), or the paper's local\n"
         "                    photon test in the shader at every sample\n"
         "  --transport-scale N  transport: volume voxels per transport voxel per axis,\n"
         "                    1..8 (default 2)\n"
         "  --multiple-scattering K  transport: multiple-scattering strength, 0..16\n"
         "                    (default 1, physical; 0: single scattering only)\n"
         "  --photons N       photons per template (per-sample) or kernel (transport),\n"
         "                    1..1024 (default 24)\n"
         "  --templates N     templates per material, 1..64 (default 8)\n"
         "  --interval N      per-sample: ray samples between photon evaluations, 1..64\n"
         "                    (default 4)\n"
         "  --radius R        template radius in world units, > 0 (default 10 x spacing)\n"
         "  --threshold T     per-sample: photon-loop cut-off on transmittance x intensity, 0..1\n"
         "  --strength S      occlusion strength, 0..100 (default 1)\n"
         "  --long-range M    per-sample: thin-part check distance in photon offsets, 1..64\n"
         "                    (default 3)\n"
         "  --help            this text\n"
         "  --version         the ScattererTemplate and VTK versions\n"
         "Numbers are plain decimal (5, 0.25, 1e-3, a leading + or -). Refused with a message:\n"
         "hexadecimal (0x10), spaces around the number, trailing characters, inf, nan,\n"
         "fractions or exponents where an integer is asked for, and values too small for a\n"
         "normal double (magnitude below 2.2e-308, e.g. 1e-320; write 0 for zero).\n"
         "Volumes that cannot give a picture are refused before rendering, with a message\n"
         "naming the file and the reason: no finite value, fewer than 2 points along an axis,\n"
         "a spacing that is not a finite number > 0 (or beyond what single precision\n"
         "resolves), an origin that is not finite (or too far out), a constant volume\n"
         "(--scene auto), and a volume whose values the transfer function leaves transparent.\n"
         "Exit status: 0 the image was written; 1 the volume cannot be read or is refused, VTK\n"
         "reported an error while rendering, the frame came out blank (background only) although\n"
         "the volume has visible values, or the PNG cannot be written (no image is written on\n"
         "failure); 2 a bad argument.\n";
}

bool ParseRenderOptions(int argc, char* argv[], RenderOptions& o, std::string& error)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc)
      {
        error = "option " + arg + " needs a value";
        return false;
      }
      out = argv[++i];
      return true;
    };
    std::string v, why;
    if (arg == "--help" || arg == "-h")
    {
      o.Help = true;
    }
    else if (arg == "--version")
    {
      o.Version = true;
    }
    else if (arg == "--json")
    {
      o.Json = true;
    }
    else if (arg == "--input")
    {
      if (!value(o.Input))
        return false;
    }
    else if (arg == "--output")
    {
      if (!value(o.Output))
        return false;
      if (o.Output.size() < 5 || o.Output.substr(o.Output.size() - 4) != ".png")
      {
        error = "--output must name a .png file, got '" + o.Output + "'";
        return false;
      }
    }
    else if (arg == "--size")
    {
      if (!value(v))
        return false;
      if (!ParseSize(v, o.Width, o.Height, why))
      {
        error = "--size '" + v + "': " + why;
        return false;
      }
    }
    else if (arg == "--frames")
    {
      if (!value(v))
        return false;
      if (!ParseInt(v, 1, 10000, o.Frames, why))
      {
        error = "--frames '" + v + "': " + why;
        return false;
      }
    }
    else if (arg == "--mode")
    {
      if (!value(o.Mode))
        return false;
      if (o.Mode != "stock" && o.Mode != "phong" && o.Mode != "template")
      {
        error = "--mode must be stock, phong or template, got '" + o.Mode + "'";
        return false;
      }
    }
    else if (arg == "--scene")
    {
      if (!value(o.Scene))
        return false;
      if (o.Scene != "auto" && o.Scene != "ct-head")
      {
        error = "--scene must be auto or ct-head, got '" + o.Scene + "'";
        return false;
      }
    }
    else if (arg == "--shadows" || arg == "--bleeding" || arg == "--thin" || arg == "--boundary" ||
      arg == "--blend")
    {
      if (!value(v))
        return false;
      bool& target = arg == "--shadows" ? o.Shadows
        : arg == "--bleeding"           ? o.Bleeding
        : arg == "--thin"               ? o.Thin
        : arg == "--boundary"           ? o.Boundary
                                        : o.Blend;
      if (!ParseOnOff(v, target))
      {
        error = arg + " must be on or off, got '" + v + "'";
        return false;
      }
    }
    else if (arg == "--paths")
    {
      if (!value(v))
        return false;
      if (v != "auto" && v != "requested")
      {
        error = "--paths must be auto or requested, got '" + v + "'";
        return false;
      }
      o.RequestedPaths = v == "requested";
    }
    else if (arg == "--illumination")
    {
      if (!value(o.Illumination))
        return false;
      if (o.Illumination != "transport" && o.Illumination != "per-sample")
      {
        error = "--illumination must be transport or per-sample, got '" + o.Illumination + "'";
        return false;
      }
    }
    else if (arg == "--photons" || arg == "--templates" || arg == "--interval" ||
      arg == "--transport-scale")
    {
      if (!value(v))
        return false;
      const int hi = arg == "--photons" ? 1024 : arg == "--transport-scale" ? 8 : 64;
      int& target = arg == "--photons" ? o.Photons
        : arg == "--templates"         ? o.Templates
        : arg == "--transport-scale"       ? o.TransportScale
                                       : o.Interval;
      if (!ParseInt(v, 1, hi, target, why))
      {
        error = arg + " '" + v + "': " + why;
        return false;
      }
    }
    else if (arg == "--radius" || arg == "--threshold" || arg == "--strength" ||
      arg == "--long-range" || arg == "--multiple-scattering")
    {
      if (!value(v))
        return false;
      const double lo = arg == "--long-range" ? 1.0 : arg == "--radius" ? 1e-9 : 0.0;
      const double hi = arg == "--threshold" ? 1.0 : arg == "--strength" ? 100.0
        : arg == "--long-range"              ? 64.0
        : arg == "--multiple-scattering"     ? 16.0
                                             : 1e9;
      double& target = arg == "--radius" ? o.Radius
        : arg == "--threshold"           ? o.Threshold
        : arg == "--strength"            ? o.Strength
        : arg == "--multiple-scattering" ? o.MultipleScattering
                                         : o.LongRange;
      if (!ParseDouble(v, lo, hi, target, why))
      {
        error = arg + " '" + v + "': " + why;
        return false;
      }
    }
    else
    {
      error = "unknown argument '" + arg + "'";
      return false;
    }
  }
  return true;
}

std::string JsonEscape(const std::string& text)
{
  std::string out;
  for (const char c : text)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\u%04x", c);
      out += buf;
    }
    else
    {
      out += c;
    }
  }
  return out;
}
}
