// vtkScattererMaterial: the defaults are the core's, the setters clamp, and NaN is
// rejected with an error that names the setter (the value and MTime are kept).
#include "vtkScattererMaterial.h"

#include "ScattererErrorObserver.h"

#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <scatterer/Material.h>

#include <gtest/gtest.h>

#include <limits>

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();

using scatterer_testing::ErrorCount;
using scatterer_testing::ErrorMentions;
}

TEST(ScattererMaterial, DefaultsAreTheCores)
{
  vtkNew<vtkScattererMaterial> m;
  const scatterer::Material core;
  EXPECT_EQ(m->GetOpacity(), core.opacity);
  EXPECT_EQ(m->GetOpacity(), 0.5);
  EXPECT_EQ(m->GetRefractiveIndex(), 1.4);
  EXPECT_EQ(m->GetDiffuseColor()[0], 1.0);
  EXPECT_EQ(m->GetSelectorType(), vtkScattererMaterial::SCALAR_RANGE);
  EXPECT_STREQ(m->GetSelectorTypeAsString(), "ScalarRange");
  EXPECT_EQ(m->GetRefractiveIndexMinValue(), scatterer::kMinRefractiveIndex);
  EXPECT_EQ(m->GetRefractiveIndexMaxValue(), scatterer::kMaxRefractiveIndex);
}

TEST(ScattererMaterial, SettersClamp)
{
  vtkNew<vtkScattererMaterial> m;
  m->SetOpacity(-0.5);
  EXPECT_EQ(m->GetOpacity(), 0.0);
  m->SetOpacity(3.0);
  EXPECT_EQ(m->GetOpacity(), 1.0);
  m->SetOpacity(0.25);
  EXPECT_EQ(m->GetOpacity(), 0.25);

  m->SetRefractiveIndex(0.0);
  EXPECT_EQ(m->GetRefractiveIndex(), scatterer::kMinRefractiveIndex);
  m->SetRefractiveIndex(-2.0);
  EXPECT_EQ(m->GetRefractiveIndex(), scatterer::kMinRefractiveIndex);
  m->SetRefractiveIndex(1e9);
  EXPECT_EQ(m->GetRefractiveIndex(), scatterer::kMaxRefractiveIndex);
  m->SetRefractiveIndex(std::numeric_limits<double>::infinity());
  EXPECT_EQ(m->GetRefractiveIndex(), scatterer::kMaxRefractiveIndex);
  m->SetRefractiveIndex(1.33);
  EXPECT_EQ(m->GetRefractiveIndex(), 1.33);

  m->SetDiffuseColor(-1.0, 0.5, 7.0);
  EXPECT_EQ(m->GetDiffuseColor()[0], 0.0);
  EXPECT_EQ(m->GetDiffuseColor()[1], 0.5);
  EXPECT_EQ(m->GetDiffuseColor()[2], 1.0);

  m->SetLabel(4);
  EXPECT_EQ(m->GetSelectorType(), vtkScattererMaterial::LABEL);
  EXPECT_EQ(m->GetLabel(), 4);
  m->SetScalarRange(-100.0, 300.0);
  EXPECT_EQ(m->GetSelectorType(), vtkScattererMaterial::SCALAR_RANGE);
  EXPECT_EQ(m->GetScalarRange()[0], -100.0);
  EXPECT_EQ(m->GetScalarRange()[1], 300.0);
  EXPECT_EQ(m->GetLabel(), 4) << "the label is kept while the range is active";
}

TEST(ScattererMaterial, NaNIsRejectedNamingTheSetter)
{
  vtkNew<vtkScattererMaterial> m;
  m->SetOpacity(0.3);
  m->SetRefractiveIndex(1.5);
  m->SetDiffuseColor(0.1, 0.2, 0.3);
  m->SetScalarRange(1.0, 2.0);
  vtkNew<vtkTest::ErrorObserver> errors;
  m->AddObserver(vtkCommand::ErrorEvent, errors);
  const vtkMTimeType mtime = m->GetMTime();

  m->SetOpacity(kNaN);
  EXPECT_TRUE(ErrorMentions(errors, "SetOpacity")) << errors->GetErrorMessage();
  EXPECT_EQ(m->GetOpacity(), 0.3);
  m->SetRefractiveIndex(kNaN);
  EXPECT_TRUE(ErrorMentions(errors, "SetRefractiveIndex")) << errors->GetErrorMessage();
  EXPECT_EQ(m->GetRefractiveIndex(), 1.5);
  m->SetDiffuseColor(0.9, kNaN, 0.9);
  EXPECT_TRUE(ErrorMentions(errors, "SetDiffuseColor")) << errors->GetErrorMessage();
  EXPECT_EQ(m->GetDiffuseColor()[0], 0.1);
  EXPECT_EQ(m->GetDiffuseColor()[1], 0.2);
  m->SetScalarRange(kNaN, 5.0);
  EXPECT_TRUE(ErrorMentions(errors, "SetScalarRange")) << errors->GetErrorMessage();
  EXPECT_EQ(m->GetScalarRange()[0], 1.0);
  EXPECT_EQ(m->GetScalarRange()[1], 2.0);
  EXPECT_EQ(ErrorCount(errors), 4u);
  EXPECT_EQ(m->GetMTime(), mtime) << "a rejected value must not modify the material";

  // Setting the same value again does not modify either.
  m->SetOpacity(0.3);
  EXPECT_EQ(m->GetMTime(), mtime);
  m->SetOpacity(0.4);
  EXPECT_GT(m->GetMTime(), mtime);
}
