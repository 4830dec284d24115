// Inflate (RFC 1950/1951/1952) without zlib: enough to verify the compressed voxel data a
// header promises and to read the header inside a .nii.gz. The header checks stay free
// of VTK and zlib so that they can be fuzzed cheaply (ScattererVolumeHeaderCheck.h).
//
//   ScattererInflate.cxx        the gzip and zlib containers and their checksums
//   ScattererDeflateDecoder.cxx the raw deflate stream inside them
#ifndef ScattererInflate_h
#define ScattererInflate_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace scatterer_io
{
namespace header_check
{
enum class InflateStatus
{
  Complete,  // the stream (every gzip member) ended, checksums right
  Limit,     // the output limit was reached first: what was decoded is sound
  Truncated, // the input ended inside the stream
  Corrupt    // invalid data; Why says what
};

struct InflateResult
{
  InflateStatus Status = InflateStatus::Corrupt;
  std::vector<std::uint8_t> Output;
  std::string Why;
};

/** The data starts with gzip's magic bytes 1f 8b. */
bool IsGzip(const std::string& data);
/** The data starts with a valid zlib header (deflate, check bits right). */
bool IsZlib(const std::string& data);

/**
 * Decodes a gzip file (all its members, as gzread does) or, with allowZlib, a zlib
 * stream, up to limit bytes. Checksums are verified for every member decoded whole.
 */
InflateResult Inflate(const std::string& data, std::size_t limit, bool allowZlib);

/**
 * Decodes one raw deflate stream (RFC 1951) from in[0, size), appending at most up to
 * limit bytes in all to out. consumed: the input bytes used (a partly used byte counts).
 * Sets why when the data is corrupt.
 */
InflateStatus InflateDeflateStream(const std::uint8_t* in, std::size_t size, std::size_t limit,
  std::vector<std::uint8_t>& out, std::string& why, std::size_t& consumed);
}
}

#endif
