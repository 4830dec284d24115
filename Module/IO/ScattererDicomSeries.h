// The DICOM side of vtkScattererVolumeReader: which series to read, with which reader,
// and where the result lies in patient space.
//
// With vtk-dicom (SCATTERER_WITH_VTK_DICOM, the top-level CMakeLists.txt) a folder is scanned
// with vtkDICOMDirectory and read with vtkDICOMReader: compressed transfer syntaxes through
// vtk-dicom's own decoders and GDCM's codecs, rescale slope/intercept (AutoRescale: stored
// values become e.g. Hounsfield units) and patient orientation (the PatientMatrix, carried
// into the image's origin and direction, LPS: ScattererVolumeOrientation.h). Without it
// (the ParaView plugin build) VTK's vtkDICOMImageReader reads uncompressed series only,
// without patient orientation; DicomSupport() says which.
#ifndef ScattererDicomSeries_h
#define ScattererDicomSeries_h

#include "ScattererVolumeOrientation.h"

#include "vtkSmartPointer.h"

#include <functional>
#include <string>

class vtkAlgorithm;
class vtkImageData;

namespace scatterer_io
{
/** True when this build reads DICOM with vtk-dicom. */
bool HasVtkDicom();

/** One line: which DICOM reader this build uses and what it does not support. */
std::string DicomSupport();

/** A configured DICOM reader, or why there is none (one sentence). */
struct DicomSeriesReader
{
  vtkSmartPointer<vtkAlgorithm> Reader;
  std::string Problem;
};

/**
 * The reader for @p path: a folder that holds one series, or one file of a series (the
 * series it belongs to is read, so a folder with several series can still be opened).
 * A folder with no DICOM image or with several series is refused, the latter with a list
 * of its series. @p watch is called on every VTK object that may report errors, before it
 * runs.
 */
DicomSeriesReader OpenDicomSeries(
  const std::string& path, const std::function<void(vtkAlgorithm*)>& watch);

/**
 * After the reader ran: checks what it delivered (one stack, one time point) and computes
 * where it lies. Sets @p oriented when the file gave a patient position and orientation.
 * Returns the problem, empty on success.
 */
std::string PlaceDicomSeries(
  vtkAlgorithm* reader, vtkImageData* image, VolumePlacement* placement, bool* oriented);
}

#endif
