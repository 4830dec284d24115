/**
 * @class   vtkScattererVolumeReader
 * @brief   Opens a volume by what its path is: MetaImage, NIfTI, VTK XML image, NRRD or a DICOM folder.
 *
 * The examples and benchmarks take any volume a user points them at. This
 * reader picks the VTK reader from the path (a directory is read as a DICOM
 * series; otherwise the extension decides: .mhd/.mha, .nii/.nii.gz, .vti,
 * .nrrd/.nhdr) and checks what came back, so a missing, unknown or truncated
 * file fails with one clear message (vtkErrorMacro, also kept in
 * GetErrorMessage()) instead of an empty or garbage volume.
 *
 * Truncation is caught before reading for raw formats by comparing the bytes
 * the header promises with the bytes on disk, and for compressed and XML
 * formats by the underlying reader's own errors.
 */
#ifndef vtkScattererVolumeReader_h
#define vtkScattererVolumeReader_h

#include "ScattererTemplateModule.h" // for export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // for ReadVolume
#include "vtkTimeStamp.h"    // for CacheTime

#include <string> // for ErrorMessage

class vtkImageData;

class SCATTERERTEMPLATE_EXPORT vtkScattererVolumeReader : public vtkImageAlgorithm
{
public:
  static vtkScattererVolumeReader* New();
  vtkTypeMacro(vtkScattererVolumeReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Path of a volume file or of a folder holding one DICOM series. */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /** The last error, empty after a successful read. */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

  /** The format the path was taken for ("MetaImage", "NIfTI", ...), empty if none. */
  const std::string& GetFormatName() const { return this->FormatName; }

  /**
   * Convenience: read @p path; returns nullptr and fills @p error on failure.
   * Reports no VTK error (the caller decides how to tell the user).
   */
  static vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, std::string* error);

protected:
  vtkScattererVolumeReader();
  ~vtkScattererVolumeReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** Reads the whole volume into Cached; on failure sets ErrorMessage. */
  bool ReadIntoCache();
  void Fail(const std::string& message);

  std::string FileName;
  std::string ErrorMessage;
  std::string FormatName;
  vtkSmartPointer<vtkImageData> Cached;
  vtkTimeStamp CacheTime;
  bool Quiet = false;

private:
  vtkScattererVolumeReader(const vtkScattererVolumeReader&) = delete;
  void operator=(const vtkScattererVolumeReader&) = delete;
};

#endif
