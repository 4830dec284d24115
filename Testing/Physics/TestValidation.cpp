// Invalid parameters are rejected with std::invalid_argument whose message names the
// parameter; meanFreePath follows lambda = 1 / (sqrt(2) * opacity).
#include <scatterer/GeneratorSettings.h>
#include <scatterer/Material.h>
#include <scatterer/Template.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

using namespace scatterer;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// Runs f, expects std::invalid_argument, and checks that every word is in the message.
void expectRejected(const std::function<void()>& f, std::initializer_list<const char*> words)
{
  try {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning " << *words.begin();
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    for (const char* w : words) {
      EXPECT_NE(message.find(w), std::string::npos) << "'" << w << "' not in: " << message;
    }
  }
}

void expectMaterialRejected(
  const std::function<void(Material&)>& change, std::initializer_list<const char*> words)
{
  Material m;
  m.name = "probe";
  change(m);
  expectRejected([&] { m.validate(); }, words);
  expectRejected([&] { generateTemplate(m, GeneratorSettings{}, 0); }, words);
}

void expectSettingsRejected(
  const std::function<void(GeneratorSettings&)>& change, std::initializer_list<const char*> words)
{
  GeneratorSettings s;
  change(s);
  expectRejected([&] { s.validate(); }, words);
  expectRejected([&] { generateTemplates(Material{}, s); }, words);
}

} // namespace

TEST(Validation, DefaultsAndExamplesAreValid)
{
  EXPECT_NO_THROW(Material{}.validate());
  EXPECT_NO_THROW(GeneratorSettings{}.validate());
  for (const Material& m : exampleTissueMaterials()) {
    EXPECT_NO_THROW(m.validate()) << m.name;
  }
}

TEST(Validation, MaterialRejectsBadOpacity)
{
  expectMaterialRejected([](Material& m) { m.opacity = kNaN; }, { "opacity", "NaN", "probe" });
  expectMaterialRejected([](Material& m) { m.opacity = -0.1; }, { "opacity", "-0.1" });
  expectMaterialRejected([](Material& m) { m.opacity = 1.5; }, { "opacity", "1.5" });
  expectMaterialRejected([](Material& m) { m.opacity = kInf; }, { "opacity" });
}

TEST(Validation, MaterialRejectsBadRefractiveIndex)
{
  expectMaterialRejected([](Material& m) { m.refractiveIndex = 0.0; }, { "refractiveIndex" });
  expectMaterialRejected([](Material& m) { m.refractiveIndex = -1.4; }, { "refractiveIndex" });
  expectMaterialRejected(
    [](Material& m) { m.refractiveIndex = kNaN; }, { "refractiveIndex", "NaN" });
  expectMaterialRejected([](Material& m) { m.refractiveIndex = kInf; }, { "refractiveIndex" });
  expectMaterialRejected([](Material& m) { m.refractiveIndex = 1e6; }, { "refractiveIndex" });
}

TEST(Validation, MaterialRejectsBadDiffuseAndSelector)
{
  expectMaterialRejected([](Material& m) { m.diffuse.g = std::nanf(""); }, { "diffuse.g", "NaN" });
  expectMaterialRejected([](Material& m) { m.diffuse.b = -0.5f; }, { "diffuse.b" });
  expectMaterialRejected(
    [](Material& m) { m.selector = Selector::range(kNaN, 1.0); }, { "selector range" });
  expectMaterialRejected(
    [](Material& m) { m.selector = Selector::range(5.0, 1.0); }, { "selector range", "lo <= hi" });
  expectMaterialRejected(
    [](Material& m) { m.selector = Selector::labelId(-3); }, { "selector label", "-3" });
  expectMaterialRejected([](Material& m) { m.name.assign(300, 'x'); }, { "name" });
}

TEST(Validation, SettingsRejectBadValues)
{
  expectSettingsRejected(
    [](GeneratorSettings& s) { s.initialLights = 0; }, { "initialLights", "0" });
  expectSettingsRejected([](GeneratorSettings& s) { s.initialLights = -4; }, { "initialLights" });
  expectSettingsRejected([](GeneratorSettings& s) { s.threshold = 0.0; }, { "threshold" });
  expectSettingsRejected([](GeneratorSettings& s) { s.threshold = -0.01; }, { "threshold" });
  expectSettingsRejected([](GeneratorSettings& s) { s.threshold = kNaN; }, { "threshold", "NaN" });
  expectSettingsRejected(
    [](GeneratorSettings& s) { s.templatesPerMaterial = 0; }, { "templatesPerMaterial" });
  expectSettingsRejected([](GeneratorSettings& s) { s.stepLength = 0.0; }, { "stepLength" });
  expectSettingsRejected([](GeneratorSettings& s) { s.stepLength = kNaN; }, { "stepLength" });
  expectSettingsRejected([](GeneratorSettings& s) { s.latticeCell = 0.0; }, { "latticeCell" });
  expectSettingsRejected([](GeneratorSettings& s) { s.latticeCell = -1.0; }, { "latticeCell" });
  expectSettingsRejected(
    [](GeneratorSettings& s) { s.maxPhotonsPerTemplate = 0; }, { "maxPhotonsPerTemplate" });
  expectSettingsRejected(
    [](GeneratorSettings& s) { s.maxEventsPerTemplate = -1; }, { "maxEventsPerTemplate" });
  expectSettingsRejected([](GeneratorSettings& s) { s.maxEventsPerTemplate = kMaxEventsCap + 1; },
    { "maxEventsPerTemplate" });
}

TEST(Validation, TemplateIndexMustBeNonNegative)
{
  expectRejected(
    [] { generateTemplate(Material{}, GeneratorSettings{}, -1); }, { "templateIndex", "-1" });
}

TEST(Validation, SelectorMatching)
{
  const Selector r = Selector::range(-50.0, 100.0);
  EXPECT_TRUE(r.matches(-50.0));
  EXPECT_TRUE(r.matches(100.0));
  EXPECT_FALSE(r.matches(100.5));
  EXPECT_FALSE(r.matches(kNaN));
  const Selector l = Selector::labelId(3);
  EXPECT_TRUE(l.matches(3.0));
  EXPECT_FALSE(l.matches(3.5));
}

TEST(MeanFreePath, FollowsMaxwellBoltzmannFormula)
{
  Material m;
  m.opacity = 0.5;
  EXPECT_DOUBLE_EQ(meanFreePath(m), 1.0 / (std::sqrt(2.0) * 0.5)); // 1.41421... radii
  m.opacity = 1.0;
  EXPECT_DOUBLE_EQ(meanFreePath(m), 1.0 / std::sqrt(2.0));
  m.opacity = 0.25;
  EXPECT_DOUBLE_EQ(meanFreePath(m), 2.0 * std::sqrt(2.0));
  m.opacity = 0.0;
  EXPECT_TRUE(std::isinf(meanFreePath(m)));
  m.opacity = kNaN;
  EXPECT_THROW(meanFreePath(m), std::invalid_argument);
}
