// scatterer-viewer: an interactive window on a volume with scatterer-template illumination.
//
// Default input: the real CT head scene (scripts/prepare-data.sh), the scene of
// scatterer-render and the benchmarks. Trackball camera (left drag rotates, middle or
// shift+left pans, right drag or wheel zooms). Keys (press h in the window for the list):
//   s shadows   b colour bleeding   t thin-part check   r boundary refraction
//   l template blending   i illumination on/off   m transport / per-sample
//   + / - quality step   p next transfer preset   [ ] level   { } window
//   o preset as defined   w screenshot   c reset camera   h help   q / e quit
// ctrl + left drag: window/level (right/left moves the ramp, up/down widens it).
// Level of detail: while the user drags, rays are cast at half the resolution in each
// direction (image sample distance 2, a quarter of the rays), with every sample along
// each ray kept, so the picture gets softer but never banded; the mapper also builds
// its transport volume coarser (InteractiveTransportScale). The illumination stays on.
// When the user lets go, a full-resolution frame with the chosen quality step follows.
// The status strip under the picture says what is shown; it never covers the volume.
//
// Testing: --play-events FILE plays recorded interaction events (vtkInteractorEventRecorder,
// e.g. made with --record FILE); "-" plays the built-in recording (drags + key presses).
// With --output FILE.png the viewer writes the last frame and exits instead of staying
// open; --test is --play-events - --size 300x300 --output scatterer-viewer-test.png for
// whichever of those was not given, and also checks that the PNG is not blank and that
// illumination was on in every frame.
#include "Common/ScattererCommandLine.h"
#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererFrameCheck.h"
#include "Common/ScattererMapperSetup.h"
#include "Common/ScattererRenderOptions.h"
#include "Common/ScattererScreenshot.h"
#include "Common/ScattererTransferPresets.h"
#include "Common/ScattererVolumeCheck.h"
#include "viewer/ScattererViewerOverlay.h"
#include "viewer/ScattererViewerTransfer.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererVolumeReader.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
/**
 * Do @p a and @p b name the same file, however spelled ("./mine.log" and "mine.log")?
 * Both existing: std::filesystem::equivalent (also through links); otherwise their
 * weakly_canonical forms (the file to be written need not exist yet). "-" (the built-in
 * recording) is no file.
 */
bool SameFile(const std::string& a, const std::string& b)
{
  namespace fs = std::filesystem;
  if (a == b)
  {
    return true;
  }
  if (a == "-" || b == "-")
  {
    return false;
  }
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec))
  {
    const bool same = fs::equivalent(a, b, ec);
    if (!ec)
    {
      return same;
    }
  }
  ec.clear();
  const fs::path ca = fs::weakly_canonical(a, ec);
  if (ec)
  {
    return false;
  }
  const fs::path cb = fs::weakly_canonical(b, ec);
  return !ec && ca == cb;
}

// The built-in recording (--play-events -): a rotation drag, key presses (shadows off
// and on, per-sample mode, quality down), a zoom drag (right button), a pan
// (shift + left), back to transport mode. Format: vtkInteractorEventRecorder stream 1.1
// ("event x y modifiers keycode repeat keysym"; modifiers 1 = shift). The key events
// are CharEvents, which the style turns into the viewer's key actions.
const char* const BuiltInEvents = R"(# StreamVersion 1.1
EnterEvent 150 150 0 0 0 0
MouseMoveEvent 150 150 0 0 0 0
LeftButtonPressEvent 150 150 0 0 0 0
MouseMoveEvent 165 152 0 0 0 0
MouseMoveEvent 180 155 0 0 0 0
MouseMoveEvent 195 160 0 0 0 0
LeftButtonReleaseEvent 195 160 0 0 0 0
KeyPressEvent 195 160 0 115 1 s
CharEvent 195 160 0 115 1 s
KeyReleaseEvent 195 160 0 115 1 s
KeyPressEvent 195 160 0 115 1 s
CharEvent 195 160 0 115 1 s
KeyReleaseEvent 195 160 0 115 1 s
KeyPressEvent 195 160 0 109 1 m
CharEvent 195 160 0 109 1 m
KeyReleaseEvent 195 160 0 109 1 m
MouseMoveEvent 150 150 0 0 0 0
RightButtonPressEvent 150 150 0 0 0 0
MouseMoveEvent 150 160 0 0 0 0
MouseMoveEvent 150 170 0 0 0 0
RightButtonReleaseEvent 150 170 0 0 0 0
KeyPressEvent 150 170 0 45 1 minus
CharEvent 150 170 0 45 1 minus
KeyReleaseEvent 150 170 0 45 1 minus
MouseMoveEvent 150 150 1 0 0 0
LeftButtonPressEvent 150 150 1 0 0 0
MouseMoveEvent 140 145 1 0 0 0
LeftButtonReleaseEvent 140 145 1 0 0 0
KeyPressEvent 140 145 0 109 1 m
CharEvent 140 145 0 109 1 m
KeyReleaseEvent 140 145 0 109 1 m
KeyPressEvent 140 145 0 43 1 plus
CharEvent 140 145 0 43 1 plus
KeyReleaseEvent 140 145 0 43 1 plus
KeyPressEvent 140 145 0 104 1 h
CharEvent 140 145 0 104 1 h
KeyReleaseEvent 140 145 0 104 1 h
)";

/** One quality step: what the +/- keys move between (index 2 is the mapper's default). */
struct QualityStep
{
  const char* Name;
  int TransportScale;
  int PhotonCap;
  int IlluminationInterval;
};
const QualityStep QualitySteps[] = {
  { "draft", 4, 8, 8 },
  { "low", 3, 16, 6 },
  { "default", scatterer::illumination::TransportScale.Default,
    scatterer::illumination::PhotonCap.Default,
    scatterer::illumination::IlluminationInterval.Default },
  { "high", 1, 48, 2 },
  { "best", 1, 96, 1 },
};
const int NumberOfQualitySteps = static_cast<int>(sizeof(QualitySteps) / sizeof(QualitySteps[0]));

// At most 40 columns a line: the help box fits a 300-pixel window.
const char* const KeyHelp = "s shadows    b bleeding    t thin\n"
                            "r boundary   l blending\n"
                            "i illumination  m transport/per-sample\n"
                            "+/- quality  p preset  o preset reset\n"
                            "[ ] level    { } window  w screenshot\n"
                            "c camera     h help      q quit\n"
                            "left drag rotate, shift/middle pan,\n"
                            "right zoom, ctrl+left window/level";

/** Image sample distance of interactive frames: a quarter of the rays, each fully sampled. */
constexpr double InteractiveImageSampleDistance = 2.0;

/** Interaction state of the window/level drag (vtkInteractorStyleImage uses the same number). */
constexpr int WindowLevelState = 1024;

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Options
{
  std::string Input;
  std::string Output;
  std::string PlayEvents;
  std::string Record;
  std::string Preset; // --preset NAME (checked while parsing); empty: chosen from the data
  int Width = 600;
  int Height = 600;
  bool SizeGiven = false;
  bool Test = false;
};

/**
 * Parses argv into @p o (CLI11 through ScattererCommandLine, as scatterer-render).
 * Returns ContinueRun, or the exit status once --help, --version or a usage error
 * has been printed.
 */
int ParseArgs(int argc, char* argv[], Options& o)
{
  CLI::App app("An interactive window on a volume with scatterer-template illumination.\n"
               "Default input: the prepared CT head, " +
      scatterer_examples::CtHeadPath() + "\n(made by scripts/prepare-data.sh in the source tree).",
    "scatterer-viewer");
  scatterer_examples::SetUpCommandLine(app);
  app.footer("Keys in the window:\n" + std::string(KeyHelp) +
    "\n"
    "Every option takes --opt VALUE or --opt=VALUE, at most once (again only with the same\n"
    "value). Refused as contradictory: --record with --output or --test (those runs end\n"
    "after the played events: nothing to record), and --record naming the --play-events\n"
    "file. The input files are read and checked before the display is needed.\n"
    "Exit status: 0 ok (with --test: every --test check passed); 1 a volume or recording\n"
    "that cannot be read or is refused, no X display, a VTK error while rendering with\n"
    "--output, the PNG cannot be written, or a --test check failed; 2 a bad command line\n"
    "(usage error); 77 --test without the prepared CT head (CTest: skipped).\n");
  const auto store = [](std::string& target)
  { return [&target](const std::string& v) { target = v; }; };
  scatterer_examples::AddValueOption(app, "--input", "PATH",
    "volume (.mhd/.mha, .nii/.nii.gz, .vti, .nrrd/.nhdr, a DICOM folder\n"
    "or one file of a DICOM series); default the prepared CT head",
    store(o.Input));
  scatterer_examples::AddValueOption(app, "--size", "WxH",
    "window size, 16..8192 each (default 600x600)",
    [&o](const std::string& v)
    {
      std::string why;
      if (!scatterer_examples::ParseSize(v, o.Width, o.Height, why))
      {
        scatterer_examples::ThrowUsageError("--size '" + v + "': " + why);
      }
      o.SizeGiven = true;
    });
  CLI::Option* play = scatterer_examples::AddValueOption(app, "--play-events", "FILE",
    "play recorded interaction events ('-': the built-in recording)", store(o.PlayEvents));
  CLI::Option* record = scatterer_examples::AddValueOption(
    app, "--record", "FILE", "record the session's interaction events to FILE", store(o.Record));
  CLI::Option* output = scatterer_examples::AddValueOption(app, "--output", "FILE.png",
    "after playing the events, write the last frame and exit",
    [&o](const std::string& v)
    {
      scatterer_examples::RequirePngPath("--output", v);
      o.Output = v;
    });
  scatterer_examples::AddValueOption(app, "--preset", "NAME",
    "transfer-function preset to start with (p cycles them in the window);\n"
    "default: ct-head for CT in Hounsfield units, auto otherwise\n" +
      scatterer_examples::TransferPresetHelp(),
    [&o](const std::string& v)
    {
      const auto& names = scatterer_examples::TransferPresetNames();
      if (std::find(names.begin(), names.end(), v) == names.end())
      {
        std::string known;
        for (const std::string& name : names)
        {
          known += " " + name;
        }
        scatterer_examples::ThrowUsageError(
          "--preset '" + v + "': no such preset (known:" + known + ")");
      }
      o.Preset = v;
    });
  CLI::Option* test = app.add_flag("--test", o.Test,
    "play the built-in recording and write scatterer-viewer-test.png\n"
    "at 300x300 (--play-events, --output and --size, when given,\n"
    "win), and fail unless the image is lit, illumination was on\n"
    "in every frame and drag frames cast at most half the rays of\n"
    "still frames (the level of detail)");
  app.callback(
    [&]()
    {
      const std::string nothingToRecord =
        "that run ends after the played events, so there is no session to record";
      scatterer_examples::RejectTogether(record, output, nothingToRecord);
      scatterer_examples::RejectTogether(record, test, nothingToRecord);
      if (record->count() > 0 && play->count() > 0 && SameFile(o.Record, o.PlayEvents))
      {
        scatterer_examples::ThrowConflict("--record", "--play-events",
          (o.Record == o.PlayEvents
              ? "both name '" + o.Record + "'"
              : "'" + o.Record + "' and '" + o.PlayEvents + "' name the same file") +
            "; the recording would overwrite the events being played");
      }
    });
  const int parsed = scatterer_examples::ParseCommandLine(app, argc, argv);
  if (parsed == scatterer_examples::ContinueRun && o.Test)
  {
    // --test fills in what was not given; an explicit --size, --output or
    // --play-events wins (a --size used to be cut to 300x300 without a word).
    if (o.PlayEvents.empty())
    {
      o.PlayEvents = "-";
    }
    if (o.Output.empty())
    {
      o.Output = "scatterer-viewer-test.png";
    }
    if (!o.SizeGiven)
    {
      o.Width = 300;
      o.Height = 300;
    }
  }
  return parsed;
}

/** The viewer's state: the mapper, what the keys toggled, and frame statistics. */
struct Viewer
{
  vtkScattererTemplateVolumeMapper* Mapper = nullptr;
  vtkRenderer* Renderer = nullptr;
  vtkRenderWindow* Window = nullptr;
  vtkVolume* Volume = nullptr;
  scatterer_viewer::ViewerOverlay* Overlay = nullptr;
  scatterer_viewer::ViewerTransfer* Transfer = nullptr;
  int Quality = 2;
  bool Interactive = false;
  std::chrono::steady_clock::time_point FrameStart;
  double LastFrameMs = 0.0;
  int Frames = 0;
  int InteractiveFrames = 0;
  int UnlitFrames = 0;    // frames rendered with illumination asked for but not active
  bool LogFrames = false; // --test: one line per frame on stdout
  std::string LastFeatures;
  std::string LastMessage; // what the last key did, when it says more than the status
  // Per frame kind: milliseconds and rays cast (viewport pixels / image sample distance^2).
  std::vector<double> StillMs, InteractiveMs, StillRays, InteractiveRays;

  /** Applies the quality step, made cheaper on interactive frames (illumination stays on). */
  void ApplyQuality()
  {
    const QualityStep& q = QualitySteps[this->Quality];
    this->Mapper->SetTransportScale(q.TransportScale);
    this->Mapper->SetImageSampleDistance(this->Interactive ? InteractiveImageSampleDistance : 1.0);
    if (this->Interactive)
    {
      // Cheaper while dragging: the mapper itself builds the transport volume at
      // InteractiveTransportScale on dragging frames; in per-sample mode the photon
      // loop is also shortened and evaluated less often along rays.
      this->Mapper->SetIlluminationInterval(std::max(2 * q.IlluminationInterval, 8));
      if (this->Mapper->GetIlluminationMode() == vtkScattererTemplateVolumeMapper::PER_SAMPLE)
      {
        this->Mapper->SetPhotonCap(std::min(q.PhotonCap, 8));
      }
      else
      {
        this->Mapper->SetPhotonCap(q.PhotonCap);
      }
    }
    else
    {
      this->Mapper->SetIlluminationInterval(q.IlluminationInterval);
      this->Mapper->SetPhotonCap(q.PhotonCap);
    }
  }

  /** The status strip: frame, transfer function, effects (ViewerOverlay::StatusLines lines). */
  std::string Describe() const
  {
    vtkScattererTemplateVolumeMapper* m = this->Mapper;
    const bool lit = m->GetIlluminationEnabled();
    std::string effects;
    auto add = [&](bool on, const char* name)
    {
      if (on)
      {
        effects += effects.empty() ? name : std::string(" ") + name;
      }
    };
    // The effects the last frame's shader used (the mapper simulates only what the
    // scene calls for, and transport mode has no thin-part check or blending).
    const std::string& used = this->LastFeatures;
    for (const char* name : { "shadow", "bleed", "thin", "boundary", "blend" })
    {
      add((" " + used + " ").find(std::string(" ") + name + " ") != std::string::npos, name);
    }
    char text[512];
    std::snprintf(text, sizeof(text), "%.0f ms %s  %s  quality %s\n%s\n%s", this->LastFrameMs,
      this->Interactive ? "drag" : "still",
      !lit ? "illumination off"
        : m->GetIlluminationMode() == vtkScattererTemplateVolumeMapper::PER_SAMPLE ? "per-sample"
                                                                                   : "transport",
      QualitySteps[this->Quality].Name, this->Transfer->Describe().c_str(),
      !this->LastMessage.empty() ? this->LastMessage.c_str()
        : effects.empty()        ? "no effect on   h: help"
                                 : (effects + "   h: help").c_str());
    return text;
  }

  void UpdateText() { this->Overlay->SetStatus(this->Describe()); }

  /** In transport mode, says that a per-sample effect's key changes nothing yet. */
  void SayPerSampleOnly(const char* effect, bool on)
  {
    if (this->Mapper->GetIlluminationMode() == vtkScattererTemplateVolumeMapper::TRANSPORT)
    {
      this->LastMessage =
        std::string(effect) + (on ? " on" : " off") + ": per-sample mode only (m)";
    }
  }

  /** Writes the window to the first free scatterer-viewer-N.png in the working folder. */
  void Screenshot()
  {
    std::string path;
    for (int n = 1; n < 10000; ++n)
    {
      path = "scatterer-viewer-" + std::to_string(n) + ".png";
      if (!std::ifstream(path))
      {
        break;
      }
    }
    const bool saved = scatterer_examples::WriteWindowPng(this->Window, path);
    this->LastMessage = saved ? "saved " + path : "cannot write " + path;
    std::cout << "scatterer-viewer: " << this->LastMessage << "\n";
  }

  /** A key of the viewer; false if it is not one (the style handles it). */
  bool HandleKey(char key)
  {
    vtkScattererTemplateVolumeMapper* m = this->Mapper;
    this->LastMessage.clear();
    switch (key)
    {
      case 's':
        m->SetShadowsEnabled(!m->GetShadowsEnabled());
        break;
      case 'b':
        m->SetColorBleedingEnabled(!m->GetColorBleedingEnabled());
        break;
      case 't':
        m->SetThinPartCheckEnabled(!m->GetThinPartCheckEnabled());
        this->SayPerSampleOnly("thin-part check", m->GetThinPartCheckEnabled());
        break;
      case 'r':
        m->SetBoundaryRefractionEnabled(!m->GetBoundaryRefractionEnabled());
        break;
      case 'l':
        m->SetTemplateBlendingEnabled(!m->GetTemplateBlendingEnabled());
        this->SayPerSampleOnly("blending", m->GetTemplateBlendingEnabled());
        break;
      case 'i':
        m->SetIlluminationEnabled(!m->GetIlluminationEnabled());
        break;
      case 'm':
        m->SetIlluminationMode(
          m->GetIlluminationMode() == vtkScattererTemplateVolumeMapper::TRANSPORT
            ? vtkScattererTemplateVolumeMapper::PER_SAMPLE
            : vtkScattererTemplateVolumeMapper::TRANSPORT);
        this->ApplyQuality();
        break;
      case '+':
      case '=':
        this->Quality = std::min(this->Quality + 1, NumberOfQualitySteps - 1);
        this->ApplyQuality();
        break;
      case '-':
      case '_':
        this->Quality = std::max(this->Quality - 1, 0);
        this->ApplyQuality();
        break;
      case 'p':
        this->Transfer->Next();
        break;
      case '[':
      case ']':
        this->Transfer->Shift(key == ']' ? 0.02 : -0.02);
        break;
      case '{':
      case '}':
        this->Transfer->Scale(key == '}' ? 1.25 : 0.8);
        break;
      case 'o':
        this->Transfer->Reset();
        break;
      case 'w':
        this->Screenshot();
        break;
      case 'c':
        this->Renderer->ResetCamera();
        break;
      case 'h':
        this->Overlay->ToggleHelp();
        std::cout << KeyHelp << "\n";
        break;
      default:
        return false;
    }
    this->UpdateText();
    this->Window->Render();
    return true;
  }
};

/** Trackball camera whose character keys are the viewer's (q/e still quit). */
class ViewerInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static ViewerInteractorStyle* New();
  vtkTypeMacro(ViewerInteractorStyle, vtkInteractorStyleTrackballCamera);
  Viewer* Owner = nullptr;

  // ctrl + left drag: window/level instead of the trackball's spin.
  void OnLeftButtonDown() override
  {
    if (this->Interactor->GetControlKey() && !this->Interactor->GetShiftKey() && this->Owner)
    {
      this->FindPokedRenderer(
        this->Interactor->GetEventPosition()[0], this->Interactor->GetEventPosition()[1]);
      this->StartState(WindowLevelState);
      return;
    }
    this->Superclass::OnLeftButtonDown();
  }

  void OnLeftButtonUp() override
  {
    if (this->State == WindowLevelState)
    {
      this->StopState();
      return;
    }
    this->Superclass::OnLeftButtonUp();
  }

  void OnMouseMove() override
  {
    if (this->State != WindowLevelState)
    {
      this->Superclass::OnMouseMove();
      return;
    }
    // A full window width moves the ramp by the data range; a window height scales
    // its width by e^2 (about 7x).
    const int* now = this->Interactor->GetEventPosition();
    const int* before = this->Interactor->GetLastEventPosition();
    const int* size = this->Interactor->GetRenderWindow()->GetSize();
    this->Owner->Transfer->Shift(static_cast<double>(now[0] - before[0]) / std::max(size[0], 1));
    this->Owner->Transfer->Scale(
      std::exp(2.0 * static_cast<double>(now[1] - before[1]) / std::max(size[1], 1)));
    this->Owner->UpdateText();
    this->Interactor->Render();
  }

  void OnChar() override
  {
    const char key = this->Interactor->GetKeyCode();
    if (this->Owner && this->Owner->HandleKey(key))
    {
      return;
    }
    // Keep quit (q, e); drop the style's other keys (w wireframe, p pick, f fly, 3 stereo,
    // j/t joystick/trackball), which mean nothing for a volume or switch the camera mode.
    if (key == 'q' || key == 'Q' || key == 'e' || key == 'E')
    {
      this->Superclass::OnChar();
    }
  }

protected:
  ViewerInteractorStyle() = default;
};
vtkStandardNewMacro(ViewerInteractorStyle);

void OnStartInteraction(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* viewer = static_cast<Viewer*>(clientData);
  viewer->Interactive = true;
  viewer->ApplyQuality();
}

void OnEndInteraction(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* viewer = static_cast<Viewer*>(clientData);
  viewer->Interactive = false;
  viewer->ApplyQuality();
  viewer->UpdateText();
  // The interactor renders the still frame right after this event.
}

void OnRenderStart(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* viewer = static_cast<Viewer*>(clientData);
  // An interactive frame is one whose time budget (1 / the window's desired update rate,
  // which the interactor sets while dragging) is below a second; this also covers frames
  // that a widget or another observer drives without interaction events.
  const bool interactive = viewer->Window->GetDesiredUpdateRate() >= 1.0;
  if (interactive != viewer->Interactive)
  {
    viewer->Interactive = interactive;
    viewer->ApplyQuality();
  }
  viewer->Overlay->Layout();
  viewer->UpdateText();
  viewer->FrameStart = std::chrono::steady_clock::now();
}

void OnRenderEnd(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* viewer = static_cast<Viewer*>(clientData);
  viewer->LastFrameMs =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - viewer->FrameStart)
      .count();
  ++viewer->Frames;
  if (viewer->Interactive)
  {
    ++viewer->InteractiveFrames;
  }
  // Rays cast: the ray caster covers the volume's viewport at 1 / image sample
  // distance of its resolution in each direction.
  int viewport[2];
  viewer->Overlay->GetVolumeViewportSize(viewport);
  const double step = viewer->Mapper->GetImageSampleDistance();
  const double rays = std::ceil(viewport[0] / step) * std::ceil(viewport[1] / step);
  (viewer->Interactive ? viewer->InteractiveMs : viewer->StillMs).push_back(viewer->LastFrameMs);
  (viewer->Interactive ? viewer->InteractiveRays : viewer->StillRays).push_back(rays);
  viewer->LastFeatures = viewer->Mapper->GetLastShaderFeatures();
  if (viewer->LogFrames)
  {
    std::printf("frame %d: %s %.0f ms, %.0f rays, %s\n", viewer->Frames,
      viewer->Interactive ? "interactive" : "still", viewer->LastFrameMs, rays,
      viewer->LastFeatures.c_str());
  }
  if (viewer->Mapper->GetIlluminationEnabled() && viewer->LastFeatures.rfind("stock", 0) == 0)
  {
    ++viewer->UnlitFrames;
  }
}

bool ReadEvents(const std::string& path, std::string& events, std::string& error)
{
  if (path == "-")
  {
    events = BuiltInEvents;
    return true;
  }
  std::ifstream in(path);
  if (!in)
  {
    error = "cannot read events from '" + path + "'";
    return false;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  events = ss.str();
  // What vtkInteractorEventRecorder writes begins with its stream version; anything else
  // (a folder, another file) played nothing, silently.
  if (!in.good() && !in.eof())
  {
    error = "cannot read events from '" + path + "'";
    return false;
  }
  if (events.rfind("# StreamVersion", 0) != 0)
  {
    error = "'" + path +
      "' is not a recording of interaction events (it does not begin with "
      "'# StreamVersion', as --record writes it)";
    return false;
  }
  return true;
}

/** Share of bytes above a dark threshold in a PNG (0 if it cannot be read). */
double LitFraction(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return 0.0;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  auto* scalars =
    vtkUnsignedCharArray::SafeDownCast(reader->GetOutput()->GetPointData()->GetScalars());
  if (!scalars || scalars->GetNumberOfValues() == 0)
  {
    return 0.0;
  }
  vtkIdType lit = 0;
  for (vtkIdType i = 0; i < scalars->GetNumberOfValues(); ++i)
  {
    lit += scalars->GetValue(i) > 8 ? 1 : 0;
  }
  return static_cast<double>(lit) / static_cast<double>(scalars->GetNumberOfValues());
}
}

int main(int argc, char* argv[])
{
  Options options;
  const int parsed = ParseArgs(argc, argv, options);
  if (parsed != scatterer_examples::ContinueRun)
  {
    return parsed; // --help, --version or a usage error, printed
  }
  std::string error;
  // The input files first, then the display: a missing or unusable file is the
  // user's to fix on any machine, and reading needs no display.
  std::string events;
  if (!options.PlayEvents.empty() && !ReadEvents(options.PlayEvents, events, error))
  {
    std::cerr << "scatterer-viewer: " << error << "\n";
    return 1;
  }
  // The recording's file too: VTK's recorder only says it cannot open it, and the
  // session went on unrecorded.
  if (!options.Record.empty() && !std::ofstream(options.Record, std::ios::app))
  {
    std::cerr << "scatterer-viewer: cannot write the recording to '" << options.Record << "'.\n";
    return 1;
  }

  const bool ctHead = options.Input.empty();
  vtkSmartPointer<vtkImageData> image =
    scatterer_examples::ReadVolumeOrCtHead(options.Input, error);
  if (!image)
  {
    std::cerr << "scatterer-viewer: " << error << "\n";
    if (ctHead && options.Test)
    {
      return scatterer_examples::ExitSkipped; // CTest: skipped
    }
    return 1;
  }
  const std::string refusal = scatterer_examples::CheckVolume(
    image, ctHead ? scatterer_examples::CtHeadPath() : options.Input, !ctHead);
  if (!refusal.empty())
  {
    std::cerr << "scatterer-viewer: " << refusal << "\n";
    return 1;
  }
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "scatterer-viewer: no X display (DISPLAY is unset); it needs a window"
                 " (for tests: xvfb-run -a -s \"-screen 0 1280x1024x24\").\n";
    return 1;
  }
  // With --output, a VTK error in any frame fails the run (as in scatterer-render):
  // the written frame would not be what was asked for. In the interactive window
  // the messages are in the terminal for the user to see.
  scatterer_examples::VtkErrorCounter vtkErrors;

  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->SetSize(options.Width, options.Height);
  window->SetWindowName("scatterer-viewer (h: help)");
  window->SetMultiSamples(0);
  renderer->SetBackground(0.0, 0.0, 0.0);

  vtkNew<vtkScattererTemplateVolumeMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vtkVolumeProperty> property;
  vtkVolume* volume = scatterer_examples::AddVolume(renderer, mapper, property);
  if (ctHead)
  {
    scatterer_examples::ApplyCtHeadProperty(property);
    scatterer_examples::ApplyCtHeadCamera(renderer);
    scatterer_examples::ApplyCtHeadLight(renderer);
    scatterer_examples::ApplyCtHeadMapperSettings(mapper);
  }
  else
  {
    scatterer_examples::ApplyAutoScene(image, property, renderer);
    mapper->SetBlendModeToComposite();
  }
  // The level of detail is the viewer's own (ApplyQuality): a fixed image sample
  // distance on interactive frames. VTK's time-driven auto-adjust also lengthens the
  // sample distance along rays (banding) and, with a budget near the still frame's
  // cost, hardly reduced the rays at all (312-338 ms dragging vs 323 ms still at 600^2).
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetImageSampleDistance(1.0);

  // The transfer function: the scene's for the CT head, else the one the histogram
  // suggests (ct-head for CT in Hounsfield units, auto otherwise).
  scatterer_viewer::ViewerTransfer transfer(image, property);
  const std::string preset = !options.Preset.empty() ? options.Preset
    : ctHead
    ? "ct-head"
    : scatterer_examples::DefaultTransferPreset(scatterer_examples::VolumeHistogram(image));
  transfer.Select(preset, error);

  Viewer viewer;
  viewer.Mapper = mapper;
  viewer.Renderer = renderer;
  viewer.Window = window;
  viewer.Volume = volume;
  viewer.LogFrames = options.Test;

  scatterer_viewer::ViewerOverlay overlay;
  overlay.Attach(window, renderer, KeyHelp);
  viewer.Overlay = &overlay;
  viewer.Transfer = &transfer;
  viewer.ApplyQuality();
  viewer.UpdateText();

  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<ViewerInteractorStyle> style;
  style->Owner = &viewer;
  interactor->SetInteractorStyle(style);
  // 4 frames/s while dragging (the ray caster's time budget), a still frame when let go.
  interactor->SetDesiredUpdateRate(4.0);
  interactor->SetStillUpdateRate(0.0001);
  window->SetDesiredUpdateRate(0.0001);

  vtkNew<vtkCallbackCommand> startInteraction;
  startInteraction->SetCallback(OnStartInteraction);
  startInteraction->SetClientData(&viewer);
  style->AddObserver(vtkCommand::StartInteractionEvent, startInteraction);
  vtkNew<vtkCallbackCommand> endInteraction;
  endInteraction->SetCallback(OnEndInteraction);
  endInteraction->SetClientData(&viewer);
  style->AddObserver(vtkCommand::EndInteractionEvent, endInteraction);
  vtkNew<vtkCallbackCommand> renderStart;
  renderStart->SetCallback(OnRenderStart);
  renderStart->SetClientData(&viewer);
  window->AddObserver(vtkCommand::StartEvent, renderStart);
  vtkNew<vtkCallbackCommand> renderEnd;
  renderEnd->SetCallback(OnRenderEnd);
  renderEnd->SetClientData(&viewer);
  window->AddObserver(vtkCommand::EndEvent, renderEnd);

  interactor->Initialize();
  window->Render();

  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(interactor);
  if (!options.Record.empty())
  {
    recorder->SetFileName(options.Record.c_str());
    recorder->On();
    recorder->Record();
  }
  if (!events.empty())
  {
    vtkNew<vtkInteractorEventRecorder> player;
    player->SetInteractor(interactor);
    player->ReadFromInputStringOn();
    player->SetInputString(events.c_str());
    player->Play();
    player->Off();
    // A still frame at the end, whatever the recording ended with.
    viewer.Interactive = false;
    viewer.ApplyQuality();
    window->Render();
  }

  if (options.Output.empty())
  {
    interactor->Start();
    recorder->Stop();
    recorder->Off();
    return 0;
  }

  if (vtkErrors.Count() > 0)
  {
    std::cerr << "scatterer-viewer: VTK reported " << vtkErrors.Count()
              << " error(s) while rendering (the first: " << vtkErrors.First()
              << "); the frame is not trusted and no image is written.\n";
    return 1;
  }
  if (!scatterer_examples::WriteWindowPng(window, options.Output))
  {
    std::cerr << "scatterer-viewer: cannot write '" << options.Output << "'.\n";
    return 1;
  }
  recorder->Stop();
  recorder->Off();
  const double lit = LitFraction(options.Output);
  std::printf("scatterer-viewer: %s, %dx%d, %d frames (%d interactive, %d without illumination),"
              " last frame %.0f ms, shader: %s, lit %.1f%%\n",
    options.Output.c_str(), options.Width, options.Height, viewer.Frames, viewer.InteractiveFrames,
    viewer.UnlitFrames, viewer.LastFrameMs, viewer.LastFeatures.c_str(), 100.0 * lit);
  const double stillRays = Median(viewer.StillRays);
  const double dragRays = Median(viewer.InteractiveRays);
  std::printf("scatterer-viewer: median still frame %.0f ms, %.0f rays; median drag frame %.0f ms,"
              " %.0f rays; transfer function %s\n",
    Median(viewer.StillMs), stillRays, Median(viewer.InteractiveMs), dragRays,
    transfer.Describe().c_str());
  if (options.Test)
  {
    bool ok = true;
    // The level of detail, counted rather than timed (shared machines are noisy): a
    // drag frame casts at most half the rays of a still frame. docs/viewer.md has the
    // timings.
    if (viewer.InteractiveFrames > 0 && !(dragRays <= 0.5 * stillRays))
    {
      std::cerr << "scatterer-viewer --test: drag frames cast " << dragRays
                << " rays, still frames " << stillRays << ": no level of detail\n";
      ok = false;
    }
    if (lit < 0.02)
    {
      std::cerr << "scatterer-viewer --test: the image is blank\n";
      ok = false;
    }
    if (viewer.InteractiveFrames < 1)
    {
      std::cerr << "scatterer-viewer --test: no interactive frame was rendered\n";
      ok = false;
    }
    if (viewer.UnlitFrames > 0 || viewer.LastFeatures.find("shadow") == std::string::npos)
    {
      std::cerr << "scatterer-viewer --test: illumination was not active in every frame\n";
      ok = false;
    }
    return ok ? 0 : 1;
  }
  return 0;
}
