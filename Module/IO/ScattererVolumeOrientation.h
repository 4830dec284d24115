// Where a volume lies in patient space: turns a reader's "data coordinates to patient
// coordinates" matrix (vtkDICOMReader::GetPatientMatrix, vtkNIFTIImageReader's sform or
// qform) into the origin, spacing and direction matrix of a vtkImageData.
//
// One convention for every format: LPS (+x toward the patient's Left, +y Posterior, +z
// Superior), the frame of DICOM (PS3.3 C.7.6.2.1.1, Image Position/Orientation Patient) and
// of ITK, hence of MetaImage and NRRD files ITK-based tools write. NIfTI's qform/sform map
// to RAS (NIfTI-1 header, nifti1.h: "+x = Right +y = Anterior +z = Superior"), so x and y
// are negated. A DICOM series and a NIfTI of the same anatomy then land on the same points.
//
// Plain C++17 without VTK (matrices are row-major double arrays), so it is tested alone.
#ifndef ScattererVolumeOrientation_h
#define ScattererVolumeOrientation_h

#include <string>

namespace scatterer_io
{
/** The patient frame a matrix maps into. */
enum class PatientFrame
{
  LPS, // DICOM, ITK
  RAS  // NIfTI
};

/** A vtkImageData's placement: world = Origin + Direction * (Spacing .* index). */
struct VolumePlacement
{
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Spacing[3] = { 1.0, 1.0, 1.0 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }; // row-major; columns are the i, j, k axes
};

/** Largest |cos| between two normalized axes still taken as rounding (float headers). */
constexpr double kMaxAxisCosine = 1e-4;

/**
 * The placement of an image whose reader delivered origin @p origin and spacing @p spacing
 * (its "data coordinates" origin + spacing .* index) and a row-major 4x4 affine @p matrix
 * from data coordinates to @p frame; the result is in LPS. Axis lengths in the matrix scale
 * the spacing (an sform may hold the voxel size); the direction keeps the file's handedness
 * (a rotation, or a rotation and a reflection). Axes that are not perpendicular within
 * kMaxAxisCosine are a shear, which a direction matrix cannot hold without distorting the
 * anatomy: then the placement is left as is and the returned sentence says why; an empty
 * string means success. Axes within the tolerance are made exactly orthonormal.
 */
std::string PlaceInPatientSpace(const double matrix[16], const double origin[3],
  const double spacing[3], PatientFrame frame, VolumePlacement* placement);
}

#endif
