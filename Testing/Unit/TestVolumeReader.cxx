// vtkScattererVolumeReader: each format opens by its path, and missing,
// unknown and truncated files fail with a message that says what and why.
#include "ScattererDicomBytes.h"
#include "vtkScattererVolumeReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkMetaImageWriter.h"
#include "vtkNIFTIImageWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkXMLImageDataWriter.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
// NX > 9: VTK's NRRD reader takes a fastest axis of <= 9 samples for vector components.
constexpr int NX = 11, NY = 5, NZ = 3;

// Voxel (i,j,k) holds i + 20 j + 200 k, so a misread axis shows.
vtkSmartPointer<vtkImageData> MakeVolume()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(NX, NY, NZ);
  image->SetSpacing(0.5, 0.75, 2.0);
  image->AllocateScalars(VTK_SHORT, 1);
  auto* p = static_cast<int16_t*>(image->GetScalarPointer());
  for (int k = 0; k < NZ; ++k)
    for (int j = 0; j < NY; ++j)
      for (int i = 0; i < NX; ++i)
        *p++ = static_cast<int16_t>(i + 20 * j + 200 * k);
  return image;
}

class VolumeReaderTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    Dir = fs::temp_directory_path() / ("scatterer-reader-" + std::string(info->name()));
    fs::remove_all(Dir);
    fs::create_directories(Dir);
  }
  void TearDown() override { fs::remove_all(Dir); }
  std::string Path(const std::string& name) const { return (Dir / name).string(); }

  // Reads and checks grid, spacing and every voxel value. With reversedSlices,
  // voxel (i,j,k) must hold the value written for slice NZ-1-k.
  void ExpectVolume(const std::string& path, bool checkSpacing = true, bool reversedSlices = false,
    bool reversedRows = false)
  {
    std::string error;
    auto image = vtkScattererVolumeReader::ReadVolume(path, &error);
    ASSERT_TRUE(image) << error;
    EXPECT_TRUE(error.empty());
    int dims[3];
    image->GetDimensions(dims);
    ASSERT_EQ(dims[0], NX);
    ASSERT_EQ(dims[1], NY);
    ASSERT_EQ(dims[2], NZ);
    if (checkSpacing)
    {
      EXPECT_NEAR(image->GetSpacing()[0], 0.5, 1e-6);
      EXPECT_NEAR(image->GetSpacing()[2], 2.0, 1e-6);
    }
    vtkDataArray* s = image->GetPointData()->GetScalars();
    for (int k = 0; k < NZ; ++k)
      for (int j = 0; j < NY; ++j)
        for (int i = 0; i < NX; ++i)
          ASSERT_EQ(s->GetTuple1(i + NX * (j + NY * k)),
            i + 20 * (reversedRows ? NY - 1 - j : j) + 200 * (reversedSlices ? NZ - 1 - k : k))
            << path << " voxel " << i << "," << j << "," << k;
  }

  void ExpectError(const std::string& path, const std::string& fragment)
  {
    std::string error;
    auto image = vtkScattererVolumeReader::ReadVolume(path, &error);
    EXPECT_FALSE(image) << path << " should not read";
    EXPECT_NE(error.find(fragment), std::string::npos)
      << "message '" << error << "' lacks '" << fragment << "'";
  }

  static void Truncate(const std::string& path, std::uintmax_t keep)
  {
    ASSERT_GT(fs::file_size(path), keep);
    fs::resize_file(path, keep);
  }

  fs::path Dir;
};

void WriteMeta(const std::string& path)
{
  vtkNew<vtkMetaImageWriter> writer;
  writer->SetInputData(MakeVolume());
  writer->SetFileName(path.c_str());
  writer->SetCompression(false);
  writer->Write();
}

void WriteNifti(const std::string& path)
{
  vtkNew<vtkNIFTIImageWriter> writer;
  writer->SetInputData(MakeVolume());
  writer->SetFileName(path.c_str());
  writer->Write();
}

void WriteVti(const std::string& path)
{
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(MakeVolume());
  writer->SetFileName(path.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->Write();
}

void WriteNrrd(const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  out << "NRRD0004\n# written by TestVolumeReader\ntype: short\ndimension: 3\n"
      << "sizes: " << NX << " " << NY << " " << NZ << "\n"
      << "spacings: 0.5 0.75 2.0\nencoding: raw\nendian: little\n\n";
  auto image = MakeVolume();
  out.write(static_cast<const char*>(image->GetScalarPointer()), NX * NY * NZ * 2);
}

// A minimal explicit-VR little-endian CT slice: enough for vtkDICOMImageReader.
void WriteDicomSlice(const std::string& path, int k)
{
  scatterer_testing::DicomBytes bytes;
  bytes.Uid(0x0002, 0x0002, "1.2.840.10008.5.1.4.1.1.2");
  bytes.Uid(0x0002, 0x0003, "1.2.3.4." + std::to_string(k + 1));
  bytes.Uid(0x0002, 0x0010, "1.2.840.10008.1.2.1");
  bytes.Text(0x0008, 0x0060, "CS", "CT");
  bytes.Uid(0x0020, 0x000E, "1.2.3.9");
  bytes.Text(0x0020, 0x0013, "IS", std::to_string(k + 1));
  bytes.Text(0x0020, 0x0032, "DS", "0\\0\\" + std::to_string(2 * k));
  bytes.Text(0x0020, 0x0037, "DS", "1\\0\\0\\0\\1\\0");
  bytes.UShort(0x0028, 0x0002, 1);
  bytes.Text(0x0028, 0x0004, "CS", "MONOCHROME2");
  bytes.UShort(0x0028, 0x0010, NY);
  bytes.UShort(0x0028, 0x0011, NX);
  bytes.Text(0x0028, 0x0030, "DS", "0.75\\0.5");
  bytes.UShort(0x0028, 0x0100, 16);
  bytes.UShort(0x0028, 0x0101, 16);
  bytes.UShort(0x0028, 0x0102, 15);
  bytes.UShort(0x0028, 0x0103, 1);
  bytes.Put16(0x7FE0);
  bytes.Put16(0x0010);
  bytes.Raw({ 'O', 'W', 0, 0 });
  bytes.Put32(NX * NY * 2);
  // DICOM stores rows top-down: write VTK's row NY-1 first.
  auto image = MakeVolume();
  for (int j = NY - 1; j >= 0; --j)
  {
    const auto* p = static_cast<const char*>(image->GetScalarPointer(0, j, k));
    bytes.Raw(p, p + NX * 2);
  }
  bytes.Write(path);
}
}

TEST_F(VolumeReaderTest, ReadsMetaImageWithSeparateData)
{
  WriteMeta(Path("v.mhd"));
  ExpectVolume(Path("v.mhd"));
}

TEST_F(VolumeReaderTest, ReadsMetaImageWithLocalData)
{
  WriteMeta(Path("v.mha"));
  ExpectVolume(Path("v.mha"));
}

TEST_F(VolumeReaderTest, ReadsNifti)
{
  WriteNifti(Path("v.nii"));
  ExpectVolume(Path("v.nii"));
}

TEST_F(VolumeReaderTest, ReadsGzippedNifti)
{
  WriteNifti(Path("v.nii.gz"));
  ExpectVolume(Path("v.nii.gz"));
}

TEST_F(VolumeReaderTest, ReadsVtkXmlImage)
{
  WriteVti(Path("v.vti"));
  ExpectVolume(Path("v.vti"));
}

TEST_F(VolumeReaderTest, ReadsNrrd)
{
  WriteNrrd(Path("v.nrrd"));
  ExpectVolume(Path("v.nrrd"));
}

TEST_F(VolumeReaderTest, ReadsDicomFolder)
{
  fs::create_directories(Dir / "series");
  for (int k = NZ - 1; k >= 0; --k) // written out of order on purpose
    WriteDicomSlice(Path("series/slice" + std::to_string(k) + ".dcm"), k);
  if (vtkScattererVolumeReader::GetDicomSupport().find("with vtk-dicom") != std::string::npos)
  {
    // vtk-dicom: slices in ascending position along the normal, rows as stored (top-down;
    // WriteDicomSlice stores VTK's row NY-1 first); TestVolumeOrientation checks placement.
    ExpectVolume(Path("series"), /*checkSpacing=*/true, /*reversedSlices=*/false,
      /*reversedRows=*/true);
  }
  else
  {
    // vtkDICOMImageReader orders slices by descending position along the slice
    // normal, so slice k of the series lands at index NZ-1-k.
    ExpectVolume(Path("series"), /*checkSpacing=*/false, /*reversedSlices=*/true);
  }
}

TEST_F(VolumeReaderTest, ReaderAlgorithmFeedsThePipeline)
{
  WriteMeta(Path("v.mhd"));
  vtkNew<vtkScattererVolumeReader> reader;
  reader->SetFileName(Path("v.mhd").c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), NX * NY * NZ);
  EXPECT_EQ(reader->GetFormatName(), "MetaImage");
}

// A failed read leaves no volume behind: the output of the last good file was kept
// (RequestData does not run when RequestInformation fails), with no error code.
TEST_F(VolumeReaderTest, FailedReadAfterAGoodOneLeavesNoVolume)
{
  WriteMeta(Path("v.mhd"));
  std::ofstream(Path("bad.nii")) << "not a volume";
  vtkNew<vtkScattererVolumeReader> reader;
  vtkNew<vtkCallbackCommand> quiet; // the errors are expected: observed, not printed
  quiet->SetCallback([](vtkObject*, unsigned long, void*, void*) {});
  reader->AddObserver(vtkCommand::ErrorEvent, quiet);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
  reader->SetFileName(Path("v.mhd").c_str());
  reader->Update();
  ASSERT_EQ(reader->GetOutput()->GetNumberOfPoints(), NX * NY * NZ);
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  for (const char* name : { "bad.nii", "absent.nii" })
  {
    SCOPED_TRACE(name);
    reader->SetFileName(Path(name).c_str());
    reader->Update();
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << "the last file's volume was kept";
    EXPECT_NE(reader->GetErrorCode(), vtkErrorCode::NoError);
  }
  reader->SetFileName(Path("v.mhd").c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), NX * NY * NZ);
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
}

TEST_F(VolumeReaderTest, MissingFileSaysSo)
{
  ExpectError(Path("absent.mhd"), "no such file");
}

TEST_F(VolumeReaderTest, UnknownExtensionSaysWhichAreKnown)
{
  std::ofstream(Path("v.xyz")) << "hello";
  ExpectError(Path("v.xyz"), "unknown format");
}

TEST_F(VolumeReaderTest, EmptyDicomFolderFails)
{
  fs::create_directories(Dir / "empty");
  ExpectError(Path("empty"), "DICOM");
}

TEST_F(VolumeReaderTest, TruncatedMetaImageDataIsCaught)
{
  WriteMeta(Path("v.mhd"));
  Truncate(Path("v.raw"), 100);
  ExpectError(Path("v.mhd"), "truncated");
}

TEST_F(VolumeReaderTest, TruncatedLocalMetaImageIsCaught)
{
  WriteMeta(Path("v.mha"));
  Truncate(Path("v.mha"), fs::file_size(Path("v.mha")) - 10);
  ExpectError(Path("v.mha"), "truncated");
}

TEST_F(VolumeReaderTest, TruncatedNiftiIsCaught)
{
  WriteNifti(Path("v.nii"));
  Truncate(Path("v.nii"), fs::file_size(Path("v.nii")) - 20);
  ExpectError(Path("v.nii"), "truncated");
}

TEST_F(VolumeReaderTest, TruncatedGzippedNiftiIsCaught)
{
  WriteNifti(Path("v.nii.gz"));
  Truncate(Path("v.nii.gz"), fs::file_size(Path("v.nii.gz")) / 2);
  ExpectError(Path("v.nii.gz"), "Cannot read NIfTI");
}

TEST_F(VolumeReaderTest, TruncatedVtiIsCaught)
{
  WriteVti(Path("v.vti"));
  Truncate(Path("v.vti"), fs::file_size(Path("v.vti")) / 2);
  ExpectError(Path("v.vti"), "Cannot read VTK XML image");
}

TEST_F(VolumeReaderTest, TruncatedNrrdIsCaught)
{
  WriteNrrd(Path("v.nrrd"));
  Truncate(Path("v.nrrd"), fs::file_size(Path("v.nrrd")) - 30);
  ExpectError(Path("v.nrrd"), "truncated");
}
