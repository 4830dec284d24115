// The input encoding of fuzz_volume_headers, shared with the seed writer (MakeSeeds.cpp).
//
//   byte 0 % 7 picks the format and how its files are laid out:
//     0 .mha      the rest is the file (MetaImage, usually ElementDataFile = LOCAL)
//     1 .mhd      detached: header + data.raw
//     2 .nrrd     the rest is the file (data attached after the blank line)
//     3 .nhdr     detached: header + data.raw
//     4 .nii      the rest is the file
//     5 .nii.gz   the rest, gzipped here (stored blocks): mutations reach the header
//     6 .nii.gz   the rest as is: mutations reach the gzip decoder
//   detached layouts: bytes 1-2 give the header length L (little-endian, clamped to what
//   is there), then L bytes of header, then the content of data.raw.
#pragma once

#include "ScattererVolumeBytes.h" // Testing/Unit: GzipStored

#include <cstddef>
#include <cstdint>
#include <string>

namespace fuzz {

enum VolumeFormat : std::uint8_t {
  kMetaImageLocal = 0,
  kMetaImageDetached = 1,
  kNrrdAttached = 2,
  kNrrdDetached = 3,
  kNifti = 4,
  kNiftiGzipped = 5,
  kNiftiGzipRaw = 6,
  kVolumeFormats = 7
};

struct VolumeFiles {
  VolumeFormat format = kMetaImageLocal;
  std::string headerName; // file name of the header (or only) file
  std::string header;     // its bytes
  bool detached = false;
  std::string data; // data.raw, when detached
};

inline VolumeFiles decodeVolumeInput(const std::uint8_t* bytes, std::size_t size)
{
  VolumeFiles files;
  if (size == 0) {
    files.headerName = "v.mha";
    return files;
  }
  files.format = static_cast<VolumeFormat>(bytes[0] % kVolumeFormats);
  const std::string rest(reinterpret_cast<const char*>(bytes + 1), size - 1);
  static const char* const names[kVolumeFormats] = { "v.mha", "v.mhd", "v.nrrd", "v.nhdr", "v.nii",
    "v.nii.gz", "v.nii.gz" };
  files.headerName = names[files.format];
  files.detached = files.format == kMetaImageDetached || files.format == kNrrdDetached;
  if (files.detached) {
    const std::size_t length = rest.size() < 2 ? 0
                                               : static_cast<std::uint8_t>(rest[0]) |
                                                   (static_cast<std::uint8_t>(rest[1]) << 8);
    const std::string body = rest.size() < 2 ? std::string() : rest.substr(2);
    files.header = body.substr(0, length < body.size() ? length : body.size());
    files.data = body.substr(files.header.size());
  } else if (files.format == kNiftiGzipped) {
    files.header = scatterer_testing::GzipStored(rest);
  } else {
    files.header = rest;
  }
  return files;
}

inline std::string encodeVolumeInput(
  VolumeFormat format, const std::string& header, const std::string& data = std::string())
{
  std::string out(1, static_cast<char>(format));
  if (format == kMetaImageDetached || format == kNrrdDetached) {
    out += static_cast<char>(header.size() & 0xff);
    out += static_cast<char>((header.size() >> 8) & 0xff);
    out += header + data;
  } else {
    out += header;
  }
  return out;
}

} // namespace fuzz
