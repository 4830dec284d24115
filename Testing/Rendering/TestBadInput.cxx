// Bad input gets a clear message and stock rendering or a clean no-op, never
// a crash (CTest label "hard"; cases listed in docs/hard-cases.md).
#include "ScattererRenderHarness.h"
#include "ScattererTestVolumes.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOutputWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkColorTransferFunction.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererTransportVolume.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

namespace
{
// Collects everything VTK reports (errors and warnings from any object).
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override { this->Text += text ? text : ""; }
  std::string Text;
};
vtkStandardNewMacro(CapturingOutputWindow);

struct Capture
{
  vtkNew<CapturingOutputWindow> Window;
  vtkSmartPointer<vtkOutputWindow> Previous;
  Capture()
  {
    this->Previous = vtkOutputWindow::GetInstance();
    vtkOutputWindow::SetInstance(this->Window);
  }
  ~Capture() { vtkOutputWindow::SetInstance(this->Previous); }
  bool Has(const std::string& s) const { return this->Window->Text.find(s) != std::string::npos; }
};

struct Stage
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkScattererTemplateVolumeMapper> Mapper;
  Stage()
  {
    scatterer_testing::ApplyShellBallPlateProperty(this->Property);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->AutomaticLightCreationOff();
    scatterer_testing::AddSceneLight(this->Renderer, 1, 0.5, 0.8);
    this->Renderer->GetActiveCamera()->SetPosition(80, -40, 60);
    this->Renderer->GetActiveCamera()->SetFocalPoint(16, 16, 16);
    vtkRenderWindow* w = scatterer_testing::SharedWindow();
    w->GetRenderers()->RemoveAllItems();
    w->AddRenderer(this->Renderer);
  }
  ~Stage()
  {
    scatterer_testing::SharedWindow()->RemoveRenderer(this->Renderer);
    this->Mapper->ReleaseGraphicsResources(scatterer_testing::SharedWindow());
  }
  std::vector<unsigned char> Render()
  {
    this->Renderer->ResetCameraClippingRange();
    return scatterer_testing::RenderAndGrab(scatterer_testing::SharedWindow());
  }
  // The shell, ball and plate lit by the stage's light: the picture that lights left out
  // must leave as it is.
  std::vector<unsigned char> RenderShellBallPlate()
  {
    this->Mapper->SetInputData(scatterer_testing::MakeShellBallPlate(32, VTK_UNSIGNED_CHAR));
    return this->Render();
  }
};
}

TEST(BadInput, NonImageInputIsRefusedWithAMessage)
{
  Capture capture;
  Stage stage;
  vtkNew<vtkPolyData> poly;
  stage.Mapper->SetInputData(poly);
  stage.Render();
  EXPECT_TRUE(capture.Has("vtkImageData")) << capture.Window->Text;
}

TEST(BadInput, EmptyImageRendersNothingWithoutCrashing)
{
  Capture capture;
  Stage stage;
  vtkNew<vtkImageData> empty;
  stage.Mapper->SetInputData(empty);
  const auto image = stage.Render();
  EXPECT_FALSE(image.empty());
  EXPECT_EQ(stage.Mapper->GetLastShaderFeatures().rfind("stock", 0) == 0 ||
      stage.Mapper->GetLastShaderFeatures() == "stock: not rendered yet",
    true)
    << stage.Mapper->GetLastShaderFeatures();
}

TEST(BadInput, MissingScalarsRenderAsStock)
{
  Capture capture;
  Stage stage;
  vtkNew<vtkImageData> noScalars;
  noScalars->SetDimensions(16, 16, 16);
  stage.Mapper->SetInputData(noScalars);
  stage.Render();
  const std::string f = stage.Mapper->GetLastShaderFeatures();
  EXPECT_TRUE(f.rfind("stock", 0) == 0) << f;
}

// An axis longer than the GPU's 3D textures: VTK cannot upload the volume and draws
// nothing. The mapper says so once, naming the limit (it called the placement degenerate
// at every frame).
TEST(BadInput, AVolumeTooLongForA3DTextureIsSaidOnce)
{
  Capture capture;
  Stage stage;
  stage.Render();
  const int limit = vtkTextureObject::GetMaximumTextureSize3D(
    vtkOpenGLRenderWindow::SafeDownCast(scatterer_testing::SharedWindow()));
  if (limit < 1 || limit > 16384)
  {
    GTEST_SKIP() << "3D texture limit " << limit;
  }
  vtkNew<vtkImageData> tall;
  tall->SetDimensions(4, 4, limit + 1);
  tall->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::fill_n(static_cast<unsigned char*>(tall->GetScalarPointer()), tall->GetNumberOfPoints(),
    static_cast<unsigned char>(200));
  stage.Mapper->SetInputData(tall);
  for (int frame = 0; frame < 3; ++frame)
  {
    stage.Render();
  }
  const std::string& text = capture.Window->Text;
  const std::string said = "VTK did not upload it to the GPU (at most " + std::to_string(limit);
  EXPECT_NE(text.find(said), std::string::npos) << text;
  EXPECT_EQ(text.find(said), text.rfind(said)) << text;
  EXPECT_EQ(text.find("degenerate"), std::string::npos) << text;
  EXPECT_EQ(stage.Mapper->GetLastShaderFeatures().rfind("stock", 0), 0u)
    << stage.Mapper->GetLastShaderFeatures();
}

// An OpenGL implementation that refuses one of the light transport volume's passes (an
// error raised as it draws) left the light texture as it was: a black volume at a first
// build, and the failed build tried again at every frame. The mapper says so once and
// renders as the stock mapper would.
TEST(BadInput, AnOpenGLErrorWhileBuildingTheLightIsSaidOnceAndRendersAsStock)
{
  Capture capture;
  Stage stage;
  stage.Mapper->IlluminationEnabledOff();
  const std::vector<unsigned char> stock = stage.RenderShellBallPlate();
  stage.Mapper->IlluminationEnabledOn();
  stage.Mapper->GetTransportVolume()->SetRaiseOpenGLErrorForTesting(true);
  std::vector<unsigned char> refused;
  for (int frame = 0; frame < 3; ++frame)
  {
    refused = stage.Render();
  }
  const std::string& text = capture.Window->Text;
  const std::string said = "OpenGL reported error 0x0500";
  EXPECT_NE(text.find(said), std::string::npos) << text;
  EXPECT_EQ(text.find(said), text.rfind(said)) << text;
  EXPECT_EQ(stage.Mapper->GetTransportVolume()->GetBuildCount(), 0);
  EXPECT_EQ(stage.Mapper->GetLastShaderFeatures().rfind("stock", 0), 0u)
    << stage.Mapper->GetLastShaderFeatures();
  ASSERT_FALSE(stock.empty());
  EXPECT_EQ(refused, stock);
}

TEST(BadInput, LabelIdsWithoutAMaterialAreNamedInAWarning)
{
  Capture capture;
  Stage stage;
  auto labels = scatterer_testing::MakeShellBallPlate(32, VTK_UNSIGNED_CHAR);
  stage.Mapper->SetInputData(labels);
  // Materials for the shell (100) and the ball (200) only: the plate (150) has none.
  stage.Mapper->AddLabelMaterial(100, 1.3, 1, 0.6, 0.5);
  stage.Mapper->AddLabelMaterial(200, 1.5, 1, 1, 0.9);
  stage.Property->SetInterpolationTypeToNearest();
  stage.Render();
  EXPECT_TRUE(capture.Has("belong to none of the requested materials")) << capture.Window->Text;
  EXPECT_TRUE(capture.Has("scalar value 150")) << capture.Window->Text;
  EXPECT_EQ(stage.Mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos);
  // The next step of a time series: fewer unassigned voxels, the same materials. Said
  // once (the count in the text made it a new warning at every step).
  vtkDataArray* scalars = labels->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    if (scalars->GetTuple1(i) == 150 && i % 2 == 0)
    {
      scalars->SetTuple1(i, 0);
    }
  }
  scalars->Modified();
  stage.Render();
  const std::string& text = capture.Window->Text;
  const std::string said = "belong to none of the requested materials";
  EXPECT_EQ(text.find(said), text.rfind(said)) << text;
}

TEST(BadInput, AbsurdParametersAreClampedOrRejectedWithTheirName)
{
  Capture capture;
  Stage stage;
  stage.Mapper->SetInputData(scatterer_testing::MakeShellBallPlate(32, VTK_UNSIGNED_CHAR));
  stage.Mapper->SetTemplateRadius(-5.0);
  EXPECT_TRUE(capture.Has("SetTemplateRadius: -5 is outside")) << capture.Window->Text;
  EXPECT_EQ(stage.Mapper->GetTemplateRadius(), 0.0);
  stage.Mapper->SetTemplatesPerMaterial(0);
  EXPECT_TRUE(capture.Has("SetTemplatesPerMaterial: 0 is outside")) << capture.Window->Text;
  EXPECT_EQ(stage.Mapper->GetTemplatesPerMaterial(), 1);
  stage.Mapper->SetOcclusionStrength(std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(capture.Has("SetOcclusionStrength: NaN is not a valid value"))
    << capture.Window->Text;
  EXPECT_EQ(stage.Mapper->GetOcclusionStrength(), 1.0);
  stage.Mapper->AddScalarRangeMaterial(std::numeric_limits<double>::quiet_NaN(), 1, 1.4, 1, 1, 1);
  EXPECT_TRUE(capture.Has("every argument must be finite")) << capture.Window->Text;
  stage.Mapper->AddScalarRangeMaterial(200, 100, 1.4, 1, 1, 1);
  EXPECT_TRUE(capture.Has("needs lo <= hi")) << capture.Window->Text;
  // Indices the physics cannot use are refused when added, not at render time.
  for (double n : { -1.0, 1e-300, 1e300 })
  {
    stage.Mapper->AddScalarRangeMaterial(100, 200, n, 1, 1, 1);
    EXPECT_TRUE(capture.Has("a refractive index in [0.0001, 10000]")) << n << capture.Window->Text;
    capture.Window->Text.clear();
  }
  // A label's error names the method called, and a refused label leaves the material
  // added before it a range material.
  stage.Mapper->AddScalarRangeMaterial(2.5, 3.5, 1.4, 1, 1, 1);
  stage.Mapper->AddLabelMaterial(3, -1.0, 1, 1, 1);
  EXPECT_TRUE(capture.Has("AddLabelMaterial: needs lo <= hi and a refractive index"))
    << capture.Window->Text;
  EXPECT_EQ(stage.Mapper->GetNumberOfRequestedMaterials(), 1);
  stage.Mapper->RemoveAllMaterials();
  EXPECT_EQ(stage.Mapper->GetNumberOfRequestedMaterials(), 0);
  // A whole volume's dimensions: three point counts or none.
  stage.Mapper->SetWholeDimensions(64, 0, 64);
  EXPECT_TRUE(capture.Has("SetWholeDimensions: needs three point counts")) << capture.Window->Text;
  EXPECT_EQ(stage.Mapper->GetWholeDimensions()[0], 0);
  // A whole set smaller than the piece (a stale setting) keeps the piece in the budget.
  const int large[3] = { 511, 511, 215 };
  const double cubic[3] = { 1, 1, 1 };
  const int own = stage.Mapper->GetEffectiveTransportScale(large, cubic, false);
  stage.Mapper->SetWholeDimensions(2, 2, 2);
  EXPECT_EQ(stage.Mapper->GetEffectiveTransportScale(large, cubic, false), own);
  stage.Mapper->SetWholeDimensions(0, 0, 0);
  // Radii at the ends of the setter's range render lit in both modes.
  stage.Mapper->SetTemplateRadius(std::numeric_limits<double>::infinity());
  EXPECT_TRUE(capture.Has("SetTemplateRadius: inf is outside")) << capture.Window->Text;
  for (double radius : { std::numeric_limits<double>::max(), 1e-300 })
  {
    stage.Mapper->SetTemplateRadius(radius);
    for (int mode :
      { vtkScattererTemplateVolumeMapper::TRANSPORT, vtkScattererTemplateVolumeMapper::PER_SAMPLE })
    {
      stage.Mapper->SetIlluminationMode(mode);
      stage.Render();
      EXPECT_EQ(stage.Mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos)
        << radius << " " << stage.Mapper->GetLastShaderFeatures();
    }
  }
  stage.Mapper->SetTemplateRadius(0.0);
  stage.Mapper->SetIlluminationModeToTransport();
  stage.Mapper->SetMaterialDerivationRange(0.0, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(capture.Has("the range must be finite")) << capture.Window->Text;
  EXPECT_GT(
    stage.Mapper->GetMaterialDerivationRange()[0], stage.Mapper->GetMaterialDerivationRange()[1])
    << "still unset: materials come from the data range";
  // After all that the mapper still illuminates, with the clamped values.
  const auto image = stage.Render();
  EXPECT_EQ(stage.Mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos)
    << stage.Mapper->GetLastShaderFeatures();
  EXPECT_GT(scatterer_testing::MeanBrightness(image), 1.0);
}

TEST(BadInput, LabelTransferFunctionsGiveOneMaterialPerLabel)
{
  Stage stage;
  vtkNew<vtkVolumeProperty> labelled;
  for (int label : { 1, 2, 5 })
  {
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0, 0.2 * label, 0.5, 0.5);
    labelled->SetLabelColor(label, color);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0, 0.5);
    labelled->SetLabelScalarOpacity(label, opacity);
  }
  stage.Mapper->AddMaterialsFromLabelTransferFunctions(labelled);
  EXPECT_EQ(stage.Mapper->GetNumberOfRequestedMaterials(), 3);
  Capture capture;
  vtkNew<vtkVolumeProperty> none;
  stage.Mapper->AddMaterialsFromLabelTransferFunctions(none);
  EXPECT_TRUE(capture.Has("no label transfer functions")) << capture.Window->Text;
  EXPECT_EQ(stage.Mapper->GetNumberOfRequestedMaterials(), 3);
}

// A light with a NaN or infinite setting would light every sample NaN (a black frame):
// it is left out, with a warning; the frame is the one the other lights give, or the
// stock mapper's when none is left.
TEST(BadInput, NonFiniteLightsAreLeftOutWithAWarning)
{
  Capture capture;
  Stage stage;
  const auto good = stage.RenderShellBallPlate();
  ASSERT_GT(scatterer_testing::MeanBrightness(good), 5.0);
  vtkLight* bad = scatterer_testing::AddSceneLight(stage.Renderer, -1, 0.2, 0.5);
  bad->SetIntensity(std::numeric_limits<double>::quiet_NaN());
  const auto withNaN = stage.Render();
  EXPECT_TRUE(capture.Has("ignores 1 switched-on light(s) with a NaN or infinite"))
    << capture.Window->Text;
  EXPECT_EQ(scatterer_testing::MaxDifference(good, withNaN), 0);

  // Only lights with infinite positions: nothing to light with, the stock picture.
  stage.Renderer->RemoveAllLights();
  vtkLight* far = scatterer_testing::AddSceneLight(stage.Renderer, 1, 0.5, 0.8);
  far->SetPosition(std::numeric_limits<double>::infinity(), 0, 0);
  const auto none = stage.Render();
  EXPECT_EQ(stage.Mapper->GetLastShaderFeatures().rfind("stock: no light", 0), 0u)
    << stage.Mapper->GetLastShaderFeatures();
  EXPECT_GT(scatterer_testing::MeanBrightness(none), 5.0) << "a black frame";
}

TEST(BadInput, LightsWithoutADirectionOrAPositiveAttenuationAreLeftOutWithAWarning)
{
  Capture capture;
  Stage stage;
  const auto good = stage.RenderShellBallPlate();
  ASSERT_GT(scatterer_testing::MeanBrightness(good), 5.0);
  // A directional light at its focal point (it was lit from +z, unasked), and a point
  // light whose attenuation is 0 at every distance (it lit everything fully).
  vtkLight* pointless = scatterer_testing::AddSceneLight(stage.Renderer, 0, 0, 0);
  pointless->SetFocalPoint(0, 0, 0);
  vtkLight* unattenuated = scatterer_testing::AddSceneLight(stage.Renderer, 16, 16, 60, 16, 16, 0);
  unattenuated->SetPositional(true);
  unattenuated->SetConeAngle(180.0);
  unattenuated->SetAttenuationValues(0, 0, 0);
  const auto with = stage.Render();
  EXPECT_TRUE(capture.Has("ignores 2 switched-on light(s) whose direction is undefined"))
    << capture.Window->Text;
  EXPECT_EQ(scatterer_testing::MaxDifference(good, with), 0);
}
