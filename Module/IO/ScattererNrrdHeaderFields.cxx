// The header of a NRRD file as vtkNrrdReader 9.1 parses it (quirks noted where they are
// handled): where it ends and the fields whose meaning depends on their order. What they
// mean for the volume is ScattererNrrdHeaderCheck.cxx's to judge.
#include "ScattererNrrdHeaderFields.h"

#include "ScattererHeaderCheckCommon.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <set>
#include <sstream>

namespace scatterer_io
{
namespace header_check
{
namespace
{
// NRRD header search, as vtkNrrdReader: the blank line must lie in the first 4 MiB.
constexpr std::size_t kNrrdHeaderWindow = 0x400000 - 1;
}

std::string ReadNrrdFields(const std::string& headerPath, NrrdFields* header)
{
  const long long headerFileBytes = FileBytes(headerPath);
  if (headerFileBytes < 0)
  {
    return "the header cannot be opened.";
  }
  const std::string window = ReadBytes(headerPath, 0,
    static_cast<std::size_t>(std::min<long long>(headerFileBytes, kNrrdHeaderWindow)));
  if (window.compare(0, 4, "NRRD") != 0)
  {
    return "not a NRRD file (no NRRD magic line).";
  }
  // The header ends at the first empty line ("\n\n" or "\n\r\n"); without one the whole
  // file is a header (a detached header).
  long long& headerBytes = header->HeaderBytes;
  std::size_t searchFrom = 1;
  while (headerBytes < 0)
  {
    const std::size_t nl = window.find('\n', searchFrom);
    if (nl == std::string::npos)
    {
      break;
    }
    if (nl + 1 < window.size() && window[nl + 1] == '\n')
    {
      headerBytes = static_cast<long long>(nl + 2);
    }
    else if (nl + 2 < window.size() && window[nl + 1] == '\r' && window[nl + 2] == '\n')
    {
      headerBytes = static_cast<long long>(nl + 3);
    }
    searchFrom = nl + 1;
  }
  const std::string text =
    headerBytes < 0 ? window : window.substr(0, static_cast<std::size_t>(headerBytes));
  if (headerBytes < 0 && window.back() != '\n')
  {
    // vtkNrrdReader parses with std::getline until an empty line; a last line without a
    // line end is returned again and again at the end of the text (the failed getline
    // leaves it in place), so the reader never stops.
    return headerFileBytes > static_cast<long long>(kNrrdHeaderWindow)
      ? "the header has no empty line within its first 4 MiB."
      : "the header's last line has no line end, on which VTK's NRRD reader loops forever.";
  }
  if (text.find('\0') != std::string::npos)
  {
    return "the header holds a NUL byte, where vtkNrrdReader stops reading it.";
  }

  // Fields are "<name>: <value>" exactly (vtkNrrdReader neither trims nor lowercases the
  // name); "<key>:=<value>" pairs and comments are skipped. Parsed in order, because the
  // reader's count of axes changes as it goes.
  std::map<std::string, std::string>& fields = header->Fields;
  int& declaredDimension = header->Dimension;
  int axesInForce = 0; // vtkNrrdReader's count when it reads a per-axis field
  std::vector<long long>& sizes = header->Sizes;
  std::vector<double>& spacing = header->Spacing;
  bool& spacingIsDirections = header->SpacingIsDirections;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line); // the magic line
  while (std::getline(lines, line) && !line.empty())
  {
    if (line[0] == '#')
    {
      continue;
    }
    const std::size_t colon = line.find(": ");
    if (colon == std::string::npos)
    {
      continue; // a key/value pair or a line the reader ignores
    }
    const std::string name = line.substr(0, colon);
    const std::string value = Trim(line.substr(colon + 2));
    static const std::set<std::string> checked = { "dimension", "sizes", "spacings", "type",
      "encoding", "data file", "datafile", "space", "space dimension", "space origin",
      "space directions", "endian", "line skip", "lineskip", "byte skip", "byteskip" };
    if (checked.count(name) && fields.count(name))
    {
      return "the field '" + name + "' appears twice.";
    }
    fields[name] = value;
    if (name == "dimension")
    {
      long long d = 0;
      if (!ParseInteger(value, &d) || d < 1 || d > 4)
      {
        return "dimension is " + Quote(value) +
          "; VTK's NRRD reader reads 1 to 4 axes (up to 3 in space and one of values per voxel).";
      }
      declaredDimension = axesInForce = static_cast<int>(d);
    }
    else if (name == "space")
    {
      // vtkNrrdReader takes any space to mean 3 axes (and refuses time).
      if (value.find("time") != std::string::npos)
      {
        return "space " + Quote(value) + " has a time axis, which VTK's NRRD reader refuses.";
      }
      axesInForce = 3;
    }
    else if (name == "space dimension")
    {
      long long d = 0;
      if (!ParseInteger(value, &d) || d < 1 || d > 4)
      {
        return "space dimension is " + Quote(value) + ", not 1 to 4.";
      }
      axesInForce = static_cast<int>(d);
    }
    else if (name == "sizes" || name == "spacings" || name == "space directions")
    {
      if (declaredDimension == 0)
      {
        return "'" + name + "' comes before 'dimension', which gives its length.";
      }
      // vtkNrrdReader sizes "sizes" and "spacings" by its axis count at that point, which a
      // "space" field before them sets to 3; "space directions" it takes as written.
      if (name != "space directions" && declaredDimension != axesInForce)
      {
        return "'" + name + "' follows a 'space' field that makes VTK's NRRD reader take " +
          std::to_string(axesInForce) + " axes, but dimension is " +
          std::to_string(declaredDimension) + ": it would drop or invent axes (write " + name +
          " before the space field).";
      }
      const std::vector<std::string> words = Split(value);
      if (static_cast<int>(words.size()) != declaredDimension)
      {
        return "'" + name + "' " + Quote(value) + " has " + std::to_string(words.size()) +
          " entries but dimension is " + std::to_string(declaredDimension) + ".";
      }
      if (name == "sizes")
      {
        for (const std::string& word : words)
        {
          long long size = 0;
          if (!ParseInteger(word, &size) || size < 1 || size > INT_MAX)
          {
            return "sizes " + Quote(value) + " is not a list of positive sizes.";
          }
          sizes.push_back(size);
        }
        continue;
      }
      if (!spacing.empty())
      {
        return "the header has both 'spacings' and 'space directions'.";
      }
      for (const std::string& word : words)
      {
        if (name == "spacings")
        {
          double s = 0;
          if (Lower(word) == "nan")
          {
            s = std::nan(""); // NRRD's "no spacing", fine for an axis of values per voxel
          }
          else if (!ParseReal(word, &s))
          {
            return "spacings " + Quote(value) + " holds " + Quote(word) + ", not a number.";
          }
          spacing.push_back(s);
          continue;
        }
        // space directions: "none" or "(x,y,z)"; the reader keeps the vector's length.
        spacingIsDirections = true;
        if (word == "none")
        {
          spacing.push_back(0.0);
          continue;
        }
        if (word.size() < 2 || word.front() != '(' || word.back() != ')')
        {
          return "space directions entry " + Quote(word) +
            " is not a vector like (1,0,0) (no spaces inside the parentheses).";
        }
        double sumOfSquares = 0;
        std::stringstream parts(word.substr(1, word.size() - 2));
        std::string part;
        int components = 0;
        while (std::getline(parts, part, ','))
        {
          double c = 0;
          if (!ParseReal(part, &c) || !std::isfinite(c))
          {
            return "space directions entry " + Quote(word) + " holds " + Quote(part) +
              ", not a finite number.";
          }
          sumOfSquares += c * c;
          ++components;
        }
        if (components == 0)
        {
          return "space directions entry " + Quote(word) + " is empty.";
        }
        spacing.push_back(std::sqrt(sumOfSquares));
      }
    }
    else if (name == "space origin")
    {
      // vtkNrrdReader reads "(x,y,z)" and keeps up to three numbers.
      if (value.size() < 2 || value.front() != '(' || value.back() != ')')
      {
        return "space origin " + Quote(value) + " is not a vector like (0,0,0).";
      }
      std::stringstream parts(value.substr(1, value.size() - 2));
      std::string part;
      int i = 0;
      while (std::getline(parts, part, ','))
      {
        double c = 0;
        if (!ParseReal(Trim(part), &c))
        {
          return "space origin " + Quote(value) + " holds " + Quote(part) + ", not a number.";
        }
        if (i < 3)
        {
          header->Origin[i] = c;
        }
        ++i;
      }
    }
  }
  return {};
}
}
}
