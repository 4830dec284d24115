// scatterer-render: renders a volume to a PNG and reports frame times.
//
// Default: the real CT head benchmark scene (Examples/Common/ScattererCtHeadScene.cxx)
// at 512x512. Run with --help for the options and the exit statuses.
#include "Common/ScattererCommandLine.h"
#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererFrameCheck.h"
#include "Common/ScattererMapperSetup.h"
#include "Common/ScattererRenderOptions.h"
#include "Common/ScattererScreenshot.h"
#include "Common/ScattererVolumeCheck.h"

#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererTransportVolume.h"
#include "vtkScattererVolumeReader.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace
{
struct FrameStats
{
  double median = 0, min = 0, max = 0;
};

FrameStats Summarize(std::vector<double> ms)
{
  FrameStats s;
  if (ms.empty())
  {
    return s;
  }
  std::sort(ms.begin(), ms.end());
  const size_t n = ms.size();
  s.median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  s.min = ms.front();
  s.max = ms.back();
  return s;
}

}

int main(int argc, char* argv[])
{
  scatterer_examples::RenderOptions options;
  const int parsed = scatterer_examples::ParseRenderOptions(argc, argv, options);
  if (parsed != scatterer_examples::ContinueRun)
  {
    return parsed; // --help, --version or a usage error, printed
  }
  std::string error;
  // The input first, then the display: a missing or unusable file is the user's
  // problem to fix whatever machine this runs on, and reading needs no display.
  const bool ctHead = options.Input.empty();
  const std::string input = ctHead ? scatterer_examples::CtHeadPath() : options.Input;
  vtkSmartPointer<vtkImageData> image =
    scatterer_examples::ReadVolumeOrCtHead(options.Input, error);
  if (!image)
  {
    std::cerr << "scatterer-render: " << error << "\n";
    return 1;
  }
  const bool autoScene = !ctHead && options.Scene != "ct-head";
  const std::string refusal = scatterer_examples::CheckVolume(image, input, autoScene);
  if (!refusal.empty())
  {
    std::cerr << "scatterer-render: " << refusal << "\n";
    return 1;
  }
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "scatterer-render: no X display (DISPLAY is unset). VTK here renders through X;"
                 " run under xvfb-run -a -s \"-screen 0 1280x1024x24\".\n";
    return 1;
  }

  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->SetSize(options.Width, options.Height);
  window->SetWindowName("scatterer-render");
  renderer->SetBackground(0.0, 0.0, 0.0);

  vtkSmartPointer<vtkGPUVolumeRayCastMapper> mapper = scatterer_examples::MakeMapper(options);
  mapper->SetInputData(image);
  vtkNew<vtkVolumeProperty> property;
  scatterer_examples::AddVolume(renderer, mapper, property);

  if (!autoScene)
  {
    scatterer_examples::ApplyCtHeadProperty(property);
    scatterer_examples::ApplyCtHeadCamera(renderer);
    scatterer_examples::ApplyCtHeadLight(renderer);
    scatterer_examples::ApplyCtHeadMapperSettings(mapper);
    scatterer_examples::ApplyCtHeadWindowSettings(window);
  }
  else
  {
    scatterer_examples::ApplyAutoScene(image, property, renderer);
    window->SetMultiSamples(0);
  }
  property->SetShade(options.Mode == "phong");

  // A transfer function that leaves every value of the volume transparent draws the
  // background only: say so instead of writing a black picture. (CheckVolume made
  // sure the finite range exists.)
  double range[2] = { 0.0, 0.0 };
  scatterer_examples::FiniteScalarRange(image, range);
  if (!scatterer_examples::OpacityVisibleOver(property, range))
  {
    std::cerr << "scatterer-render: refusing volume '" << input << "': the "
              << (autoScene ? "automatic" : "ct-head scene's")
              << " opacity transfer function is 0 over all of its values [" << range[0] << ", "
              << range[1] << "], so nothing would show.\n";
    return 1;
  }

  // Every VTK error from here to the last frame fails the run: a frame VTK could
  // not draw as asked (a texture it could not make, a shader that did not build)
  // is not the picture the options describe.
  scatterer_examples::VtkErrorCounter vtkErrors;
  const auto failedFrame = [&]()
  {
    if (vtkErrors.Count() == 0)
    {
      return false;
    }
    std::cerr << "scatterer-render: VTK reported " << vtkErrors.Count()
              << " error(s) while rendering '" << input << "' (the first: " << vtkErrors.First()
              << "); the frame is not trusted and no image is written.\n";
    return true;
  };

  // One warm-up frame (shader compilation, texture upload, transport volume), then
  // the timed frames. The transport build is timed with the GPU work finished.
  if (auto* st = vtkScattererTemplateVolumeMapper::SafeDownCast(mapper))
  {
    st->GetTransportVolume()->SetSynchronousTiming(true);
  }
  window->Render();
  window->WaitForCompletion();
  if (failedFrame())
  {
    return 1;
  }
  double firstBuildMs = 0.0;
  if (auto* st = vtkScattererTemplateVolumeMapper::SafeDownCast(mapper))
  {
    firstBuildMs = st->GetLastTransportBuildMilliseconds();
  }
  std::vector<double> frameMs;
  for (int i = 0; i < options.Frames; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    const auto stop = std::chrono::steady_clock::now();
    frameMs.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
  }
  const FrameStats stats = Summarize(frameMs);
  if (failedFrame())
  {
    return 1;
  }

  // The volume has values the transfer function shows (checked above), so a frame
  // of background only means it was not drawn: outside the camera's view (the
  // ct-head scene's camera is fixed), or lost on the way.
  vtkSmartPointer<vtkImageData> frame = scatterer_examples::GrabWindow(window);
  if (scatterer_examples::IsBlank(frame, renderer))
  {
    // Where the volume is helps to see why (far out, or beside a fixed camera).
    double origin[3], bounds[6];
    image->GetOrigin(origin);
    image->GetBounds(bounds);
    std::cerr << "scatterer-render: the frame of '" << input
              << "' came out blank (every pixel is the background) although the transfer "
                 "function gives its values ["
              << range[0] << ", " << range[1] << "] a visible opacity; the volume has origin ("
              << origin[0] << ", " << origin[1] << ", " << origin[2] << ") and bounds x ["
              << bounds[0] << ", " << bounds[1] << "], y [" << bounds[2] << ", " << bounds[3]
              << "], z [" << bounds[4] << ", " << bounds[5] << "]"
              << (autoScene ? "" : "; the ct-head scene's fixed camera may not see it")
              << "; no image is written.\n";
    return 1;
  }
  if (!scatterer_examples::WriteImagePng(frame, options.Output))
  {
    std::cerr << "scatterer-render: cannot write '" << options.Output << "'.\n";
    return 1;
  }

  std::string shader = "stock";
  double buildMs = 0.0;
  if (auto* st = vtkScattererTemplateVolumeMapper::SafeDownCast(mapper))
  {
    shader = st->GetLastShaderFeatures();
    buildMs = firstBuildMs;
  }
  if (options.Json)
  {
    std::printf("{\"mode\": \"%s\", \"input\": \"%s\", \"size\": [%d, %d], \"frames\": %d, "
                "\"shader\": \"%s\", \"settings\": \"%s\", \"transport_build_ms\": %.1f, "
                "\"frame_ms\": {\"median\": %.3f, \"min\": %.3f, \"max\": %.3f}, "
                "\"output\": \"%s\"}\n",
      options.Mode.c_str(), scatterer_examples::JsonEscape(input).c_str(), options.Width,
      options.Height, options.Frames, scatterer_examples::JsonEscape(shader).c_str(),
      scatterer_examples::JsonEscape(scatterer_examples::DescribeSettings(mapper)).c_str(), buildMs,
      stats.median, stats.min, stats.max, scatterer_examples::JsonEscape(options.Output).c_str());
  }
  else
  {
    std::printf("%s: %s, %dx%d, mode %s (%s), %d frames: median %.1f ms (min %.1f, max %.1f)\n",
      options.Output.c_str(), input.c_str(), options.Width, options.Height, options.Mode.c_str(),
      shader.c_str(), options.Frames, stats.median, stats.min, stats.max);
  }
  return 0;
}
