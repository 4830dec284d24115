// The accuracy / time trade-off benchmark (docs/accuracy.md; not part of the tests).
//
// For each scene (the CT head at a reduced size, the same under vtkLightKit's five lights
// (ParaView's default lighting), the synthetic shell + plate scene, the same lit by a
// point light, and dense, nearly white labels, dense-ball):
// renders the converged Monte Carlo reference (Reference; cached in OUT as
// reference-<scene>-<spp>spp.vti), then every GPU configuration (stock composite, stock
// Phong, template illumination over a quality ladder, a brute-force template setting)
// in one process: a warm-up frame, then N timed frames (median). Error against the
// reference after least-squares exposure normalisation (Metrics.h): RMSE, PSNR, SSIM.
// Writes OUT/accuracy.csv, OUT/accuracy-<scene>.png (log-log error vs time, Pareto front,
// every point labelled; VTK charts), OUT/accuracy-strip-<scene>.png (reference | stock
// Phong | transport default | best | error maps) and one PNG per config.
//
//   scatterer-bench-accuracy [--size WxH] [--frames N] [--spp N] [--scenes a,b] [--out DIR]
#include "ScattererReferenceScene.h"

#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererMapperSetup.h"
#include "Common/ScattererNumbers.h"
#include "scatterer_reference/Metrics.h"
#include "scatterer_reference/PathTracer.h"

#include "vtkAxis.h"
#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPiecewiseFunction.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkCamera.h"
#include "vtkChartLegend.h"
#include "vtkChartXY.h"
#include "vtkContext2D.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPen.h"
#include "vtkPlotLine.h"
#include "vtkPlotPoints.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkTextProperty.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLImageDataReader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace
{
// A scatter plot that writes each point's label next to it.
class LabelledPoints : public vtkPlotPoints
{
public:
  static LabelledPoints* New();
  vtkTypeMacro(LabelledPoints, vtkPlotPoints);
  std::vector<std::string> Labels;
  std::vector<double> X, Y;
  std::vector<bool> Below; // label under the point (to avoid a neighbour's label)
  bool Paint(vtkContext2D* painter) override
  {
    const bool ok = this->Superclass::Paint(painter);
    painter->GetTextProp()->SetFontSize(11);
    painter->GetTextProp()->SetColor(0.1, 0.1, 0.1);
    painter->GetTextProp()->SetJustificationToLeft();
    painter->GetTextProp()->SetVerticalJustificationToBottom();
    const vtkRectd ss = this->GetShiftScale();
    for (size_t i = 0; i < this->Labels.size(); ++i)
    {
      const double x = (std::log10(this->X[i]) + ss.GetX()) * ss.GetWidth();
      const double y = (std::log10(this->Y[i]) + ss.GetY()) * ss.GetHeight();
      const bool below = i < this->Below.size() && this->Below[i];
      painter->GetTextProp()->SetVerticalJustification(below ? VTK_TEXT_TOP : VTK_TEXT_BOTTOM);
      painter->DrawString(static_cast<float>(x), static_cast<float>(y), this->Labels[i].c_str());
    }
    return ok;
  }
};
vtkStandardNewMacro(LabelledPoints);

struct Config
{
  std::string Name;
  std::string Mode = "template"; // stock | phong | template
  bool PerSample = false;
  bool Interactive = false; // the volume's allocated render time below 1 s (a dragging frame)
  int PhotonCap = 24, Templates = 8, TransportScale = 2, Interval = 4;
  double LongRange = 3.0, Threshold = 0.002, SampleDistance = 0.5, MultipleScattering = 1.0;
  bool Blend = false;
  bool Shade = false; // template with the volume property's Shade on: VTK's Phong x illumination
};

std::vector<Config> Configs()
{
  std::vector<Config> c;
  Config stock;
  stock.Name = "stock_composite";
  stock.Mode = "stock";
  c.push_back(stock);
  Config phong = stock;
  phong.Name = "stock_phong";
  phong.Mode = "phong";
  c.push_back(phong);
  Config t; // the mapper's defaults (still frame)
  t.Name = "transport_default";
  c.push_back(t);
  Config interactive = t; // the mapper's defaults on a dragging frame (InteractiveTransportScale)
  interactive.Name = "transport_interactive";
  interactive.Interactive = true;
  c.push_back(interactive);
  Config single = t;
  single.Name = "transport_single_scattering";
  single.MultipleScattering = 0.0;
  c.push_back(single);
  Config shaded = t;
  shaded.Name = "transport_shaded";
  shaded.Shade = true;
  c.push_back(shaded);
  Config fine = t;
  fine.Name = "transport_fine";
  fine.TransportScale = 1;
  fine.PhotonCap = 64;
  fine.Templates = 16;
  fine.SampleDistance = 0.25;
  c.push_back(fine);
  Config ps = t; // the paper's local photon test (occluders within the template radius)
  ps.Name = "template_persample";
  ps.PerSample = true;
  c.push_back(ps);
  Config brute = ps; // the brute-force end of the per-sample ladder
  brute.Name = "template_persample_bruteforce";
  brute.Interval = 1;
  brute.PhotonCap = 256; // 1024 takes minutes per frame on llvmpipe
  brute.Threshold = 0.0;
  brute.Templates = 64;
  brute.LongRange = 16;
  brute.Blend = true;
  c.push_back(brute);
  return c;
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Row
{
  std::string Scene, Config;
  double Ms = 0, Rmse = 0, Psnr = 0, Ssim = 0, Scale = 1;
  bool Pareto = false;
};

std::vector<unsigned char> ToBytes(const std::vector<float>& rgb, double exposure)
{
  std::vector<unsigned char> b(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i)
    b[i] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(exposure * rgb[i], 0.0, 1.0)));
  return b;
}

vtkSmartPointer<vtkImageData> BytesImage(const std::vector<unsigned char>& px, int w, int h)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(w, h, 1);
  img->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(px.begin(), px.end(), static_cast<unsigned char*>(img->GetScalarPointer()));
  return img;
}

// The scene for the VTK 9.2 peer (vtk92_scattering_peer.py): volume .vti + JSON.
void ExportScene(const scatterer_reference_vtk::VtkScene& scene, int width, int height,
  const std::string& vti, const std::string& json)
{
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(scene.Image);
  w->SetFileName(vti.c_str());
  w->Write();
  std::ofstream f(json);
  f.precision(10);
  vtkVolumeProperty* p = scene.Property;
  f << "{\"width\": " << width << ", \"height\": " << height
    << ", \"sample_distance\": " << scene.SampleDistance
    << ", \"unit_distance\": " << p->GetScalarOpacityUnitDistance()
    << ", \"ambient\": " << p->GetAmbient() << ", \"diffuse\": " << p->GetDiffuse()
    << ", \"specular\": " << p->GetSpecular() << ", \"specular_power\": " << p->GetSpecularPower()
    << ",\n \"opacity\": [";
  vtkPiecewiseFunction* o = p->GetScalarOpacity();
  for (int i = 0; i < o->GetSize(); ++i)
  {
    double v[4];
    o->GetNodeValue(i, v);
    f << (i ? ", " : "") << "[" << v[0] << ", " << v[1] << "]";
  }
  f << "],\n \"color\": [";
  vtkColorTransferFunction* c = p->GetRGBTransferFunction();
  for (int i = 0; i < c->GetSize(); ++i)
  {
    double v[6];
    c->GetNodeValue(i, v);
    f << (i ? ", " : "") << "[" << v[0] << ", " << v[1] << ", " << v[2] << ", " << v[3] << "]";
  }
  vtkCamera* cam = scene.Renderer->GetActiveCamera();
  double* pos = cam->GetPosition();
  double* fp = cam->GetFocalPoint();
  double* up = cam->GetViewUp();
  double* cr = cam->GetClippingRange();
  f << "],\n \"camera\": {\"position\": [" << pos[0] << ", " << pos[1] << ", " << pos[2]
    << "], \"focal_point\": [" << fp[0] << ", " << fp[1] << ", " << fp[2] << "], \"view_up\": ["
    << up[0] << ", " << up[1] << ", " << up[2] << "], \"view_angle\": " << cam->GetViewAngle()
    << ", \"clipping_range\": [" << cr[0] << ", " << cr[1] << "]},\n \"lights\": [";
  // Written as scene lights, where the renderer puts them for this camera.
  scene.Renderer->UpdateLightsGeometryToFollowCamera();
  vtkLightCollection* lights = scene.Renderer->GetLights();
  lights->InitTraversal();
  bool first = true;
  while (vtkLight* l = lights->GetNextItem())
  {
    if (!l->GetSwitch())
    {
      continue;
    }
    double lp[3], lf[3];
    l->GetTransformedPosition(lp);
    l->GetTransformedFocalPoint(lf);
    double* dc = l->GetDiffuseColor();
    f << (first ? "" : ", ") << "{\"positional\": " << (l->GetPositional() ? "true" : "false")
      << ", \"position\": [" << lp[0] << ", " << lp[1] << ", " << lp[2] << "], \"focal_point\": ["
      << lf[0] << ", " << lf[1] << ", " << lf[2] << "], \"intensity\": " << l->GetIntensity()
      << ", \"cone_angle\": " << l->GetConeAngle() << ", \"diffuse_color\": [" << dc[0] << ", "
      << dc[1] << ", " << dc[2] << "]}";
    first = false;
  }
  f << "]}\n";
}

void WritePlot(const std::vector<Row>& rows, const std::string& scene, const std::string& path)
{
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetSize(900, 600);
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(("Error vs frame time, " + scene + " (log-log; line: Pareto front)").c_str());
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("median frame time (ms)");
  chart->GetAxis(vtkAxis::LEFT)->SetTitle("RMSE vs reference (linear RGB, exposure-normalised)");
  chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(true);
  chart->GetAxis(vtkAxis::LEFT)->SetLogScale(true);

  vtkNew<vtkTable> all;
  vtkNew<vtkDoubleArray> x, y;
  x->SetName("ms");
  y->SetName("rmse");
  all->AddColumn(x);
  all->AddColumn(y);
  std::vector<Row> sel;
  for (const Row& r : rows)
    if (r.Scene == scene && r.Rmse > 0)
      sel.push_back(r);
  all->SetNumberOfRows(static_cast<vtkIdType>(sel.size()));
  vtkNew<LabelledPoints> points;
  for (size_t i = 0; i < sel.size(); ++i)
  {
    all->SetValue(static_cast<vtkIdType>(i), 0, sel[i].Ms);
    all->SetValue(static_cast<vtkIdType>(i), 1, sel[i].Rmse);
    points->X.push_back(sel[i].Ms);
    points->Y.push_back(sel[i].Rmse);
    points->Labels.push_back(" " + sel[i].Config);
  }
  {
    // Labels of points close to an earlier one go below their point.
    double lx0 = 1e300, lx1 = -1e300, ly0 = 1e300, ly1 = -1e300;
    for (size_t i = 0; i < sel.size(); ++i)
    {
      lx0 = std::min(lx0, std::log10(sel[i].Ms));
      lx1 = std::max(lx1, std::log10(sel[i].Ms));
      ly0 = std::min(ly0, std::log10(sel[i].Rmse));
      ly1 = std::max(ly1, std::log10(sel[i].Rmse));
    }
    const double wx = std::max(1e-9, lx1 - lx0), wy = std::max(1e-9, ly1 - ly0);
    points->Below.assign(sel.size(), false);
    for (size_t i = 0; i < sel.size(); ++i)
      for (size_t j = 0; j < i; ++j)
        if (!points->Below[j] &&
          std::abs(std::log10(sel[i].Ms) - std::log10(sel[j].Ms)) < 0.25 * wx &&
          std::abs(std::log10(sel[i].Rmse) - std::log10(sel[j].Rmse)) < 0.05 * wy)
          points->Below[i] = true;
  }
  points->SetInputData(all, 0, 1);
  points->SetColor(30, 80, 200, 255);
  points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  points->SetMarkerSize(9);
  chart->AddPlot(points);

  std::vector<Row> front;
  for (const Row& r : sel)
    if (r.Pareto)
      front.push_back(r);
  std::sort(front.begin(), front.end(), [](const Row& a, const Row& b) { return a.Ms < b.Ms; });
  if (front.size() >= 2) // a line of one point is no line (VTK reports an error drawing it)
  {
    vtkNew<vtkTable> ft;
    vtkNew<vtkDoubleArray> fx, fy;
    fx->SetName("ms");
    fy->SetName("rmse");
    ft->AddColumn(fx);
    ft->AddColumn(fy);
    ft->SetNumberOfRows(static_cast<vtkIdType>(front.size()));
    for (size_t i = 0; i < front.size(); ++i)
    {
      ft->SetValue(static_cast<vtkIdType>(i), 0, front[i].Ms);
      ft->SetValue(static_cast<vtkIdType>(i), 1, front[i].Rmse);
    }
    vtkNew<vtkPlotLine> line;
    line->SetInputData(ft, 0, 1);
    line->SetColor(220, 40, 40, 255);
    line->SetWidth(2.0);
    chart->AddPlot(line);
  }
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (const Row& r : sel)
  {
    x0 = std::min(x0, r.Ms);
    x1 = std::max(x1, r.Ms);
    y0 = std::min(y0, r.Rmse);
    y1 = std::max(y1, r.Rmse);
  }
  if (!sel.empty())
  {
    // Room for the labels right of the points.
    chart->GetAxis(vtkAxis::BOTTOM)->SetBehavior(vtkAxis::FIXED);
    chart->GetAxis(vtkAxis::BOTTOM)->SetUnscaledRange(x0 / 1.5, x1 * 4.0);
    chart->GetAxis(vtkAxis::LEFT)->SetBehavior(vtkAxis::FIXED);
    chart->GetAxis(vtkAxis::LEFT)->SetUnscaledRange(y0 / 1.15, y1 * 1.15);
  }
  view->GetRenderWindow()->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(view->GetRenderWindow());
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> w;
  w->SetInputConnection(grab->GetOutputPort());
  w->SetFileName(path.c_str());
  w->Write();
}
}

int main(int argc, char* argv[])
{
  int frames = 3, width = 256, height = 256, spp = 1024;
  std::string out = "accuracy-benchmark",
              scenes = "ct-head,ct-head-light-kit,shell-plate,shell-plate-point,dense-ball", only,
              peerPython, peerScript;
  // Numbers as the example programs take them (strict, in range): --size 0x0 aborted in
  // the metrics, and --frames abc ran one frame.
  std::string why;
  const auto refused = [&why](const std::string& option, const char* value)
  {
    std::cerr << "scatterer-bench-accuracy: " << option << " '" << value << "': " << why << "\n";
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
    else if (a == "--size" && i + 1 < argc)
    {
      if (!scatterer_examples::ParseSize(argv[++i], width, height, why))
        return refused(a, argv[i]);
    }
    else if (a == "--spp" && i + 1 < argc)
    {
      if (!scatterer_examples::ParseInt(argv[++i], 1, 1 << 20, spp, why))
        return refused(a, argv[i]);
    }
    else if (a == "--scenes" && i + 1 < argc)
      scenes = argv[++i];
    else if (a == "--configs" && i + 1 < argc)
      only = argv[++i];
    else if (a == "--peer-python" && i + 1 < argc)
      peerPython = argv[++i];
    else if (a == "--peer-script" && i + 1 < argc)
      peerScript = argv[++i];
    else if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else
    {
      std::cerr << "usage: scatterer-bench-accuracy [--size WxH] [--frames N] [--spp N] "
                   "[--scenes ct-head,ct-head-light-kit,shell-plate,shell-plate-point,dense-ball] "
                   "[--configs "
                   "a,b] [--out DIR]\n"
                   "         [--peer-python 'PYTHONPATH=... /usr/bin/python3' --peer-script "
                   "vtk92_scattering_peer.py]\n";
      return 2;
    }
  }
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "no X display: run under xvfb-run (scripts/xvfb.sh)\n";
    return 1;
  }
  mkdir(out.c_str(), 0755);
  std::ofstream csv(out + "/accuracy.csv");
  csv << "scene,config,mode,illumination,photon_cap,templates,transport_scale,interval,long_range,"
         "threshold,"
         "sample_distance,frames,median_ms,rmse,psnr_db,ssim,exposure_scale,reference_spp,"
         "reference_rms_standard_error,pareto\n";
  std::vector<Row> rows;
  std::vector<std::string> csvLines;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  scatterer_examples::ApplyCtHeadWindowSettings(window);

  std::stringstream sceneList(scenes);
  for (std::string sceneName; std::getline(sceneList, sceneName, ',');)
  {
    scatterer_reference_vtk::VtkScene scene;
    std::string error;
    int exitCode = 0;
    if (!scatterer_reference_vtk::MakeNamedScene(sceneName, scene, error, exitCode))
    {
      std::cerr << error << "\n";
      return exitCode;
    }

    // The reference, cached on disk.
    const std::string refPath = out + "/reference-" + sceneName + "-" + std::to_string(width) +
      "x" + std::to_string(height) + "-" + std::to_string(spp) + "spp.vti";
    std::vector<float> ref;
    double refSe = 0.0;
    {
      vtkNew<vtkXMLImageDataReader> reader;
      struct stat st;
      if (stat(refPath.c_str(), &st) == 0)
      {
        reader->SetFileName(refPath.c_str());
        reader->Update();
        ref = scatterer_reference_vtk::ToFloatRgb(reader->GetOutput());
        auto* se = vtkFloatArray::SafeDownCast(
          reader->GetOutput()->GetPointData()->GetArray("StandardError"));
        double s2 = 0.0;
        for (vtkIdType i = 0; se && i < se->GetNumberOfTuples(); ++i)
          s2 += se->GetValue(i) * se->GetValue(i);
        refSe = se ? std::sqrt(s2 / std::max<vtkIdType>(1, se->GetNumberOfTuples())) : 0.0;
        std::printf("%s: reference from %s\n", sceneName.c_str(), refPath.c_str());
      }
      else
      {
        scatterer_reference::PathTracer tracer(scatterer_reference_vtk::Convert(
          scene.Image, scene.Property, scene.Renderer, width, height));
        scatterer_reference::RenderSettings rs;
        rs.samplesPerPixel = spp;
        rs.progress = [&](double f)
        {
          std::fprintf(stderr, "\r%s reference (%d spp): %5.1f%%", sceneName.c_str(), spp, 100 * f);
          if (f >= 1.0)
            std::fprintf(stderr, "\n");
        };
        const auto r = tracer.render(rs);
        ref = r.rgb;
        refSe = r.rmsStandardError;
        scatterer_reference_vtk::WriteFloatImage(scatterer_reference_vtk::ToImageData(r), refPath);
        std::printf(
          "%s: reference %d spp in %.1f s, RMS standard error %.3g (mean luminance %.3g)\n",
          sceneName.c_str(), spp, r.seconds, r.rmsStandardError, r.meanLuminance);
      }
    }
    const double refExposure = scatterer_reference_vtk::AutoExposure(ref);
    std::map<std::string, std::vector<float>> images;
    std::map<std::string, double> scales;

    for (const Config& config : Configs())
    {
      if (!only.empty() && ("," + only + ",").find("," + config.Name + ",") == std::string::npos)
        continue;
      vtkSmartPointer<vtkGPUVolumeRayCastMapper> mapper;
      vtkScattererTemplateVolumeMapper* st = nullptr;
      if (config.Mode == "template")
      {
        auto m = vtkSmartPointer<vtkScattererTemplateVolumeMapper>::New();
        st = m;
        m->SetIlluminationMode(config.PerSample ? vtkScattererTemplateVolumeMapper::PER_SAMPLE
                                                : vtkScattererTemplateVolumeMapper::TRANSPORT);
        m->SetPhotonCap(config.PhotonCap);
        m->SetTemplatesPerMaterial(config.Templates);
        m->SetTransportScale(config.TransportScale);
        m->SetMultipleScattering(config.MultipleScattering);
        m->SetIlluminationInterval(config.Interval);
        m->SetLongRangeMultiple(config.LongRange);
        m->SetPhotonThreshold(config.Threshold);
        m->SetTemplateBlendingEnabled(config.Blend);
        mapper = m;
      }
      else
        mapper = vtkSmartPointer<vtkOpenGLGPUVolumeRayCastMapper>::New();
      mapper->SetInputData(scene.Image);
      scatterer_examples::ApplyCtHeadMapperSettings(mapper);
      mapper->SetSampleDistance(config.SampleDistance);
      vtkNew<vtkVolumeProperty> property;
      property->DeepCopy(scene.Property);
      property->SetShade(config.Mode == "phong" || config.Shade);
      vtkNew<vtkRenderer> renderer;
      renderer->SetBackground(0, 0, 0);
      scatterer_examples::AddVolume(renderer, mapper, property);
      scatterer_reference_vtk::ApplySceneView(scene, renderer);
      window->GetRenderers()->RemoveAllItems();
      window->AddRenderer(renderer);
      // A dragging frame as VTK's interactor asks for one (the volume's allocated
      // render time falls below 1 s), or a still frame (VTK's default rate).
      window->SetDesiredUpdateRate(config.Interactive ? 20.0 : 0.0001);
      const auto warmStart = std::chrono::steady_clock::now();
      window->Render();
      window->WaitForCompletion();
      const double warmMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - warmStart)
          .count();
      std::vector<double> ms;
      const int timed = warmMs > 8000.0 ? 1 : frames; // very slow settings: one timed frame
      for (int f = 0; f < timed; ++f)
      {
        const auto start = std::chrono::steady_clock::now();
        window->Render();
        window->WaitForCompletion();
        ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
      }
      vtkNew<vtkWindowToImageFilter> grab;
      grab->SetInput(window);
      grab->ReadFrontBufferOff();
      grab->SetInputBufferTypeToRGB();
      grab->Update();
      const std::vector<float> img = scatterer_reference_vtk::ToFloatRgb(grab->GetOutput());
      const auto m = scatterer_reference::compare(img, ref, width, height);
      Row row{ sceneName, config.Name, Median(ms), m.rmse, m.psnr, m.ssim, m.scale };
      rows.push_back(row);
      images[config.Name] = img;
      scales[config.Name] = m.scale;
      std::ostringstream line;
      line << sceneName << ',' << config.Name << ',' << config.Mode << ','
           << (st ? (config.PerSample        ? "per-sample"
                        : config.Interactive ? "transport-interactive"
                                             : "transport")
                  : "-")
           << ',' << config.PhotonCap << ',' << config.Templates << ',' << config.TransportScale
           << ',' << config.Interval << ',' << config.LongRange << ',' << config.Threshold << ','
           << config.SampleDistance << ',' << ms.size() << ',' << row.Ms << ',' << m.rmse << ','
           << m.psnr << ',' << m.ssim << ',' << m.scale << ',' << spp << ',' << refSe;
      csvLines.push_back(line.str());
      std::printf("%-12s %-32s %9.1f ms  RMSE %.4f  PSNR %6.2f dB  SSIM %.4f\n", sceneName.c_str(),
        config.Name.c_str(), row.Ms, m.rmse, m.psnr, m.ssim);
      std::fflush(stdout);
      scatterer_reference_vtk::WritePng(img, width, height, m.scale * refExposure,
        out + "/" + sceneName + "-" + config.Name + ".png");
    }
    // VTK 9.2's volumetric scattering (ParaView 5.11's VTK), in a child process.
    if (!peerPython.empty() && !peerScript.empty())
    {
      const std::string vti = out + "/scene-" + sceneName + ".vti",
                        json = out + "/scene-" + sceneName + ".json";
      ExportScene(scene, width, height, vti, json);
      const std::string cmd = peerPython + " '" + peerScript + "' --volume '" + vti +
        "' --scene '" + json + "' --name " + sceneName + " --out '" + out + "' --frames " +
        std::to_string(frames);
      std::fflush(stdout);
      if (std::system(cmd.c_str()) != 0)
        std::fprintf(stderr, "VTK 9.2 peer failed: %s\n", cmd.c_str());
      std::ifstream peer(out + "/peer-" + sceneName + ".csv");
      std::string line;
      std::getline(peer, line); // header
      while (std::getline(peer, line))
      {
        std::vector<std::string> f;
        std::stringstream ls(line);
        for (std::string c; std::getline(ls, c, ',');)
          f.push_back(c);
        if (f.size() < 5)
          continue;
        vtkNew<vtkPNGReader> reader;
        reader->SetFileName(f[4].c_str());
        reader->Update();
        const std::vector<float> img = scatterer_reference_vtk::ToFloatRgb(reader->GetOutput());
        if (img.size() != ref.size())
          continue;
        const auto m = scatterer_reference::compare(img, ref, width, height);
        Row row{ sceneName, f[1], std::atof(f[3].c_str()), m.rmse, m.psnr, m.ssim, m.scale };
        rows.push_back(row);
        images[f[1]] = img;
        scales[f[1]] = m.scale;
        std::ostringstream l2;
        l2 << sceneName << ',' << f[1] << ",vtk92_scattering,-,-,-,-,-,-,-," << scene.SampleDistance
           << ',' << f[2] << ',' << row.Ms << ',' << m.rmse << ',' << m.psnr << ',' << m.ssim << ','
           << m.scale << ',' << spp << ',' << refSe;
        csvLines.push_back(l2.str());
        std::printf("%-12s %-32s %9.1f ms  RMSE %.4f  PSNR %6.2f dB  SSIM %.4f\n",
          sceneName.c_str(), f[1].c_str(), row.Ms, m.rmse, m.psnr, m.ssim);
      }
    }
    // Pareto front (time, RMSE) of this scene.
    for (Row& r : rows)
    {
      if (r.Scene != sceneName)
        continue;
      r.Pareto = true;
      for (const Row& o : rows)
        if (o.Scene == sceneName && &o != &r && o.Ms <= r.Ms && o.Rmse <= r.Rmse &&
          (o.Ms < r.Ms || o.Rmse < r.Rmse))
          r.Pareto = false;
    }
    WritePlot(rows, sceneName, out + "/accuracy-" + sceneName + ".png");

    // The strip: reference | stock Phong | transport default | best | error maps.
    std::string best;
    double bestRmse = 1e300;
    for (const Row& r : rows)
      if (r.Scene == sceneName &&
        (r.Config.rfind("template", 0) == 0 || r.Config.rfind("transport", 0) == 0) &&
        r.Rmse < bestRmse)
      {
        bestRmse = r.Rmse;
        best = r.Config;
      }
    std::vector<std::string> panels = { "stock_phong", "transport_default", best };
    vtkNew<vtkImageAppend> append;
    append->SetAppendAxis(0);
    append->AddInputData(BytesImage(ToBytes(ref, refExposure), width, height));
    std::vector<std::vector<float>> maps;
    for (const std::string& p : panels)
      if (images.count(p))
      {
        append->AddInputData(
          BytesImage(ToBytes(images[p], scales[p] * refExposure), width, height));
        maps.push_back(scatterer_reference::errorMap(images[p], ref, width, height, scales[p]));
      }
    for (const auto& map : maps)
      append->AddInputData(
        BytesImage(scatterer_reference_vtk::HeatMapBytes(map, 1.0 / refExposure), width, height));
    append->Update();
    vtkNew<vtkPNGWriter> w;
    w->SetInputConnection(append->GetOutputPort());
    w->SetFileName((out + "/accuracy-strip-" + sceneName + ".png").c_str());
    w->Write();
    std::printf("%s: strip = reference | stock_phong | transport_default | %s | error maps "
                "(|luminance difference|, white = the full display range)\n",
      sceneName.c_str(), best.c_str());
  }
  for (size_t i = 0; i < rows.size(); ++i)
    csv << csvLines[i] << ',' << (rows[i].Pareto ? 1 : 0) << "\n";
  std::printf("wrote %s/accuracy.csv\n", out.c_str());
  return 0;
}
