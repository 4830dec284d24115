// What the per-format header checks (ScattererVolumeHeaderCheck.h) share: reading the
// files a header names, splitting and parsing header words the way VTK's readers do, and
// the pieces of their one-sentence messages. Private to Module/IO; VTK-free like the
// checks, so the fuzz target compiles it directly.
#ifndef ScattererHeaderCheckCommon_h
#define ScattererHeaderCheckCommon_h

#include <cstddef>
#include <string>
#include <vector>

namespace scatterer_io
{
namespace header_check
{
// Total voxel bytes beyond which a header is absurd (256 TiB); also keeps products from
// overflowing long long.
constexpr long long kMaxVoxelBytes = 1LL << 48;

///@{
/** Files. */
// Bytes a regular file holds, or -1 if there is none.
long long FileBytes(const std::string& path);
// Up to maxBytes from offset; fewer when the file ends first. Callers bound maxBytes.
std::string ReadBytes(const std::string& path, long long offset, std::size_t maxBytes);
// A data file named in a header: relative to the header's folder, as both readers do.
std::string DataPath(const std::string& headerPath, const std::string& name);
///@}

///@{
/** Header text. */
bool IsSpace(char c);
std::string Trim(const std::string& s);
std::string Lower(std::string s);
// The words of s, split at white space.
std::vector<std::string> Split(const std::string& s);
// [+-]digits and nothing else: "3.0", "3abc" and "" are not integers. Values beyond
// 2^62 are refused (no limit here comes near).
bool ParseInteger(const std::string& s, long long* value);
// A decimal number: [+-](digits[.digits]|.digits)[(e|E)[+-]digits]. No "nan", "inf" or
// hexadecimal: the stream extraction (operator>>) MetaIO and vtkNrrdReader read voxels
// with accepts none of them. Too large a number gives +-inf; callers check finiteness.
bool ParseReal(const std::string& s, double* value);
// Parses exactly count reals from words; false if any is missing, extra or not a number.
bool ParseReals(const std::vector<std::string>& words, std::size_t count, double* values);
// a * b, or -1 once the product passes kMaxVoxelBytes (a, b >= 0).
long long Times(long long a, long long b);
///@}

///@{
/** Messages. */
// Quoted for a message; control bytes and long values are shown shortened so one bad
// byte cannot break the one-line message.
std::string Quote(const std::string& s);
std::string Number(double v);
const char* AxisName(int axis);
// "truncated: the header promises <expected> bytes of voxel data but <what> holds only ...".
std::string Shortfall(long long expected, long long actual, const std::string& what);
// "<what> gives <components> values per voxel; the volume mappers render 1 to 4."
std::string ComponentsProblem(long long components, const std::string& what);
///@}
}
}

#endif
