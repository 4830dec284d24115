#include "vtkScattererVolumeReader.h"

#include "vtkCallbackCommand.h"
#include "vtkDICOMImageReader.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLImageDataReader.h"
#include "vtksys/SystemTools.hxx"

#include "ScattererRawSizeCheck.h"

#include <algorithm>
#include <cctype>

vtkStandardNewMacro(vtkScattererVolumeReader);

namespace
{
std::string LowerCase(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Collects the errors a delegate reader reports instead of letting them print.
struct ErrorSink
{
  std::string Messages;
  vtkNew<vtkCallbackCommand> Command;
  ErrorSink()
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
      auto* self = static_cast<ErrorSink*>(client);
      std::string text = call ? static_cast<const char*>(call) : "unknown error";
      // VTK's messages start with "ERROR: In <file>, line N\nvtkClass (0x..): text";
      // keep the last line, which says what went wrong.
      while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
      {
        text.pop_back();
      }
      auto pos = text.rfind("): ");
      if (pos != std::string::npos)
      {
        text = text.substr(pos + 3);
      }
      if (!self->Messages.empty())
      {
        self->Messages += "; ";
      }
      self->Messages += text;
    });
  }
  void Watch(vtkAlgorithm* algorithm)
  {
    algorithm->AddObserver(vtkCommand::ErrorEvent, this->Command);
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
};
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
  if (!vtksys::SystemTools::FileExists(path))
  {
    this->Fail("Cannot read volume '" + path + "': no such file or directory.");
    return false;
  }

  const std::string lower = LowerCase(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  std::string sizeProblem;
  if (vtksys::SystemTools::FileIsDirectory(path))
  {
    this->FormatName = "DICOM series";
    auto dicom = vtkSmartPointer<vtkDICOMImageReader>::New();
    dicom->SetDirectoryName(path.c_str());
    reader = dicom;
  }
  else if (EndsWith(lower, ".mhd") || EndsWith(lower, ".mha"))
  {
    this->FormatName = "MetaImage";
    sizeProblem = scatterer_io::CheckMetaImageSize(path);
    auto meta = vtkSmartPointer<vtkMetaImageReader>::New();
    meta->SetFileName(path.c_str());
    reader = meta;
  }
  else if (EndsWith(lower, ".nii") || EndsWith(lower, ".nii.gz"))
  {
    this->FormatName = "NIfTI";
    sizeProblem = scatterer_io::CheckNiftiSize(path);
    auto nifti = vtkSmartPointer<vtkNIFTIImageReader>::New();
    nifti->SetFileName(path.c_str());
    reader = nifti;
  }
  else if (EndsWith(lower, ".vti"))
  {
    this->FormatName = "VTK XML image";
    auto xml = vtkSmartPointer<vtkXMLImageDataReader>::New();
    xml->SetFileName(path.c_str());
    reader = xml;
  }
  else if (EndsWith(lower, ".nrrd") || EndsWith(lower, ".nhdr"))
  {
    this->FormatName = "NRRD";
    sizeProblem = scatterer_io::CheckNrrdSize(path);
    auto nrrd = vtkSmartPointer<vtkNrrdReader>::New();
    nrrd->SetFileName(path.c_str());
    reader = nrrd;
  }
  else
  {
    this->Fail("Cannot read volume '" + path +
      "': unknown format (expected .mhd, .mha, .nii, .nii.gz, .vti, .nrrd, .nhdr or a DICOM "
      "folder).");
    return false;
  }
  if (!sizeProblem.empty())
  {
    this->Fail("Cannot read " + this->FormatName + " volume '" + path + "': " + sizeProblem);
    return false;
  }

  ErrorSink sink;
  sink.Watch(reader);
  reader->Update();
  vtkImageData* image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!sink.Messages.empty())
  {
    this->Fail("Cannot read " + this->FormatName + " volume '" + path + "': " + sink.Messages);
    return false;
  }
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  const vtkIdType points = image ? image->GetNumberOfPoints() : 0;
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (points <= 0 || dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0)
  {
    this->Fail("Cannot read " + this->FormatName + " volume '" + path +
      "': the file holds no voxels (empty, truncated or not a volume).");
    return false;
  }
  if (!scalars || scalars->GetNumberOfTuples() != points)
  {
    this->Fail("Cannot read " + this->FormatName + " volume '" + path +
      "': the voxel values are missing or fewer than the grid needs (truncated file?).");
    return false;
  }
  this->Cached = vtkSmartPointer<vtkImageData>::New();
  this->Cached->ShallowCopy(image);
  this->CacheTime.Modified();
  return true;
}

int vtkScattererVolumeReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->ReadIntoCache())
  {
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(
    vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->Cached->GetExtent(), 6);
  outInfo->Set(vtkDataObject::SPACING(), this->Cached->GetSpacing(), 3);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Cached->GetOrigin(), 3);
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

void vtkScattererVolumeReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "FormatName: " << this->FormatName << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
