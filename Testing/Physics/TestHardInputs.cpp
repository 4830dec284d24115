// Extreme but valid inputs: opacity 0 and 1, tiny and huge refractive indices, and a
// threshold of 1e-9 that must stop at the documented caps, quickly.
#include <scatterer/Template.h>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

using namespace scatterer;

namespace {

void expectClosedLedger(const Template& t)
{
  EXPECT_NEAR(t.ledger.residual(), 0.0, 1e-9);
  for (const Photon& p : t.photons) {
    ASSERT_TRUE(std::isfinite(p.position.x) && std::isfinite(p.position.y) &&
      std::isfinite(p.position.z));
    ASSERT_GT(p.intensity, 0.0f);
    ASSERT_LE(glm::length(glm::dvec3(p.position)), 1.0 + 1e-6);
  }
}

Material withOpacityAndIndex(double opacity, double n)
{
  Material m;
  m.opacity = opacity;
  m.refractiveIndex = n;
  return m;
}

} // namespace

TEST(HardInputs, TransparentMaterialStoresNothing)
{
  for (const Template& t : generateTemplates(withOpacityAndIndex(0.0, 1.4), GeneratorSettings{})) {
    expectClosedLedger(t);
    EXPECT_TRUE(t.photons.empty());
    EXPECT_EQ(t.ledger.stored, 0.0);
    EXPECT_FALSE(t.capped);
  }
}

TEST(HardInputs, OpaqueMaterialAbsorbsAtFirstEvent)
{
  GeneratorSettings s;
  for (const Template& t : generateTemplates(withOpacityAndIndex(1.0, 1.4), s)) {
    expectClosedLedger(t);
    EXPECT_EQ(t.events, static_cast<std::uint64_t>(s.initialLights)); // no branching
    EXPECT_LE(t.photons.size(), static_cast<std::size_t>(s.initialLights));
    EXPECT_GE(t.photons.size(), 1u);
    EXPECT_EQ(t.ledger.droppedBelowThreshold, 0.0);
    EXPECT_NEAR(t.ledger.stored + t.ledger.lostInTransit, 1.0, 1e-12);
  }
}

TEST(HardInputs, TinyAndHugeRefractiveIndices)
{
  for (double n : { 1e-3, 1e3 }) {
    for (double opacity : { 0.05, 0.5, 0.95 }) {
      for (const Template& t : generateTemplates(withOpacityAndIndex(opacity, n), GeneratorSettings{})) {
        SCOPED_TRACE("n " + std::to_string(n) + " opacity " + std::to_string(opacity));
        expectClosedLedger(t);
        EXPECT_FALSE(t.photons.empty());
        EXPECT_FALSE(t.capped);
      }
    }
  }
}

TEST(HardInputs, TinyThresholdStopsAtDocumentedCaps)
{
  GeneratorSettings s;
  s.threshold = 1e-9;
  ASSERT_EQ(s.maxPhotonsPerTemplate, 4096);
  ASSERT_EQ(s.maxEventsPerTemplate, 65536);
  // Opacity 0 never stores, so only the event cap can stop it; 0.5 fills the photon cap.
  for (double opacity : { 0.0, 0.01, 0.5 }) {
    const auto start = std::chrono::steady_clock::now();
    const auto templates = generateTemplates(withOpacityAndIndex(opacity, 1.4), s);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0) << "8 capped templates must stay fast (opacity " << opacity << ")";
    for (const Template& t : templates) {
      expectClosedLedger(t);
      EXPECT_TRUE(t.capped);
      EXPECT_LE(t.photons.size(), 4096u);
      EXPECT_LE(t.events, 65536u);
      EXPECT_GT(t.ledger.droppedAtCap, 0.0);
    }
  }
}

TEST(HardInputs, SmallestCapsStillCloseTheLedger)
{
  GeneratorSettings s;
  s.maxEventsPerTemplate = 1;
  const Template a = generateTemplate(withOpacityAndIndex(0.5, 1.4), s, 0);
  expectClosedLedger(a);
  EXPECT_TRUE(a.capped);
  EXPECT_EQ(a.events, 1u);
  EXPECT_EQ(a.photons.size(), 1u);

  s = GeneratorSettings{};
  s.maxPhotonsPerTemplate = 1;
  const Template b = generateTemplate(withOpacityAndIndex(0.5, 1.4), s, 0);
  expectClosedLedger(b);
  EXPECT_TRUE(b.capped);
  EXPECT_EQ(b.photons.size(), 1u);
}

TEST(HardInputs, LongStepsEscapeTheSphere)
{
  GeneratorSettings s;
  s.stepLength = 1.0; // every packet leaves the unit sphere on its first step
  const Template t = generateTemplate(withOpacityAndIndex(0.5, 1.4), s, 0);
  expectClosedLedger(t);
  EXPECT_TRUE(t.photons.empty());
  EXPECT_GT(t.ledger.escaped, 0.0);
  EXPECT_NEAR(t.ledger.escaped, std::exp(-1.0 / (1.0 / (std::sqrt(2.0) * 0.5))), 1e-12);
}
