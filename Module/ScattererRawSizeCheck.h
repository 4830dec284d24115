// Header-versus-disk size checks for raw volume formats.
//
// VTK's raw readers (MetaImage, NIfTI, NRRD) read whatever bytes exist and
// leave the rest of the volume as garbage when a file is truncated. These
// checks parse just enough of each header to know how many voxel bytes it
// promises and compare with the bytes on disk. Each returns an empty string
// when the file is complete (or when the size cannot be known in advance,
// e.g. compressed data, which the readers check themselves), else a sentence
// saying what is missing.
#ifndef ScattererRawSizeCheck_h
#define ScattererRawSizeCheck_h

#include <string>

namespace scatterer_io
{
std::string CheckMetaImageSize(const std::string& headerPath);
std::string CheckNiftiSize(const std::string& path);
std::string CheckNrrdSize(const std::string& headerPath);
}

#endif
