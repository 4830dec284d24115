// Bad volume headers (issue 13): each file is built here, byte by byte, and read
// through vtkScattererVolumeReader::ReadVolume. VTK 9.1's readers crash on some of
// these files and silently misread others; ReadVolume must refuse each one with a
// single-line message that names the file and the problem, and still read the
// valid variants correctly.
#include "vtkScattererVolumeReader.h"

#include "ScattererVolumeBytes.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMetaImageWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
constexpr int NX = 11, NY = 5, NZ = 3; // NX > 9: NRRD takes a first axis of <= 9 as components
constexpr int Voxels = NX * NY * NZ;

// Voxel n holds n - 100, so a shifted or misread volume shows in the first values.
int16_t Value(int n)
{
  return static_cast<int16_t>(n - 100);
}

std::string RawShorts(int count = Voxels)
{
  return scatterer_testing::ShortBytes(count, Value);
}

std::string AsciiShorts(int count = Voxels)
{
  return scatterer_testing::AsciiValues(count, NX, Value);
}

std::string MetaHeader(const std::string& extra, const std::string& dataFile = "v.raw")
{
  return scatterer_testing::MetaImageHeader("11 5 3", extra, dataFile);
}

std::string NrrdHeader(const std::string& fields)
{
  return scatterer_testing::NrrdHeader("built by TestVolumeHeaders", fields);
}

const std::string NrrdShort3D = "type: short\ndimension: 3\nsizes: 11 5 3\n";

// A little-endian NIfTI-1 header for the 11x5x3 short volume, data at byte 352.
std::string NiftiHeader(int16_t datatype = 4, int16_t bitpix = 16,
  std::array<float, 3> pixdim = { 1.0f, 1.0f, 1.0f }, const char* magic = "n+1")
{
  scatterer_testing::Nifti1Fields fields;
  fields.Dim = { NX, NY, NZ };
  fields.Datatype = datatype;
  fields.Bitpix = bitpix;
  fields.Pixdim = pixdim;
  fields.Magic = magic;
  return scatterer_testing::Nifti1Header(fields);
}

// A valid gzip file of stored (uncompressed) deflate blocks: enough to build gzip data
// without zlib, and its bytes are where the test expects them.
std::string Gzip(const std::string& data)
{
  return scatterer_testing::GzipStored(data);
}

class VolumeHeaderTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    Dir = fs::temp_directory_path() / ("scatterer-headers-" + std::string(info->name()));
    fs::remove_all(Dir);
    fs::create_directories(Dir);
  }
  void TearDown() override { fs::remove_all(Dir); }

  std::string Path(const std::string& name) const { return (Dir / name).string(); }

  std::string Write(const std::string& name, const std::string& bytes) const
  {
    std::ofstream(Path(name), std::ios::binary).write(bytes.data(), bytes.size());
    return Path(name);
  }

  // ReadVolume must refuse the file with one line naming it and holding every fragment.
  void ExpectRefused(const std::string& path, const std::vector<std::string>& fragments)
  {
    std::string error;
    auto image = vtkScattererVolumeReader::ReadVolume(path, &error);
    EXPECT_FALSE(image) << path << " should be refused";
    EXPECT_NE(error.find("'" + path + "'"), std::string::npos)
      << "message lacks the path: " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "message is not one line: " << error;
    for (const std::string& fragment : fragments)
    {
      EXPECT_NE(error.find(fragment), std::string::npos)
        << "message '" << error << "' lacks '" << fragment << "'";
    }
  }

  // ReadVolume must deliver the 11x5x3 volume with voxel n = n - 100 (components 1).
  void ExpectVolume(const std::string& path, double spacingX = 1.0)
  {
    std::string error;
    auto image = vtkScattererVolumeReader::ReadVolume(path, &error);
    ASSERT_TRUE(image) << error;
    int dims[3];
    image->GetDimensions(dims);
    ASSERT_EQ(dims[0], NX);
    ASSERT_EQ(dims[1], NY);
    ASSERT_EQ(dims[2], NZ);
    EXPECT_NEAR(image->GetSpacing()[0], spacingX, 1e-9);
    vtkDataArray* s = image->GetPointData()->GetScalars();
    ASSERT_EQ(s->GetNumberOfComponents(), 1);
    for (int n = 0; n < Voxels; ++n)
    {
      ASSERT_EQ(s->GetTuple1(n), Value(n)) << path << " voxel " << n;
    }
  }

  fs::path Dir;
};
}

// ---------------------------------------------------------------------------------------
// Files that crashed VTK 9.1's readers: refused before the reader sees them.

TEST_F(VolumeHeaderTest, MetaImageNegativeChannelCountIsRefused)
{
  Write("v.raw", RawShorts());
  // VTK: std::length_error from vtkImageData::AllocateScalars, exit 134.
  ExpectRefused(Write("v.mhd", MetaHeader("ElementNumberOfChannels = -3\n")),
    { "ElementNumberOfChannels", "-3", "1 to 4" });
}

TEST_F(VolumeHeaderTest, MetaImageHugeChannelCountIsRefused)
{
  Write("v.raw", RawShorts());
  ExpectRefused(Write("v.mhd", MetaHeader("ElementNumberOfChannels = 9223372036854775807\n")),
    { "ElementNumberOfChannels", "9223372036854775807" });
}

TEST_F(VolumeHeaderTest, NrrdDimensionFiveWithThreeSizesIsRefused)
{
  // VTK: SIGSEGV in vtkNrrdReader::RequestData.
  ExpectRefused(
    Write("v.nrrd",
      NrrdHeader("type: short\ndimension: 5\nsizes: 11 5 3\nencoding: raw\n") + RawShorts()),
    { "dimension", "5" });
}

TEST_F(VolumeHeaderTest, NrrdSizesMustMatchTheDimension)
{
  ExpectRefused(
    Write("v.nrrd",
      NrrdHeader("type: short\ndimension: 3\nsizes: 11 5\nencoding: raw\n") + RawShorts()),
    { "sizes", "2 entries", "dimension is 3" });
}

TEST_F(VolumeHeaderTest, NiftiUnknownDatatypeIsRefused)
{
  // VTK: SIGSEGV in vtkNIFTIImageReader::RequestInformation.
  ExpectRefused(Write("v.nii", NiftiHeader(999) + RawShorts()), { "datatype 999" });
}

TEST_F(VolumeHeaderTest, GzippedNiftiUnknownDatatypeIsRefused)
{
  // The header of a .nii.gz is inside the gzip stream: it is decoded to be checked.
  ExpectRefused(Write("v.nii.gz", Gzip(NiftiHeader(1536, 128) + RawShorts())), { "datatype 1536" });
}

// ---------------------------------------------------------------------------------------
// Files VTK 9.1 read into a wrong volume without an error.

TEST_F(VolumeHeaderTest, MetaImageCompressedFlagOnRawDataIsRefused)
{
  // VTK: "Uncompress failed" on stderr and a volume of zeros.
  Write("v.raw", RawShorts());
  ExpectRefused(Write("v.mhd", MetaHeader("CompressedData = True\n")),
    { "CompressedData = True", "not compressed" });
}

TEST_F(VolumeHeaderTest, CorruptCompressedMetaImageIsRefused)
{
  Write("v.mhd", MetaHeader("CompressedData = True\n", "v.zraw"));
  Write("v.zraw", std::string("\x78\x9c", 2) + std::string(40, '\xff')); // zlib header, junk
  ExpectRefused(Path("v.mhd"), { "compressed data is corrupt" });
}

TEST_F(VolumeHeaderTest, CompressedMetaImageIsRead)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(NX, NY, NZ);
  image->AllocateScalars(VTK_SHORT, 1);
  for (int n = 0; n < Voxels; ++n)
  {
    static_cast<int16_t*>(image->GetScalarPointer())[n] = Value(n);
  }
  vtkNew<vtkMetaImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(Path("v.mhd").c_str());
  writer->SetCompression(true);
  writer->Write();
  ExpectVolume(Path("v.mhd"));
}

TEST_F(VolumeHeaderTest, MetaImageHeaderSizePastTheDataIsRefused)
{
  // VTK: drawn from data shifted by 100 bytes, its tail past the end of the file.
  Write("v.raw", RawShorts());
  ExpectRefused(
    Write("v.mhd", MetaHeader("HeaderSize = 100\n")), { "HeaderSize (100)", "truncated" });
}

TEST_F(VolumeHeaderTest, MetaImageHeaderSizeIsHonoured)
{
  Write("skip.raw", std::string(100, 'x') + RawShorts());
  ExpectVolume(Write("skip.mhd", MetaHeader("HeaderSize = 100\n", "skip.raw")));
  // -1: the voxels are the last bytes of the file, whatever precedes them.
  Write("tail.raw", std::string(37, 'x') + RawShorts());
  ExpectVolume(Write("tail.mhd", MetaHeader("HeaderSize = -1\n", "tail.raw")));
}

TEST_F(VolumeHeaderTest, MetaImageHeaderSizeMinusOneNeedsTheWholeVolume)
{
  Write("v.raw", RawShorts(Voxels - 1));
  ExpectRefused(
    Write("v.mhd", MetaHeader("HeaderSize = -1\n")), { "HeaderSize = -1", "truncated" });
}

TEST_F(VolumeHeaderTest, NrrdAsciiJunkIsRefused)
{
  // VTK: the stream extraction fails at the junk and the volume is left as allocated.
  Write("v.txt", "12 7 junk 4\n" + AsciiShorts());
  ExpectRefused(Write("v.nhdr", NrrdHeader(NrrdShort3D + "encoding: ascii\ndata file: v.txt\n")),
    { "ascii voxel 2", "'junk'", "not a number" });
}

TEST_F(VolumeHeaderTest, NrrdAsciiShortOfNumbersIsRefused)
{
  Write("v.txt", AsciiShorts(Voxels - 10));
  ExpectRefused(Write("v.nhdr", NrrdHeader(NrrdShort3D + "encoding: ascii\ndata file: v.txt\n")),
    { "promises 165 ascii voxel values", "holds only 155" });
}

TEST_F(VolumeHeaderTest, NrrdAsciiAfterTheHeaderIsRefused)
{
  // VTK reads ascii from the start of the file, header included: every voxel 0.
  ExpectRefused(Write("v.nrrd", NrrdHeader(NrrdShort3D + "encoding: ascii\n") + AsciiShorts()),
    { "ascii data after the header" });
}

TEST_F(VolumeHeaderTest, NrrdEightBitAsciiIsRefused)
{
  // VTK reads an 8-bit ascii value as one character: "12" gives 49 and 50.
  Write("v.txt", AsciiShorts());
  ExpectRefused(
    Write("v.nhdr",
      NrrdHeader("type: uchar\ndimension: 3\nsizes: 11 5 3\nencoding: ascii\ndata file: v.txt\n")),
    { "8-bit", "character" });
}

TEST_F(VolumeHeaderTest, NrrdAsciiIsRead)
{
  Write("v.txt", AsciiShorts());
  ExpectVolume(Write("v.nhdr", NrrdHeader(NrrdShort3D + "encoding: ascii\ndata file: v.txt\n")));
}

TEST_F(VolumeHeaderTest, MetaImageBadSpacingIsRefused)
{
  Write("v.raw", RawShorts());
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
    { "ElementSpacing = nan 1 1\n", { "ElementSpacing", "not 3 numbers" } },
    { "ElementSpacing = 1e999 1 1\n", { "spacing along x is inf", "finite" } },
    { "ElementSpacing = 1 0 1\n", { "spacing along y is 0" } },
    { "ElementSpacing = 1 1 -2\n", { "spacing along z is -2", "negative" } },
    { "ElementSize = 0 1 1\n", { "spacing along x is 0" } },
  };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.first);
    ExpectRefused(Write("v.mhd", MetaHeader(c.first)), c.second);
  }
}

TEST_F(VolumeHeaderTest, NrrdBadSpacingIsRefused)
{
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
    { "spacings: nan 1 1\n", { "spacing along x is nan" } },
    { "spacings: 1 0 1\n", { "spacing along y is 0" } },
    { "spacings: 1 1 -2\n", { "spacing along z is -2", "negative" } },
    { "space: RAS\nspace directions: (1,0,0) (0,0,0) (0,0,1)\n",
      { "space directions", "axis y", "no direction" } },
    { "space: RAS\nspace directions: (nan,0,0) (0,1,0) (0,0,1)\n",
      { "space directions", "'nan'", "not a finite number" } },
  };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.first);
    ExpectRefused(
      Write("v.nrrd", NrrdHeader(NrrdShort3D + c.first + "encoding: raw\n") + RawShorts()),
      c.second);
  }
}

TEST_F(VolumeHeaderTest, NiftiBadPixdimIsRefused)
{
  const std::vector<std::pair<std::array<float, 3>, std::string>> cases = {
    { { std::nanf(""), 1, 1 }, "spacing along x is nan" },
    { { 1, 0, 1 }, "spacing along y is 0" },
    { { 1, 1, -2 }, "spacing along z is -2" },
  };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.second);
    ExpectRefused(Write("v.nii", NiftiHeader(4, 16, c.first) + RawShorts()), { c.second });
  }
}

TEST_F(VolumeHeaderTest, AbsurdOriginIsRefused)
{
  Write("v.raw", RawShorts());
  ExpectRefused(
    Write("far.mhd", MetaHeader("Offset = 1e30 0 0\n")), { "origin along x is 1e+30", "2^24" });
  ExpectRefused(
    Write("huge.mhd", MetaHeader("Offset = 0 1e999 0\n")), { "origin along y is inf", "finite" });
  ExpectRefused(
    Write("far.nrrd",
      NrrdHeader(NrrdShort3D + "space origin: (0,0,-1e30)\nencoding: raw\n") + RawShorts()),
    { "origin along z is -1e+30" });
  // A real scanner origin, hundreds of millimetres away, is fine.
  ExpectVolume(Write("near.mhd", MetaHeader("Offset = -250.5 -180 1200\n")));
}

// ---------------------------------------------------------------------------------------
// Messages that did not say what was wrong.

TEST_F(VolumeHeaderTest, TruncatedGzipNrrdSaysSo)
{
  // VTK said only ": 81" (the end of "..., GetHeaderSize(): 81").
  const std::string gz = Gzip(RawShorts());
  ExpectRefused(
    Write("v.nrrd",
      NrrdHeader(NrrdShort3D + "encoding: gzip\nendian: little\n") + gz.substr(0, gz.size() / 2)),
    { "gzip data is truncated" });
}

TEST_F(VolumeHeaderTest, CorruptGzipNrrdSaysSo)
{
  std::string gz = Gzip(RawShorts());
  gz[12] = static_cast<char>(gz[12] ^ 0x5a); // the stored block's length no longer checks
  ExpectRefused(Write("v.nrrd", NrrdHeader(NrrdShort3D + "encoding: gzip\nendian: little\n") + gz),
    { "gzip data is corrupt" });
}

TEST_F(VolumeHeaderTest, GzipNrrdCorruptPastTheCheckedPrefixSaysSo)
{
  // The check decodes the first MiB; damage beyond it is found by VTK's reader, whose
  // message is replaced by one that says what is wrong.
  const int nz = 48; // 11 x 1100 x 48 shorts: 1.16 MB
  std::string raw;
  for (int n = 0; n < 11 * 1100 * nz; ++n)
  {
    raw += static_cast<char>(n & 0xff);
    raw += static_cast<char>((n >> 8) & 0x7f);
  }
  const std::string gz = Gzip(raw);
  const std::string path = Write("v.nrrd",
    NrrdHeader("type: short\ndimension: 3\nsizes: 11 1100 48\nencoding: gzip\nendian: little\n") +
      gz.substr(0, gz.size() - 20000));
  ExpectRefused(path, { "gzip data is corrupt or truncated" });
  std::string error;
  vtkScattererVolumeReader::ReadVolume(path, &error);
  EXPECT_EQ(error.find("GetHeaderSize"), std::string::npos) << error;
}

TEST_F(VolumeHeaderTest, DicomFolderErrorIsOneLine)
{
  // VTK's executive adds "returned failure for request: vtkInformation (...)" and a dump
  // of the request over many lines.
  fs::create_directories(Dir / "series");
  Write("series/a.dcm", "not a DICOM file\n");
  ExpectRefused(Path("series"), { "no DICOM images" });
  std::string error;
  vtkScattererVolumeReader::ReadVolume(Path("series"), &error);
  EXPECT_EQ(error.find("vtkInformation"), std::string::npos) << error;
}

// ---------------------------------------------------------------------------------------
// More headers VTK 9.1 misreads, found while emulating its readers.

TEST_F(VolumeHeaderTest, NrrdDetachedRawLargerThanTheVoxelsIsRefused)
{
  // vtkImageReader2 takes the last bytes of a detached data file: the volume shifts.
  Write("v.raw", RawShorts() + "xxxx");
  ExpectRefused(Write("v.nhdr", NrrdHeader(NrrdShort3D + "encoding: raw\ndata file: v.raw\n")),
    { "334 bytes", "more than the 330", "shifting" });
}

TEST_F(VolumeHeaderTest, NrrdDetachedGzipLargerThanTheVoxelsIsRefused)
{
  // Stored blocks make the gzip file 18 bytes larger than the voxels; VTK then skips
  // 18 bytes of it and reads the rest as raw data.
  Write("v.raw.gz", Gzip(RawShorts()));
  ExpectRefused(Write("v.nhdr", NrrdHeader(NrrdShort3D + "encoding: gzip\ndata file: v.raw.gz\n")),
    { "larger than the 330 bytes", "skip" });
}

TEST_F(VolumeHeaderTest, NrrdSpaceBeforeSizesOfFourAxesIsRefused)
{
  // "space" makes vtkNrrdReader take 3 axes: "sizes: 1 11 5 3" loses its last axis.
  ExpectRefused(Write("v.nrrd",
                  NrrdHeader("type: short\ndimension: 4\nspace: RAS\nsizes: 1 11 5 3\n"
                             "encoding: raw\n") +
                    RawShorts()),
    { "'space'", "3 axes", "dimension is 4" });
}

TEST_F(VolumeHeaderTest, NrrdHeaderWithoutFinalLineEndIsRefused)
{
  // Found by fuzz_volume_headers: vtkNrrdReader re-reads a last line without '\n' forever
  // (here it appends "data.raw" to its list of data files until memory runs out).
  Write("v.raw", RawShorts());
  ExpectRefused(Write("v.nhdr", "NRRD0004\n" + NrrdShort3D + "encoding: raw\ndata file: v.raw"),
    { "no line end" });
}

TEST_F(VolumeHeaderTest, NrrdWithOneAxisInSpaceIsRefused)
{
  // Found by fuzz_volume_headers: "sizes: 2 4" is 2 values per voxel along one axis, and
  // VTK 9.1 then reads raw data from a stream it never opened (SIGSEGV); ascii data of
  // one axis stays 0.
  Write("v.raw", RawShorts(8));
  ExpectRefused(Write("v.nhdr",
                  NrrdHeader("type: short\ndimension: 2\nsizes: 2 4\nencoding: raw\n"
                             "data file: v.raw\n")),
    { "1 axis in space", "first axis as values per voxel" });
  Write("v.txt", AsciiShorts(20));
  ExpectRefused(Write("a.nhdr",
                  NrrdHeader("type: short\ndimension: 1\nsizes: 20\nencoding: ascii\n"
                             "data file: v.txt\n")),
    { "1 axis in space" });
}

TEST_F(VolumeHeaderTest, MetaImageControlCharacterIsRefused)
{
  // Found by fuzz_volume_headers: MetaIO compares field names as C strings, so
  // "ElementSpacing\0=" sets the spacing that a byte-exact reading of the name ignores.
  Write("v.raw", RawShorts());
  ExpectRefused(Write("v.mhd", MetaHeader(std::string("ElementSpacing\0= 2 2 2\n", 23))),
    { "header line 5", "control character (byte 0)" });
}

TEST_F(VolumeHeaderTest, MetaImageLongFieldNameOrValueIsRefused)
{
  // Found by fuzz_volume_headers: MetaIO strcpy()s the name of an unknown field into a
  // 255-byte buffer, and a Comment (Name, ObjectType, ...) into another; with a longer
  // one VTK 9.1 aborts ("buffer overflow detected").
  Write("v.raw", RawShorts());
  ExpectRefused(Write("name.mhd", MetaHeader("Comment" + std::string(300, 'x') + " = hello\n")),
    { "header line 5", "field name of 307 characters", "254" });
  ExpectRefused(Write("value.mhd", MetaHeader("Comment = " + std::string(300, 'x') + "\n")),
    { "header line 5", "value of 300 characters", "254" });
  // A long data file path (here 266 characters) is fine: MetaIO keeps it in a std::string.
  Write(std::string(200, 'd') + ".raw", RawShorts());
  std::string path;
  for (int i = 0; i < 31; ++i)
  {
    path += "./";
  }
  ExpectVolume(Write("path.mhd", MetaHeader("", path + std::string(200, 'd') + ".raw")));
}

TEST_F(VolumeHeaderTest, MetaImageLongIsRefused)
{
  // MetaIO reads MET_LONG as 4 bytes per value into VTK's 8-byte VTK_LONG array: voxels
  // 0-81 come out right and the rest of the volume stays zero, without an error.
  std::string ints;
  for (int n = 0; n < Voxels; ++n)
  {
    const int32_t v = Value(n);
    ints.append(reinterpret_cast<const char*>(&v), 4);
  }
  Write("v.raw", ints);
  ExpectRefused(Write("v.mhd",
                  "NDims = 3\nDimSize = 11 5 3\nElementType = MET_LONG\nElementDataFile = v.raw\n"),
    { "MET_LONG", "half the volume" });
  ExpectVolume(Write(
    "int.mhd", "NDims = 3\nDimSize = 11 5 3\nElementType = MET_INT\nElementDataFile = v.raw\n"));
}

TEST_F(VolumeHeaderTest, DataSplitOverSeveralFilesIsRefused)
{
  // vtkNrrdReader formats a pattern with snprintf (here "%n") and loops on its step.
  ExpectRefused(Write("p.nhdr", NrrdHeader(NrrdShort3D + "encoding: raw\ndata file: %n%s 1 3 0\n")),
    { "several files" });
  ExpectRefused(Write("l.nhdr", NrrdHeader(NrrdShort3D + "encoding: raw\ndata file: LIST\n")),
    { "several files" });
  ExpectRefused(Write("p.mhd", MetaHeader("", "slice%03d.raw 1 3 1")), { "several files" });
  ExpectRefused(Write("l.mhd", MetaHeader("", "LIST 2D")), { "several files" });
}

TEST_F(VolumeHeaderTest, NiftiWithSeparateImageMagicIsRefused)
{
  // Magic "ni1" (voxels in a .img file) in a .nii: VTK would read the header as voxels.
  ExpectRefused(
    Write("v.nii", NiftiHeader(4, 16, { 1, 1, 1 }, "ni1") + RawShorts()), { "'ni1'", ".img" });
}

TEST_F(VolumeHeaderTest, ValidVariantsAreRead)
{
  // The checks must not refuse what VTK reads right.
  Write("v.raw", RawShorts());
  ExpectVolume(
    Write("colon.mhd",
      "NDims: 3\nDimSize: 11 5 3\nElementType: MET_SHORT_ARRAY\nElementSpacing: 0.5 1 1\n"
      "ElementDataFile: v.raw\n"),
    0.5);
  ExpectVolume(Write("local.mha", MetaHeader("BinaryData = True\n", "LOCAL") + RawShorts()));
  ExpectVolume(
    Write("crlf.nrrd",
      "NRRD0004\r\ntype: short\r\ndimension: 3\r\nsizes: 11 5 3\r\nspacings: 0.25 1 1\r\n"
      "encoding: raw\r\nendian: little\r\n\r\n" +
        RawShorts()),
    0.25);
  ExpectVolume(Write("dirs.nrrd",
                 NrrdHeader(NrrdShort3D +
                   "space: left-posterior-superior\n"
                   "space directions: (-2,0,0) (0,1,0) (0,0,1)\n"
                   "space origin: (-120.5, 30, 7)\nencoding: raw\nendian: little\n") +
                   RawShorts()),
    2.0);
  ExpectVolume(Write(
    "gz.nrrd", NrrdHeader(NrrdShort3D + "encoding: gzip\nendian: little\n") + Gzip(RawShorts())));
  ExpectVolume(Write("v.nii", NiftiHeader() + RawShorts()));
  ExpectVolume(Write("v.nii.gz", Gzip(NiftiHeader() + RawShorts())));
}
