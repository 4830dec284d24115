#include "ScattererRenderOptions.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

namespace scatterer_examples
{
namespace
{
bool ParseInt(const std::string& text, int lo, int hi, int& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || v < lo || v > hi)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

bool ParseSize(const std::string& text, int& w, int& h)
{
  const auto x = text.find_first_of("xX");
  return x != std::string::npos && ParseInt(text.substr(0, x), 16, 8192, w) &&
    ParseInt(text.substr(x + 1), 16, 8192, h);
}
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
         "                    template : vtkScattererTemplateVolumeMapper (default: stock)\n"
         "  --scene SCENE     for --input volumes: auto (fit camera, ramp transfer function)\n"
         "                    or ct-head (the benchmark scene's camera, light and transfer\n"
         "                    functions; for CT data in HU)\n"
         "  --json            print one JSON object: settings, frame times (ms), output path\n"
         "  --help            this text\n";
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
    std::string v;
    if (arg == "--help" || arg == "-h")
    {
      o.Help = true;
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
      if (!ParseSize(v, o.Width, o.Height))
      {
        error = "--size must be WxH with W and H in 16..8192, got '" + v + "'";
        return false;
      }
    }
    else if (arg == "--frames")
    {
      if (!value(v))
        return false;
      if (!ParseInt(v, 1, 10000, o.Frames))
      {
        error = "--frames must be an integer in 1..10000, got '" + v + "'";
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
