// MetaImage (.mhd/.mha), as MetaIO (inside vtkMetaImageReader) reads it: "Name = value"
// or "Name: value" lines up to ElementDataFile, which ends the header
// (ScattererVolumeHeaderCheck.h says why headers are checked before VTK reads them).
#include "ScattererVolumeHeaderCheck.h"

#include "ScattererHeaderCheckCommon.h"
#include "ScattererInflate.h"
#include "ScattererVoxelDataCheck.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

namespace scatterer_io
{
using namespace header_check;

namespace
{
// How much of a MetaImage file may precede ElementDataFile (MetaIO has no limit; real
// headers are well under 4 KiB).
constexpr std::size_t kMetaHeaderWindow = 1 << 16;
}

HeaderCheck CheckMetaImageHeader(const std::string& headerPath)
{
  HeaderCheck check;
  check.Encoding = "raw";
  std::string& problem = check.Problem;
  const long long headerFileBytes = FileBytes(headerPath);
  if (headerFileBytes < 0)
  {
    problem = "the header cannot be opened.";
    return check;
  }
  const std::string text = ReadBytes(headerPath, 0,
    static_cast<std::size_t>(std::min<long long>(headerFileBytes, kMetaHeaderWindow)));

  std::map<std::string, std::string> fields;
  std::map<std::string, int> order; // line of each field, for "must come after NDims"
  long long headerBytes = -1;       // where LOCAL data starts
  std::size_t pos = 0;
  int lineNumber = 0;
  while (pos < text.size() && headerBytes < 0)
  {
    std::size_t end = text.find('\n', pos);
    const bool lastLine = end == std::string::npos;
    if (lastLine)
    {
      end = text.size();
    }
    const std::string line = text.substr(pos, end - pos);
    pos = lastLine ? end : end + 1;
    ++lineNumber;
    if (line.size() >= 500)
    {
      problem = "header line " + std::to_string(lineNumber) +
        " is longer than the 499 characters MetaIO reads.";
      return check;
    }
    // MetaIO compares names as C strings (a NUL ends one), ends a name at '\r' and trims
    // only blanks from it: with control characters its reading and this one would part.
    for (std::size_t i = 0; i < line.size(); ++i)
    {
      const unsigned char c = static_cast<unsigned char>(line[i]);
      if ((c < 0x20 && c != '\t' && !(c == '\r' && i + 1 == line.size())) || c == 0x7f)
      {
        problem = "header line " + std::to_string(lineNumber) +
          " holds a control character (byte " + std::to_string(c) + ").";
        return check;
      }
    }
    const std::string trimmed = Trim(line);
    if (trimmed.empty())
    {
      continue;
    }
    const std::size_t sep = trimmed.find_first_of("=:");
    if (sep == std::string::npos || sep == 0)
    {
      problem = "header line " + std::to_string(lineNumber) + " (" + Quote(trimmed) +
        ") is not 'Name = value'.";
      return check;
    }
    const std::string name = Trim(trimmed.substr(0, sep));
    if (name.size() >= 255)
    {
      // MetaIO copies the name of a field it does not know into a 255-byte buffer.
      problem = "header line " + std::to_string(lineNumber) + " has a field name of " +
        std::to_string(name.size()) + " characters; MetaIO holds at most 254.";
      return check;
    }
    // MetaIO skips every '=', ':' and blank after the name.
    std::size_t v = sep;
    while (v < trimmed.size() &&
      (trimmed[v] == '=' || trimmed[v] == ':' || trimmed[v] == ' ' || trimmed[v] == '\t'))
    {
      ++v;
    }
    const std::string value = Trim(trimmed.substr(v));
    if (value.size() >= 255 && name != "ElementDataFile")
    {
      // MetaIO copies Comment, Name, ObjectType, ObjectSubType and AcquisitionDate into
      // 255-byte buffers; no other field needs a longer value.
      problem = "header line " + std::to_string(lineNumber) + " has a value of " +
        std::to_string(value.size()) + " characters; MetaIO holds at most 254.";
      return check;
    }
    if (fields.count(name))
    {
      problem = "the field " + name + " appears twice.";
      return check;
    }
    fields[name] = value;
    order[name] = lineNumber;
    if (name == "ElementDataFile")
    {
      headerBytes = static_cast<long long>(pos);
    }
  }
  if (headerBytes < 0)
  {
    problem = "not a MetaImage header: no ElementDataFile field in its first " +
      std::to_string(kMetaHeaderWindow / 1024) + " KiB.";
    return check;
  }
  auto has = [&](const char* name) { return fields.count(name) != 0; };

  // NDims, then the fields whose length it gives.
  long long ndims = 0;
  if (!has("NDims"))
  {
    problem = "the header has no NDims field.";
    return check;
  }
  if (!ParseInteger(fields["NDims"], &ndims) || ndims < 1 || ndims > 3)
  {
    problem =
      "NDims is " + Quote(fields["NDims"]) + "; VTK's MetaImage reader reads 1, 2 or 3 dimensions.";
    return check;
  }
  const std::size_t n = static_cast<std::size_t>(ndims);
  // MetaIO reads a numeric field with operator>> for as many numbers as it expects, past
  // the end of the line if need be; a word that is not a number stops the stream, and
  // every field after it is lost. So each numeric field MetaIO knows must hold exactly
  // its count of numbers. (0: NDims numbers, -1: NDims x NDims.)
  static const std::map<std::string, int> numericFields = { { "NDims", 1 },
    { "FileFormatVersion", 1 }, { "ID", 1 }, { "ParentID", 1 }, { "CompressedDataSize", 1 },
    { "HeaderSize", 1 }, { "ElementMin", 1 }, { "ElementMax", 1 }, { "ElementNumberOfChannels", 1 },
    { "ElementNBits", 1 }, { "ElementToIntensityFunctionSlope", 1 },
    { "ElementToIntensityFunctionOffset", 1 }, { "Color", 4 }, { "DimSize", 0 },
    { "ElementSpacing", 0 }, { "ElementSize", 0 }, { "Offset", 0 }, { "Position", 0 },
    { "Origin", 0 }, { "ImagePosition", 0 }, { "CenterOfRotation", 0 }, { "SequenceID", 0 },
    { "ElementOrigin", 0 }, { "TransformMatrix", -1 }, { "Rotation", -1 }, { "Orientation", -1 },
    { "ElementDirection", -1 } };
  for (const auto& field : numericFields)
  {
    if (!has(field.first.c_str()))
    {
      continue;
    }
    if (field.second <= 0 && order[field.first] < order["NDims"])
    {
      problem = field.first + " comes before NDims, which gives its length.";
      return check;
    }
    const std::size_t count = field.second == 0 ? n
      : field.second < 0                        ? n * n
                                                : static_cast<std::size_t>(field.second);
    const std::vector<std::string> words = Split(fields[field.first]);
    double ignored = 0;
    if (words.size() != count ||
      !std::all_of(
        words.begin(), words.end(), [&](const std::string& w) { return ParseReal(w, &ignored); }))
    {
      problem = field.first + " " + Quote(fields[field.first]) + " is not " +
        std::to_string(count) + (count == 1 ? " number." : " numbers.");
      return check;
    }
  }

  if (!has("DimSize"))
  {
    problem = "the header has no DimSize field.";
    return check;
  }
  const std::vector<std::string> sizes = Split(fields["DimSize"]);
  long long voxels = 1;
  for (std::size_t i = 0; i < sizes.size() && i < n; ++i)
  {
    long long size = 0;
    if (!ParseInteger(sizes[i], &size) || size < 1 || size > INT_MAX)
    {
      problem = "DimSize " + Quote(fields["DimSize"]) + " is not a list of positive sizes.";
      return check;
    }
    voxels = Times(voxels, size);
    check.Layout.Dimensions[i] = static_cast<int>(size);
  }
  if (sizes.size() != n)
  {
    problem = "DimSize " + Quote(fields["DimSize"]) + " has " + std::to_string(sizes.size()) +
      " sizes but NDims is " + std::to_string(ndims) + ".";
    return check;
  }

  // The element types vtkMetaImageReader maps to VTK. Not MET_LONG and MET_ULONG: MetaIO
  // reads 4 bytes per value but VTK 9.1 stores them in an 8-byte VTK_LONG array, so half
  // the volume is left unread.
  static const std::map<std::string, std::pair<int, AsciiType>> types = {
    { "MET_CHAR", { 1, kAsciiInt8 } },
    { "MET_UCHAR", { 1, kAsciiUInt8 } },
    { "MET_SHORT", { 2, kAsciiInt16 } },
    { "MET_USHORT", { 2, kAsciiUInt16 } },
    { "MET_INT", { 4, kAsciiInt32 } },
    { "MET_UINT", { 4, kAsciiUInt32 } },
    { "MET_FLOAT", { 4, kAsciiFloat } },
    { "MET_DOUBLE", { 8, kAsciiDouble } },
  };
  std::string typeName = fields["ElementType"];
  // The integer *_ARRAY types read as their scalar type.
  if (typeName.size() > 6 && typeName.compare(typeName.size() - 6, 6, "_ARRAY") == 0 &&
    typeName.find("FLOAT") == std::string::npos && typeName.find("DOUBLE") == std::string::npos)
  {
    typeName = typeName.substr(0, typeName.size() - 6);
  }
  const auto type = types.find(typeName);
  if (typeName == "MET_LONG" || typeName == "MET_ULONG")
  {
    problem = "ElementType " + typeName +
      ": MetaIO reads 4 bytes per value into VTK's 8-byte "
      "long array, leaving half the volume unread (write MET_INT or MET_UINT).";
    return check;
  }
  if (!has("ElementType") || type == types.end())
  {
    problem = "ElementType " + Quote(fields["ElementType"]) +
      " is not one VTK's MetaImage reader reads (MET_CHAR, MET_UCHAR, MET_SHORT, MET_USHORT, "
      "MET_INT, MET_UINT, MET_FLOAT, MET_DOUBLE).";
    return check;
  }

  long long channels = 1;
  if (has("ElementNumberOfChannels"))
  {
    if (!ParseInteger(fields["ElementNumberOfChannels"], &channels) || channels < 1 ||
      channels > kMaxComponents)
    {
      problem = "ElementNumberOfChannels is " + Quote(fields["ElementNumberOfChannels"]) +
        "; the volume mappers render 1 to " + std::to_string(kMaxComponents) + " channels.";
      return check;
    }
  }
  check.Layout.Components = static_cast<int>(channels);

  // The NDims numbers of a spacing or origin field.
  auto vectorField = [&](const char* name, double* values)
  {
    if (ParseReals(Split(fields[name]), n, values))
    {
      return true;
    }
    problem = std::string(name) + " " + Quote(fields[name]) + " is not " + std::to_string(ndims) +
      " numbers.";
    return false;
  };
  // Spacing: ElementSpacing, else ElementSize (MetaIO copies it), else 1.
  for (const char* name : { "ElementSize", "ElementSpacing" })
  {
    if (!has(name))
    {
      continue;
    }
    double values[3] = { 1, 1, 1 };
    if (!vectorField(name, values))
    {
      return check;
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      check.Layout.Spacing[i] = values[i];
    }
  }
  // Origin: MetaIO knows four names for it; they must agree. (VTK 9.1's MetaIO does not
  // apply ElementOrigin, so this does not either.)
  std::string originField;
  for (const char* name : { "Offset", "Position", "Origin", "ImagePosition" })
  {
    if (!has(name))
    {
      continue;
    }
    double values[3] = { 0, 0, 0 };
    if (!vectorField(name, values))
    {
      return check;
    }
    if (!originField.empty() &&
      !std::equal(values, values + n, check.Layout.Origin,
        [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }))
    {
      problem = originField + " and " + name + " give different origins.";
      return check;
    }
    std::copy(values, values + n, check.Layout.Origin);
    originField = name;
  }
  problem = CheckLayout(check.Layout);
  if (!problem.empty())
  {
    return check;
  }

  // How the data is stored, and where.
  auto flag = [&](const char* name, bool fallback, bool* value)
  {
    if (!has(name))
    {
      *value = fallback;
      return true;
    }
    const std::string v = Lower(fields[name]);
    *value = v == "true" || v == "1";
    return *value || v == "false" || v == "0";
  };
  bool binary = true;
  bool compressed = false;
  if (!flag("BinaryData", true, &binary) || !flag("CompressedData", false, &compressed))
  {
    problem = "BinaryData and CompressedData must be True or False.";
    return check;
  }
  if (compressed && !binary)
  {
    problem = "CompressedData = True with BinaryData = False: MetaIO ignores the compression "
              "of ascii data.";
    return check;
  }
  long long headerSize = 0;
  if (has("HeaderSize") &&
    (!ParseInteger(fields["HeaderSize"], &headerSize) || headerSize < -1 || headerSize > INT_MAX))
  {
    problem = "HeaderSize " + Quote(fields["HeaderSize"]) +
      " is neither a byte count nor -1 (data at the end of the file).";
    return check;
  }
  if (headerSize == -1 && (compressed || !binary))
  {
    problem = "HeaderSize = -1 (data at the end of the file) works only for raw binary data, "
              "not compressed or ascii data.";
    return check;
  }
  const long long elementBytes = Times(type->second.first, channels);
  const long long promised = Times(voxels, elementBytes);
  if (promised < 0)
  {
    problem = "DimSize " + Quote(fields["DimSize"]) + " makes an absurdly large volume.";
    return check;
  }

  const std::string dataFile = fields["ElementDataFile"];
  std::string dataPath;
  std::string dataName; // for messages
  long long dataStart = 0;
  if (dataFile.empty())
  {
    problem = "ElementDataFile is empty.";
    return check;
  }
  if (dataFile == "LOCAL" || dataFile == "Local" || dataFile == "local")
  {
    dataPath = headerPath;
    dataName = "the file";
    dataStart = headerBytes;
  }
  else if (dataFile.compare(0, 4, "LIST") == 0 || dataFile.find('%') != std::string::npos)
  {
    problem = "ElementDataFile " + Quote(dataFile) +
      " splits the data over several files; this reader opens one data file (join the slices).";
    return check;
  }
  else
  {
    dataPath = DataPath(headerPath, dataFile);
    dataName = "'" + dataPath + "'";
  }
  const long long fileBytes = FileBytes(dataPath);
  if (fileBytes < 0)
  {
    problem = "its data file '" + dataPath + "' is missing.";
    return check;
  }
  if (headerSize > 0)
  {
    // MetaIO seeks to HeaderSize from the start of the data file (for LOCAL data, of the
    // header file itself).
    if (dataPath == headerPath && headerSize < headerBytes)
    {
      problem = "HeaderSize " + std::to_string(headerSize) +
        " points inside the text header, which ends at byte " + std::to_string(headerBytes) + ".";
      return check;
    }
    dataStart = headerSize;
    if (binary && !compressed && fileBytes - dataStart < promised)
    {
      std::ostringstream msg;
      msg << "truncated: " << dataName << " holds " << fileBytes
          << " bytes, fewer than HeaderSize (" << headerSize << ") plus the " << promised
          << " bytes of voxel data the header promises.";
      problem = msg.str();
      return check;
    }
  }
  else if (headerSize == -1)
  {
    // The voxels are the last bytes of the file.
    if (fileBytes - promised < (dataPath == headerPath ? headerBytes : 0))
    {
      std::ostringstream msg;
      msg << "truncated: with HeaderSize = -1 the voxels are the last " << promised << " bytes of "
          << dataName << ", but it holds only "
          << fileBytes - (dataPath == headerPath ? headerBytes : 0) << " bytes of data.";
      problem = msg.str();
      return check;
    }
    dataStart = fileBytes - promised;
  }
  const long long available = fileBytes - dataStart;
  if (available <= 0)
  {
    problem = Shortfall(promised, available, dataName);
    return check;
  }

  if (!binary)
  {
    check.Encoding = "ascii";
    problem = CheckAsciiNumbers(dataPath, dataStart, Times(voxels, channels), type->second.second,
      dataPath == headerPath ? "the file" : dataName);
    return check;
  }
  if (compressed)
  {
    long long compressedBytes = available;
    if (has("CompressedDataSize"))
    {
      if (!ParseInteger(fields["CompressedDataSize"], &compressedBytes) || compressedBytes < 1)
      {
        problem = "CompressedDataSize " + Quote(fields["CompressedDataSize"]) +
          " is not a positive byte count.";
        return check;
      }
      if (compressedBytes > available)
      {
        std::ostringstream msg;
        msg << "truncated: CompressedDataSize is " << compressedBytes << " but " << dataName
            << " holds only " << std::max(available, 0LL) << " bytes of data.";
        problem = msg.str();
        return check;
      }
    }
    const std::string start = ReadBytes(dataPath, dataStart, 2);
    check.Encoding = IsGzip(start) ? "gzip" : "zlib";
    if (!IsGzip(start) && !IsZlib(start))
    {
      problem = "CompressedData = True, but the data does not start like a zlib or gzip stream "
                "(it is probably not compressed).";
      return check;
    }
    problem =
      CheckCompressedFile(dataPath, dataStart, compressedBytes, promised, true, "compressed data");
    return check;
  }
  if (available < promised)
  {
    problem = Shortfall(promised, available, dataName);
  }
  return check;
}
}
