// Builds the volume files the header tests and the fuzz seeds need (MetaImage and NRRD
// header text, NIfTI-1/-2 header bytes, gzip and zlib streams, voxel values), for
// TestVolumeHeaders.cxx and Testing/Fuzz (MakeSeeds.cpp, VolumeHeaderInput.h). The bytes
// come from the formats' specifications (nifti1.h/nifti2.h, RFC 1950/1951/1952), not from
// the code under test: the compressed streams use stored (uncompressed) deflate blocks,
// so no zlib is needed and every voxel byte is where a test expects it.
#ifndef ScattererVolumeBytes_h
#define ScattererVolumeBytes_h

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace scatterer_testing
{
//------------------------------------------------------------------------------
// Voxel values

/** count 16-bit little-endian voxels, voxel n holding value(n). */
template <typename Value>
std::string ShortBytes(int count, Value value)
{
  std::string bytes;
  for (int n = 0; n < count; ++n)
  {
    const auto v = static_cast<std::uint16_t>(value(n));
    bytes += static_cast<char>(v & 0xff);
    bytes += static_cast<char>(v >> 8);
  }
  return bytes;
}

/** count ascii values value(n), perLine to a line, each followed by ' ' or '\n'. */
template <typename Value>
std::string AsciiValues(int count, int perLine, Value value)
{
  std::string text;
  for (int n = 0; n < count; ++n)
  {
    text += std::to_string(value(n)) + (n % perLine == perLine - 1 ? "\n" : " ");
  }
  return text;
}

//------------------------------------------------------------------------------
// Header text

/**
 * A MetaImage header of a 3D MET_SHORT volume of @p dimSize ("11 5 3"): @p fields go
 * between ElementType and ElementDataFile, which ends the header.
 */
inline std::string MetaImageHeader(
  const std::string& dimSize, const std::string& fields, const std::string& dataFile)
{
  return "ObjectType = Image\nNDims = 3\nDimSize = " + dimSize + "\nElementType = MET_SHORT\n" +
    fields + "ElementDataFile = " + dataFile + "\n";
}

/**
 * A NRRD0004 header with a comment line and @p fields ("name: value\n" each), ended by
 * the empty line after which attached data starts.
 */
inline std::string NrrdHeader(const std::string& comment, const std::string& fields)
{
  return "NRRD0004\n# " + comment + "\n" + fields + "\n";
}

//------------------------------------------------------------------------------
// NIfTI header bytes (little-endian)

/** The fields of a NIfTI-1 header that the tests vary; the rest is zero. */
struct Nifti1Fields
{
  std::array<std::int16_t, 3> Dim = { 1, 1, 1 };
  std::int16_t Datatype = 4; // DT_INT16
  std::int16_t Bitpix = 16;
  std::array<float, 3> Pixdim = { 1.0f, 1.0f, 1.0f };
  const char* Magic = "n+1"; // "ni1": the voxels are in a separate .img file
};

/** A 348-byte NIfTI-1 header padded to 352 bytes, the voxels' offset (vox_offset). */
inline std::string Nifti1Header(const Nifti1Fields& f)
{
  std::string h(352, '\0');
  auto put = [&](int offset, const void* value, std::size_t size)
  { std::memcpy(&h[static_cast<std::size_t>(offset)], value, size); };
  const std::int32_t sizeofHdr = 348;
  const std::int16_t dim[8] = { 3, f.Dim[0], f.Dim[1], f.Dim[2], 1, 1, 1, 1 };
  const float pixdim[8] = { 1.0f, f.Pixdim[0], f.Pixdim[1], f.Pixdim[2], 0, 0, 0, 0 };
  const float voxOffset = 352.0f;
  const float slope = 1.0f;
  put(0, &sizeofHdr, 4);
  put(40, dim, sizeof dim);
  put(70, &f.Datatype, 2);
  put(72, &f.Bitpix, 2);
  put(76, pixdim, sizeof pixdim);
  put(108, &voxOffset, 4);
  put(112, &slope, 4);
  put(344, f.Magic, 4);
  return h;
}

/** A 540-byte NIfTI-2 header of a 3D int16 volume padded to 544, its vox_offset. */
inline std::string Nifti2Header(
  const std::array<std::int64_t, 3>& size, const std::array<double, 3>& spacing)
{
  std::string h(544, '\0');
  auto put = [&](int offset, const void* value, std::size_t n)
  { std::memcpy(&h[static_cast<std::size_t>(offset)], value, n); };
  const std::int32_t sizeofHdr = 540;
  const std::int16_t datatype = 4;
  const std::int16_t bitpix = 16;
  const std::int64_t dim[8] = { 3, size[0], size[1], size[2], 1, 1, 1, 1 };
  const double pixdim[8] = { 1.0, spacing[0], spacing[1], spacing[2], 0, 0, 0, 0 };
  const std::int64_t voxOffset = 544;
  put(0, &sizeofHdr, 4);
  put(4, "n+2\0\r\n\032\n", 8);
  put(12, &datatype, 2);
  put(14, &bitpix, 2);
  put(16, dim, sizeof dim);
  put(104, pixdim, sizeof pixdim);
  put(168, &voxOffset, 8);
  return h;
}

//------------------------------------------------------------------------------
// Compressed streams

inline std::uint32_t Crc32(const std::string& data)
{
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char c : data)
  {
    crc ^= c;
    for (int k = 0; k < 8; ++k)
    {
      crc = (crc & 1) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
    }
  }
  return crc ^ 0xffffffffu;
}

inline std::uint32_t Adler32(const std::string& data)
{
  std::uint32_t a = 1;
  std::uint32_t b = 0;
  for (unsigned char c : data)
  {
    a = (a + c) % 65521u;
    b = (b + a) % 65521u;
  }
  return (b << 16) | a;
}

/** A raw deflate stream (RFC 1951) of stored blocks of up to 65535 bytes. */
inline std::string DeflateStored(const std::string& data)
{
  std::string out;
  std::size_t pos = 0;
  do
  {
    const std::size_t n = std::min<std::size_t>(65535, data.size() - pos);
    out += static_cast<char>(pos + n == data.size() ? 1 : 0); // BFINAL on the last block
    const auto len = static_cast<std::uint16_t>(n);
    const auto nlen = static_cast<std::uint16_t>(~len);
    out += static_cast<char>(len & 0xff);
    out += static_cast<char>(len >> 8);
    out += static_cast<char>(nlen & 0xff);
    out += static_cast<char>(nlen >> 8);
    out += data.substr(pos, n);
    pos += n;
  } while (pos < data.size());
  return out;
}

/** A valid gzip member (RFC 1952) of stored blocks. */
inline std::string GzipStored(const std::string& data)
{
  std::string out = std::string("\x1f\x8b\x08\0\0\0\0\0\0\x03", 10) + DeflateStored(data);
  for (const std::uint32_t v : { Crc32(data), static_cast<std::uint32_t>(data.size()) })
  {
    for (int i = 0; i < 4; ++i)
    {
      out += static_cast<char>((v >> (8 * i)) & 0xff); // little-endian
    }
  }
  return out;
}

/** A valid zlib stream (RFC 1950) of stored blocks. */
inline std::string ZlibStored(const std::string& data)
{
  std::string out = std::string("\x78\x01", 2) + DeflateStored(data);
  const std::uint32_t adler = Adler32(data);
  for (int i = 3; i >= 0; --i)
  {
    out += static_cast<char>((adler >> (8 * i)) & 0xff); // big-endian
  }
  return out;
}
}

#endif
