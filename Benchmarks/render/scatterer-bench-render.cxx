// Render benchmark on the CT head scene (shared/scenes/ct-head.json), all
// configurations in one process after a warm-up frame each: stock composite,
// stock Phong, and template illumination per effect set and mode.
// Writes a CSV (one row per configuration) and a PNG per configuration.
//
//   scatterer-bench-render [--frames N] [--size WxH] [--out DIR]
#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererMapperSetup.h"
#include "Common/ScattererScreenshot.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRendererCollection.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererVolumeReader.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Config
{
  std::string Name;
  std::string Mode; // stock | phong | template
  std::string Illumination = "cached";
  bool Shadows = true, Thin = true, Bleeding = true, Boundary = true;
  bool Orbit = false; // headlight + camera turning 2 degrees a frame: the cache follows
};

std::vector<Config> Configs()
{
  std::vector<Config> c;
  c.push_back({ "stock_composite", "stock" });
  c.push_back({ "stock_phong", "phong" });
  for (const char* mode : { "cached", "per-sample" })
  {
    const std::string m = mode;
    const std::string prefix = "template_" + std::string(m == "cached" ? "cached" : "persample");
    c.push_back({ prefix + "_shadow", "template", m, true, false, false, false });
    c.push_back({ prefix + "_shadow_thin", "template", m, true, true, false, false });
    c.push_back({ prefix + "_shadow_thin_bleed", "template", m, true, true, true, false });
    c.push_back({ prefix + "_all", "template", m, true, true, true, true });
  }
  Config orbit{ "template_cached_all_orbit_headlight", "template", "cached" };
  orbit.Orbit = true;
  c.push_back(orbit);
  return c;
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}

int main(int argc, char* argv[])
{
  int frames = 5, width = 512, height = 512;
  std::string out = "render-benchmark";
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--frames" && i + 1 < argc)
      frames = std::max(1, std::atoi(argv[++i]));
    else if (a == "--size" && i + 1 < argc && std::sscanf(argv[++i], "%dx%d", &width, &height) == 2)
      ;
    else if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else
    {
      std::cerr << "usage: scatterer-bench-render [--frames N] [--size WxH] [--out DIR]\n";
      return 2;
    }
  }
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "no X display: run under xvfb-run (scripts/xvfb.sh)\n";
    return 1;
  }
  std::string error;
  auto image = vtkScattererVolumeReader::ReadVolume(scatterer_examples::CtHeadPath(), &error);
  if (!image)
  {
    std::cerr << error << "\nPrepare the CT head with: bash scripts/prepare-data.sh\n";
    return 1;
  }
  std::string mkdir = "mkdir -p '" + out + "'";
  if (std::system(mkdir.c_str()) != 0)
  {
    std::cerr << "cannot create " << out << "\n";
    return 1;
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  scatterer_examples::ApplyCtHeadWindowSettings(window);
  std::ofstream csv(out + "/render.csv");
  csv << "config,mode,illumination,shader,frames,median_ms,min_ms,max_ms,ratio_to_stock,cache_update_ms\n";
  double stockMedian = 0.0;
  for (const Config& config : Configs())
  {
    scatterer_examples::RenderOptions o;
    o.Mode = config.Mode;
    o.Illumination = config.Illumination;
    o.Shadows = config.Shadows;
    o.Thin = config.Thin;
    o.Bleeding = config.Bleeding;
    o.Boundary = config.Boundary;
    auto mapper = scatterer_examples::MakeMapper(o);
    mapper->SetInputData(image);
    vtkNew<vtkVolumeProperty> property;
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    vtkNew<vtkRenderer> renderer;
    renderer->AddVolume(volume);
    scatterer_examples::ApplyCtHeadProperty(property);
    scatterer_examples::ApplyCtHeadCamera(renderer);
    scatterer_examples::ApplyCtHeadLight(renderer);
    scatterer_examples::ApplyCtHeadMapperSettings(mapper);
    property->SetShade(config.Mode == "phong");
    if (config.Orbit)
    {
      renderer->RemoveAllLights();
      renderer->AutomaticLightCreationOn(); // VTK's headlight: it moves with the camera
    }
    window->GetRenderers()->RemoveAllItems();
    window->AddRenderer(renderer);
    window->Render(); // warm-up: shader compile, uploads, cache
    window->WaitForCompletion();
    auto* st = vtkScattererTemplateVolumeMapper::SafeDownCast(mapper);
    std::vector<double> ms, cacheMs;
    for (int f = 0; f < frames; ++f)
    {
      if (config.Orbit)
      {
        renderer->GetActiveCamera()->Azimuth(2.0);
      }
      const auto start = std::chrono::steady_clock::now();
      window->Render();
      window->WaitForCompletion();
      ms.push_back(std::chrono::duration<double, std::milli>(
        std::chrono::steady_clock::now() - start).count());
      cacheMs.push_back(st ? st->GetLastCacheUpdateMilliseconds() : 0.0);
    }
    const double median = Median(ms);
    if (config.Name == "stock_composite")
    {
      stockMedian = median;
    }
    const std::string shader = st ? st->GetLastShaderFeatures() : "stock";
    csv << config.Name << ',' << config.Mode << ',' << (st ? config.Illumination : "-") << ",\""
        << shader << "\"," << frames << ',' << median << ','
        << *std::min_element(ms.begin(), ms.end()) << ',' << *std::max_element(ms.begin(), ms.end())
        << ',' << (stockMedian > 0 ? median / stockMedian : 0.0) << ',' << Median(cacheMs) << "\n";
    csv.flush();
    std::printf("%-40s median %8.1f ms  x%.2f  cache %6.1f ms  (%s)\n", config.Name.c_str(), median,
      stockMedian > 0 ? median / stockMedian : 0.0, Median(cacheMs), shader.c_str());
    scatterer_examples::WriteWindowPng(window, out + "/" + config.Name + ".png");
  }
  std::printf("wrote %s/render.csv\n", out.c_str());
  return 0;
}
