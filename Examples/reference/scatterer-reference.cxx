// Renders the Monte Carlo reference (Module/Reference) of a VTK volume scene: the CT
// head scene by default (shared/scenes/ct-head.json), the synthetic shell + plate scene,
// or any volume with the automatic transfer functions. Writes the float image (.vti or
// .mha: "Radiance" RGB + per-pixel "StandardError") and a PNG, and prints the samples
// per pixel and the noise estimate.
//
//   scatterer-reference [--scene ct-head|shell-plate] [--input VOLUME] [--size WxH]
//                       [--spp N] [--max-order N] [--seed S] [--threads N]
//                       [--output PREFIX] [--exposure E|auto] [--quiet]
#include "ScattererReferenceScene.h"

#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererRenderOptions.h"
#include "scatterer_reference/PathTracer.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkScattererVolumeReader.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
const char* kUsage =
  "usage: scatterer-reference [--scene ct-head|shell-plate] [--input VOLUME] [--size WxH]\n"
  "         [--spp N] [--max-order N] [--seed S] [--threads N] [--output PREFIX]\n"
  "         [--exposure E|auto] [--quiet] [--version]\n"
  "Monte Carlo volumetric path tracing (delta tracking, NEE with ratio tracking) of the scene;\n"
  "writes PREFIX.vti (float RGB radiance + standard error) and PREFIX.png.\n"
  "Defaults: ct-head, 256x256, 256 spp, max order 64, seed 1, all cores, output reference,\n"
  "exposure auto (99.5th-percentile luminance -> 1).\n";
}

int main(int argc, char* argv[])
{
  std::string sceneName = "ct-head", input, output = "reference", exposureArg = "auto";
  int width = 256, height = 256;
  scatterer_reference::RenderSettings settings;
  settings.samplesPerPixel = 256;
  bool quiet = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    const char* v = nullptr;
    if (a == "--help" || a == "-h")
    {
      std::cout << kUsage;
      return 0;
    }
    else if (a == "--version")
    {
      std::cout << scatterer_examples::VersionText("scatterer-reference");
      return 0;
    }
    else if (a == "--quiet")
      quiet = true;
    else if (!(v = next()))
    {
      std::cerr << "missing value for " << a << "\n" << kUsage;
      return 2;
    }
    else if (a == "--scene")
      sceneName = v;
    else if (a == "--input")
      input = v;
    else if (a == "--size")
    {
      if (std::sscanf(v, "%dx%d", &width, &height) != 2 || width < 1 || height < 1)
      {
        std::cerr << "bad --size " << v << "\n";
        return 2;
      }
    }
    else if (a == "--spp")
      settings.samplesPerPixel = std::max(1, std::atoi(v));
    else if (a == "--max-order")
      settings.maxScatteringOrder = std::max(1, std::atoi(v));
    else if (a == "--seed")
      settings.seed = std::strtoull(v, nullptr, 10);
    else if (a == "--threads")
      settings.threads = static_cast<unsigned>(std::max(0, std::atoi(v)));
    else if (a == "--output")
      output = v;
    else if (a == "--exposure")
      exposureArg = v;
    else
    {
      std::cerr << "unknown option " << a << "\n" << kUsage;
      return 2;
    }
  }

  scatterer_reference_vtk::VtkScene scene;
  std::string error;
  if (!input.empty())
  {
    scene.Name = "input";
    scene.Image = vtkScattererVolumeReader::ReadVolume(input, &error);
    if (!scene.Image)
    {
      std::cerr << error << "\n";
      return 1;
    }
    scene.Property = vtkSmartPointer<vtkVolumeProperty>::New();
    scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
    if (sceneName == "ct-head")
    {
      scatterer_examples::ApplyCtHeadProperty(scene.Property);
      scatterer_examples::ApplyCtHeadCamera(scene.Renderer);
      scatterer_examples::ApplyCtHeadLight(scene.Renderer);
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
      std::cerr << error << "\n";
      return exitCode;
    }
  }

  scatterer_reference::PathTracer tracer(
    scatterer_reference_vtk::Convert(scene.Image, scene.Property, scene.Renderer, width, height));
  if (!quiet)
  {
    settings.progress = [](double f) {
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
    std::cerr << "cannot write " << floatPath << "\n";
    return 1;
  }
  const double exposure =
    exposureArg == "auto" ? scatterer_reference_vtk::AutoExposure(r.rgb) : std::atof(exposureArg.c_str());
  if (!scatterer_reference_vtk::WritePng(r.rgb, r.width, r.height, exposure, output + ".png"))
  {
    std::cerr << "cannot write " << output << ".png\n";
    return 1;
  }
  std::printf("{\"scene\": \"%s\", \"width\": %d, \"height\": %d, \"samples_per_pixel\": %d, "
              "\"max_scattering_order\": %d, \"seed\": %llu, \"seconds\": %.2f, "
              "\"mean_luminance\": %.6g, \"rms_standard_error\": %.6g, "
              "\"relative_noise\": %.4g, \"exposure\": %.6g, \"float_image\": \"%s\", \"png\": \"%s.png\"}\n",
    scene.Name.c_str(), r.width, r.height, r.samplesPerPixel, settings.maxScatteringOrder,
    static_cast<unsigned long long>(settings.seed), r.seconds, r.meanLuminance, r.rmsStandardError,
    r.meanLuminance > 0 ? r.rmsStandardError / r.meanLuminance : 0.0, exposure, floatPath.c_str(),
    output.c_str());
  return 0;
}
