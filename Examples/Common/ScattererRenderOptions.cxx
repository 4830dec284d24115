#include "ScattererRenderOptions.h"

#include "ScattererCommandLine.h"
#include "ScattererCtHeadScene.h"

#include "scatterer/IlluminationSettings.h"
#include "vtkScattererTemplateVersion.h"
#include "vtkVersion.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace scatterer_examples
{
std::string VersionText(const std::string& program)
{
  return program + " " + vtkScattererTemplateVersion::GetVersion() + " (VTK " +
    vtkVersion::GetVTKVersion() + ")\n";
}

namespace
{
bool ParseOnOff(const std::string& text, bool& value)
{
  if (text == "on" || text == "off")
  {
    value = text == "on";
    return true;
  }
  return false;
}

/** Throws a usage error for "--name 'text': why" (the form the messages have always had). */
[[noreturn]] void BadValue(const std::string& name, const std::string& text, const std::string& why)
{
  ThrowUsageError(name + " '" + text + "': " + why);
}

/** --name WORD, one of @p choices (shown in the message when another word is given). */
CLI::Option* AddChoice(CLI::App& app, const std::string& name, const std::string& valueName,
  const std::vector<std::string>& choices, const std::string& description, std::string& target)
{
  return AddValueOption(app, name, valueName, description,
    [name, choices, &target](const std::string& v)
    {
      if (std::find(choices.begin(), choices.end(), v) == choices.end())
      {
        std::string list;
        for (size_t i = 0; i < choices.size(); ++i)
        {
          list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
        }
        ThrowUsageError(name + " must be " + list + ", got '" + v + "'");
      }
      target = v;
    });
}

CLI::Option* AddOnOff(
  CLI::App& app, const std::string& name, const std::string& description, bool& target);

/** --name on|off for a switch of the mapper: its default from the record. */
CLI::Option* AddSwitch(CLI::App& app, const std::string& name,
  const scatterer::illumination::Switch& setting, const std::string& what, bool& target)
{
  return AddOnOff(app, name, what + " (default " + (setting.Default ? "on" : "off") + ")", target);
}

CLI::Option* AddOnOff(
  CLI::App& app, const std::string& name, const std::string& description, bool& target)
{
  return AddValueOption(app, name, "on|off", description,
    [name, &target](const std::string& v)
    {
      if (!ParseOnOff(v, target))
      {
        ThrowUsageError(name + " must be on or off, got '" + v + "'");
      }
    });
}

CLI::Option* AddInt(CLI::App& app, const std::string& name, const std::string& valueName, int lo,
  int hi, const std::string& description, int& target)
{
  return AddValueOption(app, name, valueName, description,
    [=, &target](const std::string& v)
    {
      std::string why;
      if (!ParseInt(v, lo, hi, target, why))
      {
        BadValue(name, v, why);
      }
    });
}

CLI::Option* AddDouble(CLI::App& app, const std::string& name, const std::string& valueName,
  double lo, double hi, const std::string& description, double& target)
{
  return AddValueOption(app, name, valueName, description,
    [=, &target](const std::string& v)
    {
      std::string why;
      if (!ParseDouble(v, lo, hi, target, why))
      {
        BadValue(name, v, why);
      }
    });
}

/** A setting's number as --help shows it: integers exactly (1048576, not %g's 1.04858e+06,
 * which the integer parser refuses), reals as messages show them. */
std::string SettingNumber(int value)
{
  return std::to_string(value);
}

std::string SettingNumber(double value)
{
  return FormatNumber(value);
}

/** The help text of a mapper setting: @p what, then a line "lo..hi (default d)" from the record. */
template <typename T>
std::string SettingHelp(const std::string& what, const scatterer::illumination::Setting<T>& setting)
{
  return what + "\n" + SettingNumber(setting.Minimum) + ".." + SettingNumber(setting.Maximum) +
    " (default " + SettingNumber(setting.Default) + ")";
}

/** "--a, --b or --c": the names of @p options, for the help's conflict rules. */
std::string OptionNames(const std::vector<CLI::Option*>& options)
{
  std::string names;
  for (size_t i = 0; i < options.size(); ++i)
  {
    names += (i == 0 ? "" : i + 1 == options.size() ? " or " : ", ") + options[i]->get_name();
  }
  return names;
}

/** The template radius --radius accepts, world units. */
constexpr double kMinimumRadius = 1e-9, kMaximumRadius = 1e9;

/** --name N for an integer setting of the mapper: its range and default from the record. */
CLI::Option* AddSetting(CLI::App& app, const std::string& name, const std::string& valueName,
  const scatterer::illumination::Setting<int>& setting, const std::string& what, int& target)
{
  return AddInt(
    app, name, valueName, setting.Minimum, setting.Maximum, SettingHelp(what, setting), target);
}

/** --name X for a real setting of the mapper: its range and default from the record. */
CLI::Option* AddSetting(CLI::App& app, const std::string& name, const std::string& valueName,
  const scatterer::illumination::Setting<double>& setting, const std::string& what, double& target)
{
  return AddDouble(
    app, name, valueName, setting.Minimum, setting.Maximum, SettingHelp(what, setting), target);
}

/** The help's footer, the conflict rules naming the options the parser refuses. */
std::string Footer(
  const std::vector<CLI::Option*>& perSample, const std::vector<CLI::Option*>& transport)
{
  return "Numbers are plain decimal (5, 0.25, 1e-3, a leading + or -). Refused with a message:\n"
         "hexadecimal (0x10), spaces around the number, trailing characters, inf, nan,\n"
         "fractions or exponents where an integer is asked for, and values too small for a\n"
         "normal double (magnitude below 2.2e-308, e.g. 1e-320; write 0 for zero).\n"
         "Every option takes --opt VALUE or --opt=VALUE, at most once (again only with the same\n"
         "value). Options that contradict each other are refused, naming both: a template\n"
         "illumination option with --mode stock or phong; a per-sample option\n(" +
    OptionNames(perSample) + ")\nwith transport illumination (the default); a transport option\n(" +
    OptionNames(transport) +
    ") with\n--illumination per-sample; --scene auto without --input.\n"
    "Volumes that cannot give a picture are refused before rendering, with a message\n"
    "naming the file and the reason: no finite value, fewer than 2 points along an axis,\n"
    "a spacing that is not a finite number > 0 (or beyond what single precision\n"
    "resolves), an origin that is not finite (or too far out), a constant volume\n"
    "(--scene auto), and a volume whose values the transfer function leaves transparent.\n"
    "The input is read and checked before the display is needed.\n"
    "Exit status: 0 the image was written; 1 the volume cannot be read or is refused, no X\n"
    "display, VTK reported an error while rendering, the frame came out blank (background\n"
    "only) although the volume has visible values, or the PNG cannot be written (no image\n"
    "is written on failure); 2 a bad command line (usage error).\n";
}
}

int ParseRenderOptions(int argc, char* argv[], RenderOptions& o)
{
  CLI::App app("Renders a volume to a PNG and prints frame times.\n"
               "Default: the prepared CT head in its benchmark scene, 512x512. The CT head is\n" +
      CtHeadPath() + ", made by scripts/prepare-data.sh in the source tree.",
    "scatterer-render");
  SetUpCommandLine(app);

  CLI::Option* input = AddValueOption(app, "--input", "PATH",
    "volume: .mhd/.mha, .nii/.nii.gz, .vti, .nrrd/.nhdr, a DICOM folder or one file of a series\n"
    "(default: the prepared CT head)",
    [&o](const std::string& v) { o.Input = v; });
  AddValueOption(app, "--output", "FILE.png", "image to write (default ct-head.png)",
    [&o](const std::string& v)
    {
      RequirePngPath("--output", v);
      o.Output = v;
    });
  AddValueOption(app, "--size", "WxH", "window size, 16..8192 each (default 512x512)",
    [&o](const std::string& v)
    {
      std::string why;
      if (!ParseSize(v, o.Width, o.Height, why))
      {
        BadValue("--size", v, why);
      }
    });
  AddInt(app, "--frames", "N", 1, 10000,
    "timed frames after one warm-up frame, 1..10000 (default 1)", o.Frames);
  AddChoice(app, "--mode", "MODE", { "stock", "phong", "template" },
    "stock    : vtkOpenGLGPUVolumeRayCastMapper, no shading\n"
    "phong    : the stock mapper with VTK's gradient (Phong) shading\n"
    "template : vtkScattererTemplateVolumeMapper with template\n"
    "           illumination (default)",
    o.Mode);
  CLI::Option* scene = AddChoice(app, "--scene", "SCENE", { "auto", "ct-head" },
    "for --input volumes: auto (fit camera, headlight, the transfer\n"
    "function from the histogram: the ct-head one for CT in HU, else\n"
    "Otsu thresholds; default) or ct-head (the benchmark scene's camera,\n"
    "light and transfer functions; for CT data in HU)",
    o.Scene);
  app.add_flag("--json", o.Json, "print one JSON object: settings, frame times (ms), output path");

  // Template illumination. Each option is listed as for both illumination modes, or
  // for one of them only, so that a combination that would be ignored is refused.
  std::vector<CLI::Option*> both, perSample, transport;
  const std::string group = "Template illumination (--mode template only)";
  namespace il = scatterer::illumination;
  both.push_back(AddSwitch(app, "--shadows", il::Shadows, "occlusion: shadows", o.Shadows));
  both.push_back(AddSwitch(
    app, "--bleeding", il::ColorBleeding, "colour bleeding between materials", o.Bleeding));
  perSample.push_back(AddSwitch(
    app, "--thin", il::ThinPartCheck, "per-sample: thin-part check toward the light", o.Thin));
  both.push_back(AddSwitch(app, "--boundary", il::BoundaryRefraction,
    "Snell rescaling across material boundaries", o.Boundary));
  perSample.push_back(AddSwitch(
    app, "--blend", il::TemplateBlending, "per-sample: average two templates per sample", o.Blend));
  both.push_back(AddValueOption(app, "--paths", "auto|requested",
    "shader code for what the scene needs (auto, default)\nor for every effect switched on",
    [&o](const std::string& v)
    {
      if (v != "auto" && v != "requested")
      {
        ThrowUsageError("--paths must be auto or requested, got '" + v + "'");
      }
      o.RequestedPaths = v == "requested";
    }));
  CLI::Option* illumination =
    AddChoice(app, "--illumination", "transport|per-sample", { "transport", "per-sample" },
      "light transport volume built on the GPU and read once per 1, 2\n"
      "or 4 samples (transport, default), or the paper's local photon\n"
      "test in the shader every --interval samples (per-sample)",
      o.Illumination);
  both.push_back(illumination);
  transport.push_back(AddSetting(app, "--transport-scale", "N", il::TransportScale,
    "transport: volume voxels per transport voxel per axis (fewer along an axis of voxels twice as "
    "long or more)",
    o.TransportScale));
  transport.push_back(AddSetting(app, "--max-transport-voxels", "N", il::MaximumTransportVoxels,
    "transport: most voxels of a still frame's transport volume;\na larger volume is built coarser "
    "(0: no limit)",
    o.MaxTransportVoxels));
  transport.push_back(AddSetting(app, "--multiple-scattering", "K", il::MultipleScattering,
    "transport: multiple-scattering strength (1 physical,\n0 single scattering only)",
    o.MultipleScattering));
  both.push_back(AddSetting(app, "--photons", "N", il::PhotonCap,
    "photons per template (per-sample) or kernel (transport)", o.Photons));
  both.push_back(AddSetting(
    app, "--templates", "N", il::TemplatesPerMaterial, "templates per material", o.Templates));
  perSample.push_back(AddSetting(app, "--interval", "N", il::IlluminationInterval,
    "per-sample: ray samples between photon evaluations", o.Interval));
  both.push_back(AddDouble(app, "--radius", "R", kMinimumRadius, kMaximumRadius,
    "template radius in world units, " + FormatNumber(kMinimumRadius) + ".." +
      FormatNumber(kMaximumRadius) +
      "\n(default 10 x spacing); per-sample: the photon "
      "test's reach;\ntransport: only caps the in-scattering kernel, which visible\nmatter "
      "keeps far shorter",
    o.Radius));
  perSample.push_back(AddSetting(app, "--threshold", "T", il::PhotonThreshold,
    "per-sample: photon-loop cut-off on transmittance x intensity", o.Threshold));
  both.push_back(
    AddSetting(app, "--strength", "S", il::OcclusionStrength, "occlusion strength", o.Strength));
  perSample.push_back(AddSetting(app, "--long-range", "M", il::LongRangeMultiple,
    "per-sample: thin-part check distance in photon offsets", o.LongRange));
  for (auto* list : { &both, &perSample, &transport })
  {
    for (CLI::Option* option : *list)
    {
      option->group(group);
    }
  }
  app.footer(Footer(perSample, transport));

  // Combinations whose one part would be silently ignored are refused, naming both.
  app.callback(
    [&]()
    {
      for (auto* list : { &both, &perSample, &transport })
      {
        for (const CLI::Option* option : *list)
        {
          if (option->count() > 0 && o.Mode != "template")
          {
            ThrowConflict(option->get_name(), "--mode " + o.Mode,
              option->get_name() + " sets template illumination, which only --mode template has");
          }
        }
      }
      const bool explicitIllumination = illumination->count() > 0;
      const auto& ignored = o.Illumination == "transport" ? perSample : transport;
      for (const CLI::Option* option : ignored)
      {
        if (option->count() > 0)
        {
          ThrowConflict(option->get_name(), "--illumination " + o.Illumination,
            option->get_name() + " is for " +
              (o.Illumination == "transport" ? "per-sample" : "transport") + " illumination only" +
              (explicitIllumination
                  ? ""
                  : " (transport is the default; add --illumination per-sample)"));
        }
      }
      if (scene->count() > 0 && o.Scene == "auto" && input->count() == 0)
      {
        ThrowUsageError("--scene auto needs --input: the default CT head is always shown in its "
                        "ct-head scene");
      }
    });
  return ParseCommandLine(app, argc, argv);
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
