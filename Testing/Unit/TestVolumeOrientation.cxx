// vtkScattererVolumeReader places volumes in patient space (LPS) from the file's own
// orientation: DICOM's Image Orientation/Position (Patient) and NIfTI's sform/qform.
// The files are written here byte by byte, so the expected world positions come from the
// standards' formulas (DICOM PS3.3 C.7.6.2.1.1, NIfTI-1 nifti1.h), not from the readers.
#include "ScattererDicomBytes.h"
#include "vtkScattererVolumeReader.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
using Vec3 = std::array<double, 3>;

constexpr int COLS = 11, ROWS = 5, SLICES = 3; // file order: column fastest

// The stored value of file voxel (column c, row r, slice s).
int Stored(int c, int r, int s)
{
  return c + 20 * r + 200 * s;
}

class VolumeOrientationTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    Dir = fs::temp_directory_path() / ("scatterer-orientation-" + std::string(info->name()));
    fs::remove_all(Dir);
    fs::create_directories(Dir);
  }
  void TearDown() override { fs::remove_all(Dir); }
  std::string Path(const std::string& name) const { return (Dir / name).string(); }
  fs::path Dir;
};

vtkSmartPointer<vtkImageData> Read(const std::string& path)
{
  std::string error;
  auto image = vtkScattererVolumeReader::ReadVolume(path, &error);
  EXPECT_TRUE(image) << error;
  return image;
}

std::string ReadError(const std::string& path)
{
  std::string error;
  auto image = vtkScattererVolumeReader::ReadVolume(path, &error);
  EXPECT_FALSE(image) << path << " should not read";
  return error;
}

// Every voxel with value Stored(c, r, s) * slope + intercept must sit, by the image's own
// origin, spacing and direction, at expected(c, r, s).
template <typename Expected>
void ExpectPlaced(vtkImageData* image, Expected expected, double slope = 1, double intercept = 0)
{
  ASSERT_TRUE(image);
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0] * dims[1] * dims[2], COLS * ROWS * SLICES);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  // value -> file voxel
  std::vector<std::array<int, 3>> byValue(Stored(COLS, ROWS, SLICES), { -1, -1, -1 });
  for (int s = 0; s < SLICES; ++s)
    for (int r = 0; r < ROWS; ++r)
      for (int c = 0; c < COLS; ++c)
        byValue[Stored(c, r, s)] = { c, r, s };
  int checked = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
      {
        const double value = scalars->GetTuple1(i + dims[0] * (j + dims[1] * k));
        const double storedValue = (value - intercept) / slope;
        const int stored = static_cast<int>(std::lround(storedValue));
        ASSERT_NEAR(storedValue, stored, 1e-6) << "voxel " << i << "," << j << "," << k;
        ASSERT_TRUE(stored >= 0 && stored < int(byValue.size()) && byValue[stored][0] >= 0)
          << "unexpected value " << value << " at " << i << "," << j << "," << k;
        const auto& file = byValue[stored];
        const Vec3 want = expected(file[0], file[1], file[2]);
        double index[3] = { double(i), double(j), double(k) };
        double world[3];
        image->TransformContinuousIndexToPhysicalPoint(index, world);
        for (int a = 0; a < 3; ++a)
          ASSERT_NEAR(world[a], want[a], 1e-4)
            << "file voxel (" << file[0] << "," << file[1] << "," << file[2] << ") axis " << a
            << " read at index " << i << "," << j << "," << k;
        ++checked;
      }
  EXPECT_EQ(checked, COLS * ROWS * SLICES);
}

// ---- DICOM, written by hand (explicit VR little endian, or RLE lossless) -------------

struct DicomSlice
{
  std::string SeriesUid = "1.2.3.9";
  std::string Orientation = "1\\0\\0\\0\\1\\0";
  Vec3 Position = { 0, 0, 0 };
  std::string PixelSpacing = "0.75\\0.5"; // between rows \ between columns
  bool Rescale = false;
  std::string Slope = "1", Intercept = "0";
  std::string TransferSyntax = "1.2.840.10008.1.2.1";
  bool Encapsulated = false;     // pixel data as RLE fragments (PS3.5 Annex G)
  std::vector<uint8_t> Fragment; // when set, sent as the only fragment instead of RLE
};

std::string Number(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", v);
  return text;
}

// PS3.5 G.3.1: literal runs only (a control byte n < 128 copies n + 1 bytes); even length.
std::vector<uint8_t> PackBits(const std::vector<uint8_t>& bytes)
{
  std::vector<uint8_t> out;
  for (size_t at = 0; at < bytes.size(); at += 128)
  {
    const size_t n = std::min<size_t>(128, bytes.size() - at);
    out.push_back(uint8_t(n - 1));
    out.insert(out.end(), bytes.begin() + at, bytes.begin() + at + n);
  }
  if (out.size() % 2)
    out.push_back(0);
  return out;
}

void WriteDicomSlice(const std::string& path, int s, const DicomSlice& spec)
{
  scatterer_testing::DicomBytes bytes;
  const std::string instance = spec.SeriesUid + "." + std::to_string(s + 1);
  bytes.Uid(0x0002, 0x0002, "1.2.840.10008.5.1.4.1.1.2");
  bytes.Uid(0x0002, 0x0003, instance);
  bytes.Uid(0x0002, 0x0010, spec.TransferSyntax);
  bytes.Uid(0x0008, 0x0016, "1.2.840.10008.5.1.4.1.1.2");
  bytes.Uid(0x0008, 0x0018, instance);
  bytes.Text(0x0008, 0x0060, "CS", "CT");
  bytes.Text(0x0010, 0x0020, "LO", "SCATTERER");
  bytes.Uid(0x0020, 0x000D, "1.2.3.8");
  bytes.Uid(0x0020, 0x000E, spec.SeriesUid);
  bytes.Text(0x0020, 0x0011, "IS", "7");
  bytes.Text(0x0020, 0x0013, "IS", std::to_string(s + 1));
  bytes.Text(0x0020, 0x0032, "DS",
    Number(spec.Position[0]) + "\\" + Number(spec.Position[1]) + "\\" + Number(spec.Position[2]));
  bytes.Text(0x0020, 0x0037, "DS", spec.Orientation);
  bytes.UShort(0x0028, 0x0002, 1);
  bytes.Text(0x0028, 0x0004, "CS", "MONOCHROME2");
  bytes.UShort(0x0028, 0x0010, ROWS);
  bytes.UShort(0x0028, 0x0011, COLS);
  bytes.Text(0x0028, 0x0030, "DS", spec.PixelSpacing);
  bytes.UShort(0x0028, 0x0100, 16);
  bytes.UShort(0x0028, 0x0101, 16);
  bytes.UShort(0x0028, 0x0102, 15);
  bytes.UShort(0x0028, 0x0103, 0); // unsigned stored values
  if (spec.Rescale)
  {
    bytes.Text(0x0028, 0x1052, "DS", spec.Intercept);
    bytes.Text(0x0028, 0x1053, "DS", spec.Slope);
    bytes.Text(0x0028, 0x1054, "LO", "HU");
  }
  std::vector<uint16_t> pixels; // rows top-down, as DICOM stores them
  for (int r = 0; r < ROWS; ++r)
    for (int c = 0; c < COLS; ++c)
      pixels.push_back(uint16_t(Stored(c, r, s)));
  bytes.Put16(0x7FE0);
  bytes.Put16(0x0010);
  if (!spec.Encapsulated)
  {
    bytes.Raw({ 'O', 'W', 0, 0 });
    bytes.Put32(uint32_t(pixels.size() * 2));
    for (uint16_t v : pixels)
      bytes.Put16(v);
  }
  else
  {
    std::vector<uint8_t> fragment = spec.Fragment;
    if (fragment.empty())
    {
      // RLE: segment 1 the high bytes, segment 2 the low bytes (PS3.5 G.2).
      std::vector<uint8_t> high, low;
      for (uint16_t v : pixels)
      {
        high.push_back(uint8_t(v >> 8));
        low.push_back(uint8_t(v & 0xff));
      }
      const auto h = PackBits(high), l = PackBits(low);
      uint32_t header[16] = { 2, 64, uint32_t(64 + h.size()) };
      fragment.resize(64);
      std::memcpy(fragment.data(), header, 64); // little-endian host
      fragment.insert(fragment.end(), h.begin(), h.end());
      fragment.insert(fragment.end(), l.begin(), l.end());
    }
    bytes.Raw({ 'O', 'B', 0, 0 });
    bytes.Put32(0xFFFFFFFFu);
    bytes.Put16(0xFFFE);
    bytes.Put16(0xE000);
    bytes.Put32(0); // empty basic offset table
    bytes.Put16(0xFFFE);
    bytes.Put16(0xE000);
    bytes.Put32(uint32_t(fragment.size()));
    bytes.Raw(fragment.begin(), fragment.end());
    bytes.Put16(0xFFFE);
    bytes.Put16(0xE0DD);
    bytes.Put32(0);
  }
  bytes.Write(path);
}

// A sagittal series: rows run anterior->posterior (+y), columns superior->inferior (-z),
// so the slice normal row x column is -x (toward the patient's right).
const Vec3 kRow = { 0, 1, 0 }, kColumn = { 0, 0, -1 }, kNormal = { -1, 0, 0 };
const Vec3 kFirst = { 50, -100, 80 };
constexpr double kColumnSpacing = 0.5, kRowSpacing = 0.75, kSliceSpacing = 2.0;

DicomSlice Sagittal(int s)
{
  DicomSlice spec;
  spec.Orientation = "0\\1\\0\\0\\0\\-1";
  spec.PixelSpacing = "0.75\\0.5";
  for (int a = 0; a < 3; ++a)
    spec.Position[a] = kFirst[a] + s * kSliceSpacing * kNormal[a];
  return spec;
}

// DICOM PS3.3 C.7.6.2.1.1: P = S + c * dc * X + r * dr * Y, S the slice's position.
Vec3 SagittalWorld(int c, int r, int s)
{
  Vec3 p;
  for (int a = 0; a < 3; ++a)
    p[a] = kFirst[a] + s * kSliceSpacing * kNormal[a] + c * kColumnSpacing * kRow[a] +
      r * kRowSpacing * kColumn[a];
  return p;
}

void WriteSagittalSeries(const std::string& folder, DicomSlice (*make)(int))
{
  fs::create_directories(folder);
  for (int s = SLICES - 1; s >= 0; --s) // out of order on purpose
    WriteDicomSlice(folder + "/im" + std::to_string(s) + ".dcm", s, make(s));
}

bool HasVtkDicom()
{
  return vtkScattererVolumeReader::GetDicomSupport().find("with vtk-dicom") != std::string::npos;
}
}

TEST_F(VolumeOrientationTest, SagittalDicomSeriesLandsWhereItsHeaderSays)
{
  if (!HasVtkDicom())
    GTEST_SKIP() << vtkScattererVolumeReader::GetDicomSupport();
  WriteSagittalSeries(Path("sag"), Sagittal);
  auto image = Read(Path("sag"));
  ASSERT_TRUE(image);
  // Grid: spacing per index axis, origin at the first voxel of the first slice.
  EXPECT_NEAR(image->GetSpacing()[0], kColumnSpacing, 1e-6);
  EXPECT_NEAR(image->GetSpacing()[1], kRowSpacing, 1e-6);
  EXPECT_NEAR(image->GetSpacing()[2], kSliceSpacing, 1e-6);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(image->GetOrigin()[a], kFirst[a], 1e-6) << "origin axis " << a;
  // Direction columns: row direction, column direction, slice normal.
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_NEAR(image->GetDirectionMatrix()->GetElement(a, 0), kRow[a], 1e-9);
    EXPECT_NEAR(image->GetDirectionMatrix()->GetElement(a, 1), kColumn[a], 1e-9);
    EXPECT_NEAR(image->GetDirectionMatrix()->GetElement(a, 2), kNormal[a], 1e-9);
  }
  ExpectPlaced(image, SagittalWorld);
}

TEST_F(VolumeOrientationTest, DicomRescaleGivesHounsfieldUnits)
{
  if (!HasVtkDicom())
    GTEST_SKIP() << vtkScattererVolumeReader::GetDicomSupport();
  WriteSagittalSeries(Path("ct"),
    [](int s)
    {
      DicomSlice spec = Sagittal(s);
      spec.Rescale = true;
      spec.Slope = "2";
      spec.Intercept = "-1024";
      return spec;
    });
  auto image = Read(Path("ct"));
  ASSERT_TRUE(image);
  // Stored 0 is -1024 HU: the values must come out negative, in a signed type.
  EXPECT_LT(image->GetScalarRange()[0], -1000);
  ExpectPlaced(image, SagittalWorld, 2.0, -1024.0);
}

TEST_F(VolumeOrientationTest, DicomFractionalRescaleGivesFloats)
{
  if (!HasVtkDicom())
    GTEST_SKIP() << vtkScattererVolumeReader::GetDicomSupport();
  WriteSagittalSeries(Path("ct"),
    [](int s)
    {
      DicomSlice spec = Sagittal(s);
      spec.Rescale = true;
      spec.Slope = "0.5";
      spec.Intercept = "-1000";
      return spec;
    });
  auto image = Read(Path("ct"));
  ASSERT_TRUE(image);
  EXPECT_TRUE(image->GetScalarType() == VTK_FLOAT || image->GetScalarType() == VTK_DOUBLE);
  ExpectPlaced(image, SagittalWorld, 0.5, -1000.0);
}

TEST_F(VolumeOrientationTest, RleCompressedDicomSeriesReads)
{
  if (!HasVtkDicom())
    GTEST_SKIP() << vtkScattererVolumeReader::GetDicomSupport();
  WriteSagittalSeries(Path("rle"),
    [](int s)
    {
      DicomSlice spec = Sagittal(s);
      spec.TransferSyntax = "1.2.840.10008.1.2.5"; // RLE Lossless
      spec.Encapsulated = true;
      return spec;
    });
  ExpectPlaced(Read(Path("rle")), SagittalWorld);
}

// JPEG lossless, JPEG-LS and JPEG 2000 (lossless) series, made from the uncompressed one
// by GDCM's gdcmconv (Debian libgdcm-tools; scripts/install-deps.sh): every voxel comes
// back with its value and place. This is the "JPEG-lossless series" that VTK's own
// DICOM reader could not read.
TEST_F(VolumeOrientationTest, CompressedDicomSeriesRead)
{
  if (!HasVtkDicom())
    GTEST_SKIP() << vtkScattererVolumeReader::GetDicomSupport();
  if (!fs::exists("/usr/bin/gdcmconv"))
    GTEST_SKIP() << "gdcmconv is missing (apt-get install libgdcm-tools)";
  WriteSagittalSeries(Path("plain"), Sagittal);
  for (const char* codec : { "--jpeg", "--jpegls", "--j2k" })
  {
    const std::string folder = Path(std::string("series") + codec);
    fs::create_directories(folder);
    for (const auto& file : fs::directory_iterator(Path("plain")))
    {
      const std::string command = std::string("gdcmconv ") + codec + " '" + file.path().string() +
        "' '" + folder + "/" + file.path().filename().string() + "'";
      ASSERT_EQ(std::system(command.c_str()), 0) << command;
    }
    SCOPED_TRACE(codec);
    ExpectPlaced(Read(folder), SagittalWorld);
  }
}

// A transfer syntax nothing here decodes (MPEG-2 video) fails in one line.
TEST_F(VolumeOrientationTest, UnsupportedTransferSyntaxFailsInOneLine)
{
  WriteSagittalSeries(Path("mpeg"),
    [](int s)
    {
      DicomSlice spec = Sagittal(s);
      spec.TransferSyntax = "1.2.840.10008.1.2.4.100"; // MPEG2 Main Profile @ Main Level
      spec.Encapsulated = true;
      spec.Fragment = { 0x00, 0x00, 0x01, 0xB3, 0x00, 0x00, 0x00, 0x00 };
      return spec;
    });
  const std::string error = ReadError(Path("mpeg"));
  EXPECT_NE(error.find("1.2.840.10008.1.2.4.100"), std::string::npos) << error;
  std::cout << "message: " << error << "\n";
  EXPECT_EQ(error.rfind("Cannot read DICOM series volume '" + Path("mpeg") + "': ", 0), 0u)
    << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_EQ(error.find("vtkInformation"), std::string::npos) << error;
}

// A truncated JPEG-lossless stream: Debian's GDCM ends the process with an assertion
// on it, so the reader decodes GDCM's syntaxes once in a child process first. The
// process lives on and says what is wrong in one line.
TEST_F(VolumeOrientationTest, CorruptJpegStreamFailsInOneLineInsteadOfAborting)
{
  if (!HasVtkDicom())
    GTEST_SKIP() << vtkScattererVolumeReader::GetDicomSupport();
  WriteSagittalSeries(Path("jpeg"),
    [](int s)
    {
      DicomSlice spec = Sagittal(s);
      spec.TransferSyntax = "1.2.840.10008.1.2.4.70"; // JPEG lossless, first-order prediction
      spec.Encapsulated = true;
      // SOI, then a lossless frame header (SOF3) cut off after its length.
      spec.Fragment = { 0xFF, 0xD8, 0xFF, 0xC3, 0x00, 0x0B, 0x10, 0x00 };
      return spec;
    });
  const std::string error = ReadError(Path("jpeg"));
  std::cout << "message: " << error << "\n";
  EXPECT_EQ(error.rfind("Cannot read DICOM series volume '" + Path("jpeg") + "': ", 0), 0u)
    << error;
  EXPECT_NE(error.find("corrupt or truncated"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST_F(VolumeOrientationTest, FolderWithTwoSeriesIsRefusedWithAList)
{
  if (!HasVtkDicom())
    GTEST_SKIP() << vtkScattererVolumeReader::GetDicomSupport();
  fs::create_directories(Path("two"));
  for (int s = 0; s < SLICES; ++s)
  {
    DicomSlice a = Sagittal(s);
    WriteDicomSlice(Path("two/a" + std::to_string(s) + ".dcm"), s, a);
    DicomSlice b = Sagittal(s);
    b.SeriesUid = "1.2.3.10";
    WriteDicomSlice(Path("two/b" + std::to_string(s) + ".dcm"), s, b);
  }
  const std::string error = ReadError(Path("two"));
  std::cout << "message: " << error << "\n";
  EXPECT_NE(error.find("2 series"), std::string::npos) << error;
  EXPECT_NE(error.find("3 files"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  // One file names its series.
  ExpectPlaced(Read(Path("two/b1.dcm")), SagittalWorld);
}

TEST_F(VolumeOrientationTest, FolderWithoutDicomSaysSo)
{
  fs::create_directories(Path("none"));
  std::ofstream(Path("none/readme.txt")) << "no images here";
  const std::string error = ReadError(Path("none"));
  EXPECT_EQ(error.rfind("Cannot read DICOM series volume", 0), 0u) << error;
  EXPECT_NE(error.find("no DICOM image"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

// ---- NIfTI-1, written by hand (nifti1.h layout) -----------------------------------

struct NiftiSpec
{
  float PixDim[3] = { 0.5f, 0.75f, 2.0f };
  float QFac = 1.0f;
  short QFormCode = 0, SFormCode = 0;
  float Quatern[3] = { 0, 0, 0 }; // b, c, d
  float QOffset[3] = { 0, 0, 0 };
  float SRow[3][4] = {};
};

void WriteNifti(const std::string& path, const NiftiSpec& spec)
{
  std::vector<char> header(352, 0);
  auto at = [&](size_t offset, const void* value, size_t size)
  { std::memcpy(header.data() + offset, value, size); };
  const int32_t sizeofHdr = 348;
  at(0, &sizeofHdr, 4);
  const int16_t dim[8] = { 3, COLS, ROWS, SLICES, 1, 1, 1, 1 };
  at(40, dim, 16);
  const int16_t datatype = 4, bitpix = 16; // DT_INT16
  at(70, &datatype, 2);
  at(72, &bitpix, 2);
  const float pixdim[8] = { spec.QFac, spec.PixDim[0], spec.PixDim[1], spec.PixDim[2], 1, 1, 1, 1 };
  at(76, pixdim, 32);
  const float voxOffset = 352;
  at(108, &voxOffset, 4);
  at(252, &spec.QFormCode, 2);
  at(254, &spec.SFormCode, 2);
  at(256, spec.Quatern, 12);
  at(268, spec.QOffset, 12);
  at(280, spec.SRow, 48);
  at(344, "n+1", 4);
  std::ofstream out(path, std::ios::binary);
  out.write(header.data(), std::streamsize(header.size()));
  for (int s = 0; s < SLICES; ++s)
    for (int r = 0; r < ROWS; ++r)
      for (int c = 0; c < COLS; ++c)
      {
        const int16_t v = int16_t(Stored(c, r, s));
        out.write(reinterpret_cast<const char*>(&v), 2);
      }
}

Vec3 RasToLps(const Vec3& ras)
{
  return { -ras[0], -ras[1], ras[2] };
}

// nifti1.h METHOD 3: x = srow_x . (i, j, k, 1), likewise y and z (RAS).
Vec3 SFormWorld(const NiftiSpec& spec, int i, int j, int k)
{
  Vec3 ras;
  for (int a = 0; a < 3; ++a)
    ras[a] = spec.SRow[a][0] * i + spec.SRow[a][1] * j + spec.SRow[a][2] * k + spec.SRow[a][3];
  return RasToLps(ras);
}

// nifti1.h METHOD 2: R from the quaternion, (x,y,z) = R (pixdim1 i, pixdim2 j, qfac pixdim3 k)
// + qoffset (RAS).
Vec3 QFormWorld(const NiftiSpec& spec, int i, int j, int k)
{
  const double b = spec.Quatern[0], c = spec.Quatern[1], d = spec.Quatern[2];
  const double a = std::sqrt(std::max(0.0, 1.0 - b * b - c * c - d * d));
  const double R[3][3] = { { a * a + b * b - c * c - d * d, 2 * b * c - 2 * a * d,
                             2 * b * d + 2 * a * c },
    { 2 * b * c + 2 * a * d, a * a + c * c - b * b - d * d, 2 * c * d - 2 * a * b },
    { 2 * b * d - 2 * a * c, 2 * c * d + 2 * a * b, a * a + d * d - c * c - b * b } };
  const double v[3] = { spec.PixDim[0] * i, spec.PixDim[1] * j, spec.QFac * spec.PixDim[2] * k };
  Vec3 ras;
  for (int r = 0; r < 3; ++r)
    ras[r] = R[r][0] * v[0] + R[r][1] * v[1] + R[r][2] * v[2] + spec.QOffset[r];
  return RasToLps(ras);
}

// 90 degrees about z plus a flip of z (determinant < 0): i -> -y, j -> +x, k -> -z. Not a
// symmetric matrix, so a transposed direction shows.
NiftiSpec RotatedFlippedSForm()
{
  NiftiSpec spec;
  spec.SFormCode = 2; // aligned anatomical
  const float rows[3][4] = { { 0, 0.75f, 0, 10 }, { -0.5f, 0, 0, -20 }, { 0, 0, -2, 30 } };
  std::memcpy(spec.SRow, rows, sizeof(rows));
  return spec;
}

// 120 degrees about (1,1,1): a = b = c = d = 1/2 (i -> y, j -> z, k -> x; not symmetric).
NiftiSpec RotatedQForm(float qfac)
{
  NiftiSpec spec;
  spec.QFormCode = 1; // scanner anatomical
  spec.QFac = qfac;
  spec.Quatern[0] = spec.Quatern[1] = spec.Quatern[2] = 0.5f;
  spec.QOffset[0] = -5;
  spec.QOffset[1] = 12;
  spec.QOffset[2] = 7;
  return spec;
}

TEST_F(VolumeOrientationTest, NiftiSFormRotationAndFlipAreApplied)
{
  const NiftiSpec spec = RotatedFlippedSForm();
  WriteNifti(Path("s.nii"), spec);
  auto image = Read(Path("s.nii"));
  ASSERT_TRUE(image);
  // The file's left-handed index order: vtkNIFTIImageReader reverses the slices so the
  // direction is a rotation again; the voxels must still land where the sform puts them.
  EXPECT_NEAR(std::fabs(image->GetDirectionMatrix()->Determinant()), 1.0, 1e-9);
  ExpectPlaced(image, [&](int i, int j, int k) { return SFormWorld(spec, i, j, k); });
}

TEST_F(VolumeOrientationTest, NiftiSFormWinsOverQForm)
{
  NiftiSpec spec = RotatedFlippedSForm();
  const NiftiSpec q = RotatedQForm(1.0f);
  spec.QFormCode = q.QFormCode;
  std::copy(q.Quatern, q.Quatern + 3, spec.Quatern);
  std::copy(q.QOffset, q.QOffset + 3, spec.QOffset);
  WriteNifti(Path("sq.nii"), spec);
  ExpectPlaced(
    Read(Path("sq.nii")), [&](int i, int j, int k) { return SFormWorld(spec, i, j, k); });
}

TEST_F(VolumeOrientationTest, NiftiQFormOnlyIsApplied)
{
  const NiftiSpec spec = RotatedQForm(1.0f);
  WriteNifti(Path("q.nii"), spec);
  ExpectPlaced(Read(Path("q.nii")), [&](int i, int j, int k) { return QFormWorld(spec, i, j, k); });
}

TEST_F(VolumeOrientationTest, NiftiQFormWithNegativeQFacIsApplied)
{
  const NiftiSpec spec = RotatedQForm(-1.0f);
  WriteNifti(Path("q.nii"), spec);
  auto image = Read(Path("q.nii"));
  ASSERT_TRUE(image);
  EXPECT_NEAR(std::fabs(image->GetDirectionMatrix()->Determinant()), 1.0, 1e-9);
  ExpectPlaced(image, [&](int i, int j, int k) { return QFormWorld(spec, i, j, k); });
}

TEST_F(VolumeOrientationTest, NiftiWithoutFormsStaysOnTheGrid)
{
  NiftiSpec spec;
  WriteNifti(Path("plain.nii"), spec);
  ExpectPlaced(Read(Path("plain.nii")),
    [&](int i, int j, int k) {
      return Vec3{ 0.5 * i, 0.75 * j, 2.0 * k };
    });
}

TEST_F(VolumeOrientationTest, NiftiShearedSFormIsRefused)
{
  NiftiSpec spec = RotatedFlippedSForm();
  spec.SRow[0][2] = 1.0f; // k gains an x component: a shear
  WriteNifti(Path("shear.nii"), spec);
  const std::string error = ReadError(Path("shear.nii"));
  EXPECT_EQ(error.rfind("Cannot read NIfTI volume", 0), 0u) << error;
  EXPECT_NE(error.find("sheared"), std::string::npos) << error;
  std::cout << "message: " << error << "\n";
}

TEST_F(VolumeOrientationTest, NiftiShearedSFormFallsBackToQForm)
{
  NiftiSpec spec = RotatedQForm(1.0f);
  spec.SFormCode = 2;
  const float rows[3][4] = { { 0.5f, 0, 1, 0 }, { 0, 0.75f, 0, 0 }, { 0, 0, 2, 0 } };
  std::memcpy(spec.SRow, rows, sizeof(rows));
  WriteNifti(Path("shear.nii"), spec);
  ExpectPlaced(
    Read(Path("shear.nii")), [&](int i, int j, int k) { return QFormWorld(spec, i, j, k); });
}

// The same anatomy from both formats lands on the same points: the sagittal DICOM series
// and a NIfTI whose sform says the same in RAS.
TEST_F(VolumeOrientationTest, DicomAndNiftiOfTheSameAnatomyAgree)
{
  if (!HasVtkDicom())
    GTEST_SKIP() << vtkScattererVolumeReader::GetDicomSupport();
  WriteSagittalSeries(Path("sag"), Sagittal);
  NiftiSpec spec;
  spec.SFormCode = 1;
  // LPS column vectors (row * 0.5, column * 0.75, normal * 2) and kFirst, with x and y negated.
  const float rows[3][4] = { { 0, 0, 2, -50 }, { -0.5f, 0, 0, 100 }, { 0, -0.75f, 0, 80 } };
  std::memcpy(spec.SRow, rows, sizeof(rows));
  WriteNifti(Path("sag.nii"), spec);
  auto dicom = Read(Path("sag"));
  auto nifti = Read(Path("sag.nii"));
  ASSERT_TRUE(dicom && nifti);
  ExpectPlaced(dicom, SagittalWorld);
  ExpectPlaced(nifti, SagittalWorld);
}

// The placement also reaches a pipeline (RequestInformation announces the direction).
TEST_F(VolumeOrientationTest, PipelineOutputCarriesThePlacement)
{
  const NiftiSpec spec = RotatedFlippedSForm();
  WriteNifti(Path("s.nii"), spec);
  vtkNew<vtkScattererVolumeReader> reader;
  reader->SetFileName(Path("s.nii").c_str());
  reader->Update();
  ExpectPlaced(reader->GetOutput(), [&](int i, int j, int k) { return SFormWorld(spec, i, j, k); });
}
