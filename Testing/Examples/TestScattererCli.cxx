// Command-line tests of scatterer-render and scatterer-viewer (issue 13: bad input
// never crashes and never yields a silent black frame; issue 16: the command lines
// themselves, on CLI11). Each test writes its input
// volume into a fresh temporary folder (MetaImage or NRRD, written by hand so that
// any spacing or origin can be put in the header), runs the built program and checks
// the exit status, the message and, where an image is expected, the image.
//
// The rules themselves are also tested in-process (VolumeCheck.*): for files, the
// volume reader refuses bad spacing and origin before the programs' own check sees
// them, so only the in-process tests show that check working.
#include "Common/ScattererCtHeadScene.h"
#include "Common/ScattererFrameCheck.h"
#include "Common/ScattererVolumeCheck.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <sys/wait.h>
#include <vector>

#ifndef SCATTERER_RENDER_EXE
#error "SCATTERER_RENDER_EXE (path of scatterer-render) must be defined by the build"
#endif
#ifndef SCATTERER_VIEWER_EXE
#error "SCATTERER_VIEWER_EXE (path of scatterer-viewer) must be defined by the build"
#endif
#ifndef SCATTERER_SOURCE_DIR
#error                                                                                             \
  "SCATTERER_SOURCE_DIR (the source tree, for paths the help cites) must be defined by the build"
#endif

namespace fs = std::filesystem;

namespace
{
const float Inf = std::numeric_limits<float>::infinity();
const float NaN = std::numeric_limits<float>::quiet_NaN();

/** A float volume and the header text of its placement (any text, "nan" included). */
struct Volume
{
  int Dims[3] = { 16, 16, 16 };
  std::vector<float> Values;
  std::string Spacing = "1 1 1";
  std::string Origin = "0 0 0";
};

/** A ball: @p peak at the centre falling linearly to 0 at the faces, 0 outside. */
Volume Ball(int n = 16, float peak = 100.0f)
{
  Volume v;
  v.Dims[0] = v.Dims[1] = v.Dims[2] = n;
  const double c = 0.5 * (n - 1);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
      {
        const double r = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
        v.Values.push_back(static_cast<float>(peak * std::max(0.0, 1.0 - r / (0.5 * n))));
      }
  return v;
}

Volume Filled(int nx, int ny, int nz, float value)
{
  Volume v;
  v.Dims[0] = nx;
  v.Dims[1] = ny;
  v.Dims[2] = nz;
  v.Values.assign(static_cast<size_t>(nx) * ny * nz, value);
  return v;
}

/** Values 0, 1, 2, ... (not constant, so only the shape can be the problem). */
Volume Ramp(int nx, int ny, int nz)
{
  Volume v = Filled(nx, ny, nz, 0.0f);
  for (size_t i = 0; i < v.Values.size(); ++i)
  {
    v.Values[i] = static_cast<float>(i % 100);
  }
  return v;
}

void WriteRaw(const fs::path& path, const Volume& v)
{
  std::ofstream out(path, std::ios::binary | std::ios::app);
  out.write(reinterpret_cast<const char*>(v.Values.data()),
    static_cast<std::streamsize>(v.Values.size() * sizeof(float)));
}

/** Fixture: a temporary folder per test, removed afterwards. */
class Cli : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::string pattern = (fs::temp_directory_path() / "scatterer-cli-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr) << "cannot make a temporary folder";
    this->Dir = pattern;
  }
  void TearDown() override
  {
    std::error_code ignored;
    fs::remove_all(this->Dir, ignored);
  }

  /** NAME.mhd + NAME.raw (MetaImage, float, little-endian). */
  std::string WriteMetaImage(const std::string& name, const Volume& v)
  {
    const fs::path header = this->Dir / (name + ".mhd");
    std::ofstream out(header);
    out << "ObjectType = Image\nNDims = 3\nDimSize = " << v.Dims[0] << " " << v.Dims[1] << " "
        << v.Dims[2] << "\nElementType = MET_FLOAT\nElementSpacing = " << v.Spacing
        << "\nOffset = " << v.Origin << "\nElementByteOrderMSB = False\nElementDataFile = " << name
        << ".raw\n";
    out.close();
    WriteRaw(this->Dir / (name + ".raw"), v);
    return header.string();
  }

  /** NAME.nrrd, raw data attached (NRRD keeps a NaN or negative spacing as written). */
  std::string WriteNrrd(const std::string& name, const Volume& v)
  {
    const fs::path path = this->Dir / (name + ".nrrd");
    std::ofstream out(path, std::ios::binary);
    out << "NRRD0004\ntype: float\ndimension: 3\nsizes: " << v.Dims[0] << " " << v.Dims[1] << " "
        << v.Dims[2] << "\nspacings: " << v.Spacing << "\nencoding: raw\nendian: little\n\n";
    out.close();
    WriteRaw(path, v);
    return path.string();
  }

  std::string Png(const std::string& name) const { return (this->Dir / name).string(); }

  /** A viewer recording (vtkInteractorEventRecorder format): one rotation drag. */
  std::string WriteDragRecording()
  {
    const fs::path path = this->Dir / "drag.log";
    std::ofstream(path) << "# StreamVersion 1.1\n"
                           "EnterEvent 150 150 0 0 0 0\n"
                           "MouseMoveEvent 150 150 0 0 0 0\n"
                           "LeftButtonPressEvent 150 150 0 0 0 0\n"
                           "MouseMoveEvent 170 155 0 0 0 0\n"
                           "MouseMoveEvent 190 160 0 0 0 0\n"
                           "LeftButtonReleaseEvent 190 160 0 0 0 0\n";
    return path.string();
  }

  fs::path Dir;
};

struct Result
{
  int Status = -1;    // exit status; 128 + signal when killed by one
  std::string Output; // stdout and stderr together
};

std::string Quote(const std::string& arg)
{
  std::string q = "'";
  for (const char c : arg)
  {
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return q + "'";
}

/** Runs @p program with @p args; @p env is put before it (e.g. "env -u DISPLAY"). */
Result RunProgram(const std::string& program, const std::vector<std::string>& args,
  const std::string& env = std::string())
{
  std::string command = env.empty() ? std::string() : env + " ";
  command += Quote(program);
  for (const auto& a : args)
  {
    command += " " + Quote(a);
  }
  command += " 2>&1";
  Result r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
  {
    r.Output = "popen failed for: " + command;
    return r;
  }
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0)
  {
    r.Output.append(buffer, n);
  }
  const int status = pclose(pipe);
  if (WIFEXITED(status))
  {
    r.Status = WEXITSTATUS(status);
  }
  else if (WIFSIGNALED(status))
  {
    r.Status = 128 + WTERMSIG(status);
  }
  return r;
}

Result Render(const std::vector<std::string>& args)
{
  return RunProgram(SCATTERER_RENDER_EXE, args);
}

/** Renders @p input at 96x96 in @p mode to @p png. */
Result RenderFile(const std::string& input, const std::string& png,
  const std::string& mode = "template", const std::vector<std::string>& extra = {})
{
  std::vector<std::string> args = { "--input", input, "--size", "96x96", "--mode", mode, "--output",
    png };
  args.insert(args.end(), extra.begin(), extra.end());
  return Render(args);
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

/** Exit status 1, the file named, each of @p reasons in the message, no image written. */
void ExpectRefused(const Result& r, const std::string& input,
  const std::vector<std::string>& reasons, const std::string& png)
{
  EXPECT_EQ(r.Status, 1) << r.Output;
  EXPECT_TRUE(Contains(r.Output, input)) << "the message should name '" << input << "':\n"
                                         << r.Output;
  // The reasons are looked for in the message without the path, whose file name
  // may well contain the same words.
  std::string message = r.Output;
  for (auto at = message.find(input); at != std::string::npos; at = message.find(input))
  {
    message.erase(at, input.size());
  }
  for (const auto& reason : reasons)
  {
    EXPECT_TRUE(Contains(message, reason)) << "the message should say '" << reason << "':\n"
                                           << r.Output;
  }
  EXPECT_FALSE(fs::exists(png)) << "no image may be written for a refused volume";
}

/** Width, height and the number of pixels brighter than 8 in any channel; -1s if unreadable. */
struct PngStats
{
  int Width = -1, Height = -1;
  long Lit = -1;
};

PngStats ReadPng(const std::string& path)
{
  PngStats s;
  vtkNew<vtkPNGReader> reader;
  if (!fs::exists(path) || !reader->CanReadFile(path.c_str()))
  {
    return s;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  s.Width = dims[0];
  s.Height = dims[1];
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!pixels)
  {
    return s;
  }
  const int comps = std::min(pixels->GetNumberOfComponents(), 3);
  s.Lit = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    bool lit = false;
    for (int c = 0; c < comps; ++c)
    {
      lit = lit || pixels->GetTypedComponent(i, c) > 8;
    }
    s.Lit += lit ? 1 : 0;
  }
  return s;
}

const char* const Modes[] = { "template", "stock" };
}

// ---------------------------------------------------------------------------------------
// scatterer-render: what the automatic scene makes of non-finite values.

// A block of +Inf in a float ball: the automatic transfer function is laid over the
// finite range, so the ball shows (with GetScalarRange the ramp ended at +Inf and
// every finite voxel was transparent: black in every mode).
TEST_F(Cli, InfiniteBlockLeavesTheBallVisible)
{
  Volume v = Ball();
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        v.Values[(z * 16 + y) * 16 + x] = Inf;
  const std::string input = this->WriteMetaImage("inf-block", v);
  for (const char* mode : Modes)
  {
    const std::string png = this->Png(std::string("inf-block-") + mode + ".png");
    const Result r = RenderFile(input, png, mode);
    EXPECT_EQ(r.Status, 0) << mode << ":\n" << r.Output;
    const PngStats s = ReadPng(png);
    EXPECT_EQ(s.Width, 96) << mode;
    // The ball alone covers about 800 of the 9216 pixels at 96x96.
    EXPECT_GT(s.Lit, 400) << mode << ": the ball should show, not a black frame\n" << r.Output;
  }
}

TEST_F(Cli, VolumeWithNoFiniteValueIsRefused)
{
  const std::string input = this->WriteMetaImage("all-nan", Filled(16, 16, 16, NaN));
  const std::string png = this->Png("all-nan.png");
  ExpectRefused(RenderFile(input, png), input, { "all NaN or infinite" }, png);
}

// ---------------------------------------------------------------------------------------
// scatterer-render: placement (the reader refuses these first; see VolumeCheck.* below).

TEST_F(Cli, NaNSpacingIsRefused)
{
  Volume v = Ball();
  v.Spacing = "nan 1 1";
  const std::string input = this->WriteNrrd("nan-spacing", v);
  const std::string png = this->Png("nan-spacing.png");
  ExpectRefused(RenderFile(input, png), input, { "spacing" }, png);
}

TEST_F(Cli, ZeroSpacingIsRefused)
{
  Volume v = Ball();
  v.Spacing = "1 0 1";
  const std::string input = this->WriteMetaImage("zero-spacing", v);
  const std::string png = this->Png("zero-spacing.png");
  ExpectRefused(RenderFile(input, png), input, { "spacing" }, png);
}

TEST_F(Cli, NegativeSpacingIsRefused)
{
  Volume v = Ball();
  v.Spacing = "-1 1 1";
  const std::string input = this->WriteNrrd("negative-spacing", v);
  const std::string png = this->Png("negative-spacing.png");
  ExpectRefused(RenderFile(input, png), input, { "spacing", "negative" }, png);
}

TEST_F(Cli, AbsurdOriginIsRefused)
{
  Volume v = Ball();
  v.Origin = "1e30 0 0";
  const std::string input = this->WriteMetaImage("far-origin", v);
  const std::string png = this->Png("far-origin.png");
  ExpectRefused(RenderFile(input, png), input, { "origin" }, png);
}

// ---------------------------------------------------------------------------------------
// scatterer-render: shapes and values the ray caster cannot show.

TEST_F(Cli, SingleVoxelIsRefused)
{
  const std::string input = this->WriteMetaImage("one-voxel", Filled(1, 1, 1, 5.0f));
  const std::string png = this->Png("one-voxel.png");
  ExpectRefused(RenderFile(input, png), input, { "1 x 1 x 1", "at least 2" }, png);
}

TEST_F(Cli, SingleSliceIsRefused)
{
  const std::string input = this->WriteMetaImage("slice", Ramp(1, 16, 16));
  const std::string png = this->Png("slice.png");
  ExpectRefused(RenderFile(input, png), input, { "1 x 16 x 16", "at least 2" }, png);
}

TEST_F(Cli, SingleRowIsRefused)
{
  const std::string input = this->WriteMetaImage("row", Ramp(16, 1, 1));
  const std::string png = this->Png("row.png");
  ExpectRefused(RenderFile(input, png), input, { "16 x 1 x 1", "at least 2" }, png);
}

// 16384 x 1 x 1: VTK said "Invalid texture dimensions" and drew black. Refused for
// its shape before any texture is made.
TEST_F(Cli, LongRowIsRefused)
{
  const std::string input = this->WriteMetaImage("long-row", Ramp(16384, 1, 1));
  const std::string png = this->Png("long-row.png");
  ExpectRefused(RenderFile(input, png), input, { "16384 x 1 x 1", "at least 2" }, png);
}

TEST_F(Cli, ConstantVolumeIsRefusedByTheAutomaticScene)
{
  const std::string input = this->WriteMetaImage("constant", Filled(16, 16, 16, 7.0f));
  const std::string png = this->Png("constant.png");
  ExpectRefused(RenderFile(input, png), input, { "value is 7", "constant volume" }, png);
}

// --scene ct-head on a ball of values 0..100: the scene's opacity is 0 from 0 to
// 150 HU (between skin and bone), so nothing would show.
TEST_F(Cli, TransparentTransferFunctionIsRefused)
{
  const std::string input = this->WriteMetaImage("transparent", Ball());
  const std::string png = this->Png("transparent.png");
  ExpectRefused(RenderFile(input, png, "template", { "--scene", "ct-head" }), input,
    { "opacity", "nothing would show" }, png);
}

// ---------------------------------------------------------------------------------------
// scatterer-render: frames that VTK could not draw, or that come out blank.

// 16384 x 2 x 2 passes the shape rule, but no 3D texture that long fits (llvmpipe:
// 2048): VTK reports an error and used to leave a black frame with exit status 0.
TEST_F(Cli, VtkErrorWhileRenderingFailsTheRun)
{
  const std::string input = this->WriteMetaImage("too-long", Ramp(16384, 2, 2));
  for (const char* mode : Modes)
  {
    const std::string png = this->Png(std::string("too-long-") + mode + ".png");
    const Result r = RenderFile(input, png, mode);
    EXPECT_EQ(r.Status, 1) << mode << ":\n" << r.Output;
    EXPECT_TRUE(Contains(r.Output, "VTK reported")) << mode << ":\n" << r.Output;
    EXPECT_TRUE(Contains(r.Output, "too-long.mhd")) << mode << ":\n" << r.Output;
    EXPECT_FALSE(fs::exists(png)) << mode;
  }
}

// The ct-head scene's fixed camera does not see a volume placed 5000 units away: the
// frame is background only although the volume's values (0..1000 HU) are visible.
TEST_F(Cli, BlankFrameOfAVisibleVolumeFailsTheRun)
{
  Volume v = Ball(16, 1000.0f);
  v.Origin = "5000 5000 5000";
  const std::string input = this->WriteMetaImage("out-of-view", v);
  for (const char* mode : Modes)
  {
    const std::string png = this->Png(std::string("out-of-view-") + mode + ".png");
    const Result r = RenderFile(input, png, mode, { "--scene", "ct-head" });
    EXPECT_EQ(r.Status, 1) << mode << ":\n" << r.Output;
    EXPECT_TRUE(Contains(r.Output, "blank")) << mode << ":\n" << r.Output;
    EXPECT_TRUE(Contains(r.Output, input)) << mode << ":\n" << r.Output;
    EXPECT_FALSE(fs::exists(png)) << mode;
  }
}

// ---------------------------------------------------------------------------------------
// scatterer-render: number options. Parsing comes before any file or display.

TEST_F(Cli, NumbersAreParsedStrictly)
{
  struct Case
  {
    std::vector<std::string> Args;
    std::string Why;
  };
  const Case cases[] = {
    { { "--frames", "0x10" }, "hexadecimal" },
    { { "--threshold", "0x0.1p0" }, "hexadecimal" },
    { { "--frames", " 5" }, "spaces" },
    { { "--frames", "5 " }, "spaces" },
    { { "--frames", "5abc" }, "not a decimal integer" },
    { { "--frames", "2.5" }, "not an integer" },
    { { "--photons", "1e2" }, "not an integer" },
    { { "--strength", "1.5x" }, "not a decimal number" },
    { { "--strength", "inf" }, "not a finite number" },
    { { "--strength", "-Infinity" }, "not a finite number" },
    { { "--radius", "nan" }, "not a finite number" },
    { { "--threshold", "1e-320" }, "too small to represent" },
    { { "--threshold", "1e-400" }, "too small to represent" },
    { { "--radius", "1e400" }, "too large to represent" },
    { { "--threshold", "2" }, "[0, 1]" },
    { { "--frames", "99999999999999999999" }, "1..10000" },
    { { "--size", "96x0x10" }, "height" },
    { { "--size", "96" }, "WxH" },
  };
  // A missing input: should an argument wrongly pass, the run ends at once (exit 1)
  // instead of rendering the CT head.
  const std::string missing = (this->Dir / "missing.mhd").string();
  for (const auto& c : cases)
  {
    std::vector<std::string> args = c.Args;
    args.insert(args.end(), { "--input", missing });
    const Result r = Render(args);
    const std::string shown = c.Args[0] + " '" + c.Args[1] + "'";
    EXPECT_EQ(r.Status, 2) << shown << ":\n" << r.Output;
    EXPECT_TRUE(Contains(r.Output, shown)) << "the message should name " << shown << ":\n"
                                           << r.Output;
    EXPECT_TRUE(Contains(r.Output, c.Why)) << shown << " should say '" << c.Why << "':\n"
                                           << r.Output;
  }
}

// Plain decimals, with a sign or an exponent, are still numbers (and 0 is not "too small").
TEST_F(Cli, PlainDecimalNumbersAreAccepted)
{
  const std::string input = this->WriteMetaImage("ball", Ball());
  const std::string png = this->Png("ball.png");
  const Result r = RenderFile(input, png, "template",
    { "--illumination", "per-sample", "--threshold", "0", "--strength", "+0.5", "--radius", "2.5e0",
      "--frames", "+1", "--photons", "08" });
  EXPECT_EQ(r.Status, 0) << r.Output;
  EXPECT_GT(ReadPng(png).Lit, 400) << r.Output;
}

TEST_F(Cli, HelpSaysWhichNumbersAreRefused)
{
  const Result r = Render({ "--help" });
  EXPECT_EQ(r.Status, 0) << r.Output;
  for (const char* part :
    { "plain decimal", "hexadecimal (0x10)", "inf, nan", "1e-320", "Exit status" })
  {
    EXPECT_TRUE(Contains(r.Output, part)) << "--help should mention '" << part << "'";
  }
}

// --help printed integer settings with %g ("1.04858e+06", which the integer parser
// refuses) and listed two of the three transport options refused with
// --illumination per-sample.
TEST_F(Cli, HelpShowsNumbersAndConflictsAsTheParserTakesThem)
{
  const Result r = Render({ "--help" });
  EXPECT_EQ(r.Status, 0) << r.Output;
  EXPECT_TRUE(Contains(r.Output, "0..2147483647 (default 1048576)")) << r.Output;
  EXPECT_FALSE(Contains(r.Output, "1.04858e+06")) << r.Output;
  EXPECT_TRUE(
    Contains(r.Output, "(--transport-scale, --max-transport-voxels or --multiple-scattering)"))
    << r.Output;
  EXPECT_TRUE(Contains(r.Output, "1e-09..1e+09")) << r.Output;
  // The default as printed is taken back; with per-sample illumination it is refused.
  const Result typed = RunProgram(SCATTERER_RENDER_EXE,
    { "--max-transport-voxels", "1048576", "--illumination", "per-sample", "--input",
      (this->Dir / "missing.mhd").string() },
    "env -u DISPLAY");
  EXPECT_EQ(typed.Status, 2) << typed.Output;
  EXPECT_TRUE(Contains(typed.Output, "--max-transport-voxels and --illumination per-sample"))
    << typed.Output;
}

// ---------------------------------------------------------------------------------------
// Input before display (both programs): a missing file on a machine without a
// display is reported as the missing file, not as "no X display".

TEST_F(Cli, MissingInputIsReportedBeforeTheDisplay)
{
  const std::string missing = (this->Dir / "missing.mhd").string();
  for (const char* program : { SCATTERER_RENDER_EXE, SCATTERER_VIEWER_EXE })
  {
    const Result r = RunProgram(program, { "--input", missing }, "env -u DISPLAY");
    EXPECT_EQ(r.Status, 1) << program << ":\n" << r.Output;
    EXPECT_TRUE(Contains(r.Output, "no such file")) << program << ":\n" << r.Output;
    EXPECT_FALSE(Contains(r.Output, "X display")) << program << ":\n" << r.Output;
  }
}

// ---------------------------------------------------------------------------------------
// scatterer-viewer: the same volume check, and --test honours an explicit --size.

TEST_F(Cli, ViewerRefusesAVolumeWithNoFiniteValue)
{
  const std::string input = this->WriteMetaImage("all-inf", Filled(16, 16, 16, Inf));
  const std::string png = this->Png("viewer-all-inf.png");
  const Result r =
    RunProgram(SCATTERER_VIEWER_EXE, { "--input", input, "--play-events", "-", "--output", png });
  ExpectRefused(r, input, { "all NaN or infinite" }, png);
}

// The viewer writing its last frame (--output) fails on a VTK error as scatterer-render does.
TEST_F(Cli, ViewerFailsOnAVtkErrorWhenWritingTheFrame)
{
  const std::string input = this->WriteMetaImage("too-long", Ramp(16384, 2, 2));
  const std::string png = this->Png("viewer-too-long.png");
  const Result r = RunProgram(SCATTERER_VIEWER_EXE,
    { "--input", input, "--play-events", this->WriteDragRecording(), "--size", "96x96", "--output",
      png });
  EXPECT_EQ(r.Status, 1) << r.Output;
  EXPECT_TRUE(Contains(r.Output, "VTK reported")) << r.Output;
  EXPECT_FALSE(fs::exists(png));
}

// "--test --size 600x600" used to render at 300x300 without a word. The recording is
// one rotation drag, quicker than the built-in one.
TEST_F(Cli, ViewerTestModeKeepsAnExplicitSize)
{
  const std::string input = this->WriteMetaImage("ball", Ball());
  const std::string events = this->WriteDragRecording();
  const std::string png = this->Png("viewer-size.png");
  const Result r = RunProgram(SCATTERER_VIEWER_EXE,
    { "--test", "--input", input, "--play-events", events, "--size", "400x336", "--output", png });
  EXPECT_EQ(r.Status, 0) << r.Output;
  const PngStats s = ReadPng(png);
  EXPECT_EQ(s.Width, 400) << r.Output;
  EXPECT_EQ(s.Height, 336) << r.Output;
}

// ---------------------------------------------------------------------------------------
// The command lines (issue 16): CLI11 through Examples/Common/ScattererCommandLine.

namespace
{
/** The programs whose command lines are tested (scatterer-reference when built). */
std::vector<std::string> Programs()
{
  std::vector<std::string> programs = { SCATTERER_RENDER_EXE, SCATTERER_VIEWER_EXE };
#ifdef SCATTERER_REFERENCE_EXE
  programs.push_back(SCATTERER_REFERENCE_EXE);
#endif
  return programs;
}

std::string ProgramName(const std::string& path)
{
  return fs::path(path).filename().string();
}

/** Exit status 2, "<program>: " before the message, each of @p parts in it, the --help hint. */
void ExpectUsageError(
  const Result& r, const std::string& program, const std::vector<std::string>& parts)
{
  const std::string name = ProgramName(program);
  EXPECT_EQ(r.Status, 2) << name << ":\n" << r.Output;
  EXPECT_EQ(r.Output.rfind(name + ": ", 0), 0u) << r.Output;
  for (const auto& part : parts)
  {
    EXPECT_TRUE(Contains(r.Output, part)) << name << ": the message should say '" << part << "':\n"
                                          << r.Output;
  }
  EXPECT_TRUE(Contains(r.Output, "Run '" + name + " --help' for the options.")) << r.Output;
}
}

#ifdef SCATTERER_REFERENCE_EXE
// scatterer-reference lays both CT head scenes (one light, the light kit) over a volume
// given with --input, and refuses --input for a built-in synthetic scene.
TEST_F(Cli, ReferenceTakesAnInputInTheCtHeadScenesOnly)
{
  const std::string input = this->WriteMetaImage("ball", Ball());
  const Result builtIn =
    RunProgram(SCATTERER_REFERENCE_EXE, { "--scene", "shell-plate", "--input", input });
  ExpectUsageError(
    builtIn, SCATTERER_REFERENCE_EXE, { "--scene shell-plate", "--input", "built-in" });
  const std::string prefix = (this->Dir / "ball-light-kit").string();
  const Result lightKit = RunProgram(SCATTERER_REFERENCE_EXE,
    { "--scene", "ct-head-light-kit", "--input", input, "--size", "16x16", "--spp", "1", "--quiet",
      "--output", prefix });
  EXPECT_EQ(lightKit.Status, 0) << lightKit.Output;
  EXPECT_TRUE(fs::exists(prefix + ".vti")) << lightKit.Output;
}

// The accuracy benchmark's dense scene is built in: it renders without data, and refuses
// --input as the other synthetic scenes do.
TEST_F(Cli, ReferenceRendersTheBuiltInDenseScene)
{
  const std::string prefix = (this->Dir / "dense-ball").string();
  const Result dense = RunProgram(SCATTERER_REFERENCE_EXE,
    { "--scene", "dense-ball", "--size", "16x16", "--spp", "4", "--quiet", "--output", prefix });
  EXPECT_EQ(dense.Status, 0) << dense.Output;
  EXPECT_TRUE(Contains(dense.Output, "\"scene\": \"dense-ball\"")) << dense.Output;
  EXPECT_TRUE(fs::exists(prefix + ".vti")) << dense.Output;
  EXPECT_FALSE(Contains(dense.Output, "\"mean_luminance\": 0,")) << dense.Output;
  const Result withInput = RunProgram(SCATTERER_REFERENCE_EXE,
    { "--scene", "dense-ball", "--input", this->WriteMetaImage("ball", Ball()) });
  ExpectUsageError(
    withInput, SCATTERER_REFERENCE_EXE, { "--scene dense-ball", "--input", "built-in" });
}
#endif

// --opt=value means what --opt value means, in both programs.
TEST_F(Cli, OptionEqualsValueIsAccepted)
{
  const std::string input = this->WriteMetaImage("ball", Ball());
  const std::string renderPng = this->Png("render-equals.png");
  const Result render = Render({ "--input=" + input, "--size=96x96", "--frames=1",
    "--mode=template", "--output=" + renderPng });
  EXPECT_EQ(render.Status, 0) << render.Output;
  EXPECT_GT(ReadPng(renderPng).Lit, 400) << render.Output;

  const std::string viewerPng = this->Png("viewer-equals.png");
  const Result viewer = RunProgram(SCATTERER_VIEWER_EXE,
    { "--input=" + input, "--play-events=" + this->WriteDragRecording(), "--size=96x80",
      "--preset=ct-bone", "--output=" + viewerPng });
  EXPECT_EQ(viewer.Status, 0) << viewer.Output;
  EXPECT_TRUE(Contains(viewer.Output, "transfer function ct-bone")) << viewer.Output;
  const PngStats s = ReadPng(viewerPng);
  EXPECT_EQ(s.Width, 96) << viewer.Output;
  EXPECT_EQ(s.Height, 80) << viewer.Output;
}

// --max-transport-voxels reaches the mapper (the settings --json reports are read back
// from it), and a budget far below the ball's transport voxels still lights it.
TEST_F(Cli, MaxTransportVoxelsReachesTheMapper)
{
  const std::string input = this->WriteMetaImage("ball", Ball());
  const std::string png = this->Png("ball-budget.png");
  const Result r = RenderFile(input, png, "template", { "--json", "--max-transport-voxels", "64" });
  EXPECT_EQ(r.Status, 0) << r.Output;
  EXPECT_TRUE(Contains(r.Output, "max_transport_voxels=64 ")) << r.Output;
  EXPECT_GT(ReadPng(png).Lit, 400) << r.Output;
}

// The viewer's transfer-function keys and mouse: p (next preset), ] (level up), } (window
// wider), ctrl + left drag (window/level), w (screenshot into the working folder).
TEST_F(Cli, ViewerPresetWindowLevelAndScreenshotKeys)
{
  const std::string input = this->WriteMetaImage("ball", Ball());
  const fs::path events = this->Dir / "keys.log";
  auto key = [](int code, const char* sym)
  {
    std::string k;
    for (const char* e : { "KeyPressEvent", "CharEvent", "KeyReleaseEvent" })
    {
      k += std::string(e) + " 48 40 0 " + std::to_string(code) + " 1 " + sym + "\n";
    }
    return k;
  };
  // Modifiers 2 = control. The drag: 12 pixels right (level +12.5 % of the range) and
  // 10 down (window x e^(2 * -10 / 80) = 0.78).
  std::ofstream(events) << "# StreamVersion 1.1\nEnterEvent 48 40 0 0 0 0\n"
                        << key(112, "p") << key(93, "bracketright") << key(93, "bracketright")
                        << key(125, "braceright")
                        << "MouseMoveEvent 48 40 2 0 0 0\n"
                           "LeftButtonPressEvent 48 40 2 0 0 0\n"
                           "MouseMoveEvent 54 35 2 0 0 0\n"
                           "MouseMoveEvent 60 30 2 0 0 0\n"
                           "LeftButtonReleaseEvent 60 30 2 0 0 0\n"
                        << key(119, "w");
  const std::string png = this->Png("keys.png");
  const Result r = RunProgram(SCATTERER_VIEWER_EXE,
    { "--input", input, "--play-events", events.string(), "--size", "96x80", "--output", png },
    "cd " + Quote(this->Dir.string()) + " &&");
  ASSERT_EQ(r.Status, 0) << r.Output;
  // The ball is not CT: it opens with "auto"; p moves on to "ct-head".
  const size_t at = r.Output.find("transfer function ct-head  level ");
  ASSERT_NE(at, std::string::npos) << r.Output;
  double level = 0.0, window = 0.0;
  ASSERT_EQ(std::sscanf(r.Output.c_str() + at, "transfer function ct-head level %lf window x%lf",
              &level, &window),
    2)
    << r.Output;
  const double range = 100.0; // the ball's values: 0..100 (about)
  EXPECT_NEAR(level, (0.02 + 0.02 + 12.0 / 96.0) * range, 0.05 * range) << r.Output;
  EXPECT_NEAR(window, 1.25 * std::exp(2.0 * -10.0 / 80.0), 0.05) << r.Output;
  EXPECT_TRUE(Contains(r.Output, "saved scatterer-viewer-1.png")) << r.Output;
  EXPECT_EQ(ReadPng((this->Dir / "scatterer-viewer-1.png").string()).Width, 96) << r.Output;
}

// An unknown preset is a usage error that lists the known ones, before any file is read.
TEST_F(Cli, ViewerUnknownPresetIsAUsageError)
{
  const Result r =
    RunProgram(SCATTERER_VIEWER_EXE, { "--preset", "bones", "--input", "/nonexistent.mhd" });
  EXPECT_EQ(r.Status, 2) << r.Output;
  EXPECT_TRUE(Contains(r.Output, "'bones'")) << r.Output;
  EXPECT_TRUE(Contains(r.Output, "ct-bone")) << r.Output;
}

// The viewer's files are checked before the display, each with a message: an --output
// that is not a .png (PNG bytes were written under any name), --play-events that are not
// a recording (nothing was played, silently), a --record file that cannot be written (the
// session went on unrecorded).
TEST_F(Cli, ViewerRefusesFilesItCannotUse)
{
  std::ofstream(this->Dir / "garbage.log") << "not events\n";
  const std::string garbage = (this->Dir / "garbage.log").string();
  const Result jpg = RunProgram(SCATTERER_VIEWER_EXE, { "--test", "--output", "frame.jpg" });
  EXPECT_EQ(jpg.Status, 2) << jpg.Output;
  EXPECT_TRUE(Contains(jpg.Output, "must name a .png file")) << jpg.Output;
  for (const std::string& events : { garbage, this->Dir.string() })
  {
    const Result r = RunProgram(SCATTERER_VIEWER_EXE,
      { "--play-events", events, "--output", this->Png("events.png") }, "env -u DISPLAY");
    EXPECT_EQ(r.Status, 1) << r.Output;
    EXPECT_TRUE(Contains(r.Output, "is not a recording")) << r.Output;
  }
  const Result record = RunProgram(SCATTERER_VIEWER_EXE,
    { "--record", (this->Dir / "no-such-dir" / "r.log").string() }, "env -u DISPLAY");
  EXPECT_EQ(record.Status, 1) << record.Output;
  EXPECT_TRUE(Contains(record.Output, "cannot write the recording")) << record.Output;
}

// Options that contradict each other (one would be silently ignored or overridden)
// are refused with exit status 2 and a message naming both. The input is missing and
// there is no display: should a case wrongly pass, the run ends at once with status 1.
TEST_F(Cli, ConflictingOptionsAreRefused)
{
  struct Case
  {
    std::string Program;
    std::vector<std::string> Args;
    std::vector<std::string> Named;
  };
  const std::string missing = (this->Dir / "missing.mhd").string();
  const std::string log = (this->Dir / "session.log").string();
  const std::string drag = this->WriteDragRecording();
  const std::string dotDrag = (this->Dir / "." / "drag.log").string();
  const Case cases[] = {
    { SCATTERER_RENDER_EXE, { "--mode", "stock", "--photons", "8" },
      { "--photons", "--mode stock" } },
    { SCATTERER_RENDER_EXE, { "--mode=phong", "--illumination=per-sample" },
      { "--illumination", "--mode phong" } },
    { SCATTERER_RENDER_EXE, { "--interval", "4" }, { "--interval", "--illumination transport" } },
    { SCATTERER_RENDER_EXE, { "--illumination", "per-sample", "--transport-scale", "2" },
      { "--transport-scale", "--illumination per-sample" } },
    { SCATTERER_RENDER_EXE, { "--frames", "3", "--frames=4" }, { "--frames", "'3'", "'4'" } },
    { SCATTERER_VIEWER_EXE, { "--record", log, "--output", this->Png("v.png") },
      { "--record", "--output" } },
    { SCATTERER_VIEWER_EXE, { "--test", "--record", log }, { "--record", "--test" } },
    { SCATTERER_VIEWER_EXE, { "--record", log, "--play-events", log },
      { "--record", "--play-events" } },
    // The same file spelled another way (./) was accepted, and the recording overwrote
    // the events: an existing file, and one still to be written.
    { SCATTERER_VIEWER_EXE, { "--record", dotDrag, "--play-events", drag },
      { "--record", "--play-events", "name the same file" } },
    { SCATTERER_VIEWER_EXE,
      { "--record", (this->Dir / "." / "session.log").string(), "--play-events", log },
      { "--record", "--play-events", "name the same file" } },
    { SCATTERER_VIEWER_EXE, { "--size", "96x96", "--size", "128x128" }, { "--size", "'96x96'" } },
  };
  for (const auto& c : cases)
  {
    std::vector<std::string> args = c.Args;
    args.insert(args.end(), { "--input", missing });
    ExpectUsageError(RunProgram(c.Program, args, "env -u DISPLAY"), c.Program, c.Named);
  }
  // --scene auto would be ignored for the CT head (no --input).
  ExpectUsageError(RunProgram(SCATTERER_RENDER_EXE, { "--scene", "auto" }, "env -u DISPLAY"),
    SCATTERER_RENDER_EXE, { "--scene auto", "--input" });
  // The same value twice is not a contradiction.
  const Result same = RunProgram(
    SCATTERER_RENDER_EXE, { "--frames", "3", "--frames=3", "--input", missing }, "env -u DISPLAY");
  EXPECT_EQ(same.Status, 1) << same.Output;
  EXPECT_TRUE(Contains(same.Output, "no such file")) << same.Output;
}

TEST_F(Cli, UnknownOptionIsAUsageError)
{
  for (const std::string& program : Programs())
  {
    ExpectUsageError(RunProgram(program, { "--no-such-option" }), program,
      { "unknown argument '--no-such-option'" });
  }
}

TEST_F(Cli, MissingValueIsAUsageError)
{
  for (const std::string& program : Programs())
  {
    ExpectUsageError(RunProgram(program, { "--size" }), program, { "option --size needs a value" });
    ExpectUsageError(
      RunProgram(program, { "--output=" }), program, { "option --output needs a value" });
  }
}

// --help exits 0 and documents every exit status the program uses.
TEST_F(Cli, HelpExitsZeroAndListsTheExitStatuses)
{
  for (const std::string& program : Programs())
  {
    const Result r = RunProgram(program, { "--help" });
    EXPECT_EQ(r.Status, 0) << r.Output;
    for (const char* part : { "Exit status: 0 ", "; 1 ", "; 2 a bad command line", "--opt=VALUE" })
    {
      EXPECT_TRUE(Contains(r.Output, part))
        << ProgramName(program) << " --help should say '" << part << "':\n"
        << r.Output;
    }
  }
  EXPECT_TRUE(Contains(RunProgram(SCATTERER_VIEWER_EXE, { "--help" }).Output, "77 --test without"));
}

// Every file path the help cites is one the user has: in the source tree (relative
// paths) or the prepared CT head's place. Path-like words: a '/' and a file name with
// an extension ("transport/per-sample" and ".mhd/.mha" are not paths).
TEST_F(Cli, HelpCitesOnlyPathsTheUserHas)
{
  for (const std::string& program : Programs())
  {
    const Result r = RunProgram(program, { "--help" });
    std::vector<std::string> paths;
    std::string word;
    const auto take = [&]()
    {
      while (!word.empty() && std::string("(),;:'\".").find(word.back()) != std::string::npos)
        word.pop_back();
      while (!word.empty() && std::string("(,;:'\"").find(word.front()) != std::string::npos)
        word.erase(0, 1);
      const fs::path p(word);
      bool dotted = false;
      for (const auto& part : p)
        dotted =
          dotted || (!part.empty() && part.string()[0] == '.' && part != "." && part != "..");
      if (word.find('/') != std::string::npos && word.rfind("--", 0) != 0 &&
        p.filename().has_extension() && (p.is_absolute() || !dotted))
        paths.push_back(word);
      word.clear();
    };
    for (const char c : r.Output)
    {
      if (std::isspace(static_cast<unsigned char>(c)))
        take();
      else
        word += c;
    }
    take();
    EXPECT_FALSE(paths.empty()) << ProgramName(program) << " --help cites no path at all:\n"
                                << r.Output;
    for (const std::string& path : paths)
    {
      const bool has = fs::path(path).is_absolute()
        ? path == scatterer_examples::CtHeadPath() || fs::exists(path)
        : fs::exists(fs::path(SCATTERER_SOURCE_DIR) / path);
      EXPECT_TRUE(has) << ProgramName(program) << " --help cites '" << path
                       << "', which is neither in the source tree nor the CT head's place";
    }
  }
}

// ---------------------------------------------------------------------------------------
// The rules in-process, on images no reader has vetted.

namespace
{
vtkNew<vtkImageData> MakeImage(int n, float value)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfValues(static_cast<vtkIdType>(n) * n * n);
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    values->SetValue(i, value + static_cast<float>(i % 7));
  }
  image->GetPointData()->SetScalars(values);
  return image;
}
}

TEST(VolumeCheck, AcceptsAnOrdinaryVolume)
{
  auto image = MakeImage(4, 0.0f);
  EXPECT_EQ(scatterer_examples::CheckVolume(image, "ok.vti", true), "");
}

TEST(VolumeCheck, RefusesSpacingThatIsNotAFiniteNumberAboveZero)
{
  const double bad[] = { std::nan(""), 0.0, -1.0, std::numeric_limits<double>::infinity() };
  for (const double s : bad)
  {
    auto image = MakeImage(4, 0.0f);
    image->SetSpacing(1.0, s, 1.0);
    const std::string why = scatterer_examples::CheckVolume(image, "v.vti", true);
    EXPECT_TRUE(Contains(why, "'v.vti'") && Contains(why, "spacing")) << s << ": " << why;
  }
}

TEST(VolumeCheck, RefusesAnOriginThatIsNotFinite)
{
  auto image = MakeImage(4, 0.0f);
  image->SetOrigin(0.0, 0.0, std::numeric_limits<double>::infinity());
  const std::string why = scatterer_examples::CheckVolume(image, "v.vti", true);
  EXPECT_TRUE(Contains(why, "origin")) << why;
}

TEST(VolumeCheck, FiniteRangeIgnoresNaNAndInfinities)
{
  auto image = MakeImage(4, 10.0f); // values 10..16
  auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  values->SetValue(0, NaN);
  values->SetValue(1, Inf);
  values->SetValue(2, -Inf);
  double range[2] = { 0, 0 };
  ASSERT_TRUE(scatterer_examples::FiniteScalarRange(image, range));
  EXPECT_EQ(range[0], 10.0);
  EXPECT_EQ(range[1], 16.0);
}

TEST(VolumeCheck, OpacityVisibleOverLooksInsideTheRangeOnly)
{
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(150.0, 0.0);
  opacity->AddPoint(300.0, 0.8);
  property->SetScalarOpacity(opacity);
  const double below[2] = { 0.0, 100.0 };
  const double across[2] = { 0.0, 1000.0 };
  const double inside[2] = { 200.0, 210.0 }; // between two nodes
  EXPECT_FALSE(scatterer_examples::OpacityVisibleOver(property, below));
  EXPECT_TRUE(scatterer_examples::OpacityVisibleOver(property, across));
  EXPECT_TRUE(scatterer_examples::OpacityVisibleOver(property, inside));

  // A spike between two transparent ends: visible only through the node inside.
  vtkNew<vtkPiecewiseFunction> spike;
  spike->AddPoint(0.0, 0.0);
  spike->AddPoint(50.0, 0.5);
  spike->AddPoint(100.0, 0.0);
  property->SetScalarOpacity(spike);
  const double aroundSpike[2] = { 0.0, 100.0 };
  const double besideSpike[2] = { 100.0, 200.0 };
  EXPECT_TRUE(scatterer_examples::OpacityVisibleOver(property, aroundSpike));
  EXPECT_FALSE(scatterer_examples::OpacityVisibleOver(property, besideSpike));
}

// One version number (CMake/ScattererTemplateVersion.cmake) reaches every program.
TEST(Version, EveryProgramPrintsTheOneVersion)
{
  const std::pair<const char*, const char*> programs[] = {
    { "scatterer-render", SCATTERER_RENDER_EXE }, { "scatterer-viewer", SCATTERER_VIEWER_EXE }
  };
  for (const auto& p : programs)
  {
    const Result r = RunProgram(p.second, { "--version" });
    EXPECT_EQ(r.Status, 0) << p.first;
    EXPECT_EQ(
      r.Output.rfind(std::string(p.first) + " " + SCATTERER_EXPECTED_VERSION + " (VTK ", 0), 0u)
      << r.Output;
  }
}
