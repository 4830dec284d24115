// Renders the Monte Carlo reference (Reference) of a VTK volume scene: the CT
// head scene by default (Examples/Common/ScattererCtHeadScene.cxx), the synthetic shell +
// plate scene, or any volume with the CT head's or the automatic transfer functions. Writes the
// float image (.vti or .mha: "Radiance" RGB + per-pixel "StandardError") and a PNG, and prints the
// samples per pixel and the noise estimate.
//
// Run with --help for the options and the exit statuses.
#include "ScattererReferenceScene.h"

#include "Common/ScattererCommandLine.h"
#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererRenderOptions.h"
#include "scatterer_reference/PathTracer.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkScattererVolumeReader.h"
#include "vtkVolumeProperty.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

namespace
{
struct ReferenceOptions
{
  // A named scene (scatterer_reference_vtk::kNamedScenes) or auto (--input only).
  std::string Scene = "ct-head";
  std::string Input, Output = "reference", Exposure = "auto";
  int Width = 256, Height = 256;
  bool Quiet = false;
};

/** --name N: a plain decimal integer in lo..hi, as in scatterer-render. */
CLI::Option* AddInt(CLI::App& app, const std::string& name, int lo, int hi,
  const std::string& description, std::function<void(int)> set)
{
  return scatterer_examples::AddValueOption(app, name, "N", description,
    [=](const std::string& v)
    {
      int value = 0;
      std::string why;
      if (!scatterer_examples::ParseInt(v, lo, hi, value, why))
      {
        scatterer_examples::ThrowUsageError(name + " '" + v + "': " + why);
      }
      set(value);
    });
}

/** ContinueRun, or the exit status once --help, --version or a usage error is printed. */
int ParseArgs(
  int argc, char* argv[], ReferenceOptions& o, scatterer_reference::RenderSettings& settings)
{
  CLI::App app("Monte Carlo volumetric path tracing (delta tracking, NEE with ratio tracking) of\n"
               "the scene; writes PREFIX.vti (float RGB radiance + standard error) and PREFIX.png\n"
               "and prints one JSON line.",
    "scatterer-reference");
  scatterer_examples::SetUpCommandLine(app);
  app.footer("Numbers are plain decimal integers (as in scatterer-render); every option takes\n"
             "--opt VALUE or --opt=VALUE, at most once (again only with the same value).\n"
             "Refused as contradictory: --scene shell-plate, shell-plate-point or dense-ball with\n"
             "--input (a built-in volume), --scene auto without --input.\n"
             "Exit status: 0 the images were written; 1 the volume or the prepared CT head cannot\n"
             "be read, or an image cannot be written; 2 a bad command line (usage error).\n");
  CLI::Option* scene = scatterer_examples::AddValueOption(app, "--scene", "SCENE",
    "ct-head (default: the prepared CT head, " + scatterer_examples::CtHeadPath() +
      ",\nmade by scripts/prepare-data.sh in the source tree, or --input in that scene),\n"
      "ct-head-light-kit (the same lit by vtkLightKit, ParaView's default lighting),\n"
      "shell-plate (synthetic), shell-plate-point (lit by a point light), dense-ball\n"
      "(synthetic: dense, nearly white labels), or auto (--input with automatic transfer\n"
      "functions)",
    [&o](const std::string& v)
    {
      if (!scatterer_reference_vtk::IsNamedScene(v) && v != "auto")
      {
        scatterer_examples::ThrowUsageError("--scene must be " +
          std::string(scatterer_reference_vtk::kNamedScenes) + ", or auto, got '" + v + "'");
      }
      o.Scene = v;
    });
  CLI::Option* input = scatterer_examples::AddValueOption(app, "--input", "VOLUME",
    "volume file, DICOM folder or one file of a DICOM series, in a ct-head scene or --scene auto",
    [&o](const std::string& v) { o.Input = v; });
  scatterer_examples::AddValueOption(app, "--size", "WxH",
    "image size, 16..8192 each (default 256x256)",
    [&o](const std::string& v)
    {
      std::string why;
      if (!scatterer_examples::ParseSize(v, o.Width, o.Height, why))
      {
        scatterer_examples::ThrowUsageError("--size '" + v + "': " + why);
      }
    });
  AddInt(app, "--spp", 1, 1000000, "samples per pixel, 1..1000000 (default 256)",
    [&settings](int v) { settings.samplesPerPixel = v; });
  AddInt(app, "--max-order", 1, 100000, "highest scattering order, 1..100000 (default 64)",
    [&settings](int v) { settings.maxScatteringOrder = v; });
  AddInt(app, "--seed", 0, 2147483647, "random seed, 0..2147483647 (default 1)",
    [&settings](int v) { settings.seed = static_cast<std::uint64_t>(v); });
  AddInt(app, "--threads", 0, 4096, "worker threads, 0..4096 (default 0: all cores)",
    [&settings](int v) { settings.threads = static_cast<unsigned>(v); });
  scatterer_examples::AddValueOption(app, "--output", "PREFIX", "output prefix (default reference)",
    [&o](const std::string& v) { o.Output = v; });
  scatterer_examples::AddValueOption(app, "--exposure", "E|auto",
    "PNG exposure > 0, or auto (default: 99.5th-percentile luminance -> 1)",
    [&o](const std::string& v)
    {
      double e = 0.0;
      std::string why;
      if (v != "auto" && !scatterer_examples::ParseDouble(v, 1e-9, 1e9, e, why))
      {
        scatterer_examples::ThrowUsageError("--exposure '" + v + "': " + why + " (or auto)");
      }
      o.Exposure = v;
    });
  app.add_flag("--quiet", o.Quiet, "no progress on stderr");
  app.callback(
    [&]()
    {
      const bool builtIn = scatterer_reference_vtk::IsNamedScene(o.Scene) &&
        !scatterer_reference_vtk::IsCtHeadScene(o.Scene);
      if (builtIn && input->count() > 0)
      {
        scatterer_examples::ThrowConflict("--scene " + o.Scene, "--input",
          o.Scene +
            " is a built-in volume; for a file use --scene ct-head, ct-head-light-kit or auto");
      }
      if (o.Scene == "auto" && scene->count() > 0 && input->count() == 0)
      {
        scatterer_examples::ThrowUsageError(
          "--scene auto needs --input: it lays transfer functions over a given volume");
      }
    });
  return scatterer_examples::ParseCommandLine(app, argc, argv);
}
}

int main(int argc, char* argv[])
{
  ReferenceOptions options;
  scatterer_reference::RenderSettings settings;
  settings.samplesPerPixel = 256;
  const int parsed = ParseArgs(argc, argv, options, settings);
  if (parsed != scatterer_examples::ContinueRun)
  {
    return parsed; // --help, --version or a usage error, printed
  }
  const std::string& sceneName = options.Scene;
  const std::string& input = options.Input;
  const std::string& output = options.Output;
  const std::string& exposureArg = options.Exposure;
  const int width = options.Width, height = options.Height;
  const bool quiet = options.Quiet;

  scatterer_reference_vtk::VtkScene scene;
  std::string error;
  if (!input.empty())
  {
    scene.Name = "input";
    scene.Image = vtkScattererVolumeReader::ReadVolume(input, &error);
    if (!scene.Image)
    {
      std::cerr << "scatterer-reference: " << error << "\n";
      return 1;
    }
    scene.Property = vtkSmartPointer<vtkVolumeProperty>::New();
    scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
    if (scatterer_reference_vtk::IsCtHeadScene(sceneName))
    {
      scatterer_examples::ApplyCtHeadProperty(scene.Property);
      scatterer_examples::ApplyCtHeadCamera(scene.Renderer);
      if (sceneName == "ct-head-light-kit")
      {
        scatterer_reference_vtk::ApplyLightKit(scene.Renderer);
      }
      else
      {
        scatterer_examples::ApplyCtHeadLight(scene.Renderer);
      }
    }
    else
    {
      scatterer_examples::ApplyAutoScene(scene.Image, scene.Property, scene.Renderer);
      scene.Renderer->CreateLight(); // the headlight
    }
  }
  else
  {
    int exitCode = 0;
    if (!scatterer_reference_vtk::MakeNamedScene(sceneName, scene, error, exitCode))
    {
      std::cerr << "scatterer-reference: " << error << "\n";
      return exitCode;
    }
  }

  scatterer_reference::PathTracer tracer(
    scatterer_reference_vtk::Convert(scene.Image, scene.Property, scene.Renderer, width, height));
  if (!quiet)
  {
    settings.progress = [](double f)
    {
      std::fprintf(stderr, "\rreference: %5.1f%%", 100.0 * f);
      if (f >= 1.0)
        std::fprintf(stderr, "\n");
    };
  }
  const scatterer_reference::RenderResult r = tracer.render(settings);
  auto image = scatterer_reference_vtk::ToImageData(r);
  const std::string floatPath = output + ".vti";
  if (!scatterer_reference_vtk::WriteFloatImage(image, floatPath))
  {
    std::cerr << "scatterer-reference: cannot write " << floatPath << "\n";
    return 1;
  }
  const double exposure = exposureArg == "auto" ? scatterer_reference_vtk::AutoExposure(r.rgb)
                                                : std::atof(exposureArg.c_str());
  if (!scatterer_reference_vtk::WritePng(r.rgb, r.width, r.height, exposure, output + ".png"))
  {
    std::cerr << "scatterer-reference: cannot write " << output << ".png\n";
    return 1;
  }
  std::printf(
    "{\"scene\": \"%s\", \"width\": %d, \"height\": %d, \"samples_per_pixel\": %d, "
    "\"max_scattering_order\": %d, \"seed\": %llu, \"seconds\": %.2f, "
    "\"mean_luminance\": %.6g, \"rms_standard_error\": %.6g, "
    "\"relative_noise\": %.4g, \"exposure\": %.6g, \"float_image\": \"%s\", \"png\": \"%s.png\"}\n",
    scene.Name.c_str(), r.width, r.height, r.samplesPerPixel, settings.maxScatteringOrder,
    static_cast<unsigned long long>(settings.seed), r.seconds, r.meanLuminance, r.rmsStandardError,
    r.meanLuminance > 0 ? r.rmsStandardError / r.meanLuminance : 0.0, exposure, floatPath.c_str(),
    output.c_str());
  return 0;
}
