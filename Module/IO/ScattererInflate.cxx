// The gzip (RFC 1952) and zlib (RFC 1950) containers of a deflate stream, with their
// checksums (ScattererInflate.h); the stream itself is ScattererDeflateDecoder.cxx's.
#include "ScattererInflate.h"

#include <array>

namespace scatterer_io
{
namespace header_check
{
namespace
{
std::uint32_t Crc32(const std::uint8_t* data, std::size_t size)
{
  static const std::array<std::uint32_t, 256> table = []
  {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n)
    {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k)
      {
        c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      }
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t crc = 0xffffffffu;
  for (std::size_t i = 0; i < size; ++i)
  {
    crc = table[(crc ^ data[i]) & 0xff] ^ (crc >> 8);
  }
  return crc ^ 0xffffffffu;
}

std::uint32_t Adler32(const std::uint8_t* data, std::size_t size)
{
  std::uint32_t a = 1;
  std::uint32_t b = 0;
  for (std::size_t i = 0; i < size; ++i)
  {
    a = (a + data[i]) % 65521u;
    b = (b + a) % 65521u;
  }
  return (b << 16) | a;
}

std::uint32_t Le32(const std::uint8_t* p)
{
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
    (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

}

bool IsGzip(const std::string& data)
{
  return data.size() >= 2 && static_cast<std::uint8_t>(data[0]) == 0x1f &&
    static_cast<std::uint8_t>(data[1]) == 0x8b;
}

bool IsZlib(const std::string& data)
{
  if (data.size() < 2)
  {
    return false;
  }
  const unsigned cmf = static_cast<std::uint8_t>(data[0]);
  const unsigned flg = static_cast<std::uint8_t>(data[1]);
  return (cmf & 0x0f) == 8 && (cmf >> 4) <= 7 && ((cmf << 8) | flg) % 31 == 0;
}

InflateResult Inflate(const std::string& data, std::size_t limit, bool allowZlib)
{
  InflateResult result;
  const auto* in = reinterpret_cast<const std::uint8_t*>(data.data());
  const std::size_t size = data.size();
  if (allowZlib && IsZlib(data))
  {
    if (static_cast<std::uint8_t>(data[1]) & 0x20)
    {
      result.Why = "it needs a preset dictionary";
      return result;
    }
    std::size_t consumed = 0;
    result.Status =
      InflateDeflateStream(in + 2, size - 2, limit, result.Output, result.Why, consumed);
    if (result.Status == InflateStatus::Complete)
    {
      const std::size_t end = 2 + consumed;
      if (end + 4 > size)
      {
        result.Status = InflateStatus::Truncated;
      }
      else if (((static_cast<std::uint32_t>(in[end]) << 24) | (in[end + 1] << 16) |
                 (in[end + 2] << 8) | in[end + 3]) !=
        Adler32(result.Output.data(), result.Output.size()))
      {
        result.Status = InflateStatus::Corrupt;
        result.Why = "its Adler-32 check fails";
      }
    }
    return result;
  }
  std::size_t pos = 0;
  do
  {
    // Member header: 1f 8b 08 FLG MTIME(4) XFL OS [EXTRA] [NAME] [COMMENT] [HCRC].
    if (pos + 10 > size)
    {
      result.Status = InflateStatus::Truncated;
      return result;
    }
    if (in[pos] != 0x1f || in[pos + 1] != 0x8b || in[pos + 2] != 8 || (in[pos + 3] & 0xe0))
    {
      result.Status = InflateStatus::Corrupt;
      result.Why = "not a gzip member header";
      return result;
    }
    const unsigned flags = in[pos + 3];
    pos += 10;
    if (flags & 4)
    {
      if (pos + 2 > size)
      {
        result.Status = InflateStatus::Truncated;
        return result;
      }
      pos += 2 + (in[pos] | (in[pos + 1] << 8));
    }
    for (const unsigned flag : { 8u, 16u })
    {
      if (flags & flag)
      {
        while (pos < size && in[pos] != 0)
        {
          ++pos;
        }
        ++pos;
      }
    }
    if (flags & 2)
    {
      pos += 2;
    }
    if (pos > size)
    {
      result.Status = InflateStatus::Truncated;
      return result;
    }
    const std::size_t memberStart = result.Output.size();
    std::size_t consumed = 0;
    result.Status =
      InflateDeflateStream(in + pos, size - pos, limit, result.Output, result.Why, consumed);
    if (result.Status != InflateStatus::Complete)
    {
      return result;
    }
    pos += consumed;
    if (pos + 8 > size)
    {
      result.Status = InflateStatus::Truncated;
      return result;
    }
    const std::size_t memberBytes = result.Output.size() - memberStart;
    if (Le32(in + pos) != Crc32(result.Output.data() + memberStart, memberBytes) ||
      Le32(in + pos + 4) != static_cast<std::uint32_t>(memberBytes))
    {
      result.Status = InflateStatus::Corrupt;
      result.Why = "its CRC-32 or length check fails";
      return result;
    }
    pos += 8;
    // gzread goes on with a following member and ignores anything else after one.
  } while (pos + 1 < size && in[pos] == 0x1f && in[pos + 1] == 0x8b);
  return result;
}
}
}
