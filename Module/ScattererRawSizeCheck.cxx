#include "ScattererRawSizeCheck.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace scatterer_io
{
namespace
{
// Bytes a file holds, or -1 if it cannot be opened.
long long FileBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  return in ? static_cast<long long>(in.tellg()) : -1;
}

std::string Trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  const auto e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string Directory(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

std::string Shortfall(long long expected, long long actual, const std::string& what)
{
  std::ostringstream msg;
  msg << "truncated: the header promises " << expected << " bytes of voxel data but " << what
      << " holds only " << actual << ".";
  return msg.str();
}

// Product of the listed extents, or -1 if a number is missing, non-positive or absurd.
long long VoxelCount(const std::string& list)
{
  std::istringstream in(list);
  long long count = 1;
  long long n = 0;
  int axes = 0;
  while (in >> n)
  {
    if (n <= 0 || n > (1LL << 24))
    {
      return -1;
    }
    count *= n;
    if (count > (1LL << 40))
    {
      return -1;
    }
    ++axes;
  }
  return axes > 0 ? count : -1;
}
}

std::string CheckMetaImageSize(const std::string& headerPath)
{
  std::ifstream in(headerPath, std::ios::binary);
  if (!in)
  {
    return "the header cannot be opened.";
  }
  static const std::map<std::string, int> typeBytes = { { "MET_CHAR", 1 }, { "MET_UCHAR", 1 },
    { "MET_SHORT", 2 }, { "MET_USHORT", 2 }, { "MET_INT", 4 }, { "MET_UINT", 4 },
    { "MET_LONG", 4 }, { "MET_ULONG", 4 }, { "MET_LONG_LONG", 8 }, { "MET_ULONG_LONG", 8 },
    { "MET_FLOAT", 4 }, { "MET_DOUBLE", 8 } };
  std::map<std::string, std::string> fields;
  std::string line;
  long long headerBytes = 0;
  int lines = 0;
  while (std::getline(in, line) && ++lines < 200)
  {
    headerBytes += static_cast<long long>(line.size()) + 1;
    const auto eq = line.find('=');
    if (eq == std::string::npos)
    {
      continue;
    }
    const std::string key = Trim(line.substr(0, eq));
    fields[key] = Trim(line.substr(eq + 1));
    if (key == "ElementDataFile")
    {
      break; // by the MetaImage rules, the last header field
    }
  }
  if (fields.find("ElementDataFile") == fields.end())
  {
    return "not a MetaImage header (no ElementDataFile field).";
  }
  if (fields.find("DimSize") == fields.end())
  {
    return "not a MetaImage header (no DimSize field).";
  }
  if (Lower(fields["CompressedData"]) == "true")
  {
    return ""; // compressed size is unknown in advance; the reader checks it
  }
  const long long voxels = VoxelCount(fields["DimSize"]);
  if (voxels < 0)
  {
    return "DimSize '" + fields["DimSize"] + "' is not a list of positive sizes.";
  }
  const auto type = typeBytes.find(fields["ElementType"]);
  if (type == typeBytes.end())
  {
    return "ElementType '" + fields["ElementType"] + "' is not a known MetaImage type.";
  }
  long long channels = 1;
  if (fields.count("ElementNumberOfChannels"))
  {
    channels = std::max(1LL, std::atoll(fields["ElementNumberOfChannels"].c_str()));
  }
  const long long expected = voxels * type->second * channels;
  const std::string dataFile = fields["ElementDataFile"];
  if (dataFile == "LOCAL")
  {
    const long long actual = FileBytes(headerPath) - headerBytes;
    return actual < expected ? Shortfall(expected, actual, "the file") : "";
  }
  if (dataFile.find(' ') != std::string::npos || dataFile.find('%') != std::string::npos ||
    dataFile == "LIST")
  {
    return ""; // a slice list or pattern: the reader checks each file
  }
  const std::string dataPath = dataFile[0] == '/' ? dataFile : Directory(headerPath) + dataFile;
  const long long actual = FileBytes(dataPath);
  if (actual < 0)
  {
    return "its data file '" + dataPath + "' is missing.";
  }
  return actual < expected ? Shortfall(expected, actual, "'" + dataPath + "'") : "";
}

std::string CheckNiftiSize(const std::string& path)
{
  if (path.size() > 3 && Lower(path.substr(path.size() - 3)) == ".gz")
  {
    return ""; // gzip streams are checked by zlib inside the reader
  }
  std::ifstream in(path, std::ios::binary);
  unsigned char header[348];
  if (!in.read(reinterpret_cast<char*>(header), sizeof(header)))
  {
    return "truncated: shorter than the 348-byte NIfTI-1 header.";
  }
  auto read16 = [&](int offset, bool swap) {
    uint16_t v;
    std::memcpy(&v, header + offset, 2);
    if (swap)
    {
      v = static_cast<uint16_t>((v >> 8) | (v << 8));
    }
    return static_cast<int16_t>(v);
  };
  int32_t sizeofHdr;
  std::memcpy(&sizeofHdr, header, 4);
  const bool swap = sizeofHdr != 348;
  if (swap && sizeofHdr != 0x5C010000)
  {
    return ""; // not NIfTI-1 (e.g. NIfTI-2): leave it to the reader
  }
  const int ndim = read16(40, swap);
  if (ndim < 1 || ndim > 7)
  {
    return "the header's dim[0] is not in 1..7.";
  }
  long long voxels = 1;
  for (int i = 1; i <= ndim; ++i)
  {
    const int n = read16(40 + 2 * i, swap);
    if (n <= 0)
    {
      return "the header has a non-positive dimension.";
    }
    voxels *= n;
  }
  const int bitpix = read16(72, swap);
  uint32_t offsetBits;
  std::memcpy(&offsetBits, header + 108, 4);
  if (swap)
  {
    offsetBits = ((offsetBits >> 24) & 0xff) | ((offsetBits >> 8) & 0xff00) |
      ((offsetBits << 8) & 0xff0000) | (offsetBits << 24);
  }
  float voxOffset;
  std::memcpy(&voxOffset, &offsetBits, 4);
  if (!(voxOffset >= 0.0f) || bitpix <= 0)
  {
    return "the header's vox_offset or bitpix is invalid.";
  }
  const long long expected = static_cast<long long>(voxOffset) + voxels * bitpix / 8;
  const long long actual = FileBytes(path);
  return actual < expected ? Shortfall(expected, actual, "the file") : "";
}

std::string CheckNrrdSize(const std::string& headerPath)
{
  std::ifstream in(headerPath, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 4, "NRRD") != 0)
  {
    return "not a NRRD file (no NRRD magic line).";
  }
  long long headerBytes = static_cast<long long>(line.size()) + 1;
  std::map<std::string, std::string> fields;
  int lines = 0;
  while (std::getline(in, line) && ++lines < 500)
  {
    headerBytes += static_cast<long long>(line.size()) + 1;
    if (Trim(line).empty())
    {
      break; // blank line ends the header; attached data follows
    }
    if (line[0] == '#')
    {
      continue;
    }
    const auto colon = line.find(':');
    if (colon != std::string::npos)
    {
      fields[Lower(Trim(line.substr(0, colon)))] = Trim(line.substr(colon + 1));
    }
  }
  const std::string encoding = Lower(fields["encoding"]);
  if (encoding != "raw")
  {
    return ""; // gzip/ascii: the reader reports its own errors
  }
  const long long voxels = VoxelCount(fields["sizes"]);
  if (voxels < 0)
  {
    return "'sizes' is not a list of positive sizes.";
  }
  const std::string type = Lower(fields["type"]);
  int bytes = 0;
  if (type.find("char") != std::string::npos || type.find("int8") != std::string::npos)
  {
    bytes = 1;
  }
  else if (type.find("short") != std::string::npos || type.find("int16") != std::string::npos)
  {
    bytes = 2;
  }
  else if (type.find("longlong") != std::string::npos || type.find("int64") != std::string::npos ||
    type == "double")
  {
    bytes = 8;
  }
  else if (type.find("int") != std::string::npos || type == "float")
  {
    bytes = 4;
  }
  else
  {
    return "type '" + type + "' is not a known NRRD type.";
  }
  const long long expected = voxels * bytes;
  std::string dataFile = fields.count("data file") ? fields["data file"] : fields["datafile"];
  if (dataFile.empty())
  {
    const long long actual = FileBytes(headerPath) - headerBytes;
    return actual < expected ? Shortfall(expected, actual, "the file") : "";
  }
  const std::string dataPath = dataFile[0] == '/' ? dataFile : Directory(headerPath) + dataFile;
  const long long actual = FileBytes(dataPath);
  if (actual < 0)
  {
    return "its data file '" + dataPath + "' is missing.";
  }
  return actual < expected ? Shortfall(expected, actual, "'" + dataPath + "'") : "";
}
}
