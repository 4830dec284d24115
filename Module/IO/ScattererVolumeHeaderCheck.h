// Header validation for the volume formats vtkScattererVolumeReader opens through
// VTK's readers: MetaImage (.mhd/.mha), NRRD (.nrrd/.nhdr) and NIfTI (.nii/.nii.gz).
//
// VTK 9.1's readers trust their headers. A negative channel count, a dimension
// that disagrees with the sizes or an unknown NIfTI datatype crashes them; a
// HeaderSize past the data, a CompressedData flag on raw data, ascii junk, NaN
// or zero spacing or a truncated file gives a wrong or empty volume without
// an error. These checks parse each header the way the VTK reader will (same
// field syntax, same defaults, same quirks; each quirk is named where it is
// handled) and refuse anything that reader would crash on or misread, before
// it sees the file. They also compare the header with the data behind it:
// enough raw bytes, ascii numbers that parse, compressed data that really is
// a zlib/gzip stream and decodes (the first MiB is decoded, and all of it when
// the volume is that small).
//
// Plain C++17 with no VTK and no zlib (a small inflater is built in), so the
// checks can be fuzzed cheaply (Testing/Fuzz, docs/fuzzing.md). Every problem
// is one sentence without the header's path: the caller names the file.
//
// One source per format: ScattererMetaImageHeaderCheck.cxx,
// ScattererNrrdHeaderCheck.cxx (its header parsed by ScattererNrrdHeaderFields.cxx)
// and ScattererNiftiHeaderCheck.cxx. What they share: CheckLayout and the helpers of
// ScattererHeaderCheckCommon.h (ScattererVolumeHeaderCheck.cxx), the voxel data checks
// (ScattererVoxelDataCheck.h) and the inflater (ScattererInflate.h).
#ifndef ScattererVolumeHeaderCheck_h
#define ScattererVolumeHeaderCheck_h

#include <cstddef>
#include <string>

namespace scatterer_io
{
/** The grid a header promises, as the VTK reader will deliver it. */
struct VolumeLayout
{
  int Dimensions[3] = { 1, 1, 1 };
  int Components = 1;
  double Spacing[3] = { 1.0, 1.0, 1.0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
};

/** The verdict on one header: Problem is empty when the file may be read. */
struct HeaderCheck
{
  std::string Problem;
  VolumeLayout Layout;  // meaningful only when Problem is empty
  std::string Encoding; // how the voxels are stored: "raw", "ascii", "gzip" or "zlib"
};

///@{
/** The limits the checks apply (docs/hard-cases.md, "Bad input"). */
constexpr int kMaxComponents = 4;                   // what VTK's volume mappers render
constexpr double kMinSpacing = 1e-12;               // beyond these the single-precision renderer
constexpr double kMaxSpacing = 1e12;                // loses the grid
constexpr double kMaxOriginInSpacings = 16777216.0; // 2^24: float resolves no finer
constexpr std::size_t kInflateCheckBytes = std::size_t(1) << 20; // decoded to verify a stream
///@}

HeaderCheck CheckMetaImageHeader(const std::string& headerPath);
HeaderCheck CheckNrrdHeader(const std::string& headerPath);
/** .nii, or .nii.gz (gzip is decoded here; a .nii.gz that is not gzip is read as is, like VTK). */
HeaderCheck CheckNiftiHeader(const std::string& path);

/**
 * Spacing finite and in [kMinSpacing, kMaxSpacing], origin finite and within
 * kMaxOriginInSpacings spacings of 0 on each axis, and 1..kMaxComponents
 * components. Empty if the layout is sound. Used on each header's promise and
 * again on what the VTK reader delivered (also for formats without a header
 * check, such as DICOM series and VTK XML images, where checkComponents is false).
 */
std::string CheckLayout(const VolumeLayout& layout, bool checkComponents = true);
}

#endif
