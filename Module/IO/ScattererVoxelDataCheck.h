// Checks of the voxel data behind a header, shared by the MetaImage, NRRD and NIfTI
// checks (ScattererVolumeHeaderCheck.h): ascii numbers that the reader's operator>> will
// parse, and compressed data that really decodes to what the header promises.
#ifndef ScattererVoxelDataCheck_h
#define ScattererVoxelDataCheck_h

#include <string>

namespace scatterer_io
{
namespace header_check
{
enum class NumberKind
{
  Integer,
  Real
};

/** The ascii values a voxel type holds. */
struct AsciiType
{
  NumberKind Kind;
  double Min;
  double Max;
};

///@{
/**
 * The C types both readers know, by size. The 64-bit integer limits stop short of 2^63
 * because ParseInteger refuses values beyond 2^62.
 */
constexpr AsciiType kAsciiInt8 = { NumberKind::Integer, -128, 127 };
constexpr AsciiType kAsciiUInt8 = { NumberKind::Integer, 0, 255 };
constexpr AsciiType kAsciiInt16 = { NumberKind::Integer, -32768, 32767 };
constexpr AsciiType kAsciiUInt16 = { NumberKind::Integer, 0, 65535 };
constexpr AsciiType kAsciiInt32 = { NumberKind::Integer, -2147483648.0, 2147483647.0 };
constexpr AsciiType kAsciiUInt32 = { NumberKind::Integer, 0, 4294967295.0 };
constexpr AsciiType kAsciiInt64 = { NumberKind::Integer, -4.6e18, 4.6e18 };
constexpr AsciiType kAsciiUInt64 = { NumberKind::Integer, 0, 4.6e18 };
constexpr AsciiType kAsciiFloat = { NumberKind::Real, -3.4e38, 3.4e38 };
constexpr AsciiType kAsciiDouble = { NumberKind::Real, -1.7e308, 1.7e308 };
///@}

/**
 * Ascii voxel data: VTK and MetaIO read it with operator>>, which stops at the first
 * token that is not a number of the voxel type and leaves the rest of the volume as it
 * was. So every token up to the promised count must be one. where names the file in
 * messages. Empty if sound.
 */
std::string CheckAsciiNumbers(const std::string& path, long long offset, long long promised,
  const AsciiType& type, const std::string& where);

/**
 * Compressed voxel data from offset (bytes of it; all of it is read when small, else
 * enough for the check): the stream decodes, to at least the promised bytes when it is
 * decoded whole. allowZlib: a zlib stream is accepted besides gzip. what names the
 * encoding in messages. Empty if sound.
 */
std::string CheckCompressedFile(const std::string& path, long long offset, long long bytes,
  long long promised, bool allowZlib, const std::string& what);
}
}

#endif
