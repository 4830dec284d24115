/**
 * @class   vtkScattererVolumeReader
 * @brief   Opens a volume by what its path is: MetaImage, NIfTI, VTK XML image, NRRD or a DICOM
 * folder.
 *
 * The examples and benchmarks take any volume a user points them at. This
 * reader picks the VTK reader from the path (a directory is read as a DICOM
 * series; otherwise the extension decides: .mhd/.mha, .nii/.nii.gz, .vti,
 * .nrrd/.nhdr) and checks what came back, so a missing, unknown or truncated
 * file fails with one clear message (vtkErrorMacro, also kept in
 * GetErrorMessage()) instead of an empty or garbage volume.
 *
 * MetaImage, NRRD and NIfTI headers are validated before VTK's reader sees
 * them (ScattererVolumeHeaderCheck.h): VTK 9.1's readers crash on some bad
 * headers (a negative channel count, a dimension that disagrees with the
 * sizes, an unknown NIfTI datatype) and silently misread others (a HeaderSize
 * past the data, raw data flagged as compressed, ascii junk, NaN or zero
 * spacing, a truncated file). The checks also compare the header with the
 * data behind it. After reading, the volume VTK delivered must match the grid
 * the header promised and have a finite, positive spacing and a finite origin
 * (for every format). Any exception a reader throws becomes an error too, so
 * no file makes ReadVolume crash.
 *
 * Placement in patient space, in one convention for all formats: LPS (DICOM's and
 * ITK's; ScattererVolumeOrientation.h says why). A DICOM series' Image Orientation and
 * Position (Patient) and a NIfTI's sform (sform_code > 0), else qform (qform_code > 0),
 * become the output's origin, spacing and direction matrix, so the same anatomy lands on
 * the same points from either format. MetaImage, NRRD and VTK XML images keep the
 * axis-aligned grid VTK 9.1's readers deliver (docs/data.md).
 *
 * A folder or a .dcm/.dicom path is read as a DICOM series (ScattererDicomSeries.h: with
 * vtk-dicom when the build has it, else VTK's vtkDICOMImageReader; GetDicomSupport()).
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

  /**
   * One line: which DICOM reader this build uses (vtk-dicom, or VTK's vtkDICOMImageReader
   * in builds without it, such as the ParaView plugin) and what it does not support.
   */
  static std::string GetDicomSupport();

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

  /** Reads the whole volume into Cached; on failure sets ErrorMessage. Never throws. */
  bool ReadIntoCache();
  /** ReadIntoCache's work: validate the header, read, compare with the header. */
  bool ReadChecked();
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
