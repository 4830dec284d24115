// scatterer-viewer: an interactive window on a volume with scatterer-template illumination.
//
// Default input: the real CT head scene (scripts/prepare-data.sh), the scene of
// scatterer-render and the benchmarks. Trackball camera (left drag rotates, middle or
// shift+left pans, right drag or wheel zooms). Keys (press h in the window for the list):
//   s shadows   b colour bleeding   t thin-part check   r boundary refraction
//   l template blending   i illumination on/off   m transport / per-sample
//   + / - quality step   c reset camera   h help   q / e quit
// While the user drags, frames are interactive: VTK's desired update rate
// (interactor SetDesiredUpdateRate) lets the ray caster render at a reduced image
// sample distance, and the mapper switches to a cheaper illumination setting
// (longer illumination interval, fewer photons per sample in per-sample mode). The
// illumination stays on. When the user lets go, the still update rate gives a
// full-quality frame with the chosen quality step.
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
#include "Common/ScattererRenderOptions.h"
#include "Common/ScattererScreenshot.h"
#include "Common/ScattererVolumeCheck.h"

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
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
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
  { "default", 2, 24, 4 },
  { "high", 1, 48, 2 },
  { "best", 1, 96, 1 },
};
const int NumberOfQualitySteps = static_cast<int>(sizeof(QualitySteps) / sizeof(QualitySteps[0]));

const char* const KeyHelp = "s shadows  b bleeding  t thin  r boundary  l blending\n"
                            "i illumination  m transport/per-sample  +/- quality\n"
                            "c reset camera  h help  q quit  drag: rotate/pan/zoom";

struct Options
{
  std::string Input;
  std::string Output;
  std::string PlayEvents;
  std::string Record;
  std::string Preset; // --preset NAME; empty: none (the name is checked where presets are applied)
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
    "Exit status: 0 ok (with --test: the image is lit and illumination was on in every\n"
    "frame); 1 a volume or recording that cannot be read or is refused, no X display, a\n"
    "VTK error while rendering with --output, the PNG cannot be written, or a --test check\n"
    "failed; 2 a bad command line (usage error); 77 --test without the prepared CT head\n"
    "(CTest: skipped).\n");
  const auto store = [](std::string& target) {
    return [&target](const std::string& v) { target = v; };
  };
  scatterer_examples::AddValueOption(app, "--input", "PATH",
    "volume (.mhd/.mha, .nii/.nii.gz, .vti, .nrrd, DICOM folder);\n"
    "default the prepared CT head",
    store(o.Input));
  scatterer_examples::AddValueOption(
    app, "--size", "WxH", "window size, 16..8192 each (default 600x600)", [&o](const std::string& v) {
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
    "after playing the events, write the last frame and exit", store(o.Output));
  scatterer_examples::AddValueOption(
    app, "--preset", "NAME", "start with the named preset of settings", store(o.Preset));
  CLI::Option* test = app.add_flag("--test", o.Test,
    "play the built-in recording and write scatterer-viewer-test.png\n"
    "at 300x300 (--play-events, --output and --size, when given,\n"
    "win), and fail unless the image is lit and illumination was on\n"
    "in every frame");
  app.callback([&]() {
    const std::string nothingToRecord =
      "that run ends after the played events, so there is no session to record";
    scatterer_examples::RejectTogether(record, output, nothingToRecord);
    scatterer_examples::RejectTogether(record, test, nothingToRecord);
    if (record->count() > 0 && play->count() > 0 && o.Record == o.PlayEvents)
    {
      scatterer_examples::ThrowConflict("--record", "--play-events",
        "both name '" + o.Record + "'; the recording would overwrite the events being played");
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
  vtkTextActor* Status = nullptr;
  vtkTextActor* Help = nullptr;
  int Quality = 2;
  bool Interactive = false;
  std::chrono::steady_clock::time_point FrameStart;
  double LastFrameMs = 0.0;
  int Frames = 0;
  int InteractiveFrames = 0;
  int UnlitFrames = 0; // frames rendered with illumination asked for but not active
  bool LogFrames = false; // --test: one line per frame on stdout
  std::string LastFeatures;

  /** Applies the quality step, made cheaper on interactive frames (illumination stays on). */
  void ApplyQuality()
  {
    const QualityStep& q = QualitySteps[this->Quality];
    this->Mapper->SetTransportScale(q.TransportScale);
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

  std::string Describe() const
  {
    auto onOff = [](bool v) { return v ? "on" : "off"; };
    vtkScattererTemplateVolumeMapper* m = this->Mapper;
    char text[512];
    std::snprintf(text, sizeof(text),
      "%.0f ms/frame (%s)\n"
      "illumination %s, %s, quality %s (+/-)\n"
      "shadow %s bleed %s thin %s boundary %s blend %s\n"
      "transport x%d  photons %d  interval %d   h: help",
      this->LastFrameMs, this->Interactive ? "interactive" : "still",
      onOff(m->GetIlluminationEnabled()),
      m->GetIlluminationMode() == vtkScattererTemplateVolumeMapper::PER_SAMPLE ? "per-sample"
                                                                               : "transport",
      QualitySteps[this->Quality].Name, onOff(m->GetShadowsEnabled()),
      onOff(m->GetColorBleedingEnabled()), onOff(m->GetThinPartCheckEnabled()),
      onOff(m->GetBoundaryRefractionEnabled()), onOff(m->GetTemplateBlendingEnabled()),
      m->GetTransportScale(), m->GetPhotonCap(), m->GetIlluminationInterval());
    return text;
  }

  void UpdateText() { this->Status->SetInput(this->Describe().c_str()); }

  /** A key of the viewer; false if it is not one (the style handles it). */
  bool HandleKey(char key)
  {
    vtkScattererTemplateVolumeMapper* m = this->Mapper;
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
        break;
      case 'r':
        m->SetBoundaryRefractionEnabled(!m->GetBoundaryRefractionEnabled());
        break;
      case 'l':
        m->SetTemplateBlendingEnabled(!m->GetTemplateBlendingEnabled());
        break;
      case 'i':
        m->SetIlluminationEnabled(!m->GetIlluminationEnabled());
        break;
      case 'm':
        m->SetIlluminationMode(m->GetIlluminationMode() == vtkScattererTemplateVolumeMapper::TRANSPORT
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
      case 'c':
        this->Renderer->ResetCamera();
        break;
      case 'h':
        this->Help->SetVisibility(!this->Help->GetVisibility());
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
  viewer->UpdateText();
  viewer->FrameStart = std::chrono::steady_clock::now();
}

void OnRenderEnd(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* viewer = static_cast<Viewer*>(clientData);
  viewer->LastFrameMs = std::chrono::duration<double, std::milli>(
    std::chrono::steady_clock::now() - viewer->FrameStart)
                          .count();
  ++viewer->Frames;
  if (viewer->Interactive)
  {
    ++viewer->InteractiveFrames;
  }
  viewer->LastFeatures = viewer->Mapper->GetLastShaderFeatures();
  if (viewer->LogFrames)
  {
    std::printf("frame %d: %s %.0f ms, %s\n", viewer->Frames,
      viewer->Interactive ? "interactive" : "still", viewer->LastFrameMs,
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
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(reader->GetOutput()->GetPointData()->GetScalars());
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

  const bool ctHead = options.Input.empty();
  vtkSmartPointer<vtkImageData> image = scatterer_examples::ReadVolumeOrCtHead(options.Input, error);
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
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
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
  // Interactive frames: the ray caster lowers the image sample distance to meet the
  // desired update rate (VTK's own mechanism, no shader rebuild); still frames get all
  // the time they need (full resolution).
  mapper->AutoAdjustSampleDistancesOn();
  mapper->SetMinimumImageSampleDistance(1.0);
  mapper->SetMaximumImageSampleDistance(4.0);

  Viewer viewer;
  viewer.Mapper = mapper;
  viewer.Renderer = renderer;
  viewer.Window = window;
  viewer.Volume = volume;
  viewer.LogFrames = options.Test;

  vtkNew<vtkTextActor> status;
  status->GetTextProperty()->SetFontSize(options.Width < 400 ? 10 : 14);
  status->GetTextProperty()->SetColor(1.0, 1.0, 0.6);
  status->SetDisplayPosition(6, 6);
  renderer->AddActor2D(status);
  vtkNew<vtkTextActor> helpText;
  helpText->SetInput(KeyHelp);
  helpText->GetTextProperty()->SetFontSize(options.Width < 400 ? 10 : 14);
  helpText->GetTextProperty()->SetColor(0.7, 0.9, 1.0);
  helpText->GetTextProperty()->SetVerticalJustificationToTop();
  helpText->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  helpText->GetPositionCoordinate()->SetValue(0.02, 0.98);
  helpText->SetVisibility(false);
  renderer->AddActor2D(helpText);
  viewer.Status = status;
  viewer.Help = helpText;
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
    options.Output.c_str(), options.Width, options.Height, viewer.Frames,
    viewer.InteractiveFrames, viewer.UnlitFrames, viewer.LastFrameMs, viewer.LastFeatures.c_str(),
    100.0 * lit);
  if (options.Test)
  {
    bool ok = true;
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
