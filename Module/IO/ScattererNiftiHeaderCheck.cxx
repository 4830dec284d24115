// NIfTI-1 and -2 (and Analyze 7.5), as vtkNIFTIImageReader reads a single .nii file,
// or a .nii.gz whose gzip stream is decoded here (ScattererVolumeHeaderCheck.h says why
// headers are checked before VTK reads them).
#include "ScattererVolumeHeaderCheck.h"

#include "ScattererHeaderCheckCommon.h"
#include "ScattererInflate.h"
#include "ScattererVoxelDataCheck.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace scatterer_io
{
using namespace header_check;

HeaderCheck CheckNiftiHeader(const std::string& path)
{
  HeaderCheck check;
  check.Encoding = "raw";
  std::string& problem = check.Problem;
  const long long fileBytes = FileBytes(path);
  if (fileBytes < 0)
  {
    problem = "the file cannot be opened.";
    return check;
  }
  constexpr std::size_t kNifti2Bytes = 540;
  std::string bytes = ReadBytes(path, 0, kNifti2Bytes);
  const bool gzip = IsGzip(bytes); // gzopen reads anything else as is
  if (gzip)
  {
    check.Encoding = "gzip";
    const InflateResult r = Inflate(ReadBytes(path, 0,
                                      static_cast<std::size_t>(std::min<long long>(fileBytes,
                                        static_cast<long long>(kInflateCheckBytes) + (1 << 16)))),
      kNifti2Bytes, false);
    if (r.Status == InflateStatus::Corrupt)
    {
      problem = "its gzip data is corrupt (" + r.Why + ").";
      return check;
    }
    bytes.assign(r.Output.begin(), r.Output.end());
  }
  if (bytes.size() < 348)
  {
    problem = "truncated: shorter than the 348-byte NIfTI-1 header.";
    return check;
  }
  const auto* h = reinterpret_cast<const std::uint8_t*>(bytes.data());

  // Version, as vtkNIFTIImageReader::CheckNIFTIVersion: NIfTI-2's magic is where NIfTI-1
  // keeps data_type.
  int version = 0;
  if (h[4] == 'n' && (h[5] == '+' || h[5] == 'i') && h[6] >= '2' && h[6] <= '9' && h[7] == 0)
  {
    if (h[8] != '\r' || h[9] != '\n' || h[10] != 032 || h[11] != '\n')
    {
      problem = "the NIfTI-2 header was damaged by a newline conversion.";
      return check;
    }
    if (h[6] != '2')
    {
      problem = "NIfTI version " + std::string(1, static_cast<char>(h[6])) + " is not supported.";
      return check;
    }
    version = 2;
  }
  else if (h[344] == 'n' && (h[345] == '+' || h[345] == 'i') && h[346] == '1' && h[347] == 0)
  {
    version = 1;
  }
  if (version == 2 && bytes.size() < kNifti2Bytes)
  {
    problem = "truncated: shorter than the 540-byte NIfTI-2 header.";
    return check;
  }
  const long long headerSize = version == 2 ? 540 : 348;
  if (version == 1 && h[345] == 'i')
  {
    problem = "its magic 'ni1' says the voxels are in a separate .img file; this reader opens "
              "single-file .nii volumes.";
    return check;
  }

  // Byte order: the reader swaps when dim[0] is outside 0..7.
  auto read = [&](int offset, int size, bool swap)
  {
    std::uint64_t v = 0;
    for (int i = 0; i < size; ++i)
    {
      const int k = swap ? size - 1 - i : i;
      v |= static_cast<std::uint64_t>(h[offset + k]) << (8 * i);
    }
    return v;
  };
  const int dimOffset = version == 2 ? 16 : 40;
  const int dimSize = version == 2 ? 8 : 2;
  auto signedValue = [&](int offset, int size, bool swap) -> long long
  {
    const std::uint64_t v = read(offset, size, swap);
    if (size == 2)
      return static_cast<std::int16_t>(v);
    if (size == 4)
      return static_cast<std::int32_t>(v);
    return static_cast<std::int64_t>(v);
  };
  const long long dim0 = signedValue(dimOffset, dimSize, false);
  const bool swap = dim0 < 0 || dim0 > 7;
  auto float32 = [&](int offset)
  {
    const auto bits = static_cast<std::uint32_t>(read(offset, 4, swap));
    float f = 0;
    std::memcpy(&f, &bits, 4);
    return f;
  };
  const long long sizeofHdr = signedValue(0, 4, swap);
  if (sizeofHdr != headerSize)
  {
    problem = "not a NIfTI header (sizeof_hdr is " + std::to_string(sizeofHdr) + ", not " +
      std::to_string(headerSize) + ", in either byte order).";
    return check;
  }
  const long long ndim = signedValue(dimOffset, dimSize, swap);
  if (ndim < 1 || ndim > 7)
  {
    problem = "dim[0] (the number of axes) is " + std::to_string(ndim) + ", not 1 to 7.";
    return check;
  }
  long long dims[8] = { ndim, 1, 1, 1, 1, 1, 1, 1 };
  long long voxels = 1;
  for (int i = 1; i <= ndim; ++i)
  {
    dims[i] = signedValue(dimOffset + dimSize * i, dimSize, swap);
    if (dims[i] < 1 || dims[i] > INT_MAX)
    {
      problem =
        "dim[" + std::to_string(i) + "] is " + std::to_string(dims[i]) + ", not a positive size.";
      return check;
    }
    voxels = Times(voxels, dims[i]);
  }

  // The datatypes vtkNIFTIImageReader maps (any other crashes VTK 9.1's reader).
  struct NiftiType
  {
    int Code;
    int Bits;
    int Components;
  };
  static const NiftiType types[] = { { 2, 8, 1 }, { 4, 16, 1 }, { 8, 32, 1 }, { 16, 32, 1 },
    { 32, 64, 2 }, { 64, 64, 1 }, { 128, 24, 3 }, { 256, 8, 1 }, { 512, 16, 1 }, { 768, 32, 1 },
    { 1024, 64, 1 }, { 1280, 64, 1 }, { 1792, 128, 2 }, { 2304, 32, 4 } };
  const int typeOffset = version == 2 ? 12 : 70;
  const long long datatype = signedValue(typeOffset, 2, swap);
  const long long bitpix = signedValue(typeOffset + 2, 2, swap);
  const NiftiType* type = nullptr;
  for (const NiftiType& t : types)
  {
    if (t.Code == datatype)
    {
      type = &t;
    }
  }
  if (!type)
  {
    problem = "datatype " + std::to_string(datatype) +
      " is not one VTK's NIfTI reader reads (2, 4, 8, 16, 32, 64, 128, 256, 512, 768, 1024, "
      "1280, 1792, 2304).";
    return check;
  }
  if (bitpix != type->Bits)
  {
    problem = "bitpix is " + std::to_string(bitpix) + " but datatype " + std::to_string(datatype) +
      " has " + std::to_string(type->Bits) + " bits per voxel.";
    return check;
  }
  // A 5th axis holds values per voxel; a 4th (time) and the 6th and 7th are read as their
  // first frame.
  const long long components = type->Components * (ndim >= 5 ? dims[5] : 1);
  if (components > kMaxComponents)
  {
    problem = ComponentsProblem(components,
      "datatype " + std::to_string(datatype) + " with dim[5] = " + std::to_string(dims[5]));
    return check;
  }
  check.Layout.Components = static_cast<int>(components);

  // pixdim[1..3] is the spacing; the reader replaces 0 by 1, which is right only for an
  // axis the image does not have.
  const int pixdimOffset = version == 2 ? 104 : 76;
  for (int i = 1; i <= 3; ++i)
  {
    double s = 0;
    if (version == 2)
    {
      const std::uint64_t bits = read(pixdimOffset + 8 * i, 8, swap);
      std::memcpy(&s, &bits, 8);
    }
    else
    {
      s = float32(pixdimOffset + 4 * i);
    }
    if (s == 0 && i > ndim)
    {
      s = 1;
    }
    check.Layout.Dimensions[i - 1] = static_cast<int>(dims[i]);
    check.Layout.Spacing[i - 1] = s;
  }
  // The origin is 0: the NIfTI offset belongs to the qform/sform matrices, which this
  // reader does not apply.
  problem = CheckLayout(check.Layout);
  if (!problem.empty())
  {
    return check;
  }

  double voxOffset = 0;
  if (version == 2)
  {
    voxOffset = static_cast<double>(signedValue(168, 8, swap));
  }
  else
  {
    voxOffset = float32(108);
  }
  if (!std::isfinite(voxOffset) || voxOffset < headerSize || voxOffset > 1e15)
  {
    problem = "vox_offset is " + Number(voxOffset) + ", not a byte offset past the " +
      std::to_string(headerSize) + "-byte header.";
    return check;
  }
  const long long dataStart = static_cast<long long>(voxOffset); // the reader truncates too
  const long long promised = Times(voxels, type->Bits / 8);
  const long long expected = promised < 0 ? -1 : dataStart + promised;
  if (promised < 0 || expected > kMaxVoxelBytes)
  {
    problem = "its dimensions make an absurdly large volume.";
    return check;
  }
  if (!gzip)
  {
    if (fileBytes < expected)
    {
      problem = Shortfall(expected, fileBytes, "the file");
    }
    return check;
  }
  // .nii.gz: header and voxels are one gzip stream; decode it as far as the check goes.
  problem = CheckCompressedFile(path, 0, fileBytes, expected, false, "gzip data");
  return check;
}
}
