// Render benchmark on the CT head scene (shared/scenes/ct-head.json): frame times of
// stock composite, stock Phong, the light transport volume and the per-sample photon
// test, with the camera still and orbiting under the renderer's headlight (the light
// moves every frame, so the transport volume is rebuilt every frame), under a point light
// circling the head (camera still; a positional light's sweep every frame), and of a
// vtkMultiVolume (the CT head and a ball above it), all in one process after a
// warm-up frame each. Optionally on the CT head resampled to other
// dimensions (the same physical extent). Writes a CSV row per configuration and a PNG
// per configuration. Column peak_rss_mib is the process's peak resident memory so far
// (run one configuration per process with --only to compare memory); the last five are
// the median time of each stage of the transport volume's rebuild (medium, sweeps,
// arriving light, gather, diffusion), each waiting for the GPU.
//
//   scatterer-bench-render [--frames N] [--size WxH] [--out DIR] [--resample XxYxZ]
//                          [--only a,b] [--append] [--slice-sweep] [--pairs N]
//
// --pairs N: instead, each selected configuration's frames alternating with those of its
// stock counterpart, N pairs, and the median of the pairs' ratios (RunPairs, paired.csv).
//
// Built as scatterer-bench-render-egl (SCATTERER_BENCH_EGL), the same benchmark renders
// into a headless EGL context (ScattererEglContext.h) instead of an X window: for GPU
// machines without a display.
#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererMapperSetup.h"
#include "Common/ScattererNumbers.h"
#include "Common/ScattererScreenshot.h"

#ifdef SCATTERER_BENCH_EGL
#include "ScattererEglContext.h"
#include "vtkGenericOpenGLRenderWindow.h"
#endif
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkMath.h"
#include "vtkMultiVolume.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRendererCollection.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererTransportVolume.h"
#include "vtkScattererVolumeReader.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Config
{
  std::string Name;
  std::string Mode; // stock | phong | template
  std::string Illumination = "transport";
  bool Orbit = false;       // headlight + camera turning 2 degrees a frame: the light moves
  bool Interactive = false; // frames as VTK's interactor asks while dragging (rate 20/s)
  bool Multi = false;       // a vtkMultiVolume: the CT head and a ball above it (MultiScene)
  bool LightKit = false;    // orbit under vtkLightKit (5 camera lights, ParaView's default)
  // camera still, one point light (a scene light, no cone) circling the volume 2 degrees
  // a frame: a positional light's sweep rebuilt every frame
  bool PointLight = false;
  // camera still, the opacity function's last point nudged every frame, as while a user
  // drags it: the medium's passes (0a-0d) rebuilt every frame
  bool TransferEdit = false;
};

std::vector<Config> Configs()
{
  return {
    { "stock_composite", "stock" },
    { "stock_composite_orbit", "stock", "transport", true },
    { "stock_phong", "phong" },
    { "transport_still", "template" },
    { "transport_orbit_headlight", "template", "transport", true },
    { "transport_orbit_headlight_interactive", "template", "transport", true, true },
    { "transport_orbit_lightkit", "template", "transport", true, false, false, true },
    { "transport_orbit_lightkit_interactive", "template", "transport", true, true, false, true },
    { "transport_point_light_moving", "template", "transport", false, false, false, false, true },
    { "transport_transfer_edit", "template", "transport", false, false, false, false, false, true },
    { "persample_still", "template", "per-sample" },
    { "stock_multivolume", "stock", "transport", false, false, true },
    { "transport_multivolume_still", "template", "transport", false, false, true },
    { "transport_multivolume_orbit_headlight", "template", "transport", true, false, true },
  };
}

// A vtkMultiVolume: the CT head (input 0) and a red ball of 48^3 voxels of 1 mm (input 1,
// placed by its own volume above the head, which it shadows): the transport volume spans
// both, on the CT head's voxel lattice.
vtkSmartPointer<vtkMultiVolume> MultiScene(
  vtkGPUVolumeRayCastMapper* mapper, vtkImageData* head, vtkVolumeProperty* headProperty)
{
  const int n = 48;
  vtkNew<vtkImageData> ball;
  ball->SetDimensions(n, n, n);
  ball->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* p = static_cast<unsigned char*>(ball->GetScalarPointer());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, ++p)
      {
        const int di = i - n / 2, dj = j - n / 2, dk = k - n / 2;
        *p = di * di + dj * dj + dk * dk <= 20 * 20 ? 255 : 0;
      }
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(128, 0.0);
  opacity->AddPoint(255, 0.5);
  vtkNew<vtkColorTransferFunction> colour;
  colour->AddRGBPoint(0, 0.9, 0.2, 0.15);
  colour->AddRGBPoint(255, 0.9, 0.2, 0.15);
  vtkNew<vtkVolumeProperty> ballProperty;
  ballProperty->SetScalarOpacity(opacity);
  ballProperty->SetColor(colour);
  ballProperty->SetInterpolationTypeToLinear();
  vtkNew<vtkVolume> headVolume, ballVolume;
  headVolume->SetProperty(headProperty);
  ballVolume->SetProperty(ballProperty);
  ballVolume->SetPosition(122.0 - n / 2, 150.0 - n / 2, 185.0 - n / 2);
  mapper->SetInputDataObject(0, head);
  mapper->SetInputDataObject(1, ball);
  auto multi = vtkSmartPointer<vtkMultiVolume>::New();
  multi->SetMapper(mapper);
  multi->SetVolume(headVolume, 0);
  multi->SetVolume(ballVolume, 1);
  return multi;
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Peak resident set size of this process (VmHWM), MiB.
double PeakRssMiB()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmHWM:", 0) == 0)
    {
      return std::atof(line.c_str() + 6) / 1024.0;
    }
  }
  return 0.0;
}

// The configuration that a --pairs run alternates with `config`: the stock composite
// still, orbiting with it, or the stock vtkMultiVolume, the frames its ratio is taken to.
Config StockCounterpart(const Config& config)
{
  Config stock{ config.Multi ? "stock_multivolume"
      : config.Orbit         ? "stock_composite_orbit"
                             : "stock_composite",
    "stock" };
  stock.Orbit = config.Orbit;
  stock.Multi = config.Multi;
  return stock;
}

// The q-th quantile (0..1) of v, linearly interpolated between order statistics.
double Quantile(std::vector<double> v, double q)
{
  std::sort(v.begin(), v.end());
  const double at = q * static_cast<double>(v.size() - 1);
  const size_t below = static_cast<size_t>(at);
  const size_t above = std::min(below + 1, v.size() - 1);
  return v[below] + (at - static_cast<double>(below)) * (v[above] - v[below]);
}

// One configuration's scene: its mapper, volume property and renderer, and what moves
// from frame to frame (the camera, the point light, the opacity function).
struct Scene
{
  Config Setup;
  vtkSmartPointer<vtkGPUVolumeRayCastMapper> Mapper;
  vtkScattererTemplateVolumeMapper* Template = nullptr; // null for the stock mappers
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLight> PointLight;
  double Centre[3] = { 0, 0, 0 }, Radius = 1.0, Toward[3] = { 0, 0, 1 }, Up[3] = { 0, 1, 0 },
         Right[3] = { 1, 0, 0 };

  Scene(const Config& config, vtkImageData* image, bool sliceSweep)
    : Setup(config)
  {
    scatterer_examples::RenderOptions o;
    o.Mode = config.Mode;
    o.Illumination = config.Illumination;
    this->Mapper = scatterer_examples::MakeMapper(o);
    this->Mapper->SetInputData(image);
    this->Template = vtkScattererTemplateVolumeMapper::SafeDownCast(this->Mapper);
    if (this->Template)
    {
      // build times include the GPU work
      this->Template->GetTransportVolume()->SetSynchronousTiming(true);
      // --slice-sweep: directional lights swept one slice per draw (A/B measurements)
      this->Template->GetTransportVolume()->SetSweepLinesInParallel(!sliceSweep);
    }
    if (config.Multi)
    {
      this->Renderer->AddVolume(MultiScene(this->Mapper, image, this->Property));
    }
    else
    {
      scatterer_examples::AddVolume(this->Renderer, this->Mapper, this->Property);
    }
    scatterer_examples::ApplyCtHeadProperty(this->Property);
    scatterer_examples::ApplyCtHeadCamera(this->Renderer);
    scatterer_examples::ApplyCtHeadLight(this->Renderer);
    scatterer_examples::ApplyCtHeadMapperSettings(this->Mapper);
    this->Property->SetShade(config.Mode == "phong");
    if (config.Orbit)
    {
      this->Renderer->RemoveAllLights();
      this->Renderer->AutomaticLightCreationOn(); // VTK's headlight: it moves with the camera
    }
    if (config.LightKit)
    {
      this->Renderer->AutomaticLightCreationOff();
      vtkNew<vtkLightKit> kit;
      kit->AddLightsToRenderer(this->Renderer);
    }
    if (config.PointLight)
    {
      // 1.5 bounding radii from the head's centre, on a circle through the camera's side
      // of it, above the centre.
      image->GetCenter(this->Centre);
      this->Radius = 0.75 * image->GetLength(); // the bounding box's diagonal
      vtkCamera* camera = this->Renderer->GetActiveCamera();
      camera->GetDirectionOfProjection(this->Toward);
      camera->GetViewUp(this->Up);
      vtkMath::Cross(this->Toward, this->Up, this->Right);
      vtkMath::Normalize(this->Right);
      this->Renderer->AutomaticLightCreationOff();
      this->Renderer->RemoveAllLights();
      this->PointLight->SetLightTypeToSceneLight();
      this->PointLight->PositionalOn();
      this->PointLight->SetConeAngle(180.0);
      this->PointLight->SetFocalPoint(this->Centre);
      this->Renderer->AddLight(this->PointLight);
      this->PlacePointLight(30.0);
    }
  }

  // The point light at `degrees` on its circle (0: between the camera and the head).
  void PlacePointLight(double degrees)
  {
    const double t = vtkMath::RadiansFromDegrees(degrees);
    double p[3];
    for (int a = 0; a < 3; ++a)
    {
      p[a] = this->Centre[a] +
        this->Radius * (std::sin(t) * this->Right[a] - std::cos(t) * this->Toward[a]) +
        0.5 * this->Radius * this->Up[a];
    }
    this->PointLight->SetPosition(p);
  }

  // What changes before timed frame `frame` (from 0) is drawn.
  void Advance(int frame)
  {
    if (this->Setup.Orbit)
    {
      this->Renderer->GetActiveCamera()->Azimuth(2.0);
    }
    if (this->Setup.PointLight)
    {
      this->PlacePointLight(30.0 + 2.0 * (frame + 1));
    }
    if (this->Setup.TransferEdit)
    {
      vtkPiecewiseFunction* opacity = this->Property->GetScalarOpacity();
      double node[4];
      opacity->GetNodeValue(opacity->GetSize() - 1, node);
      node[1] *= frame % 2 == 0 ? 0.99 : 1.0 / 0.99;
      opacity->SetNodeValue(opacity->GetSize() - 1, node);
    }
  }

  // Draws the scene as the window's one renderer; its milliseconds, the GPU work finished.
  double Draw(vtkRenderWindow* window)
  {
    vtkRendererCollection* renderers = window->GetRenderers();
    if (renderers->GetNumberOfItems() != 1 || renderers->GetFirstRenderer() != this->Renderer)
    {
      renderers->RemoveAllItems();
      window->AddRenderer(this->Renderer);
    }
    window->SetDesiredUpdateRate(this->Setup.Interactive ? 20.0 : 0.0001);
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
  }
};

// --pairs N: each selected configuration other than the stock composite against its stock
// counterpart (StockCounterpart), their timed frames alternating, N pairs, the stock frame
// first in even pairs and second in odd ones. A pair's ratio is taken over two frames
// drawn a second apart, so the drift of a shared machine over a run (within one run of
// 2026-12-08 the CT head's stock composite measured 399 ms still and 511 ms orbiting, the
// same work, and the still ratio 1.06x to 1.60x that day) cancels, where the ratios of
// configurations drawn one after the other (render.csv) carry it. Writes OUT/paired.csv:
// the pairs' median ratio and quartiles, each side's median frame, the median build.
int RunPairs(vtkRenderWindow* window, vtkImageData* image, const std::string& volumeName,
  const std::string& out, int pairs, const std::function<bool(const std::string&)>& selected,
  bool sliceSweep, bool append)
{
  const std::string csvPath = out + "/paired.csv";
  const bool header = !append || !std::ifstream(csvPath).good();
  std::ofstream csv(csvPath, append ? std::ios::app : std::ios::trunc);
  if (header)
  {
    csv << "volume,config,stock_config,pairs,ratio_median,ratio_q1,ratio_q3,stock_median_ms,"
           "median_ms,build_ms,shader\n";
  }
  int paired = 0;
  for (const Config& config : Configs())
  {
    if (config.Mode == "stock" || !selected(config.Name))
      continue;
    ++paired;
    const Config stockConfig = StockCounterpart(config);
    Scene stock(stockConfig, image, sliceSweep), scene(config, image, sliceSweep);
    stock.Draw(window); // warm-up each: shader compile, uploads, transport volume
    scene.Draw(window);
    std::vector<double> ratios, stockMs, ms, buildMs;
    for (int f = 0; f < pairs; ++f)
    {
      stock.Advance(f);
      scene.Advance(f);
      double s = 0.0, t = 0.0;
      if (f % 2 == 0)
      {
        s = stock.Draw(window);
        t = scene.Draw(window);
      }
      else
      {
        t = scene.Draw(window);
        s = stock.Draw(window);
      }
      stockMs.push_back(s);
      ms.push_back(t);
      ratios.push_back(t / s);
      buildMs.push_back(scene.Template ? scene.Template->GetLastTransportBuildMilliseconds() : 0.0);
    }
    const std::string shader = scene.Template ? scene.Template->GetLastShaderFeatures() : "stock";
    csv << volumeName << ',' << config.Name << ',' << stockConfig.Name << ',' << pairs << ','
        << Median(ratios) << ',' << Quantile(ratios, 0.25) << ',' << Quantile(ratios, 0.75) << ','
        << Median(stockMs) << ',' << Median(ms) << ',' << Median(buildMs) << ",\"" << shader
        << "\"\n";
    csv.flush();
    std::printf(
      "%-12s %-40s x%.3f (quartiles %.3f-%.3f, %d pairs)  %8.1f / %8.1f ms  build %6.1f ms\n",
      volumeName.c_str(), config.Name.c_str(), Median(ratios), Quantile(ratios, 0.25),
      Quantile(ratios, 0.75), pairs, Median(ms), Median(stockMs), Median(buildMs));
  }
  if (paired == 0)
  {
    std::cerr << "--pairs: no configuration to pair with stock composite among those "
                 "--only selects (a stock configuration is the other side of every pair)\n";
    return 2;
  }
  std::printf("wrote %s\n", csvPath.c_str());
  return 0;
}
}

int main(int argc, char* argv[])
{
  int frames = 5, pairs = 0, width = 512, height = 512, resample[3] = { 0, 0, 0 };
  std::string out = "render-benchmark", only;
  bool append = false, sliceSweep = false;
  // Numbers as the example programs take them (strict, in range): --size -5x-5 and
  // --frames abc ran anyway.
  std::string why;
  const auto refused = [&why](const std::string& option, const char* value)
  {
    std::cerr << "scatterer-bench-render: " << option << " '" << value << "': " << why << "\n";
    return 2;
  };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--frames" && i + 1 < argc)
    {
      if (!scatterer_examples::ParseInt(argv[++i], 1, 1000, frames, why))
        return refused(a, argv[i]);
    }
    else if (a == "--pairs" && i + 1 < argc)
    {
      if (!scatterer_examples::ParseInt(argv[++i], 1, 1000, pairs, why))
        return refused(a, argv[i]);
    }
    else if (a == "--size" && i + 1 < argc)
    {
      if (!scatterer_examples::ParseSize(argv[++i], width, height, why))
        return refused(a, argv[i]);
    }
    else if (a == "--resample" && i + 1 < argc &&
      std::sscanf(argv[++i], "%dx%dx%d", &resample[0], &resample[1], &resample[2]) == 3)
      ;
    else if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--only" && i + 1 < argc)
      only = argv[++i];
    else if (a == "--append")
      append = true;
    else if (a == "--slice-sweep")
      sliceSweep = true;
    else
    {
      std::cerr << "usage: scatterer-bench-render [--frames N] [--size WxH] [--out DIR] "
                   "[--resample XxYxZ] [--only a,b] [--append] [--slice-sweep] [--pairs N]\n";
      return 2;
    }
  }
#ifdef SCATTERER_BENCH_EGL
  std::setvbuf(stdout, nullptr, _IOLBF, 0); // lines survive a `timeout` kill under a pipe
  scatterer_egl::Context egl;
  if (!egl.Create(width, height))
  {
    std::cerr << "EGL: no OpenGL context\n";
    return 1;
  }
#else
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "no X display: run under xvfb-run (scripts/xvfb.sh)\n";
    return 1;
  }
#endif
  std::string error;
  vtkSmartPointer<vtkImageData> image =
    vtkScattererVolumeReader::ReadVolume(scatterer_examples::CtHeadPath(), &error);
  if (!image)
  {
    std::cerr << error << "\nPrepare the CT head with: bash scripts/prepare-data.sh\n";
    return 1;
  }
  if (resample[0] > 1 && resample[1] > 1 && resample[2] > 1)
  {
    vtkNew<vtkImageResize> resize; // trilinear, the same physical extent
    resize->SetInputData(image);
    resize->SetOutputDimensions(resample[0], resample[1], resample[2]);
    resize->Update();
    image = resize->GetOutput();
  }
  int dims[3];
  image->GetDimensions(dims);
  const std::string volumeName =
    std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]);
  std::string mkdir = "mkdir -p '" + out + "'";
  if (std::system(mkdir.c_str()) != 0)
  {
    std::cerr << "cannot create " << out << "\n";
    return 1;
  }

#ifdef SCATTERER_BENCH_EGL
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  egl.Attach(window);
  window->SetSize(width, height);
  if (!egl.InitializeVtk(window))
  {
    std::cerr << "VTK did not accept the EGL context\n";
    return 1;
  }
#else
  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
#endif
  scatterer_examples::ApplyCtHeadWindowSettings(window);
  const std::string csvPath = out + "/render.csv";
  const bool header = !append || !std::ifstream(csvPath).good();
  std::ofstream csv(csvPath, append ? std::ios::app : std::ios::trunc);
  if (header)
  {
    csv << "volume,config,mode,illumination,orbit,interactive,shader,frames,median_ms,min_ms,"
           "max_ms,ratio_to_stock,build_ms,transport_dims,transport_gpu_mib,peak_rss_mib,"
           "build_medium_ms,build_sweeps_ms,build_arriving_ms,build_gather_ms,"
           "build_diffusion_ms\n";
  }
  const auto selected = [&only](const std::string& name)
  { return only.empty() || ("," + only + ",").find("," + name + ",") != std::string::npos; };
  if (pairs > 0)
  {
    return RunPairs(window, image, volumeName, out, pairs, selected, sliceSweep, append);
  }
  double stockStill = 0.0, stockOrbit = 0.0, stockMulti = 0.0;
  for (const Config& config : Configs())
  {
    if (!selected(config.Name))
      continue;
    Scene scene(config, image, sliceSweep);
    vtkScattererTemplateVolumeMapper* st = scene.Template;
    scene.Draw(window); // warm-up: shader compile, uploads, transport volume
    // The build's stages per frame: medium, sweeps, arriving, gather, diffusion.
    std::vector<double> ms, buildMs, stageMs[5];
    for (int f = 0; f < frames; ++f)
    {
      scene.Advance(f);
      ms.push_back(scene.Draw(window));
      buildMs.push_back(st ? st->GetLastTransportBuildMilliseconds() : 0.0);
      const auto stages = st ? st->GetTransportVolume()->GetLastBuildStageMilliseconds()
                             : vtkScattererTransportVolume::StageMilliseconds();
      int i = 0;
      for (double stage :
        { stages.Medium, stages.Sweeps, stages.Arriving, stages.Gather, stages.Diffusion })
      {
        stageMs[i++].push_back(stage);
      }
    }
    const double median = Median(ms);
    if (config.Name == "stock_composite")
      stockStill = median;
    if (config.Name == "stock_composite_orbit")
      stockOrbit = median;
    if (config.Name == "stock_multivolume")
      stockMulti = median;
    // Multi-volume frames against the stock multi-volume still frame (the stock ray
    // caster's orbit costs what its still frame does: measured above).
    const double stock = config.Multi ? stockMulti : config.Orbit ? stockOrbit : stockStill;
    const std::string shader = st ? st->GetLastShaderFeatures() : "stock";
    int tdims[3] = { 0, 0, 0 };
    double gpuMiB = 0.0;
    if (st && st->GetIlluminationMode() == vtkScattererTemplateVolumeMapper::TRANSPORT)
    {
      st->GetTransportVolume()->GetDimensions(tdims);
      gpuMiB = st->GetTransportVolume()->GetGPUBytes() / (1024.0 * 1024.0);
    }
    const std::string tname = st
      ? std::to_string(tdims[0]) + "x" + std::to_string(tdims[1]) + "x" + std::to_string(tdims[2])
      : "-";
    csv << volumeName << ',' << config.Name << ',' << config.Mode << ','
        << (st ? config.Illumination : "-") << ',' << config.Orbit << ',' << config.Interactive
        << ",\"" << shader << "\"," << frames << ',' << median << ','
        << *std::min_element(ms.begin(), ms.end()) << ',' << *std::max_element(ms.begin(), ms.end())
        << ',' << (stock > 0 ? median / stock : 0.0) << ',' << Median(buildMs) << ',' << tname
        << ',' << gpuMiB << ',' << PeakRssMiB();
    for (const auto& stage : stageMs)
    {
      csv << ',' << Median(stage);
    }
    csv << "\n";
    csv.flush();
    std::printf("%-12s %-40s median %8.1f ms  x%.2f  build %6.1f ms  rss %6.0f MiB  (%s)\n",
      volumeName.c_str(), config.Name.c_str(), median, stock > 0 ? median / stock : 0.0,
      Median(buildMs), PeakRssMiB(), shader.c_str());
    scatterer_examples::WriteWindowPng(window, out + "/" + volumeName + "-" + config.Name + ".png");
  }
  std::printf("wrote %s\n", csvPath.c_str());
  return 0;
}
