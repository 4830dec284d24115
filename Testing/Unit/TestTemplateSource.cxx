// vtkScattererTemplateSource: the output is the core's templates point for point,
// with the documented arrays; progress is reported; templates survive a save/load
// round trip bit for bit; bad files and invalid materials give an error (with a
// message that says what) and never a crash; the settings clamp and reject NaN.
// (vtkScattererMaterial's own tests are in TestMaterial.cxx.)
#include "vtkScattererTemplateSource.h"

#include "ScattererErrorObserver.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkScattererMaterial.h"
#include "vtkStringArray.h"
#include "vtkTestErrorObserver.h"

#include <scatterer/Template.h>
#include <scatterer/TemplateIO.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();

using scatterer_testing::ErrorCount;
using scatterer_testing::ErrorMentions;
using scatterer_testing::WatchErrors;

// Records every ProgressEvent value.
struct ProgressRecorder
{
  std::vector<double> Values;
  vtkNew<vtkCallbackCommand> Command;
  explicit ProgressRecorder(vtkAlgorithm* algorithm)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* client, void* call)
      { static_cast<ProgressRecorder*>(client)->Values.push_back(*static_cast<double*>(call)); });
    this->Algorithm = algorithm;
    this->Tag = algorithm->AddObserver(vtkCommand::ProgressEvent, this->Command);
  }
  ~ProgressRecorder() { this->Algorithm->RemoveObserver(this->Tag); }
  // Values strictly between 0 and 1: the executive itself reports 0 and 1 around
  // every execution, so only these show work done by the source.
  std::size_t Intermediate() const
  {
    std::size_t n = 0;
    for (double v : this->Values)
    {
      n += (v > 0.0 && v < 1.0) ? 1 : 0;
    }
    return n;
  }
  ProgressRecorder(const ProgressRecorder&) = delete;
  ProgressRecorder& operator=(const ProgressRecorder&) = delete;
  vtkSmartPointer<vtkAlgorithm> Algorithm;
  unsigned long Tag = 0;
};

vtkSmartPointer<vtkScattererMaterial> ToVtk(const scatterer::Material& m)
{
  auto material = vtkSmartPointer<vtkScattererMaterial>::New();
  material->SetName(m.name.c_str());
  material->SetOpacity(m.opacity);
  material->SetRefractiveIndex(m.refractiveIndex);
  material->SetDiffuseColor(m.diffuse.r, m.diffuse.g, m.diffuse.b);
  if (m.selector.kind == scatterer::Selector::Kind::Label)
  {
    material->SetLabel(m.selector.label);
  }
  else
  {
    material->SetScalarRange(m.selector.lo, m.selector.hi);
  }
  return material;
}

vtkSmartPointer<vtkScattererTemplateSource> SourceFor(
  const std::vector<scatterer::Material>& materials, const scatterer::GeneratorSettings& s)
{
  auto source = vtkSmartPointer<vtkScattererTemplateSource>::New();
  for (const auto& m : materials)
  {
    source->AddMaterial(ToVtk(m));
  }
  source->SetTemplatesPerMaterial(s.templatesPerMaterial);
  source->SetInitialLights(s.initialLights);
  source->SetThreshold(s.threshold);
  source->SetSeed(s.seed);
  return source;
}

std::uint32_t Bits(float v)
{
  std::uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// Every point, array value and cell of @p a equals @p b bit for bit.
void ExpectIdentical(vtkPolyData* a, vtkPolyData* b)
{
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfVerts(), b->GetNumberOfVerts());
  auto* pa = vtkFloatArray::SafeDownCast(a->GetPoints()->GetData());
  auto* pb = vtkFloatArray::SafeDownCast(b->GetPoints()->GetData());
  ASSERT_TRUE(pa && pb);
  EXPECT_EQ(0,
    std::memcmp(pa->GetPointer(0), pb->GetPointer(0),
      sizeof(float) * 3 * static_cast<std::size_t>(a->GetNumberOfPoints())));
  for (const char* name : { "Intensity", "TemplateId", "MaterialId" })
  {
    auto* xa = a->GetPointData()->GetArray(name);
    auto* xb = b->GetPointData()->GetArray(name);
    ASSERT_TRUE(xa && xb) << name;
    ASSERT_EQ(xa->GetDataType(), xb->GetDataType()) << name;
    ASSERT_EQ(xa->GetNumberOfTuples(), xb->GetNumberOfTuples()) << name;
    EXPECT_EQ(0,
      std::memcmp(xa->GetVoidPointer(0), xb->GetVoidPointer(0),
        static_cast<std::size_t>(xa->GetNumberOfTuples()) * xa->GetDataTypeSize()))
      << name;
  }
}

class TemplateSourceTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    Dir = fs::temp_directory_path() / ("scatterer-source-" + std::string(info->name()));
    fs::remove_all(Dir);
    fs::create_directories(Dir);
  }
  void TearDown() override { fs::remove_all(Dir); }
  std::string Path(const std::string& name) const { return (Dir / name).string(); }
  fs::path Dir;
};
}

// The output is scatterer::generateAllTemplates for the same inputs: the same
// photons, in the same order, bit for bit (so the same count).
TEST_F(TemplateSourceTest, OutputIsTheCoresTemplates)
{
  const auto materials = scatterer::exampleTissueMaterials();
  scatterer::GeneratorSettings defaults;
  scatterer::GeneratorSettings custom;
  custom.templatesPerMaterial = 3;
  custom.initialLights = 2;
  custom.threshold = 0.02;
  custom.seed = 12345;
  for (const auto& settings : { defaults, custom })
  {
    auto source = SourceFor(materials, settings);
    source->Update();
    vtkPolyData* out = source->GetOutput();
    const auto core = scatterer::generateAllTemplates(materials, settings);

    vtkIdType expected = 0;
    for (const auto& perMaterial : core)
      for (const auto& t : perMaterial)
        expected += static_cast<vtkIdType>(t.photons.size());
    ASSERT_GT(expected, 0);
    ASSERT_EQ(out->GetNumberOfPoints(), expected);
    EXPECT_EQ(out->GetNumberOfVerts(), expected);
    EXPECT_EQ(source->GetNumberOfPhotons(), expected);
    EXPECT_EQ(source->GetNumberOfTemplates(),
      static_cast<int>(materials.size()) * settings.templatesPerMaterial);
    EXPECT_GE(source->GetMaxLedgerResidual(), 0.0);
    EXPECT_LT(source->GetMaxLedgerResidual(), 1e-9);
    EXPECT_EQ(source->GetNumberOfCappedTemplates(), 0);

    auto* intensity = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("Intensity"));
    ASSERT_TRUE(intensity);
    vtkIdType id = 0;
    for (const auto& perMaterial : core)
      for (const auto& t : perMaterial)
        for (const auto& photon : t.photons)
        {
          double p[3];
          out->GetPoint(id, p);
          ASSERT_EQ(Bits(static_cast<float>(p[0])), Bits(photon.position.x)) << id;
          ASSERT_EQ(Bits(static_cast<float>(p[1])), Bits(photon.position.y)) << id;
          ASSERT_EQ(Bits(static_cast<float>(p[2])), Bits(photon.position.z)) << id;
          ASSERT_EQ(Bits(intensity->GetValue(id)), Bits(photon.intensity)) << id;
          ++id;
        }
  }
}

TEST_F(TemplateSourceTest, ArraysHaveTypesRangesAndSortedIntensities)
{
  const auto materials = scatterer::exampleTissueMaterials();
  auto source = SourceFor(materials, scatterer::GeneratorSettings());
  source->SetTemplatesPerMaterial(5);
  source->Update();
  vtkPolyData* out = source->GetOutput();
  const vtkIdType n = out->GetNumberOfPoints();
  ASSERT_GT(n, 0);

  auto* intensity = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("Intensity"));
  auto* templateId = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("TemplateId"));
  auto* materialId = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("MaterialId"));
  ASSERT_TRUE(intensity) << "Intensity must be a vtkFloatArray";
  ASSERT_TRUE(templateId) << "TemplateId must be a vtkIntArray";
  ASSERT_TRUE(materialId) << "MaterialId must be a vtkIntArray";
  EXPECT_EQ(out->GetPointData()->GetScalars(), intensity);
  ASSERT_EQ(intensity->GetNumberOfTuples(), n);
  ASSERT_EQ(templateId->GetNumberOfTuples(), n);
  ASSERT_EQ(materialId->GetNumberOfTuples(), n);

  auto* names = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("MaterialName"));
  ASSERT_TRUE(names);
  ASSERT_EQ(names->GetNumberOfValues(), 4);
  EXPECT_EQ(names->GetValue(3), materials[3].name);

  std::vector<int> seen(4 * 5, 0);
  double stored[4 * 5] = {};
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int m = materialId->GetValue(i);
    const int t = templateId->GetValue(i);
    ASSERT_GE(m, 0);
    ASSERT_LT(m, 4);
    ASSERT_GE(t, 0);
    ASSERT_LT(t, 5);
    const float v = intensity->GetValue(i);
    ASSERT_GT(v, 0.0f) << i;
    ASSERT_LE(v, 1.0f) << i;
    double p[3];
    out->GetPoint(i, p);
    ASSERT_LE(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0 + 1e-5) << i;
    ++seen[m * 5 + t];
    stored[m * 5 + t] += v;
    if (i > 0)
    {
      const int pm = materialId->GetValue(i - 1);
      const int pt = templateId->GetValue(i - 1);
      // Templates are contiguous blocks in (material, template) order ...
      ASSERT_TRUE(pm < m || (pm == m && pt <= t)) << i;
      // ... and sorted by descending intensity within a block.
      if (pm == m && pt == t)
      {
        ASSERT_GE(intensity->GetValue(i - 1), v) << "not sorted at point " << i;
      }
    }
  }
  for (int k = 0; k < 4 * 5; ++k)
  {
    EXPECT_GT(seen[k], 0) << "template " << k << " has no photons";
    // A template's photons hold its stored energy: a fraction of 1.
    EXPECT_GT(stored[k], 0.3) << k;
    EXPECT_LT(stored[k], 1.0) << k;
  }
  // One vertex cell per point.
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  out->GetVerts()->GetCellAtId(n - 1, npts, pts);
  EXPECT_EQ(npts, 1);
  EXPECT_EQ(pts[0], n - 1);
}

TEST_F(TemplateSourceTest, TemplateRadiusScalesWithoutRegenerating)
{
  auto source = SourceFor(scatterer::exampleTissueMaterials(), scatterer::GeneratorSettings());
  source->Update();
  vtkNew<vtkPolyData> unit;
  unit->DeepCopy(source->GetOutput());

  ProgressRecorder progress(source);
  source->SetTemplateRadius(2.5);
  EXPECT_EQ(source->GetTemplateRadius(), 2.5);
  source->Update();
  vtkPolyData* scaled = source->GetOutput();
  ASSERT_EQ(scaled->GetNumberOfPoints(), unit->GetNumberOfPoints());
  EXPECT_EQ(progress.Intermediate(), 0u) << "a new radius must not regenerate the templates";
  for (vtkIdType i = 0; i < unit->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    unit->GetPoint(i, a);
    scaled->GetPoint(i, b);
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_EQ(static_cast<float>(b[c]), static_cast<float>(a[c] * 2.5)) << i;
    }
  }

  vtkNew<vtkTest::ErrorObserver> errors;
  WatchErrors(source, errors);
  for (double bad : { 0.0, -1.0, kNaN, std::numeric_limits<double>::infinity() })
  {
    errors->Clear();
    source->SetTemplateRadius(bad);
    EXPECT_TRUE(ErrorMentions(errors, "SetTemplateRadius")) << bad;
    EXPECT_EQ(source->GetTemplateRadius(), 2.5);
  }
}

TEST_F(TemplateSourceTest, ProgressEventsAreFiredAndEndAtOne)
{
  auto source = SourceFor(scatterer::exampleTissueMaterials(), scatterer::GeneratorSettings());
  ProgressRecorder progress(source);
  source->Update();
  const int templates = 4 * 8;
  ASSERT_EQ(source->GetNumberOfTemplates(), templates);
  // One event per template: 1/32, 2/32, ..., 31/32 in between, then 1.
  ASSERT_GE(progress.Intermediate(), static_cast<std::size_t>(templates - 1));
  EXPECT_EQ(progress.Values.back(), 1.0);
  for (std::size_t i = 1; i < progress.Values.size(); ++i)
  {
    EXPECT_GE(progress.Values[i], progress.Values[i - 1]) << "progress went back at event " << i;
  }
  EXPECT_GE(progress.Values.front(), 0.0);
  EXPECT_LT(progress.Values.front(), 0.5);

  // Settings change -> regenerated, with progress again.
  progress.Values.clear();
  source->SetSeed(7);
  source->Update();
  EXPECT_GE(progress.Intermediate(), static_cast<std::size_t>(templates - 1));
  ASSERT_FALSE(progress.Values.empty());
  EXPECT_EQ(progress.Values.back(), 1.0);

  // Outside the pipeline (SaveTemplates generates on its own) there is no
  // executive to add 0 and 1: the source itself reports 0, 1/32, ..., 32/32.
  {
    auto fresh = SourceFor(scatterer::exampleTissueMaterials(), scatterer::GeneratorSettings());
    ProgressRecorder own(fresh);
    ASSERT_TRUE(fresh->SaveTemplates(Path("progress.scattpl").c_str()));
    ASSERT_EQ(own.Values.size(), static_cast<std::size_t>(templates + 1));
    for (int k = 0; k <= templates; ++k)
    {
      EXPECT_DOUBLE_EQ(own.Values[static_cast<std::size_t>(k)], double(k) / templates) << k;
    }
    EXPECT_EQ(own.Values.back(), 1.0);
  }

  // A material change regenerates too (the source's MTime includes the materials).
  progress.Values.clear();
  const vtkIdType before = source->GetOutput()->GetNumberOfPoints();
  source->GetMaterial(0)->SetOpacity(0.9);
  source->Update();
  EXPECT_GE(progress.Intermediate(), static_cast<std::size_t>(templates - 1));
  EXPECT_NE(source->GetOutput()->GetNumberOfPoints(), before);
}

// AbortExecute (set from a progress observer) stops generation: an empty output
// and no error; the next update after a change generates everything.
TEST_F(TemplateSourceTest, AbortGivesAnEmptyOutputWithoutError)
{
  auto source = SourceFor(scatterer::exampleTissueMaterials(), scatterer::GeneratorSettings());
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback(
    [](vtkObject* caller, unsigned long, void*, void* call)
    {
      const double progress = *static_cast<double*>(call);
      if (progress > 0.0 && progress < 1.0)
      {
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
      }
    });
  const unsigned long tag = source->AddObserver(vtkCommand::ProgressEvent, abort);
  vtkNew<vtkTest::ErrorObserver> errors;
  WatchErrors(source, errors);
  source->Update();
  EXPECT_FALSE(errors->GetError()) << errors->GetErrorMessage();
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(source->GetNumberOfTemplates(), 0);

  source->RemoveObserver(tag);
  source->Modified();
  source->Update();
  EXPECT_EQ(source->GetNumberOfTemplates(), 32);
  EXPECT_GT(source->GetOutput()->GetNumberOfPoints(), 0);
}

TEST_F(TemplateSourceTest, SaveLoadRoundTripIsBitIdentical)
{
  auto materials = scatterer::exampleTissueMaterials();
  materials[2].selector = scatterer::Selector::labelId(7);
  scatterer::GeneratorSettings settings;
  settings.templatesPerMaterial = 4;
  settings.seed = 99;
  auto saver = SourceFor(materials, settings);
  saver->SetInitialLights(3);
  saver->SetStepLength(0.04);
  saver->Update();
  const std::string path = Path("set.scattpl");
  ASSERT_TRUE(saver->SaveTemplates(path.c_str()));
  ASSERT_GT(fs::file_size(path), 68u);

  auto loader = vtkSmartPointer<vtkScattererTemplateSource>::New();
  vtkNew<vtkTest::ErrorObserver> errors;
  WatchErrors(loader, errors);
  ASSERT_TRUE(loader->LoadTemplates(path.c_str())) << errors->GetErrorMessage();
  EXPECT_FALSE(errors->GetError()) << errors->GetErrorMessage();

  // Materials and settings reflect the file.
  ASSERT_EQ(loader->GetNumberOfMaterials(), 4);
  for (int m = 0; m < 4; ++m)
  {
    vtkScattererMaterial* a = saver->GetMaterial(m);
    vtkScattererMaterial* b = loader->GetMaterial(m);
    ASSERT_TRUE(b);
    EXPECT_STREQ(a->GetName(), b->GetName());
    EXPECT_EQ(a->GetOpacity(), b->GetOpacity());
    EXPECT_EQ(a->GetRefractiveIndex(), b->GetRefractiveIndex());
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(a->GetDiffuseColor()[c], b->GetDiffuseColor()[c]);
    }
    EXPECT_EQ(a->GetSelectorType(), b->GetSelectorType());
  }
  EXPECT_EQ(loader->GetMaterial(2)->GetSelectorType(), vtkScattererMaterial::LABEL);
  EXPECT_EQ(loader->GetMaterial(2)->GetLabel(), 7);
  EXPECT_EQ(loader->GetMaterial(1)->GetScalarRange()[0], materials[1].selector.lo);
  EXPECT_EQ(loader->GetMaterial(1)->GetScalarRange()[1], materials[1].selector.hi);
  EXPECT_EQ(loader->GetTemplatesPerMaterial(), 4);
  EXPECT_EQ(loader->GetInitialLights(), 3);
  EXPECT_EQ(loader->GetSeed(), 99u);
  EXPECT_EQ(loader->GetStepLength(), 0.04);
  EXPECT_EQ(loader->GetNumberOfTemplates(), 16);

  ProgressRecorder progress(loader);
  loader->Update();
  EXPECT_EQ(progress.Intermediate(), 0u) << "loaded templates must be output, not regenerated";
  ExpectIdentical(saver->GetOutput(), loader->GetOutput());
  EXPECT_FALSE(errors->GetError()) << errors->GetErrorMessage();

  // Saving the loaded set writes the same bytes.
  const std::string again = Path("again.scattpl");
  ASSERT_TRUE(loader->SaveTemplates(again.c_str()));
  std::ifstream fa(path, std::ios::binary), fb(again, std::ios::binary);
  const std::string bytesA((std::istreambuf_iterator<char>(fa)), std::istreambuf_iterator<char>());
  const std::string bytesB((std::istreambuf_iterator<char>(fb)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(bytesA == bytesB) << "re-saved file differs";
}

// A file's templates are output as they are, even when regenerating from its
// settings would give something else; a later change regenerates.
TEST_F(TemplateSourceTest, LoadedTemplatesStayUntilSomethingChanges)
{
  scatterer::Material material;
  material.name = "custom";
  scatterer::GeneratorSettings settings;
  settings.templatesPerMaterial = 2;
  scatterer::GeneratorSettings other = settings;
  other.seed = settings.seed + 1;
  scatterer::TemplateSet set;
  set.settings = settings; // claims the default seed ...
  set.materials.push_back(
    { material, scatterer::generateTemplates(material, other) }); // ... but is not
  const std::string path = Path("foreign.scattpl");
  scatterer::saveTemplates(path, set);

  auto source = vtkSmartPointer<vtkScattererTemplateSource>::New();
  ASSERT_TRUE(source->LoadTemplates(path.c_str()));
  source->Update();
  auto* intensity =
    vtkFloatArray::SafeDownCast(source->GetOutput()->GetPointData()->GetArray("Intensity"));
  ASSERT_TRUE(intensity);
  ASSERT_EQ(source->GetOutput()->GetNumberOfPoints(),
    static_cast<vtkIdType>(
      set.materials[0].templates[0].photons.size() + set.materials[0].templates[1].photons.size()));
  EXPECT_EQ(Bits(intensity->GetValue(0)), Bits(set.materials[0].templates[0].photons[0].intensity));

  // Changing the material regenerates from the (new) inputs.
  source->GetMaterial(0)->SetRefractiveIndex(1.5);
  source->Update();
  material.refractiveIndex = 1.5;
  const auto regenerated = scatterer::generateAllTemplates({ material }, settings);
  const auto expected =
    static_cast<vtkIdType>(regenerated[0][0].photons.size() + regenerated[0][1].photons.size());
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), expected);
  intensity =
    vtkFloatArray::SafeDownCast(source->GetOutput()->GetPointData()->GetArray("Intensity"));
  ASSERT_TRUE(intensity);
  EXPECT_EQ(Bits(intensity->GetValue(0)), Bits(regenerated[0][0].photons[0].intensity));
}

TEST_F(TemplateSourceTest, LoadingABadFileFailsWithAMessage)
{
  auto source = SourceFor(scatterer::exampleTissueMaterials(), scatterer::GeneratorSettings());
  source->SetTemplatesPerMaterial(2);
  source->Update();
  const vtkIdType points = source->GetOutput()->GetNumberOfPoints();
  ASSERT_GT(points, 0);
  const std::string good = Path("good.scattpl");
  ASSERT_TRUE(source->SaveTemplates(good.c_str()));
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 100u);

  auto write = [this](const std::string& name, const std::string& data)
  {
    std::ofstream out(Path(name), std::ios::binary);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    return Path(name);
  };
  struct Case
  {
    std::string Path;
    std::string Mention;
  };
  const std::vector<Case> cases = {
    { Path("missing.scattpl"), "missing" },
    { write("truncated.scattpl", bytes.substr(0, bytes.size() / 2)), "truncated" },
    { write("header-only.scattpl", bytes.substr(0, 20)), "truncated" },
    { write("empty.scattpl", ""), "truncated" },
    { write("garbage.scattpl", std::string(300, '\x5a')), "bad magic" },
    { write("corrupt.scattpl", bytes.substr(0, 200) + char(bytes[200] ^ 0x40) + bytes.substr(201)),
      "(at byte" },
  };
  vtkNew<vtkTest::ErrorObserver> errors;
  WatchErrors(source, errors);
  for (const auto& c : cases)
  {
    errors->Clear();
    EXPECT_FALSE(source->LoadTemplates(c.Path.c_str())) << c.Path;
    ASSERT_TRUE(errors->GetError()) << c.Path << ": no error reported";
    EXPECT_TRUE(ErrorMentions(errors, c.Mention)) << c.Path << ": " << errors->GetErrorMessage();
    EXPECT_TRUE(ErrorMentions(errors, c.Path))
      << "the message should name the file: " << errors->GetErrorMessage();
    // The source is as it was.
    EXPECT_EQ(source->GetNumberOfMaterials(), 4);
    EXPECT_EQ(source->GetTemplatesPerMaterial(), 2);
    source->Update();
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), points);
  }

  errors->Clear();
  EXPECT_FALSE(source->LoadTemplates(nullptr));
  EXPECT_FALSE(source->LoadTemplates(""));
  EXPECT_EQ(ErrorCount(errors), 2u);
  errors->Clear();
  EXPECT_FALSE(source->SaveTemplates(Path("no/such/dir/out.scattpl").c_str()));
  EXPECT_TRUE(ErrorMentions(errors, "cannot open for writing")) << errors->GetErrorMessage();
}

// Materials the core rejects give an error and an empty output, never a crash;
// fixing the material recovers.
TEST_F(TemplateSourceTest, InvalidMaterialIsAnErrorNotACrash)
{
  auto source = vtkSmartPointer<vtkScattererTemplateSource>::New();
  vtkNew<vtkScattererMaterial> good;
  good->SetName("good");
  vtkNew<vtkScattererMaterial> bad;
  bad->SetName("bad");
  source->AddMaterial(good);
  source->AddMaterial(bad);
  vtkNew<vtkTest::ErrorObserver> errors;
  WatchErrors(source, errors);
  bad->AddObserver(vtkCommand::ErrorEvent, errors);

  // NaN never reaches the core: the setter rejects it and keeps the value.
  bad->SetOpacity(kNaN);
  EXPECT_TRUE(ErrorMentions(errors, "SetOpacity")) << errors->GetErrorMessage();
  EXPECT_EQ(bad->GetOpacity(), 0.5);
  errors->Clear();
  source->Update();
  EXPECT_FALSE(errors->GetError()) << errors->GetErrorMessage();
  const vtkIdType points = source->GetOutput()->GetNumberOfPoints();
  EXPECT_GT(points, 0);

  struct Case
  {
    std::function<void()> Break;
    std::string Mention;
  };
  const std::vector<Case> cases = {
    { [&] { bad->SetScalarRange(5.0, 1.0); }, "lo <= hi" },
    { [&] { bad->SetScalarRange(0.0, std::numeric_limits<double>::infinity()); }, "finite" },
    { [&] { bad->SetLabel(-3); }, "label must be >= 0" },
    { [&] { bad->SetName(std::string(300, 'x').c_str()); }, "at most 255 bytes" },
  };
  for (const auto& c : cases)
  {
    errors->Clear();
    c.Break();
    EXPECT_EQ(source->GetExecutive()->Update(), 0) << "the update must report the failure";
    EXPECT_TRUE(ErrorMentions(errors, c.Mention)) << c.Mention << ": " << errors->GetErrorMessage();
    EXPECT_TRUE(ErrorMentions(errors, "material 1")) << errors->GetErrorMessage();
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(source->GetNumberOfTemplates(), 0);
    errors->Clear();
    EXPECT_FALSE(source->SaveTemplates(Path("bad.scattpl").c_str()));
    EXPECT_TRUE(ErrorMentions(errors, "SaveTemplates")) << errors->GetErrorMessage();
    EXPECT_FALSE(fs::exists(Path("bad.scattpl")));

    // Repair: back to the good output.
    bad->SetName("bad");
    bad->SetScalarRange(0.0, 1.0);
    errors->Clear();
    EXPECT_EQ(source->GetExecutive()->Update(), 1);
    EXPECT_FALSE(errors->GetError()) << errors->GetErrorMessage();
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), points);
  }

  errors->Clear();
  source->AddMaterial(nullptr);
  EXPECT_TRUE(ErrorMentions(errors, "AddMaterial")) << errors->GetErrorMessage();
  EXPECT_EQ(source->GetNumberOfMaterials(), 2);
  EXPECT_EQ(source->GetMaterial(2), nullptr);
  EXPECT_EQ(source->GetMaterial(-1), nullptr);
  source->RemoveAllMaterials();
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(ScattererTemplateSourceSettings, DefaultsClampAndNaN)
{
  vtkNew<vtkScattererTemplateSource> s;
  const scatterer::GeneratorSettings core;
  EXPECT_EQ(s->GetTemplatesPerMaterial(), 8);
  EXPECT_EQ(s->GetInitialLights(), 4);
  EXPECT_EQ(s->GetThreshold(), 0.01);
  EXPECT_EQ(s->GetSeed(), core.seed);
  EXPECT_EQ(s->GetStepLength(), core.stepLength);
  EXPECT_EQ(s->GetLatticeCell(), core.latticeCell);
  EXPECT_EQ(s->GetMaxPhotonsPerTemplate(), core.maxPhotonsPerTemplate);
  EXPECT_EQ(s->GetMaxEventsPerTemplate(), core.maxEventsPerTemplate);
  EXPECT_EQ(s->GetTemplateRadius(), 1.0);
  EXPECT_EQ(s->GetNumberOfTemplates(), 0);

  s->SetTemplatesPerMaterial(0);
  EXPECT_EQ(s->GetTemplatesPerMaterial(), 1);
  s->SetTemplatesPerMaterial(5000);
  EXPECT_EQ(s->GetTemplatesPerMaterial(), 1024);
  s->SetInitialLights(-3);
  EXPECT_EQ(s->GetInitialLights(), 1);
  s->SetThreshold(0.0);
  EXPECT_EQ(s->GetThreshold(), 1e-9);
  s->SetThreshold(5.0);
  EXPECT_EQ(s->GetThreshold(), 1.0);

  vtkNew<vtkTest::ErrorObserver> errors;
  WatchErrors(s, errors);
  s->SetThreshold(kNaN);
  EXPECT_TRUE(ErrorMentions(errors, "SetThreshold")) << errors->GetErrorMessage();
  EXPECT_EQ(s->GetThreshold(), 1.0);
  s->SetStepLength(kNaN);
  EXPECT_TRUE(ErrorMentions(errors, "SetStepLength")) << errors->GetErrorMessage();
  EXPECT_EQ(s->GetStepLength(), core.stepLength);
  s->SetLatticeCell(kNaN);
  EXPECT_TRUE(ErrorMentions(errors, "SetLatticeCell")) << errors->GetErrorMessage();
  EXPECT_EQ(s->GetLatticeCell(), core.latticeCell);
}
