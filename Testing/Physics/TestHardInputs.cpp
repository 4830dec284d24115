// Extreme but valid inputs: opacity 0 and 1, tiny and huge refractive indices, and a
// threshold of 1e-9 that must stop at the documented caps. Work is bounded by counts
// (events, photons), never by wall-clock time: timed tests fail on loaded or
// sanitizer builds.
#include <scatterer/Template.h>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

using namespace scatterer;

namespace {

void expectClosedLedger(const Template& t)
{
  EXPECT_NEAR(t.ledger.residual(), 0.0, 1e-9);
  for (const Photon& p : t.photons) {
    ASSERT_TRUE(
      std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z));
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
      for (const Template& t :
        generateTemplates(withOpacityAndIndex(opacity, n), GeneratorSettings{})) {
        SCOPED_TRACE("n " + std::to_string(n) + " opacity " + std::to_string(opacity));
        expectClosedLedger(t);
        EXPECT_FALSE(t.photons.empty());
        EXPECT_FALSE(t.capped);
      }
    }
  }
}

// The caps bound the work: a template processes at most maxEventsPerTemplate packets
// (each one pop and at most two pushes on a heap that the cap bounds too), so 8 capped
// templates do at most 8 * 65536 events whatever the machine's load. The counts are
// asserted exactly, not timed.
TEST(HardInputs, TinyThresholdStopsAtDocumentedCaps)
{
  GeneratorSettings s;
  s.threshold = 1e-9;
  ASSERT_EQ(s.templatesPerMaterial, 8);
  ASSERT_EQ(s.maxPhotonsPerTemplate, 4096);
  ASSERT_EQ(s.maxEventsPerTemplate, 65536);
  const auto maxEvents = static_cast<std::uint64_t>(s.maxEventsPerTemplate);
  const auto maxPhotons = static_cast<std::size_t>(s.maxPhotonsPerTemplate);
  // Opacity 0 never stores, so only the event cap can stop it; 0.01 and 0.5 fill the
  // photon cap first.
  for (double opacity : { 0.0, 0.01, 0.5 }) {
    SCOPED_TRACE("opacity " + std::to_string(opacity));
    const auto templates = generateTemplates(withOpacityAndIndex(opacity, 1.4), s);
    ASSERT_EQ(templates.size(), static_cast<std::size_t>(s.templatesPerMaterial));
    std::uint64_t totalEvents = 0;
    for (const Template& t : templates) {
      expectClosedLedger(t);
      EXPECT_TRUE(t.capped);
      EXPECT_GT(t.ledger.droppedAtCap, 0.0);
      EXPECT_LE(t.photons.size(), maxPhotons);
      EXPECT_LE(t.events, maxEvents);
      if (opacity == 0.0) {
        EXPECT_EQ(t.events, maxEvents); // stopped by the event cap, exactly at it
        EXPECT_TRUE(t.photons.empty());
      } else {
        EXPECT_EQ(t.photons.size(), maxPhotons); // stopped by the photon cap, exactly at it
        EXPECT_LT(t.events, maxEvents);          // ... before the event cap
        EXPECT_GE(t.events, t.photons.size());   // every photon took an event
      }
      totalEvents += t.events;
    }
    EXPECT_LE(totalEvents, templates.size() * maxEvents);
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
