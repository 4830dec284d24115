// The voxel data checks of ScattererVoxelDataCheck.h.
#include "ScattererVoxelDataCheck.h"

#include "ScattererHeaderCheckCommon.h"
#include "ScattererInflate.h"
#include "ScattererVolumeHeaderCheck.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace scatterer_io
{
namespace header_check
{
namespace
{
// The most bytes deflate can expand one byte of input to (a 258-byte match costs at
// least 2 bits), with room for a tiny stream's fixed overhead.
constexpr long long kMaxInflateRatio = 1032;

// Verifies compressed voxel data: the stream decodes, to at least the promised bytes
// when it is decoded whole. compressed is the start of the stream (all of it when
// whole); what names the encoding in messages.
std::string CheckCompressed(const std::string& compressed, bool whole, long long compressedBytes,
  long long promised, bool allowZlib, const std::string& what)
{
  const long long capacity = Times(kMaxInflateRatio, compressedBytes);
  if (capacity >= 0 && promised > capacity + 1024)
  {
    std::ostringstream msg;
    msg << "the header promises " << promised << " bytes of voxel data, more than "
        << compressedBytes << " bytes of " << what << " can hold (deflate expands at most "
        << kMaxInflateRatio << ":1).";
    return msg.str();
  }
  const std::size_t limit = static_cast<std::size_t>(
    std::min<long long>(promised, static_cast<long long>(kInflateCheckBytes)));
  const InflateResult r = Inflate(compressed, limit, allowZlib);
  std::ostringstream msg;
  switch (r.Status)
  {
    case InflateStatus::Limit:
      return "";
    case InflateStatus::Complete:
      if (static_cast<long long>(r.Output.size()) >= promised)
      {
        return "";
      }
      msg << "truncated: the " << what << " decodes to " << r.Output.size()
          << " bytes but the header promises " << promised << ".";
      return msg.str();
    case InflateStatus::Truncated:
      if (!whole)
      {
        return ""; // only a prefix was read: what it holds is sound
      }
      msg << "the " << what << " is truncated: the stream ends after " << r.Output.size()
          << " decoded bytes of the " << promised << " the header promises.";
      return msg.str();
    case InflateStatus::Corrupt:
    default:
      msg << "the " << what << " is corrupt (" << r.Why << ") after " << r.Output.size()
          << " decoded bytes.";
      return msg.str();
  }
}

}

std::string CheckCompressedFile(const std::string& path, long long offset, long long bytes,
  long long promised, bool allowZlib, const std::string& what)
{
  // Stored deflate blocks cost 5 bytes per 64 KiB, so this much input covers the
  // kInflateCheckBytes the check decodes.
  const long long window = static_cast<long long>(kInflateCheckBytes) + (1 << 16);
  const long long take = std::min(bytes, window);
  const std::string data = ReadBytes(path, offset, static_cast<std::size_t>(std::max(take, 0LL)));
  if (static_cast<long long>(data.size()) < take)
  {
    return "its data cannot be read.";
  }
  return CheckCompressed(data, take == bytes, bytes, promised, allowZlib, what);
}

std::string CheckAsciiNumbers(const std::string& path, long long offset, long long promised,
  const AsciiType& type, const std::string& where)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return where + " cannot be opened.";
  }
  in.seekg(offset);
  std::string token;
  long long count = 0;
  // Tokens are read by hand so that a run of bytes without whitespace cannot grow one
  // without bound: no number the voxel types hold needs more than 64 characters.
  auto next = [&]()
  {
    token.clear();
    std::streambuf* buffer = in.rdbuf();
    int c = buffer->sbumpc();
    while (c != std::char_traits<char>::eof() && IsSpace(static_cast<char>(c)))
    {
      c = buffer->sbumpc();
    }
    while (
      c != std::char_traits<char>::eof() && !IsSpace(static_cast<char>(c)) && token.size() <= 64)
    {
      token += static_cast<char>(c);
      c = buffer->sbumpc();
    }
    return !token.empty();
  };
  while (count < promised && next())
  {
    bool ok = false;
    if (type.Kind == NumberKind::Integer)
    {
      long long v = 0;
      ok = ParseInteger(token, &v) && v >= type.Min && v <= type.Max;
    }
    else
    {
      double v = 0;
      ok = ParseReal(token, &v) && std::isfinite(v);
    }
    if (!ok)
    {
      std::ostringstream msg;
      msg << "ascii voxel " << count << " in " << where << " is " << Quote(token)
          << ", not a number the voxel type holds (" << Number(type.Min) << " to "
          << Number(type.Max) << (type.Kind == NumberKind::Integer ? ", integers" : "") << ").";
      return msg.str();
    }
    ++count;
  }
  if (count < promised)
  {
    std::ostringstream msg;
    msg << "truncated: the header promises " << promised << " ascii voxel values but " << where
        << " holds only " << count << ".";
    return msg.str();
  }
  return "";
}
}
}
