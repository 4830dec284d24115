// The shader composer: the GLSL for a set of features carries exactly the
// code those features need (an effect that is off is absent from the text).
#include "ScattererShaderComposer.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using scatterer_shader::Features;

namespace
{
std::string All(const Features& f)
{
  return scatterer_shader::IlluminationDeclarations(f) +
    scatterer_shader::ShadingInitialization(f) + scatterer_shader::ShadingImplementation(f) +
    scatterer_shader::ShadingExit(f);
}

bool Has(const std::string& text, const std::string& token)
{
  return text.find(token) != std::string::npos;
}

Features PerSampleAllOn()
{
  Features f;
  f.Transport = false;
  f.Materials = 2;
  f.Lights = 2;
  f.Positional = true;
  f.Blend2 = true;
  return f;
}
}

TEST(ShaderComposer, PreprocessKeepsAndDropsBlocks)
{
  const std::string text =
    "a\n//ST::IF X\nb\n//ST::IF Y\nc\n//ST::ELSE\nd\n//ST::ENDIF\n//ST::ENDIF\ne @N@\n";
  EXPECT_EQ(scatterer_shader::Preprocess(text, { { "X", true }, { "Y", true } }, { { "N", "7" } }),
    "a\nb\nc\ne 7\n");
  EXPECT_EQ(
    scatterer_shader::Preprocess(text, { { "X", true } }, { { "N", "7" } }), "a\nb\nd\ne 7\n");
  EXPECT_EQ(scatterer_shader::Preprocess(text, { { "Y", true } }, {}), "a\ne @N@\n");
}

TEST(ShaderComposer, PreprocessRejectsUnbalancedMarkers)
{
  EXPECT_THROW(scatterer_shader::Preprocess("//ST::IF X\na\n", {}, {}), std::runtime_error);
  EXPECT_THROW(scatterer_shader::Preprocess("a\n//ST::ENDIF\n", {}, {}), std::runtime_error);
}

TEST(ShaderComposer, NoMarkerOrPlaceholderReachesTheDriver)
{
  for (bool transport : { true, false })
  {
    Features f = PerSampleAllOn();
    f.Transport = transport;
    const std::string glsl = All(f);
    EXPECT_FALSE(Has(glsl, "//ST::")) << transport;
    EXPECT_FALSE(Has(glsl, "@")) << transport;
    EXPECT_TRUE(Has(glsl, transport ? "#define ST_LIGHT_SLOTS 6" : "#define ST_LIGHT_SLOTS 2"))
      << transport;
    EXPECT_TRUE(Has(glsl, "#define ST_MAX_MATERIALS 8")) << transport;
  }
}

TEST(ShaderComposer, PerSampleCarriesThePhotonLoopAndTransportDoesNot)
{
  Features f = PerSampleAllOn();
  EXPECT_TRUE(Has(All(f), "st_gatherTemplate"));
  EXPECT_TRUE(Has(All(f), "st_templates"));
  EXPECT_FALSE(Has(All(f), "st_transport"));
  f.Transport = true;
  EXPECT_FALSE(Has(All(f), "st_gatherTemplate"));
  EXPECT_FALSE(Has(All(f), "st_templates"));
  EXPECT_FALSE(Has(All(f), "st_matRange")); // the transport volume resolved the materials
  EXPECT_TRUE(Has(All(f), "st_transport"));
}

TEST(ShaderComposer, EachEffectSwitchedOffIsAbsent)
{
  struct Case
  {
    const char* Name;
    void (*Off)(Features&);
    const char* Token; // code only that effect needs
  };
  const Case cases[] = {
    { "shadow", [](Features& f) { f.Shadow = false; }, "st_transmittance" },
    { "thin", [](Features& f) { f.Thin = false; }, "st_longRange" },
    { "bleed", [](Features& f) { f.Bleed = false; }, "st_matColor" },
    { "boundary", [](Features& f) { f.Boundary = false; }, "st_speedRatio" },
    { "positional", [](Features& f) { f.Positional = false; }, "st_lightPos" },
    { "blend2", [](Features& f) { f.Blend2 = false; }, "7919" },
    { "one material", [](Features& f) { f.Materials = 1; }, "st_speedRatio" },
  };
  for (const auto& c : cases)
  {
    Features on = PerSampleAllOn();
    EXPECT_TRUE(Has(All(on), c.Token)) << c.Name << " on should carry " << c.Token;
    Features off = on;
    c.Off(off);
    EXPECT_FALSE(Has(All(off), c.Token)) << c.Name << " off should not carry " << c.Token;
  }
}

TEST(ShaderComposer, PhongKeepsVtkShadingAndNormalizes)
{
  Features f;
  f.Phong = true;
  EXPECT_TRUE(Has(All(f), "st_unlitNorm"));
  f.Phong = false;
  EXPECT_FALSE(Has(All(f), "st_unlitNorm"));
}

TEST(ShaderComposer, DescribeNamesTheFeatures)
{
  Features f = PerSampleAllOn();
  EXPECT_EQ(
    f.Describe(), "per-sample lights=2 materials=2 shadow thin bleed boundary positional blend2");
}

// Every distinct text is a program VTK keeps for the window's lifetime, so the
// number of materials (a uniform) must not change the text, and the number of
// lights only through its slots (1, 2, 4, 6; docs/hard-cases.md, "Lifecycle soak").
TEST(ShaderComposer, TextDependsOnLightSlotsOnly)
{
  for (bool transport : { false, true })
  {
    Features a = PerSampleAllOn();
    a.Transport = transport;
    Features b = a;
    a.Lights = 3;
    a.Materials = 2;
    b.Lights = 4;
    b.Materials = 8;
    EXPECT_EQ(All(a), All(b)) << (transport ? "transport" : "per sample");
    b.Lights = 1;
    EXPECT_EQ(All(a) == All(b), transport) << "one light has its own per-sample text";
  }
  const int expected[] = { 1, 2, 4, 4, 6, 6 };
  Features f = PerSampleAllOn();
  for (int lights = 1; lights <= 6; ++lights)
  {
    f.Lights = lights;
    EXPECT_EQ(scatterer_shader::LightSlots(f), expected[lights - 1]) << lights;
  }
}

TEST(ShaderComposer, MultiVolumeCompositesEachInputWithItsOwnSamplerAndMatrices)
{
  // VTK 9.1 numbers a vtkMultiVolume's samplers and transfer functions from 0 and its
  // matrices from 1 (0 is the box): each input's block must read its own.
  Features f;
  f.Parts = 3;
  const std::string impl = scatterer_shader::ShadingImplementation(f);
  for (int part = 0; part < 3; ++part)
  {
    const std::string k = std::to_string(part), m = std::to_string(part + 1);
    EXPECT_TRUE(Has(impl, "texture3D(in_volume[" + k + "], texPos)")) << part;
    EXPECT_TRUE(Has(impl, "in_opacityTransferFunc_" + k + "[0]")) << part;
    EXPECT_TRUE(Has(impl, "in_colorTransferFunc_" + k + "[0]")) << part;
    EXPECT_TRUE(Has(impl, "in_inverseTextureDatasetMatrix[" + m + "]")) << part;
  }
  EXPECT_FALSE(Has(impl, "in_volume[3]"));
  EXPECT_FALSE(Has(impl, "@"));
  EXPECT_FALSE(Has(impl, "//ST::"));
  // The light is looked up from the world position, through the box's matrices.
  EXPECT_TRUE(Has(scatterer_shader::ShadingInitialization(f), "in_volumeMatrix[0]"));
  f.Parts = 0;
  EXPECT_FALSE(Has(scatterer_shader::ShadingInitialization(f), "in_volumeMatrix[0]"));
  EXPECT_FALSE(Has(scatterer_shader::ShadingImplementation(f), "in_colorTransferFunc_"));
}

TEST(ShaderComposer, SamplesThatShareALightReadCarryTheRayLoopsOwnStep)
{
  // One pass of VTK's ray loop composites LightStride samples and reads the light once.
  // Each sample after the first must take the loop's own step and per-sample code (its
  // termination, cropping, masks), which VTK fills in wherever its tags stand.
  Features f;
  f.LightStride = 4;
  const std::string impl = scatterer_shader::ShadingImplementation(f);
  auto count = [&](const std::string& token)
  {
    int n = 0;
    for (auto at = impl.find(token); at != std::string::npos; at = impl.find(token, at + 1))
    {
      ++n;
    }
    return n;
  };
  EXPECT_EQ(count("texture3D(in_volume[0], g_dataPos)"), 4);
  EXPECT_EQ(count("st_transportRead("), 1);
  // The group's reads are compressed as they are taken (the samples between interpolate
  // the compressed light), so no sample compresses again.
  EXPECT_EQ(count("st_shownLight(st_transportRead("), 1);
  EXPECT_EQ(count("st_shownLight("), 1);
  EXPECT_EQ(count("g_dataPos += g_dirStep;"), 3);
  for (const char* tag :
    { "//VTK::Terminate::Impl", "//VTK::Base::Impl", "//VTK::Cropping::Impl",
      "//VTK::BinaryMask::Impl", "//VTK::CompositeMask::Impl", "//VTK::PreComputeGradients::Impl",
      "//VTK::RenderToImage::Impl", "//VTK::DepthPass::Impl" })
  {
    EXPECT_EQ(count(tag), 3) << tag;
  }
  EXPECT_EQ(count("{"), count("}"));
  EXPECT_FALSE(Has(impl, "@"));
  EXPECT_TRUE(Has(
    scatterer_shader::ShadingInitialization(f), "st_lightEnd = st_shownLight(st_transportRead"));
  EXPECT_EQ(
    f.Describe(), "transport lights=1 materials=1 shadow thin bleed boundary light-stride=4");

  // Stride 1, the per-sample mode and a vtkMultiVolume read the light at every sample.
  for (int variant = 0; variant < 3; ++variant)
  {
    Features g;
    g.LightStride = variant == 0 ? 1 : 4;
    g.Transport = variant != 1;
    g.Parts = variant == 2 ? 2 : 0;
    const std::string text = scatterer_shader::ShadingImplementation(g);
    EXPECT_FALSE(Has(text, "//VTK::")) << variant;
    EXPECT_FALSE(Has(text, "st_lightEnd")) << variant;
    EXPECT_FALSE(Has(g.Describe(), "light-stride")) << variant;
  }
}

TEST(ShaderComposer, TheLightInsideADenseTexelRunsAfterTheRayLoopOnly)
{
  // The ray's first dense samples are kept in the loop and lit again after it
  // (scatterer_shading_exit.glsl); without the feature neither part is in the text, and
  // the loop keeps its samples without a branch or an indexed store (llvmpipe runs both
  // for every sample).
  Features f;
  f.LightStride = 4;
  EXPECT_EQ(scatterer_shader::ShadingExit(f), "");
  EXPECT_FALSE(Has(scatterer_shader::ShadingImplementation(f), "st_surface"));
  EXPECT_FALSE(Has(f.Describe(), "surface"));
  f.SurfaceDetail = true;
  const std::string exit = scatterer_shader::ShadingExit(f);
  EXPECT_TRUE(Has(exit, "g_fragColor.rgb += st_surfaceChange(0);"));
  EXPECT_FALSE(Has(exit, "//ST::"));
  const std::string impl = scatterer_shader::ShadingImplementation(f);
  EXPECT_FALSE(Has(impl, "st_surfaceAt[st_surfaceCount]"));
  EXPECT_TRUE(Has(impl, "st_surfaceAt = mix(st_surfaceAt"));
  EXPECT_TRUE(Has(scatterer_shader::IlluminationDeclarations(f), "vec3 st_surfaceChange(int k)"));
  EXPECT_TRUE(Has(scatterer_shader::ShadingInitialization(f), "st_surfaceCount = 0;"));
  EXPECT_EQ(f.Describe(),
    "transport lights=1 materials=1 shadow thin bleed boundary surface "
    "light-stride=4");
}
