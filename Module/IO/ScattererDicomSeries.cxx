#include "ScattererDicomSeries.h"

#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtksys/SystemTools.hxx"

#ifdef SCATTERER_WITH_VTK_DICOM
#include "vtkDICOMConfig.h"
#include "vtkDICOMDictHash.h"
#include "vtkDICOMDirectory.h"
#include "vtkDICOMMetaData.h"
#include "vtkDICOMReader.h"
#else
#include "vtkDICOMImageReader.h"
#endif

#include <csignal>
#include <cstring>
#include <sstream>

#if defined(__unix__)
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace scatterer_io
{
#ifdef SCATTERER_WITH_VTK_DICOM
bool HasVtkDicom()
{
  return true;
}

std::string DicomSupport()
{
#ifdef DICOM_USE_GDCM
  const char* codecs = "RLE and deflate; JPEG baseline/extended/lossless, JPEG-LS and JPEG 2000 "
                       "through GDCM";
#else
  const char* codecs = "RLE and deflate only (no GDCM: no JPEG, JPEG-LS or JPEG 2000)";
#endif
  return std::string("DICOM is read with vtk-dicom ") + DICOM_VERSION +
    ": uncompressed and compressed transfer syntaxes (" + codecs +
    "), rescale slope/intercept and patient orientation (LPS).";
}

namespace
{
std::string Canonical(const std::string& path)
{
  return vtksys::SystemTools::CollapseFullPath(vtksys::SystemTools::GetRealPath(path));
}

// "#3 'AX 5mm' CT, 120 files, e.g. IM0042": enough for a user to tell series apart.
// Transfer syntaxes (PS3.5 A.4, PS3.6 Annex A) and who decodes them in this build:
// vtk-dicom itself the uncompressed, deflate and RLE ones; GDCM (Debian links it with
// libjpeg 8/12/16-bit, CharLS and OpenJPEG) the JPEG, JPEG-LS and JPEG 2000 ones.
struct Syntax
{
  const char* Uid;
  const char* Name;
  bool NeedsGdcm;
};
const Syntax kSyntaxes[] = {
  { "1.2.840.10008.1.2", "implicit VR little endian", false },
  { "1.2.840.10008.1.2.1", "explicit VR little endian", false },
  { "1.2.840.10008.1.2.2", "explicit VR big endian", false },
  { "1.2.840.10008.1.2.1.99", "deflated explicit VR little endian", false },
  { "1.2.840.10008.1.2.5", "RLE lossless", false },
  { "1.2.840.10008.1.2.4.50", "JPEG baseline", true },
  { "1.2.840.10008.1.2.4.51", "JPEG extended", true },
  { "1.2.840.10008.1.2.4.57", "JPEG lossless", true },
  { "1.2.840.10008.1.2.4.70", "JPEG lossless SV1", true },
  { "1.2.840.10008.1.2.4.80", "JPEG-LS lossless", true },
  { "1.2.840.10008.1.2.4.81", "JPEG-LS near-lossless", true },
  { "1.2.840.10008.1.2.4.90", "JPEG 2000 lossless", true },
  { "1.2.840.10008.1.2.4.91", "JPEG 2000", true },
};

bool Decodable(const std::string& uid)
{
  for (const Syntax& syntax : kSyntaxes)
  {
    if (uid == syntax.Uid)
    {
#ifdef DICOM_USE_GDCM
      return true;
#else
      return !syntax.NeedsGdcm;
#endif
    }
  }
  return false;
}

bool DecodedByGdcm(const std::string& uid)
{
  for (const Syntax& syntax : kSyntaxes)
  {
    if (uid == syntax.Uid)
    {
      return syntax.NeedsGdcm;
    }
  }
  return false;
}

/**
 * Decodes @p reader's series once in a child process: empty when that worked, else
 * what went wrong. Debian's GDCM 3.0 ends the process with an assertion (abort) on
 * a truncated or corrupt JPEG stream, where it should report an error; a crash in
 * the child is a message here. Costs one more decode, for GDCM's syntaxes only.
 */
std::string TrialDecodeInChild(vtkAlgorithm* reader)
{
#if defined(__unix__)
  const pid_t child = fork();
  if (child < 0)
  {
    return ""; // no child: decode in this process as before
  }
  if (child == 0)
  {
    // The child's messages would repeat the parent's; the exit status says it all.
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0)
    {
      dup2(null, 1);
      dup2(null, 2);
    }
    reader->Update();
    _exit(0);
  }
  int status = 0;
  // A decoder that hangs is stopped after a minute (a CT series decodes in seconds).
  for (int waited = 0; waitpid(child, &status, WNOHANG) == 0; ++waited)
  {
    if (waited >= 6000)
    {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      return "decoding its pixel data did not finish within a minute";
    }
    usleep(10000);
  }
  if (WIFSIGNALED(status))
  {
    return std::string("its compressed pixel data cannot be decoded: the decoder crashed (") +
      strsignal(WTERMSIG(status)) + "), so the stream is corrupt or truncated";
  }
#else
  (void)reader;
#endif
  return "";
}

std::string SyntaxName(const std::string& uid)
{
  for (const Syntax& syntax : kSyntaxes)
  {
    if (uid == syntax.Uid)
    {
      return syntax.Name;
    }
  }
  if (uid.rfind("1.2.840.10008.1.2.4.10", 0) == 0)
  {
    return "MPEG or HEVC video";
  }
  return "unknown";
}

std::string DescribeSeries(vtkDICOMDirectory* directory, int series)
{
  std::ostringstream out;
  vtkDICOMMetaData* meta = directory->GetMetaDataForSeries(series);
  vtkStringArray* files = directory->GetFileNamesForSeries(series);
  out << "#" << (meta ? meta->Get(DC::SeriesNumber).AsString() : std::string("?"));
  const std::string description = meta ? meta->Get(DC::SeriesDescription).AsString() : "";
  if (!description.empty())
  {
    out << " '" << description << "'";
  }
  const std::string modality = meta ? meta->Get(DC::Modality).AsString() : "";
  if (!modality.empty())
  {
    out << " " << modality;
  }
  const vtkIdType count = files ? files->GetNumberOfValues() : 0;
  out << ", " << count << (count == 1 ? " file" : " files");
  if (count > 0)
  {
    out << ", e.g. " << vtksys::SystemTools::GetFilenameName(files->GetValue(0));
  }
  return out.str();
}
}

DicomSeriesReader OpenDicomSeries(
  const std::string& path, const std::function<void(vtkAlgorithm*)>& watch)
{
  DicomSeriesReader result;
  const bool folder = vtksys::SystemTools::FileIsDirectory(path);
  vtkNew<vtkDICOMDirectory> directory;
  directory->SetDirectoryName(
    folder ? path.c_str() : vtksys::SystemTools::GetFilenamePath(Canonical(path)).c_str());
  directory->SetScanDepth(1); // the folder's own files: a series is one folder
  watch(directory);
  directory->Update();
  const int seriesCount = directory->GetNumberOfSeries();
  int chosen = -1;
  if (folder)
  {
    if (seriesCount == 0)
    {
      result.Problem = "the folder holds no DICOM images (no file in it is DICOM with pixel data).";
      return result;
    }
    if (seriesCount > 1)
    {
      // Refused rather than guessed: the largest series may as well be a second
      // reconstruction of the same scan (another kernel or slice thickness) as the one meant.
      std::string list;
      for (int i = 0; i < seriesCount; ++i)
      {
        list += (i ? "; " : "") + DescribeSeries(directory, i);
      }
      result.Problem = "the folder holds " + std::to_string(seriesCount) + " series (" + list +
        "); give the path of one file of the series to read.";
      return result;
    }
    chosen = 0;
  }
  else
  {
    const std::string wanted = Canonical(path);
    for (int i = 0; i < seriesCount && chosen < 0; ++i)
    {
      vtkStringArray* files = directory->GetFileNamesForSeries(i);
      for (vtkIdType f = 0; files && f < files->GetNumberOfValues(); ++f)
      {
        if (Canonical(files->GetValue(f)) == wanted)
        {
          chosen = i;
          break;
        }
      }
    }
    if (chosen < 0)
    {
      result.Problem = "the file is not a DICOM image with pixel data.";
      return result;
    }
  }
  vtkNew<vtkDICOMReader> reader;
  reader->SetFileNames(directory->GetFileNamesForSeries(chosen));
  // Rows as stored (top-down): memory index (i, j, k) is DICOM's (column, row, slice), as
  // in ITK, and the direction matrix from Image Orientation (Patient) places it; flipping
  // rows for VTK's bottom-up habit is not needed once the direction is carried.
  reader->SetMemoryRowOrderToFileNative();
  // Stored values through the modality LUT's slope and intercept (e.g. to Hounsfield units);
  // the output is float when the rescaled values do not fit 16-bit integers.
  reader->AutoRescaleOn();
  watch(reader);
  // Headers only: refuse transfer syntaxes this build cannot decode before any pixel is
  // read, because vtk-dicom then delivers zeros with no error (only a GDCM warning).
  reader->UpdateInformation();
  bool gdcm = false; // some file needs GDCM's codecs (JPEG, JPEG-LS, JPEG 2000)
  if (vtkDICOMMetaData* meta = reader->GetMetaData())
  {
    for (int i = 0; i < meta->GetNumberOfInstances(); ++i)
    {
      const std::string syntax = meta->Get(i, DC::TransferSyntaxUID).AsString();
      if (!syntax.empty() && !Decodable(syntax))
      {
        result.Problem = "its transfer syntax " + syntax + " (" + SyntaxName(syntax) +
          ") is not one this build decodes; " + DicomSupport();
        return result;
      }
      gdcm = gdcm || DecodedByGdcm(syntax);
    }
  }
  if (gdcm)
  {
    result.Problem = TrialDecodeInChild(reader);
    if (!result.Problem.empty())
    {
      return result;
    }
  }
  result.Reader = reader;
  return result;
}

std::string PlaceDicomSeries(
  vtkAlgorithm* algorithm, vtkImageData* image, VolumePlacement* placement, bool* oriented)
{
  *oriented = false;
  auto* reader = vtkDICOMReader::SafeDownCast(algorithm);
  if (!reader || !image)
  {
    return "internal error: not a vtkDICOMReader.";
  }
  vtkDICOMMetaData* meta = reader->GetMetaData();
  const vtkIdType stacks = reader->GetStackIDs() ? reader->GetStackIDs()->GetNumberOfValues() : 0;
  if (stacks > 1)
  {
    return "the series holds " + std::to_string(stacks) +
      " stacks of slices (several orientations or positions in one series), which are not "
      "one volume.";
  }
  if (reader->GetTimeDimension() > 1)
  {
    return "the series holds " + std::to_string(reader->GetTimeDimension()) +
      " time points; only single-time volumes are read.";
  }
  vtkMatrix4x4* patient = reader->GetPatientMatrix();
  if (!patient || !meta || !meta->Has(DC::ImageOrientationPatient) ||
    !meta->Has(DC::ImagePositionPatient))
  {
    // No patient frame (e.g. secondary capture): the grid stays where the reader put it.
    return {};
  }
  double matrix[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      matrix[4 * r + c] = patient->GetElement(r, c);
    }
  }
  // Image Orientation/Position (Patient) are LPS by definition (PS3.3 C.7.6.2.1.1).
  const std::string problem = PlaceInPatientSpace(
    matrix, image->GetOrigin(), image->GetSpacing(), PatientFrame::LPS, placement);
  *oriented = problem.empty();
  return problem;
}

#else // VTK's vtkDICOMImageReader

bool HasVtkDicom()
{
  return false;
}

std::string DicomSupport()
{
  return "DICOM is read with VTK's vtkDICOMImageReader (built without vtk-dicom): uncompressed "
         "transfer syntaxes only, no rescale to stored units, no patient orientation.";
}

DicomSeriesReader OpenDicomSeries(
  const std::string& path, const std::function<void(vtkAlgorithm*)>& watch)
{
  DicomSeriesReader result;
  if (!vtksys::SystemTools::FileIsDirectory(path))
  {
    result.Problem = "this build reads DICOM folders only (one file picks its series only with "
                     "vtk-dicom); give the folder of the series.";
    return result;
  }
  auto reader = vtkSmartPointer<vtkDICOMImageReader>::New();
  reader->SetDirectoryName(path.c_str());
  watch(reader);
  result.Reader = reader;
  return result;
}

std::string PlaceDicomSeries(vtkAlgorithm*, vtkImageData*, VolumePlacement*, bool* oriented)
{
  *oriented = false;
  return {};
}
#endif
}
