// NRRD (.nrrd/.nhdr): what the header parsed by ScattererNrrdHeaderFields.cxx means
// for the volume vtkNrrdReader 9.1 will deliver, and whether the data behind it holds
// that volume (quirks noted where they are handled).
#include "ScattererVolumeHeaderCheck.h"

#include "ScattererHeaderCheckCommon.h"
#include "ScattererInflate.h"
#include "ScattererNrrdHeaderFields.h"
#include "ScattererVoxelDataCheck.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace scatterer_io
{
using namespace header_check;

HeaderCheck CheckNrrdHeader(const std::string& headerPath)
{
  HeaderCheck check;
  std::string& problem = check.Problem;
  NrrdFields header;
  problem = ReadNrrdFields(headerPath, &header);
  if (!problem.empty())
  {
    return check;
  }
  std::map<std::string, std::string>& fields = header.Fields;
  const int declaredDimension = header.Dimension;
  const std::vector<long long>& sizes = header.Sizes;
  const std::vector<double>& spacing = header.Spacing;
  const bool spacingIsDirections = header.SpacingIsDirections;
  const long long headerBytes = header.HeaderBytes;
  std::copy(header.Origin, header.Origin + 3, check.Layout.Origin);

  if (declaredDimension == 0 || sizes.empty())
  {
    problem = "the header lacks 'dimension' or 'sizes' (written as 'name: value').";
    return check;
  }
  // Voxel type: the names vtkNrrdReader knows (after trimming), with their ascii range.
  struct NrrdType
  {
    std::vector<const char*> Names;
    int Bytes;
    AsciiType Ascii;
  };
  static const std::vector<NrrdType> types = {
    { { "signed char", "int8", "int8_t" }, 1, kAsciiInt8 },
    { { "uchar", "unsigned char", "uint8", "uint8_t" }, 1, kAsciiUInt8 },
    { { "short", "short int", "signed short", "signed short int", "int16", "int16_t" }, 2,
      kAsciiInt16 },
    { { "ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t" }, 2, kAsciiUInt16 },
    { { "int", "signed int", "int32", "int32_t" }, 4, kAsciiInt32 },
    { { "uint", "unsigned int", "uint32", "uint32_t" }, 4, kAsciiUInt32 },
    { { "longlong", "long long", "long long int", "signed long long", "signed long long int",
        "int64", "int64_t" },
      8, kAsciiInt64 },
    { { "ulonglong", "unsigned long long", "unsigned long long int", "uint64", "uint64_t" }, 8,
      kAsciiUInt64 },
    { { "float" }, 4, kAsciiFloat },
    { { "double" }, 8, kAsciiDouble },
  };
  const NrrdType* type = nullptr;
  for (const NrrdType& t : types)
  {
    for (const char* typeName : t.Names)
    {
      if (fields["type"] == typeName)
      {
        type = &t;
      }
    }
  }
  if (!type)
  {
    problem = "type " + Quote(fields["type"]) + " is not a NRRD type VTK's reader reads.";
    return check;
  }

  // NRRD has no separate count of values per voxel; vtkNrrdReader takes the first axis
  // as one when there are 4 axes, when it has at most 9 samples, or when its spacing is 0
  // (space direction "none").
  std::size_t firstSpatial = 0;
  if (sizes.size() > 3 || sizes[0] <= 9 || (!spacing.empty() && spacing[0] == 0))
  {
    if (sizes[0] > kMaxComponents)
    {
      problem = ComponentsProblem(sizes[0],
        "VTK's NRRD reader takes the first axis as values per voxel (it does for 4 axes, for "
        "at most 9 samples or for a 'none' direction), and its size " +
          std::to_string(sizes[0]));
      return check;
    }
    check.Layout.Components = static_cast<int>(sizes[0]);
    firstSpatial = 1;
  }
  if (sizes.size() - firstSpatial < 2)
  {
    // With one axis in space vtkImageReader2 reads raw data from a file it never opened
    // (a crash), ascii data stays 0 and gzip data is refused.
    problem = "sizes " + Quote(fields["sizes"]) + " leave " +
      std::to_string(sizes.size() - firstSpatial) +
      " axis in space; VTK's NRRD reader needs 2 or 3" +
      (firstSpatial ? " (it takes the first axis as values per voxel)." : ".");
    return check;
  }
  long long voxels = 1;
  for (long long size : sizes)
  {
    voxels = Times(voxels, size);
  }
  for (std::size_t axis = firstSpatial; axis < sizes.size(); ++axis)
  {
    const std::size_t i = axis - firstSpatial;
    check.Layout.Dimensions[i] = static_cast<int>(sizes[axis]);
    if (axis < spacing.size())
    {
      check.Layout.Spacing[i] = spacing[axis];
      if (spacingIsDirections && spacing[axis] == 0)
      {
        problem = std::string("space directions gives axis ") + AxisName(static_cast<int>(i)) +
          " no direction ('none' or a zero vector).";
        return check;
      }
    }
  }
  problem = CheckLayout(check.Layout);
  if (!problem.empty())
  {
    return check;
  }
  const long long promised = Times(voxels, type->Bytes);
  if (promised < 0)
  {
    problem = "sizes " + Quote(fields["sizes"]) + " make an absurdly large volume.";
    return check;
  }

  for (const char* skip : { "line skip", "lineskip", "byte skip", "byteskip" })
  {
    long long skipped = 0;
    if (fields.count(skip) && (!ParseInteger(fields[skip], &skipped) || skipped != 0))
    {
      problem = std::string("'") + skip + ": " + fields[skip] +
        "' is not supported by VTK's NRRD reader (it reads data right after the header).";
      return check;
    }
  }
  if (fields.count("endian") && fields["endian"] != "little" && fields["endian"] != "big")
  {
    problem = "endian " + Quote(fields["endian"]) + " is neither little nor big.";
    return check;
  }
  const std::string encoding = Lower(fields.count("encoding") ? fields["encoding"] : "raw");
  if (encoding == "raw")
  {
    check.Encoding = "raw";
  }
  else if (encoding == "ascii" || encoding == "txt" || encoding == "text")
  {
    check.Encoding = "ascii";
  }
  else if (encoding == "gzip" || encoding == "gz")
  {
    check.Encoding = "gzip";
  }
  else
  {
    problem = "encoding " + Quote(fields["encoding"]) +
      " is not supported (VTK's NRRD reader reads raw, ascii and gzip).";
    return check;
  }

  // Where the data is.
  std::string dataFile = fields.count("data file") ? fields["data file"] : "";
  if (dataFile.empty() && fields.count("datafile"))
  {
    dataFile = fields["datafile"];
  }
  const bool detached = fields.count("data file") || fields.count("datafile");
  if (fields.count("data file") && fields.count("datafile"))
  {
    problem = "the header has both 'data file' and 'datafile'.";
    return check;
  }
  std::string dataPath = headerPath;
  std::string dataName = "the file";
  long long dataStart = headerBytes;
  if (detached)
  {
    const std::vector<std::string> words = Split(dataFile);
    if (words.empty())
    {
      problem = "'data file' is empty.";
      return check;
    }
    if (words[0] == "LIST" || words.size() >= 4)
    {
      // The reader formats a pattern with snprintf and loops without bounds on its step;
      // one data file is what this reader supports.
      problem = "'data file: " + dataFile +
        "' splits the data over several files; this reader opens one data file (join them).";
      return check;
    }
    dataPath = DataPath(headerPath, dataFile);
    dataName = "'" + dataPath + "'";
    dataStart = 0;
  }
  else if (headerBytes < 0)
  {
    problem = "the header does not end with an empty line, and names no data file.";
    return check;
  }
  const long long fileBytes = FileBytes(dataPath);
  if (fileBytes < 0)
  {
    problem = "its data file '" + dataPath + "' is missing.";
    return check;
  }
  const long long available = fileBytes - dataStart;

  if (check.Encoding == "ascii")
  {
    if (!detached)
    {
      problem = "ascii data after the header: VTK's NRRD reader reads ascii from the start of the "
                "file, header included (put the numbers in a detached data file).";
      return check;
    }
    if (type->Bytes == 1)
    {
      problem = "ascii data of an 8-bit type: VTK's NRRD reader reads each value as a character, "
                "not a number.";
      return check;
    }
    problem = CheckAsciiNumbers(dataPath, 0, voxels, type->Ascii, dataName);
    return check;
  }
  if (check.Encoding == "gzip")
  {
    if (detached && available > promised)
    {
      // vtkImageReader2 takes a detached file's last <voxel bytes> bytes as the data; for
      // a gzip file larger than the raw voxels that skips the start of the stream.
      std::ostringstream msg;
      msg << "the gzip data file " << dataName << " (" << available << " bytes) is larger than the "
          << promised
          << " bytes of voxels it holds; VTK's NRRD reader would skip its start (store these "
             "voxels raw).";
      problem = msg.str();
      return check;
    }
    if (!IsGzip(ReadBytes(dataPath, dataStart, 2)))
    {
      problem = "encoding is gzip, but the data does not start like a gzip stream.";
      return check;
    }
    problem = CheckCompressedFile(dataPath, dataStart, available, promised, false, "gzip data");
    return check;
  }
  if (available < promised)
  {
    problem = Shortfall(promised, available, dataName);
  }
  else if (detached && available > promised)
  {
    // vtkImageReader2 takes a detached file's last bytes as the voxels (data at the end).
    std::ostringstream msg;
    msg << "the data file " << dataName << " holds " << available << " bytes, more than the "
        << promised
        << " bytes of voxels the header promises; VTK's NRRD reader would read its last bytes, "
           "shifting the volume.";
    problem = msg.str();
  }
  return check;
}
}
