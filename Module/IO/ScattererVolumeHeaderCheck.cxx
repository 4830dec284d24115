// The shared part of the volume header checks: CheckLayout, which every format's check
// and vtkScattererVolumeReader apply, and the helpers of ScattererHeaderCheckCommon.h.
// The formats: ScattererMetaImageHeaderCheck.cxx, ScattererNrrdHeaderCheck.cxx (with
// ScattererNrrdHeaderFields.cxx) and ScattererNiftiHeaderCheck.cxx.
#include "ScattererVolumeHeaderCheck.h"

#include "ScattererHeaderCheckCommon.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace scatterer_io
{
namespace header_check
{
//------------------------------------------------------------------------------
// Files and text

long long FileBytes(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
  {
    return -1;
  }
  const auto size = std::filesystem::file_size(path, ec);
  return ec ? -1 : static_cast<long long>(size);
}

std::string ReadBytes(const std::string& path, long long offset, std::size_t maxBytes)
{
  std::string data;
  std::ifstream in(path, std::ios::binary);
  if (!in || offset < 0)
  {
    return data;
  }
  in.seekg(offset);
  data.resize(maxBytes);
  in.read(&data[0], static_cast<std::streamsize>(maxBytes));
  data.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return data;
}

std::string DataPath(const std::string& headerPath, const std::string& name)
{
  const std::filesystem::path file(name);
  if (file.is_absolute())
  {
    return name;
  }
  return (std::filesystem::path(headerPath).parent_path() / file).string();
}

bool IsSpace(char c)
{
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

std::string Trim(const std::string& s)
{
  std::size_t b = 0;
  std::size_t e = s.size();
  while (b < e && IsSpace(s[b]))
  {
    ++b;
  }
  while (e > b && IsSpace(s[e - 1]))
  {
    --e;
  }
  return s.substr(b, e - b);
}

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::vector<std::string> Split(const std::string& s)
{
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < s.size())
  {
    while (i < s.size() && IsSpace(s[i]))
    {
      ++i;
    }
    std::size_t j = i;
    while (j < s.size() && !IsSpace(s[j]))
    {
      ++j;
    }
    if (j > i)
    {
      words.push_back(s.substr(i, j - i));
    }
    i = j;
  }
  return words;
}

std::string Quote(const std::string& s)
{
  std::string out = "'";
  for (std::size_t i = 0; i < s.size() && i < 60; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    out += (c < 0x20 || c >= 0x7f) ? '?' : static_cast<char>(c);
  }
  return out + (s.size() > 60 ? "...'" : "'");
}

std::string Number(double v)
{
  std::ostringstream out;
  out << v;
  return out.str();
}

const char* AxisName(int axis)
{
  static const char* const names[] = { "x", "y", "z" };
  return names[axis];
}

bool ParseInteger(const std::string& s, long long* value)
{
  std::size_t i = 0;
  bool negative = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-'))
  {
    negative = s[i] == '-';
    ++i;
  }
  if (i == s.size())
  {
    return false;
  }
  unsigned long long v = 0;
  for (; i < s.size(); ++i)
  {
    if (s[i] < '0' || s[i] > '9')
    {
      return false;
    }
    v = v * 10 + static_cast<unsigned>(s[i] - '0');
    if (v > (1ULL << 62))
    {
      return false;
    }
  }
  *value = negative ? -static_cast<long long>(v) : static_cast<long long>(v);
  return true;
}

bool ParseReal(const std::string& s, double* value)
{
  const std::size_t n = s.size();
  std::size_t i = 0;
  auto digit = [&](std::size_t k) { return k < n && s[k] >= '0' && s[k] <= '9'; };
  if (i < n && (s[i] == '+' || s[i] == '-'))
  {
    ++i;
  }
  std::size_t digits = 0;
  while (digit(i))
  {
    ++i;
    ++digits;
  }
  if (i < n && s[i] == '.')
  {
    ++i;
    while (digit(i))
    {
      ++i;
      ++digits;
    }
  }
  if (digits == 0)
  {
    return false;
  }
  if (i < n && (s[i] == 'e' || s[i] == 'E'))
  {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-'))
    {
      ++i;
    }
    if (!digit(i))
    {
      return false;
    }
    while (digit(i))
    {
      ++i;
    }
  }
  if (i != n)
  {
    return false;
  }
  *value = std::strtod(s.c_str(), nullptr);
  return true;
}

long long Times(long long a, long long b)
{
  if (a < 0 || b < 0 || (b != 0 && a > kMaxVoxelBytes / b))
  {
    return -1;
  }
  return a * b;
}

std::string Shortfall(long long expected, long long actual, const std::string& what)
{
  std::ostringstream msg;
  msg << "truncated: the header promises " << expected << " bytes of voxel data but " << what
      << " holds only " << std::max(actual, 0LL) << ".";
  return msg.str();
}

bool ParseReals(const std::vector<std::string>& words, std::size_t count, double* values)
{
  if (words.size() != count)
  {
    return false;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    if (!ParseReal(words[i], &values[i]))
    {
      return false;
    }
  }
  return true;
}

std::string ComponentsProblem(long long components, const std::string& what)
{
  std::ostringstream msg;
  msg << what << " gives " << components << " values per voxel; the volume mappers render 1 to "
      << kMaxComponents << ".";
  return msg.str();
}
}

using namespace header_check;

//------------------------------------------------------------------------------
std::string CheckLayout(const VolumeLayout& layout, bool checkComponents)
{
  for (int i = 0; i < 3; ++i)
  {
    if (layout.Dimensions[i] < 1)
    {
      return std::string("the grid is empty along ") + AxisName(i) + ".";
    }
  }
  if (checkComponents && (layout.Components < 1 || layout.Components > kMaxComponents))
  {
    return ComponentsProblem(layout.Components, "it");
  }
  for (int i = 0; i < 3; ++i)
  {
    const double s = layout.Spacing[i];
    const std::string axis = std::string("the spacing along ") + AxisName(i) + " is " + Number(s);
    if (!std::isfinite(s))
    {
      return axis + ", not a finite number.";
    }
    if (s == 0)
    {
      return axis + ": voxels need a positive size.";
    }
    if (s < 0)
    {
      return axis +
        ", negative: vtkImageData needs a positive spacing, and taking its absolute "
        "value would silently mirror the axis (write a positive spacing; a flip belongs "
        "in the orientation).";
    }
    if (s < kMinSpacing || s > kMaxSpacing)
    {
      return axis + ", outside [" + Number(kMinSpacing) + ", " + Number(kMaxSpacing) +
        "], which the single-precision renderer cannot resolve.";
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    const double o = layout.Origin[i];
    const std::string axis = std::string("the origin along ") + AxisName(i) + " is " + Number(o);
    if (!std::isfinite(o))
    {
      return axis + ", not a finite number.";
    }
    if (std::fabs(o) > kMaxOriginInSpacings * layout.Spacing[i])
    {
      return axis + ", more than 2^24 voxel spacings (" + Number(layout.Spacing[i]) +
        ") from 0, too far for single precision to tell neighbouring voxels apart.";
    }
  }
  return "";
}
}
