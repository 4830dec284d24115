// Regressions for what fuzzing (Testing/Fuzz, docs/fuzzing.md) found in the physics core.
#include <scatterer/Template.h>
#include <scatterer/TemplateIO.h>

#include <gtest/gtest.h>

#include <sstream>

using namespace scatterer;

// Opacities so small that every absorbed amount underflows float (< 7e-46) used to leave
// ledger.stored at a rounding residue such as -4e-315 after the underflowed cells were
// taken out of it; writeTemplates then refused the generator's own templates ("energy
// ledger has a negative or non-finite entry").
TEST(FuzzRegressions, UnderflowingOpacityLeavesNoNegativeLedgerEntry)
{
  for (double opacity : { 1e-320, 1e-300, 7.6154311270414583e-298, 1e-200, 1e-100 }) {
    Material m;
    m.opacity = opacity;
    GeneratorSettings s;
    s.initialLights = 64;
    s.maxEventsPerTemplate = 1000;
    const std::vector<Template> templates = generateTemplates(m, s);
    for (const Template& t : templates) {
      const EnergyLedger& l = t.ledger;
      for (double f :
        { l.stored, l.lostInTransit, l.escaped, l.droppedBelowThreshold, l.droppedAtCap }) {
        EXPECT_GE(f, 0.0) << "opacity " << opacity;
      }
      EXPECT_NEAR(l.residual(), 0.0, 1e-12);
      if (t.photons.empty()) {
        EXPECT_EQ(l.stored, 0.0) << "opacity " << opacity;
      }
    }
    TemplateSet set;
    set.settings = s;
    set.materials.push_back({ m, templates });
    std::ostringstream out;
    EXPECT_NO_THROW(writeTemplates(out, set)) << "opacity " << opacity;
  }
}
