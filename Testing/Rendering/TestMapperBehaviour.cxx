// How vtkScattererTemplateVolumeMapper behaves as a drop-in: which shader code
// it generates for a scene, when it falls back to stock rendering (and says
// so once), that it rebuilds the shader only when the GLSL changes, that it
// leaves nothing behind on a volume, and that occlusion only ever darkens.
// Renders under X (CTest runs under xvfb-run); all tests share one window.
#include "ScattererErrorObserver.h"
#include "ScattererRenderHarness.h"
#include "ScattererShaderInstaller.h"
#include "ScattererTestVolumes.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRendererCollection.h"
#include "vtkRenderer.h"
#include "vtkScattererTemplateVolumeMapper.h"
#include "vtkScattererTransportVolume.h"
#include "vtkShader.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkLightCollection.h"
#include "vtkLightKit.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
constexpr int N = 48;

vtkRenderWindow* Window()
{
  return scatterer_testing::SharedWindow();
}

using scatterer_testing::ErrorCount;
using scatterer_testing::EventCounter;
using scatterer_testing::LastError;
using scatterer_testing::LastWarning;
using scatterer_testing::MaxDifference;
using scatterer_testing::MeanBrightness;
using scatterer_testing::WarningCount;

struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkVolumeProperty> Property;
  vtkSmartPointer<vtkImageData> Image;
  vtkNew<vtkScattererTemplateVolumeMapper> Mapper;
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> Stock;

  explicit Scene(bool twoMaterials = false, int lights = 1)
  {
    this->Image = scatterer_testing::MakeShellBallPlate(N, VTK_UNSIGNED_CHAR);
    scatterer_testing::ApplyShellBallPlateProperty(this->Property);
    if (twoMaterials)
    {
      // A gap in the opacity between shell and ball: two derived materials.
      vtkPiecewiseFunction* o = this->Property->GetScalarOpacity();
      o->RemoveAllPoints();
      o->AddPoint(0, 0);
      o->AddPoint(80, 0);
      o->AddPoint(100, 0.2);
      o->AddPoint(120, 0);
      o->AddPoint(170, 0);
      o->AddPoint(200, 0.9);
    }
    for (auto* m : { static_cast<vtkGPUVolumeRayCastMapper*>(this->Mapper),
           static_cast<vtkGPUVolumeRayCastMapper*>(this->Stock) })
    {
      m->SetInputData(this->Image);
      m->AutoAdjustSampleDistancesOff();
      m->SetSampleDistance(0.5);
    }
    this->Volume->SetProperty(this->Property);
    this->Volume->SetMapper(this->Mapper);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->AutomaticLightCreationOff();
    for (int l = 0; l < lights; ++l)
    {
      scatterer_testing::AddSceneLight(this->Renderer, 1.0, 0.4 - l, 0.8);
    }
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.5 * N, 0.5 * N, 0.5 * N);
    camera->SetPosition(2.2 * N, -0.9 * N, 1.4 * N);
    camera->SetViewUp(0, 0, 1);
    this->Renderer->ResetCameraClippingRange();
    Window()->GetRenderers()->RemoveAllItems();
    Window()->AddRenderer(this->Renderer);
  }
  ~Scene()
  {
    Window()->RemoveRenderer(this->Renderer);
    this->Mapper->ReleaseGraphicsResources(Window());
    this->Stock->ReleaseGraphicsResources(Window());
  }

  std::vector<unsigned char> Render() { return scatterer_testing::RenderAndGrab(Window()); }

  std::vector<unsigned char> RenderStock()
  {
    this->Volume->SetMapper(this->Stock);
    auto image = this->Render();
    this->Volume->SetMapper(this->Mapper);
    return image;
  }

  // Renders twice: the mapper must say once that it renders as stock, in a warning
  // that contains @p says, and draw exactly the stock mapper's picture.
  void ExpectStockWithOneWarning(const std::string& says)
  {
    vtkNew<vtkTest::ErrorObserver> warnings;
    this->Mapper->AddObserver(vtkCommand::WarningEvent, warnings);
    const auto first = this->Render();
    this->Render();
    EXPECT_EQ(WarningCount(warnings), 1u);
    EXPECT_NE(LastWarning(warnings).find(says), std::string::npos) << LastWarning(warnings);
    EXPECT_EQ(MaxDifference(first, this->RenderStock()), 0);
    this->Mapper->RemoveObserver(warnings);
  }

  // The illumination GLSL currently on the volume's shader property.
  std::string InstalledGLSL()
  {
    auto* sp = vtkOpenGLShaderProperty::SafeDownCast(this->Volume->GetShaderProperty());
    std::string text;
    for (const auto& r : sp->GetAllShaderReplacements())
    {
      text += r.second.Replacement;
    }
    return text;
  }
};

}

TEST(MapperBehaviour, OneMaterialSceneHasNoBoundaryOrBleedingCode)
{
  Scene scene;
  scene.Render();
  const std::string features = scene.Mapper->GetLastShaderFeatures();
  EXPECT_NE(features.find("materials=1"), std::string::npos) << features;
  EXPECT_EQ(features.find("boundary"), std::string::npos) << features;
  EXPECT_EQ(features.find("bleed"), std::string::npos) << features;
  const std::string glsl = scene.InstalledGLSL();
  EXPECT_NE(glsl.find("st_transport"), std::string::npos);
  EXPECT_EQ(glsl.find("st_speedRatio"), std::string::npos);
  EXPECT_EQ(glsl.find("st_matColor"), std::string::npos);
}

TEST(MapperBehaviour, TwoMaterialSceneGetsBoundaryAndBleeding)
{
  Scene scene(true);
  scene.Mapper->SetIlluminationModeToPerSample();
  scene.Render();
  const std::string features = scene.Mapper->GetLastShaderFeatures();
  EXPECT_NE(features.find("materials=2"), std::string::npos) << features;
  EXPECT_NE(features.find("boundary"), std::string::npos) << features;
  const std::string glsl = scene.InstalledGLSL();
  EXPECT_NE(glsl.find("st_speedRatio"), std::string::npos);
  EXPECT_NE(glsl.find("st_gatherTemplate"), std::string::npos);
}

TEST(MapperBehaviour, SwitchedOffEffectIsAbsentFromTheShader)
{
  Scene scene(true);
  scene.Mapper->SetIlluminationModeToPerSample();
  scene.Mapper->ShadowsEnabledOff();
  scene.Render();
  const std::string glsl = scene.InstalledGLSL();
  EXPECT_EQ(glsl.find("st_transmittance"), std::string::npos);
  EXPECT_EQ(glsl.find("st_longRange"), std::string::npos);
  EXPECT_EQ(scene.Mapper->GetLastShaderFeatures().find("shadow"), std::string::npos);
}

TEST(MapperBehaviour, AsRequestedKeepsCodeTheSceneDoesNotNeed)
{
  Scene scene;
  scene.Mapper->SetIlluminationModeToPerSample();
  scene.Mapper->SetLongRangeMultiple(1.0); // automatic: the thin check cannot help
  scene.Render();
  EXPECT_EQ(scene.Mapper->GetLastShaderFeatures().find("thin"), std::string::npos);
  scene.Mapper->SetShaderPathSelectionToAsRequested();
  scene.Render();
  EXPECT_NE(scene.Mapper->GetLastShaderFeatures().find("thin"), std::string::npos);
  EXPECT_NE(scene.InstalledGLSL().find("st_longRange"), std::string::npos);
}

TEST(MapperBehaviour, NoLightMeansNoIlluminationCodeAndStockPixels)
{
  Scene scene(false, 0);
  const auto ours = scene.Render();
  EXPECT_EQ(scene.Mapper->GetLastShaderFeatures(),
    "stock: no light is switched on with an intensity above 0");
  EXPECT_EQ(scatterer_shader::CountIlluminationLeftovers(scene.Volume), 0);
  EXPECT_EQ(MaxDifference(ours, scene.RenderStock()), 0);
}

TEST(MapperBehaviour, OtherBlendModesRenderAsStockWithOneWarning)
{
  Scene scene;
  scene.Mapper->SetBlendModeToMaximumIntensity();
  scene.Stock->SetBlendModeToMaximumIntensity();
  scene.ExpectStockWithOneWarning("maximum intensity");
}

TEST(MapperBehaviour, MultiComponentDataInPerSampleModeRendersAsStockWithOneWarning)
{
  // The per-sample photon test reads one scalar; the transport mode lights components.
  Scene scene;
  auto la = vtkSmartPointer<vtkImageData>::New();
  la->SetDimensions(N, N, N);
  la->AllocateScalars(VTK_UNSIGNED_CHAR, 2);
  auto* p = static_cast<unsigned char*>(la->GetScalarPointer());
  auto* s = static_cast<unsigned char*>(scene.Image->GetScalarPointer());
  for (int i = 0; i < N * N * N; ++i)
  {
    p[2 * i] = static_cast<unsigned char>(255 - s[i]);
    p[2 * i + 1] = s[i];
  }
  scene.Property->SetIndependentComponents(false);
  scene.Mapper->SetInputData(la);
  scene.Stock->SetInputData(la);
  scene.Mapper->SetIlluminationMode(vtkScattererTemplateVolumeMapper::PER_SAMPLE);
  scene.ExpectStockWithOneWarning("per-sample");
}

// The per-sample photon test reads the voxels as they are, so matter the picture hides
// would still cast shadows (a roof cropped away halved the light under it): with clipping
// planes, cropping (unless cropped matter is meant to cast shadows) or a gradient opacity
// that hides matter, that mode renders as stock and says why once.
TEST(MapperBehaviour, HiddenMatterInPerSampleModeRendersAsStockWithOneWarning)
{
  for (const std::string hide : { "clipping planes", "cropping", "gradient opacity" })
  {
    SCOPED_TRACE(hide);
    Scene scene;
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(0.5 * N, 0.5 * N, 0.5 * N);
    plane->SetNormal(-1.0, 0.3, 0.2);
    vtkNew<vtkPiecewiseFunction> gradientOpacity;
    gradientOpacity->AddPoint(0, 0.2);
    gradientOpacity->AddPoint(20, 1.0);
    for (auto* m : { static_cast<vtkGPUVolumeRayCastMapper*>(scene.Mapper),
           static_cast<vtkGPUVolumeRayCastMapper*>(scene.Stock) })
    {
      if (hide == "clipping planes")
      {
        m->AddClippingPlane(plane);
      }
      else if (hide == "cropping")
      {
        m->CroppingOn();
        m->SetCroppingRegionPlanes(0, 0.8 * N, 0, N, 0, 0.7 * N);
      }
    }
    if (hide == "gradient opacity")
    {
      scene.Property->SetGradientOpacity(gradientOpacity);
    }
    scene.Mapper->SetIlluminationMode(vtkScattererTemplateVolumeMapper::PER_SAMPLE);
    scene.ExpectStockWithOneWarning(hide + " in per-sample mode");
    if (hide == "cropping")
    {
      // Cropped matter meant to cast shadows (a piece's ghost voxels): lit.
      scene.Mapper->CroppedMatterCastsShadowsOn();
      scene.Render();
      EXPECT_EQ(scene.Mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos)
        << scene.Mapper->GetLastShaderFeatures();
    }
  }
}

// Per-sample mode classifies each photon's scalar into a material. For 8-bit data the ray
// caster's normalised scalar at the data's maximum comes out a little above 1, past the
// last material's range, and a ball at the data's maximum was left unlit (as stock). With
// one voxel of 255 in a corner (the same ball below the maximum) it was lit.
TEST(MapperBehaviour, PerSampleLightsMatterAtTheDataMaximum)
{
  const int n = 48;
  const auto render = [n](bool voxelAbove, bool stock)
  {
    auto image = scatterer_testing::MakeComponentVolume(n, 1,
      [n, voxelAbove](int i, int j, int k, int) -> unsigned char
      {
        const double r2 =
          (i - 24.0) * (i - 24.0) + (j - 24.0) * (j - 24.0) + (k - 30.0) * (k - 30.0);
        if (voxelAbove && i == 0 && j == 0 && k == n - 1)
        {
          return 255;
        }
        return r2 <= 64.0 ? 200 : (k >= 4 && k <= 6 ? 100 : 0);
      });
    vtkNew<vtkVolumeProperty> property;
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0, 0.0);
    opacity->AddPoint(50, 0.0);
    opacity->AddPoint(90, 0.6);
    opacity->AddPoint(255, 0.9);
    property->SetScalarOpacity(opacity);
    property->SetInterpolationTypeToNearest();
    vtkSmartPointer<vtkGPUVolumeRayCastMapper> mapper;
    if (stock)
    {
      mapper = vtkSmartPointer<vtkOpenGLGPUVolumeRayCastMapper>::New();
    }
    else
    {
      auto ours = vtkSmartPointer<vtkScattererTemplateVolumeMapper>::New();
      ours->SetIlluminationModeToPerSample();
      mapper = ours;
    }
    mapper->SetInputData(image);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    vtkNew<vtkRenderer> renderer;
    renderer->AddVolume(volume);
    scatterer_testing::LightAndViewBallAbovePlate(renderer, n);
    return scatterer_testing::RenderSceneOnce(renderer, mapper);
  };
  const auto atMaximum = render(false, false), belowMaximum = render(true, false);
  const auto stock = render(false, true);
  const auto same = scatterer_testing::CompareRgb(atMaximum, belowMaximum, 16);
  const auto lit = scatterer_testing::CompareRgb(atMaximum, stock, 16);
  std::printf("at the maximum against below it: mean %.2f, %.2f%% over 16; against stock: mean "
              "%.2f\n",
    same.Mean, 100.0 * same.FractionOver, lit.Mean);
  EXPECT_LT(same.FractionOver, 0.01) << "matter at the data's maximum is lit otherwise";
  EXPECT_GT(lit.Mean, 2.0) << "the scene is not lit at all: no test";
}

// A material derivation range where the opacity is 0 leaves no material for a volume
// that shows: it renders as stock, and says so once, naming the range (it said nothing,
// and its reason blamed the transfer function).
TEST(MapperBehaviour, DerivationRangeWithoutMatterRendersAsStockAndSaysWhy)
{
  Scene scene;
  scene.Mapper->SetMaterialDerivationRange(2, 5);
  scene.ExpectStockWithOneWarning("derivation range [2, 5]");
  EXPECT_NE(scene.Mapper->GetLastShaderFeatures().find("derivation range"), std::string::npos)
    << scene.Mapper->GetLastShaderFeatures();
}

TEST(MapperBehaviour, UniformOnlyChangesDoNotRebuildTheShader)
{
  for (int mode :
    { vtkScattererTemplateVolumeMapper::TRANSPORT, vtkScattererTemplateVolumeMapper::PER_SAMPLE })
  {
    Scene scene;
    scene.Mapper->SetIlluminationMode(mode);
    // VTK fires UpdateShaderEvent only on frames that reuse the shader.
    EventCounter reused(scene.Mapper, vtkCommand::UpdateShaderEvent);
    scene.Render();
    scene.Render();
    ASSERT_EQ(reused.Count, 1) << "mode " << mode;
    scene.Mapper->SetOcclusionStrength(0.5);
    scene.Mapper->SetPhotonThreshold(0.01);
    scene.Mapper->SetTemplateRadius(3.0);
    scene.Render();
    EXPECT_EQ(reused.Count, 2) << "a uniform-only change rebuilt the shader (mode " << mode << ")";
    // Shadows off: the photon test's code goes (per-sample); the transport volume is
    // rebuilt without attenuation and read by the same code (transport).
    const int builds = scene.Mapper->GetTransportVolume()->GetBuildCount();
    scene.Mapper->ShadowsEnabledOff();
    scene.Render();
    if (mode == vtkScattererTemplateVolumeMapper::PER_SAMPLE)
    {
      EXPECT_EQ(reused.Count, 2)
        << "switching the photon test's shadows off must change the shader";
    }
    else
    {
      EXPECT_EQ(reused.Count, 3) << "switching the transport's shadows off rebuilt the shader";
      EXPECT_EQ(scene.Mapper->GetTransportVolume()->GetBuildCount(), builds + 1)
        << "switching the transport's shadows off did not rebuild its light";
    }
  }
}

TEST(MapperBehaviour, ShadowsOffKeepTheMultipleScattering)
{
  // One material (no bleeding or boundary code): with shadows off the transport volume
  // still carries the light scattered in the medium, an effect of its own; with that
  // off too there is none, and the volume renders as stock. Shadows off used to mean
  // stock whatever the multiple scattering (the viewer's 's' key turned all lighting off).
  Scene scene;
  scene.Mapper->ShadowsEnabledOff();
  const auto scattered = scene.Render();
  const std::string features = scene.Mapper->GetLastShaderFeatures();
  EXPECT_EQ(features.rfind("transport", 0), 0u) << features;
  scene.Mapper->SetMultipleScattering(0.0);
  const auto none = scene.Render();
  EXPECT_EQ(scene.Mapper->GetLastShaderFeatures(), "stock: no illumination effect is switched on");
  EXPECT_EQ(MaxDifference(none, scene.RenderStock()), 0);
  EXPECT_GT(MaxDifference(scattered, none), 20) << "the multiple scattering shows nothing";
}

TEST(MapperBehaviour, VolumeGivenToAnotherMapperKeepsNoLeftovers)
{
  Scene scene;
  scene.Render();
  ASSERT_GT(scatterer_shader::CountIlluminationLeftovers(scene.Volume), 0);
  scene.Volume->SetMapper(scene.Stock);
  EXPECT_EQ(scatterer_shader::CountIlluminationLeftovers(scene.Volume), 0);
  const auto afterSwitch = scene.Render();
  // A fresh volume with the stock mapper draws the same picture.
  vtkNew<vtkVolume> fresh;
  fresh->SetProperty(scene.Property);
  fresh->SetMapper(scene.Stock);
  scene.Renderer->RemoveVolume(scene.Volume);
  scene.Renderer->AddVolume(fresh);
  EXPECT_EQ(MaxDifference(afterSwitch, scene.Render()), 0);
}

TEST(MapperBehaviour, IlluminationOffLeavesNoLeftovers)
{
  Scene scene;
  scene.Render();
  scene.Mapper->IlluminationEnabledOff();
  const auto off = scene.Render();
  EXPECT_EQ(scatterer_shader::CountIlluminationLeftovers(scene.Volume), 0);
  EXPECT_EQ(MaxDifference(off, scene.RenderStock()), 0);
}

TEST(MapperBehaviour, ReleaseGraphicsResourcesThenRenderGivesTheSamePicture)
{
  Scene scene;
  const auto before = scene.Render();
  scene.Mapper->ReleaseGraphicsResources(Window());
  const auto after = scene.Render();
  EXPECT_EQ(MaxDifference(before, after), 0);
}

TEST(MapperBehaviour, WindowResizeKeepsRendering)
{
  Scene scene;
  scene.Render();
  Window()->SetSize(120, 90);
  const auto small = scene.Render();
  Window()->SetSize(160, 160);
  EXPECT_EQ(small.size(), 120u * 90u * 4u);
  EXPECT_GT(MeanBrightness(small), 5.0);
  EXPECT_EQ(scene.Mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos);
}

TEST(MapperBehaviour, ShaderThatFailsToCompileFallsBackToStockWithAnError)
{
  Scene scene;
  scene.Mapper->SetExtraShaderCodeForTesting("this is not GLSL;\n");
  vtkNew<vtkTest::ErrorObserver> errors;
  scene.Mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  const auto image = scene.Render();
  EXPECT_GE(ErrorCount(errors), 1u);
  EXPECT_NE(LastError(errors).find("failed to compile"), std::string::npos) << LastError(errors);
  EXPECT_EQ(scene.Mapper->GetLastShaderFeatures().rfind("stock", 0), 0u);
  EXPECT_EQ(MaxDifference(image, scene.RenderStock()), 0);
}

TEST(MapperBehaviour, OcclusionOnlyEverDarkens)
{
  for (int mode :
    { vtkScattererTemplateVolumeMapper::TRANSPORT, vtkScattererTemplateVolumeMapper::PER_SAMPLE })
  {
    Scene scene(true);
    scene.Mapper->SetIlluminationMode(mode);
    scene.Mapper->ColorBleedingEnabledOff();
    scene.Mapper->SetOcclusionStrength(0.0);
    const auto open = scene.Render();
    scene.Mapper->SetOcclusionStrength(1.0);
    const auto occluded = scene.Render();
    int brighter = 0;
    for (size_t i = 0; i < open.size(); ++i)
    {
      brighter += int(occluded[i]) > int(open[i]) + 1 ? 1 : 0;
    }
    EXPECT_EQ(brighter, 0) << "mode " << mode;
    EXPECT_LT(MeanBrightness(occluded), MeanBrightness(open) - 1.0) << "mode " << mode;
  }
}

TEST(MapperBehaviour, SeveralVolumesAndRenderersRender)
{
  Scene left(true);
  Scene right;
  left.Renderer->SetViewport(0, 0, 0.5, 1);
  right.Renderer->SetViewport(0.5, 0, 1, 1);
  Window()->AddRenderer(left.Renderer);
  const auto image = right.Render();
  EXPECT_EQ(left.Mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos);
  EXPECT_EQ(right.Mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos);
  EXPECT_GT(MeanBrightness(image), 5.0);
}

// Illumination changes colours, never what is drawn where: with cropping, a
// clipping plane and opaque geometry cutting the volume, the pixels covered
// by the volume (and hidden by the geometry) are the stock mapper's.
TEST(MapperBehaviour, CroppingClippingAndOpaqueGeometryCoverTheSamePixelsAsStock)
{
  Scene scene(true);
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.5 * N, 0.5 * N, 0.5 * N);
  plane->SetNormal(-1.0, 0.3, 0.2);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.7 * N, 0.5 * N, 0.5 * N);
  sphere->SetRadius(0.25 * N);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(sphereMapper);
  actor->GetProperty()->SetColor(0.2, 0.8, 0.3);
  scene.Renderer->AddActor(actor);
  scene.Renderer->SetBackground(0.1, 0.1, 0.2);
  for (auto* m : { static_cast<vtkGPUVolumeRayCastMapper*>(scene.Mapper),
         static_cast<vtkGPUVolumeRayCastMapper*>(scene.Stock) })
  {
    m->AddClippingPlane(plane);
    m->CroppingOn();
    m->SetCroppingRegionPlanes(0, 0.8 * N, 0, N, 0, 0.7 * N);
    m->SetCroppingRegionFlagsToSubVolume();
  }
  const auto ours = scene.Render();
  ASSERT_EQ(scene.Mapper->GetLastShaderFeatures().rfind("stock", 0), std::string::npos)
    << scene.Mapper->GetLastShaderFeatures();
  const auto stock = scene.RenderStock();
  const unsigned char bg[3] = { 26, 26, 51 };
  auto covered = [&](const std::vector<unsigned char>& img, size_t i)
  {
    return std::abs(img[i] - bg[0]) + std::abs(img[i + 1] - bg[1]) + std::abs(img[i + 2] - bg[2]) >
      6;
  };
  size_t differ = 0, coveredCount = 0, geometrySame = 0, geometry = 0;
  for (size_t i = 0; i < stock.size(); i += 4)
  {
    coveredCount += covered(stock, i) ? 1 : 0;
    differ += covered(stock, i) != covered(ours, i) ? 1 : 0;
    // Opaque green sphere pixels in front of the volume are untouched.
    if (stock[i + 1] > 150 && stock[i] < 90 && stock[i + 2] < 110)
    {
      ++geometry;
      geometrySame +=
        (stock[i] == ours[i] && stock[i + 1] == ours[i + 1] && stock[i + 2] == ours[i + 2]) ? 1 : 0;
    }
  }
  EXPECT_GT(coveredCount, stock.size() / 4 / 20) << "the scene shows nothing";
  EXPECT_LT(differ, stock.size() / 4 / 200) << differ << " pixels covered differently from stock";
  EXPECT_GT(geometry, 100u) << "the sphere is not visible";
  EXPECT_EQ(geometrySame, geometry) << "pixels of the opaque sphere changed";
}

TEST(MapperBehaviour, HeadlightShinesFromTheCameraWhetherOrNotTheRendererMovesIt)
{
  // A headlight sits at the camera (vtkLight). The renderer moves it there only while
  // LightFollowCamera is on; VTK 9.1's ray caster lights a lone headlight from the camera
  // either way. With following switched off, the light came from where the headlight
  // was last placed (or from vtkLight's default place, had it never been).
  const auto addHeadlight = [](Scene& scene)
  {
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    scene.Renderer->AddLight(headlight);
  };
  Scene scene(false, 0);
  addHeadlight(scene);
  const auto before = scene.Render();
  scene.Renderer->LightFollowCameraOff();
  scene.Renderer->GetActiveCamera()->Azimuth(70);
  scene.Renderer->ResetCameraClippingRange();
  const auto notFollowing = scene.Render();
  scene.Renderer->LightFollowCameraOn();
  const auto following = scene.Render();
  EXPECT_LE(MaxDifference(notFollowing, following), 1)
    << "the headlight stayed where the renderer last put it";
  EXPECT_GT(MaxDifference(before, following), 40) << "the camera's turn changes nothing: no test";

  Scene fresh(false, 0);
  addHeadlight(fresh);
  fresh.Renderer->LightFollowCameraOff();
  fresh.Renderer->GetActiveCamera()->Azimuth(70);
  fresh.Renderer->ResetCameraClippingRange();
  EXPECT_LE(MaxDifference(fresh.Render(), following), 1)
    << "a headlight never placed by the renderer shines from vtkLight's default place";
}

TEST(MapperBehaviour, OneVolumeShownInTwoWindowsIsLitInEach)
{
  // One volume (one mapper) in two windows, rendered in turn: each frame is the picture
  // a single window shows. In per-sample mode the frame after each switch of window was
  // drawn unlit (the template texture made for the new window was released mid-frame,
  // when the ray caster let the old window go).
  for (const bool perSample : { true, false })
  {
    Scene scene(false, 1);
    if (perSample)
    {
      scene.Mapper->SetIlluminationModeToPerSample();
    }
    const auto single = scene.Render();
    vtkNew<vtkRenderWindow> other;
    other->SetSize(Window()->GetSize());
    other->SetMultiSamples(0);
    vtkNew<vtkRenderer> renderer;
    renderer->AutomaticLightCreationOff();
    renderer->AddLight(vtkLight::SafeDownCast(scene.Renderer->GetLights()->GetItemAsObject(0)));
    renderer->SetActiveCamera(scene.Renderer->GetActiveCamera());
    renderer->AddVolume(scene.Volume);
    other->AddRenderer(renderer);
    int worst = 0;
    for (int frame = 0; frame < 2; ++frame)
    {
      worst = std::max(worst, MaxDifference(scatterer_testing::RenderAndGrab(other), single));
      worst = std::max(worst, MaxDifference(scene.Render(), single));
    }
    EXPECT_LE(worst, 1) << (perSample ? "per-sample" : "transport")
                        << ": a frame after a switch of window is not the single window's";
    EXPECT_NE(scene.Mapper->GetLastShaderFeatures().rfind("stock", 0), 0u)
      << scene.Mapper->GetLastShaderFeatures();
    scene.Mapper->ReleaseGraphicsResources(other);
  }
}

TEST(MapperBehaviour, LightKitLightsTheVolumeWithEveryLight)
{
  // ParaView's default lighting: vtkLightKit's key, fill and back lights, which follow
  // the camera. The transport volume carries each of them.
  Scene scene(false, 0);
  vtkNew<vtkLightKit> kit;
  kit->AddLightsToRenderer(scene.Renderer);
  const int lights = scene.Renderer->GetLights()->GetNumberOfItems();
  ASSERT_GE(lights, 3);
  const auto all = scene.Render();
  const std::string features = scene.Mapper->GetLastShaderFeatures();
  EXPECT_EQ(features.rfind("transport lights=" + std::to_string(lights), 0), 0u) << features;
  const auto stock = scene.RenderStock();
  int blackHoles = 0;
  for (size_t i = 0; i < all.size(); i += 4)
  {
    const bool shown = std::max({ stock[i], stock[i + 1], stock[i + 2] }) >= 24;
    blackHoles += shown && std::max({ all[i], all[i + 1], all[i + 2] }) == 0 ? 1 : 0;
  }
  EXPECT_EQ(blackHoles, 0) << "pixels the stock mapper shows came out black";
  // The key light alone gives less light than the whole kit.
  vtkCollectionSimpleIterator it;
  vtkLight* light = nullptr;
  int index = 0;
  for (scene.Renderer->GetLights()->InitTraversal(it);
       (light = scene.Renderer->GetLights()->GetNextLight(it));)
  {
    light->SetSwitch(index++ == 0);
  }
  const auto key = scene.Render();
  EXPECT_LT(MeanBrightness(key) + 2.0, MeanBrightness(all))
    << "the kit's other lights add no light";
}

TEST(MapperBehaviour, WithShadeOnABrighterLightNeverDarkensThePicture)
{
  // Shade on: VTK's Phong colour (which carries the light's intensity, clamped to 1)
  // times the light's visibility. The visibility is a ratio and must not pass through the
  // highlight knee, which made it fall as 1 / intensity (intensity 1000: a black frame).
  for (int mode :
    { vtkScattererTemplateVolumeMapper::TRANSPORT, vtkScattererTemplateVolumeMapper::PER_SAMPLE })
  {
    Scene scene;
    scene.Mapper->SetIlluminationMode(mode);
    scene.Property->ShadeOn();
    vtkLight* light = vtkLight::SafeDownCast(scene.Renderer->GetLights()->GetItemAsObject(0));
    double previous = 0.0;
    for (double intensity : { 1.0, 2.0, 10.0, 1000.0 })
    {
      light->SetIntensity(intensity);
      const double mean = MeanBrightness(scene.Render());
      EXPECT_GE(mean, previous - 0.5) << "mode " << mode << ", intensity " << intensity;
      previous = mean;
    }
    const double stock = MeanBrightness(scene.RenderStock());
    std::cout << "mode " << mode << ": intensity 1000 " << previous << ", stock " << stock << "\n";
    EXPECT_GT(previous, 0.5 * stock) << "mode " << mode;
  }
}

// A ball of radius 40 with a soft edge, over a cube 96 long, sampled at `spacing`: the
// same object whatever the voxels' shape.
vtkSmartPointer<vtkImageData> SampledBall(const double spacing[3])
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  int dims[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = static_cast<int>(96.0 / spacing[a] + 0.5) + 1;
  }
  image->SetDimensions(dims);
  image->SetSpacing(spacing[0], spacing[1], spacing[2]);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* v = static_cast<float*>(image->GetScalarPointer());
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
      {
        const double x = i * spacing[0] - 48, y = j * spacing[1] - 48, z = k * spacing[2] - 48;
        const double r = std::sqrt(x * x + y * y + z * z);
        *v++ = static_cast<float>(std::min(std::max((40.0 - r) * 40.0 + 100.0, 0.0), 1000.0));
      }
  return image;
}

// The scene's two mappers on SampledBall(spacing), opaque from the value 600 on (0.8 per
// unit, none below 300), seen from above at an angle.
void ShowSampledBall(Scene& scene, const double spacing[3])
{
  scene.Image = SampledBall(spacing);
  scene.Mapper->SetInputData(scene.Image);
  scene.Stock->SetInputData(scene.Image);
  vtkPiecewiseFunction* opacity = scene.Property->GetScalarOpacity();
  opacity->RemoveAllPoints();
  opacity->AddPoint(0, 0);
  opacity->AddPoint(300, 0);
  opacity->AddPoint(600, 0.8);
  opacity->AddPoint(1000, 0.9);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(48, 48, 48);
  camera->SetPosition(48, -122, 178);
  scene.Renderer->ResetCameraClippingRange();
}

TEST(MapperBehaviour, TheSameSceneInAnotherLengthUnitIsLitAlike)
{
  // The scene in metres or micrometres rather than its unit: spacing, opacity unit
  // distance, sample distance and camera scaled alike. The stock ray caster draws the
  // same picture; the transport stored extinctions in world units at half precision, out
  // of its range at these scales, and lost its multiple scattering (micro-CT in metres).
  std::vector<unsigned char> reference;
  for (double s : { 1.0, 1e-3, 1e-6, 1e6 })
  {
    Scene scene;
    scene.Image->SetSpacing(s, s, s);
    scene.Property->SetScalarOpacityUnitDistance(
      scene.Property->GetScalarOpacityUnitDistance() * s);
    scene.Mapper->SetSampleDistance(0.5 * s);
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.5 * N * s, 0.5 * N * s, 0.5 * N * s);
    camera->SetPosition(2.2 * N * s, -0.9 * N * s, 1.4 * N * s);
    scene.Renderer->ResetCameraClippingRange();
    const auto image = scene.Render();
    if (s == 1.0)
    {
      reference = image;
      continue;
    }
    EXPECT_LE(MaxDifference(image, reference), 8) << "scale " << s;
    EXPECT_NEAR(MeanBrightness(image), MeanBrightness(reference), 0.2) << "scale " << s;
  }
}

TEST(MapperBehaviour, NonCubicVoxelsAreLitAsTheSameObjectInCubicOnes)
{
  // An MRI's voxels three times as long along one axis (z, then x) against cubic ones. At
  // scale 2 the long axis had transport texels 6 voxels of the short axes long and
  // diffusion texels 12: the ball showed rings and turned red (docs/model.md, "Its
  // grid"). The stock ray caster's own difference between the samplings is the floor.
  std::vector<unsigned char> lit[3], stock[3];
  const double spacings[3][3] = { { 1.5, 1.5, 1.5 }, { 1.5, 1.5, 4.5 }, { 4.5, 1.5, 1.5 } };
  for (int s = 0; s < 3; ++s)
  {
    Scene scene;
    ShowSampledBall(scene, spacings[s]);
    vtkColorTransferFunction* colour = scene.Property->GetRGBTransferFunction();
    colour->RemoveAllPoints();
    colour->AddRGBPoint(0, 1, 0.9, 0.8);
    colour->AddRGBPoint(1000, 1, 0.95, 0.9);
    lit[s] = scene.Render();
    stock[s] = scene.RenderStock();
  }
  for (int s = 1; s < 3; ++s)
  {
    const auto e = scatterer_testing::CompareWays(
      s == 1 ? "long z voxels" : "long x voxels", lit[0], lit[s], stock[0], stock[s]);
    // With the same strides on every axis: means 10.1 and 5.9, worst 172 and 158; with
    // texels and diffusion texels about as long along the long axis: 2.4 and 2.1, worst
    // 89 and 63 (the rest: the sweep's axis and the ray's samples along the long voxels).
    EXPECT_GT(e.Illumination.Mean, 5.0); // lit at all
    EXPECT_LT(e.Lit.Mean, 3.5);
    EXPECT_LT(e.Lit.Worst, 120);
  }
}

TEST(MapperBehaviour, FramesDraggedWithLongerStepsReadTheLightAtEverySample)
{
  // VTK's default AutoAdjustSampleDistances lengthens the ray's step while the user drags,
  // by 2 / its reduction factor (here at its floor, 1 / MaximumImageSampleDistance: 8 times
  // the still step). Reads of the light planned for the still step, 2 samples ahead, then
  // lay 2 texels deep in the ball: the dragged frame 2.15 levels from the still frame on
  // average, up to 103; every sample reading the light, 1.25 and 53, the rest the long
  // step's own (its first sample in the ball lies deeper; stock changes by 0.17).
  const double cubic[3] = { 1.5, 1.5, 1.5 };
  Scene scene;
  ShowSampledBall(scene, cubic);
  for (auto* m : { static_cast<vtkGPUVolumeRayCastMapper*>(scene.Mapper),
         static_cast<vtkGPUVolumeRayCastMapper*>(scene.Stock) })
  {
    m->AutoAdjustSampleDistancesOn();
    m->SetMaximumImageSampleDistance(4);
  }
  const double still = Window()->GetDesiredUpdateRate();
  const auto stillStock = scene.RenderStock();
  const auto stillImage = scene.Render();
  // Still: 1.5 mm steps (the voxel) against 3 mm texels.
  EXPECT_NE(scene.Mapper->GetLastShaderFeatures().find("light-stride=2"), std::string::npos)
    << scene.Mapper->GetLastShaderFeatures();
  Window()->SetDesiredUpdateRate(1000.0);
  std::vector<unsigned char> dragged, draggedStock;
  for (int frame = 0; frame < 5; ++frame) // the reduction settles at its floor
  {
    dragged = scene.Render();
  }
  const std::string features = scene.Mapper->GetLastShaderFeatures();
  for (int frame = 0; frame < 5; ++frame)
  {
    draggedStock = scene.RenderStock();
  }
  Window()->SetDesiredUpdateRate(still);
  EXPECT_EQ(features.find("light-stride"), std::string::npos) << features;
  const auto d = scatterer_testing::CompareRgb(stillImage, dragged, 16);
  const auto ds = scatterer_testing::CompareRgb(stillStock, draggedStock, 16);
  std::printf("dragged vs still: mean %.3f, worst %d (stock: %.3f, %d)\n", d.Mean, d.Worst, ds.Mean,
    ds.Worst);
  EXPECT_LT(d.Mean, 1.7);
  EXPECT_LT(d.Worst, 80);
  // And the next still frame is the still frame again.
  EXPECT_LE(MaxDifference(scene.Render(), stillImage), 2);
}
