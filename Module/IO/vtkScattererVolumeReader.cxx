#include "vtkScattererVolumeReader.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageHeader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLImageDataReader.h"
#include "vtksys/SystemTools.hxx"

#include "ScattererDicomSeries.h"
#include "ScattererHeaderCheckCommon.h"
#include "ScattererReaderErrors.h"
#include "ScattererVolumeHeaderCheck.h"
#include "ScattererVolumeOrientation.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <sstream>

vtkStandardNewMacro(vtkScattererVolumeReader);

namespace
{
bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
    s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A VTK file reader of type Reader, set to read path.
template <typename Reader>
vtkSmartPointer<vtkAlgorithm> NewFileReader(const std::string& path)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

std::string Describe(const scatterer_io::VolumeLayout& layout)
{
  std::ostringstream out;
  out << layout.Dimensions[0] << "x" << layout.Dimensions[1] << "x" << layout.Dimensions[2]
      << " grid of " << layout.Components << "-component voxels, spacing (" << layout.Spacing[0]
      << ", " << layout.Spacing[1] << ", " << layout.Spacing[2] << "), origin (" << layout.Origin[0]
      << ", " << layout.Origin[1] << ", " << layout.Origin[2] << ")";
  return out.str();
}

bool Same(double a, double b)
{
  return std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b));
}

bool SameLayout(const scatterer_io::VolumeLayout& a, const scatterer_io::VolumeLayout& b)
{
  for (int i = 0; i < 3; ++i)
  {
    if (a.Dimensions[i] != b.Dimensions[i] || !Same(a.Spacing[i], b.Spacing[i]) ||
      !Same(a.Origin[i], b.Origin[i]))
    {
      return false;
    }
  }
  return a.Components == b.Components;
}

void CopyMatrix(vtkMatrix4x4* m, double out[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[4 * r + c] = m->GetElement(r, c);
    }
  }
}

// NIfTI-1 (nifti1.h, "METHOD 3" then "METHOD 2"): the sform when sform_code > 0, else the
// qform when qform_code > 0, else no anatomical frame (method 1: the grid stays at the
// origin, unrotated). vtkNIFTIImageReader hands both as matrices from its data coordinates
// (pixdim factored out; with qfac = -1 it reversed the slices and adjusted the matrices).
// A sheared sform cannot become a direction; the qform (a rotation by construction) then
// places the volume if the file has one.
std::string PlaceNifti(vtkNIFTIImageReader* reader, vtkImageData* image,
  scatterer_io::VolumePlacement* placement, bool* oriented)
{
  *oriented = false;
  vtkNIFTIImageHeader* header = reader->GetNIFTIHeader();
  const bool sform = header && header->GetSFormCode() > 0 && reader->GetSFormMatrix();
  const bool qform = header && header->GetQFormCode() > 0 && reader->GetQFormMatrix();
  double matrix[16];
  std::string problem;
  if (sform)
  {
    CopyMatrix(reader->GetSFormMatrix(), matrix);
    problem = scatterer_io::PlaceInPatientSpace(
      matrix, image->GetOrigin(), image->GetSpacing(), scatterer_io::PatientFrame::RAS, placement);
    if (problem.empty())
    {
      *oriented = true;
      return {};
    }
    if (!qform)
    {
      return "the sform: " + problem;
    }
  }
  if (qform)
  {
    CopyMatrix(reader->GetQFormMatrix(), matrix);
    problem = scatterer_io::PlaceInPatientSpace(
      matrix, image->GetOrigin(), image->GetSpacing(), scatterer_io::PatientFrame::RAS, placement);
    *oriented = problem.empty();
    return problem.empty() ? std::string() : "the qform: " + problem;
  }
  return {};
}
}

vtkScattererVolumeReader::vtkScattererVolumeReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkScattererVolumeReader::~vtkScattererVolumeReader() = default;

void vtkScattererVolumeReader::Fail(const std::string& message)
{
  this->ErrorMessage = message;
  this->Cached = nullptr;
  if (!this->Quiet)
  {
    vtkErrorMacro(<< message);
  }
}

bool vtkScattererVolumeReader::ReadIntoCache()
{
  if (this->Cached && this->CacheTime > this->GetMTime())
  {
    return true;
  }
  this->ErrorMessage.clear();
  this->FormatName.clear();
  this->Cached = nullptr;
  const std::string& path = this->FileName;
  if (path.empty())
  {
    this->Fail("No input path was given (SetFileName).");
    return false;
  }
  // Nothing a file holds may crash the program: whatever escapes the checks and VTK's
  // readers as an exception becomes an error naming the file.
  try
  {
    return this->ReadChecked();
  }
  catch (const std::bad_alloc&)
  {
    this->Fail("Cannot read volume '" + path + "': not enough memory for it.");
  }
  catch (const std::exception& e)
  {
    this->Fail(
      "Cannot read volume '" + path + "': reading failed with an exception (" + e.what() + ").");
  }
  catch (...)
  {
    this->Fail("Cannot read volume '" + path + "': reading failed with an unknown exception.");
  }
  return false;
}

bool vtkScattererVolumeReader::ReadChecked()
{
  const std::string& path = this->FileName;
  if (!vtksys::SystemTools::FileExists(path))
  {
    this->Fail("Cannot read volume '" + path + "': no such file or directory.");
    return false;
  }

  const std::string lower = scatterer_io::header_check::Lower(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  // Formats with a header are validated before VTK's reader sees them (VTK 9.1's readers
  // crash on or misread bad headers; ScattererVolumeHeaderCheck.h).
  bool checked = false;
  scatterer_io::HeaderCheck header;
  scatterer_io::ReaderErrorSink sink;
  std::string dicomProblem;
  if (vtksys::SystemTools::FileIsDirectory(path) || EndsWith(lower, ".dcm") ||
    EndsWith(lower, ".dicom"))
  {
    this->FormatName = "DICOM series";
    auto dicom = scatterer_io::OpenDicomSeries(path, [&sink](vtkAlgorithm* a) { sink.Watch(a); });
    reader = dicom.Reader;
    dicomProblem = dicom.Problem;
  }
  else if (EndsWith(lower, ".mhd") || EndsWith(lower, ".mha"))
  {
    this->FormatName = "MetaImage";
    header = scatterer_io::CheckMetaImageHeader(path);
    checked = true;
    reader = NewFileReader<vtkMetaImageReader>(path);
  }
  else if (EndsWith(lower, ".nii") || EndsWith(lower, ".nii.gz"))
  {
    this->FormatName = "NIfTI";
    header = scatterer_io::CheckNiftiHeader(path);
    checked = true;
    reader = NewFileReader<vtkNIFTIImageReader>(path);
  }
  else if (EndsWith(lower, ".vti"))
  {
    this->FormatName = "VTK XML image";
    reader = NewFileReader<vtkXMLImageDataReader>(path);
  }
  else if (EndsWith(lower, ".nrrd") || EndsWith(lower, ".nhdr"))
  {
    this->FormatName = "NRRD";
    header = scatterer_io::CheckNrrdHeader(path);
    checked = true;
    reader = NewFileReader<vtkNrrdReader>(path);
  }
  else
  {
    this->Fail("Cannot read volume '" + path +
      "': unknown format (expected .mhd, .mha, .nii, .nii.gz, .vti, .nrrd, .nhdr, a DICOM "
      "folder or a .dcm file of a series).");
    return false;
  }
  const std::string failure = "Cannot read " + this->FormatName + " volume '" + path + "': ";
  if (!header.Problem.empty() || !dicomProblem.empty())
  {
    this->Fail(failure + header.Problem + dicomProblem);
    return false;
  }
  if (this->FormatName != "DICOM series")
  {
    sink.Watch(reader);
  }
  std::string ioErrors;
  if (this->FormatName == "MetaImage")
  {
    scatterer_io::CerrCapture capture;
    reader->Update();
    ioErrors = capture.Errors();
  }
  else
  {
    reader->Update();
  }
  if (sink.Failed() || !ioErrors.empty())
  {
    std::string why = sink.Failed() ? sink.Text() : "MetaIO reports: " + ioErrors;
    if (this->FormatName == "DICOM series" &&
      why.find("does not contain any DICOM images") != std::string::npos)
    {
      // vtkDICOMImageReader's words ("Couldn't get sorted files. Slices may be in wrong
      // order!; Either a filename was not specified or ...") describe its own state.
      why = "the folder holds no DICOM images that VTK's DICOM reader can parse";
    }
    if (this->FormatName == "DICOM series" && !scatterer_io::HasVtkDicom())
    {
      // Compressed series are the usual reason here; say what this build cannot do.
      why += " (" + scatterer_io::DicomSupport() + ")";
    }
    if (checked && header.Encoding == "gzip" && why.find("gzip") != std::string::npos)
    {
      // vtkNrrdReader's own words ("Couldn't read gzip data from nrrd file: <path>
      // 330/64, GetHeaderSize(): 64") do not say what is wrong with the file.
      why = "its gzip data is corrupt or truncated: zlib could not decode all the voxels the "
            "header promises";
    }
    this->Fail(failure + why + ".");
    return false;
  }
  vtkImageData* image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  const vtkIdType points = image ? image->GetNumberOfPoints() : 0;
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (points <= 0 || dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0)
  {
    this->Fail(failure + "the file holds no voxels (empty, truncated or not a volume).");
    return false;
  }
  if (!scalars || scalars->GetNumberOfTuples() != points)
  {
    this->Fail(
      failure + "the voxel values are missing or fewer than the grid needs (truncated file?).");
    return false;
  }

  // What VTK delivered must be what the header promised, and sound for rendering (for
  // DICOM and VTK XML images this is the only check of spacing and origin).
  scatterer_io::VolumeLayout delivered;
  for (int i = 0; i < 3; ++i)
  {
    delivered.Dimensions[i] = dims[i];
    delivered.Spacing[i] = image->GetSpacing()[i];
    delivered.Origin[i] = image->GetOrigin()[i];
  }
  delivered.Components = scalars->GetNumberOfComponents();
  if (checked && !SameLayout(delivered, header.Layout))
  {
    this->Fail(failure + "VTK's reader delivered a " + Describe(delivered) +
      ", but the header promises a " + Describe(header.Layout) +
      "; refusing a volume that may be misread.");
    return false;
  }
  const std::string layoutProblem = scatterer_io::CheckLayout(delivered, checked);
  if (!layoutProblem.empty())
  {
    this->Fail(failure + layoutProblem);
    return false;
  }
  // Where the grid lies in patient space (LPS; ScattererVolumeOrientation.h): DICOM's
  // patient matrix, NIfTI's sform or qform. The other formats keep what VTK's reader gave.
  scatterer_io::VolumePlacement placement;
  bool oriented = false;
  std::string placementProblem;
  if (this->FormatName == "DICOM series")
  {
    placementProblem = scatterer_io::PlaceDicomSeries(reader, image, &placement, &oriented);
  }
  else if (this->FormatName == "NIfTI")
  {
    placementProblem =
      PlaceNifti(vtkNIFTIImageReader::SafeDownCast(reader), image, &placement, &oriented);
  }
  if (!placementProblem.empty())
  {
    this->Fail(failure + placementProblem);
    return false;
  }
  if (oriented)
  {
    scatterer_io::VolumeLayout placed = delivered;
    std::copy(placement.Origin, placement.Origin + 3, placed.Origin);
    std::copy(placement.Spacing, placement.Spacing + 3, placed.Spacing);
    const std::string placedProblem = scatterer_io::CheckLayout(placed, checked);
    if (!placedProblem.empty())
    {
      this->Fail(failure + "placed in patient space, " + placedProblem);
      return false;
    }
  }
  this->Cached = vtkSmartPointer<vtkImageData>::New();
  this->Cached->ShallowCopy(image);
  if (oriented)
  {
    this->Cached->SetOrigin(placement.Origin);
    this->Cached->SetSpacing(placement.Spacing);
    this->Cached->SetDirectionMatrix(placement.Direction);
  }
  this->CacheTime.Modified();
  return true;
}

int vtkScattererVolumeReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->ReadIntoCache())
  {
    // No volume: the output must not keep the last file's (RequestData does not run),
    // and the pipeline's error code says the read failed.
    if (vtkImageData* output = vtkImageData::GetData(outputVector, 0))
    {
      output->Initialize();
    }
    this->SetErrorCode(this->FileName.empty() || !vtksys::SystemTools::FileExists(this->FileName)
        ? vtkErrorCode::CannotOpenFileError
        : vtkErrorCode::FileFormatError);
    return 0;
  }
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->Cached->GetExtent(), 6);
  outInfo->Set(vtkDataObject::SPACING(), this->Cached->GetSpacing(), 3);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Cached->GetOrigin(), 3);
  outInfo->Set(vtkDataObject::DIRECTION(), this->Cached->GetDirectionMatrix()->GetData(), 9);
  vtkDataArray* scalars = this->Cached->GetPointData()->GetScalars();
  vtkDataObject::SetPointDataActiveScalarInfo(
    outInfo, scalars->GetDataType(), scalars->GetNumberOfComponents());
  return 1;
}

int vtkScattererVolumeReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->Cached)
  {
    return 0;
  }
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  output->ShallowCopy(this->Cached);
  return 1;
}

vtkSmartPointer<vtkImageData> vtkScattererVolumeReader::ReadVolume(
  const std::string& path, std::string* error)
{
  vtkNew<vtkScattererVolumeReader> reader;
  reader->Quiet = true;
  reader->SetFileName(path.c_str());
  if (!reader->ReadIntoCache())
  {
    if (error)
    {
      *error = reader->GetErrorMessage();
    }
    return nullptr;
  }
  if (error)
  {
    error->clear();
  }
  return reader->Cached;
}

std::string vtkScattererVolumeReader::GetDicomSupport()
{
  return scatterer_io::DicomSupport();
}

void vtkScattererVolumeReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "FormatName: " << this->FormatName << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
