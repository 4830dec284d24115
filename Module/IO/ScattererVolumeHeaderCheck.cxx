#include "ScattererVolumeHeaderCheck.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <system_error>
#include <vector>

namespace scatterer_io
{
namespace
{
// Total voxel bytes beyond which a header is absurd (256 TiB); also keeps products from
// overflowing long long.
constexpr long long kMaxVoxelBytes = 1LL << 48;
// The most bytes deflate can expand one byte of input to (a 258-byte match costs at
// least 2 bits), with room for a tiny stream's fixed overhead.
constexpr long long kMaxInflateRatio = 1032;
// NRRD header search, as vtkNrrdReader: the blank line must lie in the first 4 MiB.
constexpr std::size_t kNrrdHeaderWindow = 0x400000 - 1;
// How much of a MetaImage file may precede ElementDataFile (MetaIO has no limit; real
// headers are well under 4 KiB).
constexpr std::size_t kMetaHeaderWindow = 1 << 16;

//------------------------------------------------------------------------------
// Files and text

// Bytes a regular file holds, or -1 if there is none.
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

// Up to maxBytes from offset; fewer when the file ends first. Callers bound maxBytes.
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

// A data file named in a header: relative to the header's folder, as both readers do.
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

// Quoted for a message; control bytes and long values are shown shortened so one bad
// byte cannot break the one-line message.
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

// [+-]digits and nothing else: "3.0", "3abc" and "" are not integers. Values beyond
// 2^62 are refused (no limit here comes near).
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

// A decimal number: [+-](digits[.digits]|.digits)[(e|E)[+-]digits]. No "nan", "inf" or
// hexadecimal: the stream extraction (operator>>) MetaIO and vtkNrrdReader read voxels
// with accepts none of them. Too large a number gives +-inf; callers check finiteness.
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

// a * b, or -1 once the product passes kMaxVoxelBytes (a, b >= 0).
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

//------------------------------------------------------------------------------
// Inflate (RFC 1950/1951/1952), enough to verify a stream and to read a .nii.gz header.
// Modelled on zlib's reference decoder "puff": canonical Huffman codes decoded bit by bit,
// which is slow but short and needs no tables; it decodes at most kInflateCheckBytes.

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

struct Huffman
{
  std::array<std::uint16_t, 16> Count{};   // codes of each length
  std::array<std::uint16_t, 288> Symbol{}; // symbols ordered by code
};

// Builds a canonical code from code lengths. Returns 0 for a complete code, > 0 for an
// incomplete one (unused codes left), < 0 for an over-subscribed (invalid) one.
int BuildHuffman(Huffman& h, const std::uint8_t* lengths, int n)
{
  h.Count.fill(0);
  for (int s = 0; s < n; ++s)
  {
    h.Count[lengths[s]]++;
  }
  if (h.Count[0] == n)
  {
    return 0; // no codes: complete, but any use of it is an error
  }
  int left = 1;
  for (int len = 1; len < 16; ++len)
  {
    left <<= 1;
    left -= h.Count[len];
    if (left < 0)
    {
      return left;
    }
  }
  std::array<std::uint16_t, 16> offsets{};
  for (int len = 1; len < 15; ++len)
  {
    offsets[len + 1] = static_cast<std::uint16_t>(offsets[len] + h.Count[len]);
  }
  for (int s = 0; s < n; ++s)
  {
    if (lengths[s] != 0)
    {
      h.Symbol[offsets[lengths[s]]++] = static_cast<std::uint16_t>(s);
    }
  }
  return left;
}

class Inflater
{
public:
  Inflater(const std::uint8_t* in, std::size_t size, std::size_t limit, std::vector<std::uint8_t>& out)
    : In(in)
    , Size(size)
    , Limit(limit)
    , Out(out)
  {
  }

  // Decodes one raw deflate stream, appending to the output.
  InflateStatus Run(std::string& why)
  {
    int last = 0;
    do
    {
      unsigned header = 0;
      if (!this->Bits(3, header))
      {
        return InflateStatus::Truncated;
      }
      last = header & 1;
      InflateStatus status = InflateStatus::Complete;
      switch (header >> 1)
      {
        case 0:
          status = this->Stored(why);
          break;
        case 1:
          status = this->Fixed(why);
          break;
        case 2:
          status = this->Dynamic(why);
          break;
        default:
          why = "invalid block type";
          return InflateStatus::Corrupt;
      }
      if (status != InflateStatus::Complete)
      {
        return status;
      }
    } while (!last);
    return InflateStatus::Complete;
  }

  // Input bytes used so far (a partly used byte counts).
  std::size_t Consumed() const { return this->Pos; }

private:
  const std::uint8_t* In;
  std::size_t Size;
  std::size_t Limit;
  std::vector<std::uint8_t>& Out;
  std::size_t Pos = 0;
  unsigned BitBuffer = 0;
  int BitCount = 0;

  bool Bits(int n, unsigned& value)
  {
    value = 0;
    for (int i = 0; i < n; ++i)
    {
      if (this->BitCount == 0)
      {
        if (this->Pos >= this->Size)
        {
          return false;
        }
        this->BitBuffer = this->In[this->Pos++];
        this->BitCount = 8;
      }
      value |= (this->BitBuffer & 1u) << i;
      this->BitBuffer >>= 1;
      --this->BitCount;
    }
    return true;
  }

  // A symbol, -1 when the input ends, -2 for a code that is not in the table.
  int Decode(const Huffman& h)
  {
    int code = 0;
    int first = 0;
    int index = 0;
    for (int len = 1; len < 16; ++len)
    {
      unsigned bit = 0;
      if (!this->Bits(1, bit))
      {
        return -1;
      }
      code |= static_cast<int>(bit);
      const int count = h.Count[len];
      if (code - count < first)
      {
        return h.Symbol[index + (code - first)];
      }
      index += count;
      first += count;
      first <<= 1;
      code <<= 1;
    }
    return -2;
  }

  bool Put(std::uint8_t byte)
  {
    if (this->Out.size() >= this->Limit)
    {
      return false;
    }
    this->Out.push_back(byte);
    return true;
  }

  InflateStatus Stored(std::string& why)
  {
    this->BitCount = 0; // to the byte boundary
    if (this->Pos + 4 > this->Size)
    {
      return InflateStatus::Truncated;
    }
    const unsigned len = this->In[this->Pos] | (this->In[this->Pos + 1] << 8);
    const unsigned nlen = this->In[this->Pos + 2] | (this->In[this->Pos + 3] << 8);
    this->Pos += 4;
    if (len != (~nlen & 0xffffu))
    {
      why = "stored block length check failed";
      return InflateStatus::Corrupt;
    }
    for (unsigned i = 0; i < len; ++i)
    {
      if (this->Pos >= this->Size)
      {
        return InflateStatus::Truncated;
      }
      if (!this->Put(this->In[this->Pos++]))
      {
        return InflateStatus::Limit;
      }
    }
    return InflateStatus::Complete;
  }

  InflateStatus Codes(const Huffman& lengthCode, const Huffman& distanceCode, std::string& why)
  {
    static const std::uint16_t lengthBase[29] = { 3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19,
      23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258 };
    static const std::uint8_t lengthExtra[29] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
      2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0 };
    static const std::uint16_t distanceBase[30] = { 1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49,
      65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289,
      16385, 24577 };
    static const std::uint8_t distanceExtra[30] = { 0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5,
      6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13 };
    for (;;)
    {
      int symbol = this->Decode(lengthCode);
      if (symbol == -1)
      {
        return InflateStatus::Truncated;
      }
      if (symbol < 0)
      {
        why = "invalid literal/length code";
        return InflateStatus::Corrupt;
      }
      if (symbol < 256)
      {
        if (!this->Put(static_cast<std::uint8_t>(symbol)))
        {
          return InflateStatus::Limit;
        }
        continue;
      }
      if (symbol == 256)
      {
        return InflateStatus::Complete;
      }
      symbol -= 257;
      if (symbol >= 29)
      {
        why = "invalid length symbol";
        return InflateStatus::Corrupt;
      }
      unsigned extra = 0;
      if (!this->Bits(lengthExtra[symbol], extra))
      {
        return InflateStatus::Truncated;
      }
      const unsigned length = lengthBase[symbol] + extra;
      symbol = this->Decode(distanceCode);
      if (symbol == -1)
      {
        return InflateStatus::Truncated;
      }
      if (symbol < 0 || symbol >= 30)
      {
        why = "invalid distance code";
        return InflateStatus::Corrupt;
      }
      if (!this->Bits(distanceExtra[symbol], extra))
      {
        return InflateStatus::Truncated;
      }
      const std::size_t distance = distanceBase[symbol] + extra;
      if (distance > this->Out.size())
      {
        why = "distance too far back";
        return InflateStatus::Corrupt;
      }
      for (unsigned i = 0; i < length; ++i)
      {
        if (!this->Put(this->Out[this->Out.size() - distance]))
        {
          return InflateStatus::Limit;
        }
      }
    }
  }

  InflateStatus Fixed(std::string& why)
  {
    std::uint8_t lengths[288 + 30];
    int s = 0;
    for (; s < 144; ++s)
      lengths[s] = 8;
    for (; s < 256; ++s)
      lengths[s] = 9;
    for (; s < 280; ++s)
      lengths[s] = 7;
    for (; s < 288; ++s)
      lengths[s] = 8;
    for (; s < 288 + 30; ++s)
      lengths[s] = 5;
    Huffman lengthCode;
    Huffman distanceCode;
    BuildHuffman(lengthCode, lengths, 288);
    BuildHuffman(distanceCode, lengths + 288, 30);
    return this->Codes(lengthCode, distanceCode, why);
  }

  InflateStatus Dynamic(std::string& why)
  {
    static const std::uint8_t order[19] = { 16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13,
      2, 14, 1, 15 };
    unsigned nlen = 0;
    unsigned ndist = 0;
    unsigned ncode = 0;
    if (!this->Bits(5, nlen) || !this->Bits(5, ndist) || !this->Bits(4, ncode))
    {
      return InflateStatus::Truncated;
    }
    nlen += 257;
    ndist += 1;
    ncode += 4;
    if (nlen > 286 || ndist > 30)
    {
      why = "too many length or distance symbols";
      return InflateStatus::Corrupt;
    }
    std::uint8_t lengths[320] = {};
    for (unsigned i = 0; i < ncode; ++i)
    {
      unsigned len = 0;
      if (!this->Bits(3, len))
      {
        return InflateStatus::Truncated;
      }
      lengths[order[i]] = static_cast<std::uint8_t>(len);
    }
    Huffman lengthCode;
    Huffman distanceCode;
    if (BuildHuffman(lengthCode, lengths, 19) != 0)
    {
      why = "incomplete code-lengths code";
      return InflateStatus::Corrupt;
    }
    unsigned index = 0;
    while (index < nlen + ndist)
    {
      const int symbol = this->Decode(lengthCode);
      if (symbol == -1)
      {
        return InflateStatus::Truncated;
      }
      if (symbol < 0)
      {
        why = "invalid code-lengths code";
        return InflateStatus::Corrupt;
      }
      if (symbol < 16)
      {
        lengths[index++] = static_cast<std::uint8_t>(symbol);
        continue;
      }
      std::uint8_t len = 0;
      unsigned repeat = 0;
      bool ok = true;
      if (symbol == 16)
      {
        if (index == 0)
        {
          why = "repeat with no first length";
          return InflateStatus::Corrupt;
        }
        len = lengths[index - 1];
        ok = this->Bits(2, repeat);
        repeat += 3;
      }
      else if (symbol == 17)
      {
        ok = this->Bits(3, repeat);
        repeat += 3;
      }
      else
      {
        ok = this->Bits(7, repeat);
        repeat += 11;
      }
      if (!ok)
      {
        return InflateStatus::Truncated;
      }
      if (index + repeat > nlen + ndist)
      {
        why = "too many code lengths";
        return InflateStatus::Corrupt;
      }
      while (repeat-- > 0)
      {
        lengths[index++] = len;
      }
    }
    if (lengths[256] == 0)
    {
      why = "no end-of-block code";
      return InflateStatus::Corrupt;
    }
    // As puff: an incomplete code is allowed only when it has a single symbol.
    int left = BuildHuffman(lengthCode, lengths, static_cast<int>(nlen));
    if (left < 0 || (left > 0 && nlen - lengthCode.Count[0] != 1))
    {
      why = "invalid literal/length code lengths";
      return InflateStatus::Corrupt;
    }
    left = BuildHuffman(distanceCode, lengths + nlen, static_cast<int>(ndist));
    if (left < 0 || (left > 0 && ndist - distanceCode.Count[0] != 1))
    {
      why = "invalid distance code lengths";
      return InflateStatus::Corrupt;
    }
    return this->Codes(lengthCode, distanceCode, why);
  }
};

std::uint32_t Crc32(const std::uint8_t* data, std::size_t size)
{
  static const std::array<std::uint32_t, 256> table = [] {
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

// Decodes a gzip file (all its members, as gzread does) or, with allowZlib, a zlib
// stream, up to limit bytes. Checksums are verified for every member decoded whole.
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
    Inflater inflater(in + 2, size - 2, limit, result.Output);
    result.Status = inflater.Run(result.Why);
    if (result.Status == InflateStatus::Complete)
    {
      const std::size_t end = 2 + inflater.Consumed();
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
    Inflater inflater(in + pos, size - pos, limit, result.Output);
    result.Status = inflater.Run(result.Why);
    if (result.Status != InflateStatus::Complete)
    {
      return result;
    }
    pos += inflater.Consumed();
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
  const std::size_t limit =
    static_cast<std::size_t>(std::min<long long>(promised, static_cast<long long>(kInflateCheckBytes)));
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

// Reads compressed data from offset: all of it when small, else enough for the check.
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

//------------------------------------------------------------------------------
// Ascii voxel data: VTK and MetaIO read it with operator>>, which stops at the first
// token that is not a number of the voxel type and leaves the rest of the volume as it
// was. So every token up to the promised count must be one.

enum class NumberKind
{
  Integer,
  Real
};

struct AsciiType
{
  NumberKind Kind;
  double Min;
  double Max;
};

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
  auto next = [&]() {
    token.clear();
    std::streambuf* buffer = in.rdbuf();
    int c = buffer->sbumpc();
    while (c != std::char_traits<char>::eof() && IsSpace(static_cast<char>(c)))
    {
      c = buffer->sbumpc();
    }
    while (c != std::char_traits<char>::eof() && !IsSpace(static_cast<char>(c)) && token.size() <= 64)
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

//------------------------------------------------------------------------------
// Shared by the formats

// Parses exactly count reals from words; false if any is missing, extra or not a number.
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
      return axis + ", negative: vtkImageData needs a positive spacing, and taking its absolute "
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

//------------------------------------------------------------------------------
// MetaImage, as MetaIO (inside vtkMetaImageReader) reads it: "Name = value" or
// "Name: value" lines up to ElementDataFile, which ends the header.
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
        problem = "header line " + std::to_string(lineNumber) + " holds a control character (byte " +
          std::to_string(c) + ").";
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
    while (v < trimmed.size() && (trimmed[v] == '=' || trimmed[v] == ':' || trimmed[v] == ' ' ||
                                   trimmed[v] == '\t'))
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
    problem = "NDims is " + Quote(fields["NDims"]) +
      "; VTK's MetaImage reader reads 1, 2 or 3 dimensions.";
    return check;
  }
  const std::size_t n = static_cast<std::size_t>(ndims);
  // MetaIO reads a numeric field with operator>> for as many numbers as it expects, past
  // the end of the line if need be; a word that is not a number stops the stream, and
  // every field after it is lost. So each numeric field MetaIO knows must hold exactly
  // its count of numbers. (0: NDims numbers, -1: NDims x NDims.)
  static const std::map<std::string, int> numericFields = { { "NDims", 1 },
    { "FileFormatVersion", 1 }, { "ID", 1 }, { "ParentID", 1 }, { "CompressedDataSize", 1 },
    { "HeaderSize", 1 }, { "ElementMin", 1 }, { "ElementMax", 1 },
    { "ElementNumberOfChannels", 1 }, { "ElementNBits", 1 },
    { "ElementToIntensityFunctionSlope", 1 }, { "ElementToIntensityFunctionOffset", 1 },
    { "Color", 4 }, { "DimSize", 0 }, { "ElementSpacing", 0 }, { "ElementSize", 0 },
    { "Offset", 0 }, { "Position", 0 }, { "Origin", 0 }, { "ImagePosition", 0 },
    { "CenterOfRotation", 0 }, { "SequenceID", 0 }, { "ElementOrigin", 0 },
    { "TransformMatrix", -1 }, { "Rotation", -1 }, { "Orientation", -1 },
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
      !std::all_of(words.begin(), words.end(), [&](const std::string& w) { return ParseReal(w, &ignored); }))
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
    { "MET_CHAR", { 1, { NumberKind::Integer, -128, 127 } } },
    { "MET_UCHAR", { 1, { NumberKind::Integer, 0, 255 } } },
    { "MET_SHORT", { 2, { NumberKind::Integer, -32768, 32767 } } },
    { "MET_USHORT", { 2, { NumberKind::Integer, 0, 65535 } } },
    { "MET_INT", { 4, { NumberKind::Integer, -2147483648.0, 2147483647.0 } } },
    { "MET_UINT", { 4, { NumberKind::Integer, 0, 4294967295.0 } } },
    { "MET_FLOAT", { 4, { NumberKind::Real, -3.4e38, 3.4e38 } } },
    { "MET_DOUBLE", { 8, { NumberKind::Real, -1.7e308, 1.7e308 } } },
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
    problem = "ElementType " + typeName + ": MetaIO reads 4 bytes per value into VTK's 8-byte "
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

  // Spacing: ElementSpacing, else ElementSize (MetaIO copies it), else 1.
  for (const char* name : { "ElementSize", "ElementSpacing" })
  {
    if (!has(name))
    {
      continue;
    }
    double values[3] = { 1, 1, 1 };
    if (!ParseReals(Split(fields[name]), n, values))
    {
      problem = std::string(name) + " " + Quote(fields[name]) + " is not " +
        std::to_string(ndims) + " numbers.";
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
    if (!ParseReals(Split(fields[name]), n, values))
    {
      problem = std::string(name) + " " + Quote(fields[name]) + " is not " +
        std::to_string(ndims) + " numbers.";
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
  auto flag = [&](const char* name, bool fallback, bool* value) {
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
      msg << "truncated: " << dataName << " holds " << fileBytes << " bytes, fewer than HeaderSize ("
          << headerSize << ") plus the " << promised << " bytes of voxel data the header promises.";
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
          << dataName << ", but it holds only " << fileBytes - (dataPath == headerPath ? headerBytes : 0)
          << " bytes of data.";
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
    problem = CheckCompressedFile(dataPath, dataStart, compressedBytes, promised, true,
      "compressed data");
    return check;
  }
  if (available < promised)
  {
    problem = Shortfall(promised, available, dataName);
  }
  return check;
}

//------------------------------------------------------------------------------
// NRRD, as vtkNrrdReader 9.1 reads it (quirks noted where they are handled).
HeaderCheck CheckNrrdHeader(const std::string& headerPath)
{
  HeaderCheck check;
  std::string& problem = check.Problem;
  const long long headerFileBytes = FileBytes(headerPath);
  if (headerFileBytes < 0)
  {
    problem = "the header cannot be opened.";
    return check;
  }
  const std::string window = ReadBytes(headerPath, 0,
    static_cast<std::size_t>(std::min<long long>(headerFileBytes, kNrrdHeaderWindow)));
  if (window.compare(0, 4, "NRRD") != 0)
  {
    problem = "not a NRRD file (no NRRD magic line).";
    return check;
  }
  // The header ends at the first empty line ("\n\n" or "\n\r\n"); without one the whole
  // file is a header (a detached header).
  long long headerBytes = -1;
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
  const std::string header =
    headerBytes < 0 ? window : window.substr(0, static_cast<std::size_t>(headerBytes));
  if (headerBytes < 0 && window.back() != '\n')
  {
    // vtkNrrdReader parses with std::getline until an empty line; a last line without a
    // line end is returned again and again at the end of the text (the failed getline
    // leaves it in place), so the reader never stops.
    problem = headerFileBytes > static_cast<long long>(kNrrdHeaderWindow)
      ? "the header has no empty line within its first 4 MiB."
      : "the header's last line has no line end, on which VTK's NRRD reader loops forever.";
    return check;
  }
  if (header.find('\0') != std::string::npos)
  {
    problem = "the header holds a NUL byte, where vtkNrrdReader stops reading it.";
    return check;
  }

  // Fields are "<name>: <value>" exactly (vtkNrrdReader neither trims nor lowercases the
  // name); "<key>:=<value>" pairs and comments are skipped. Parsed in order, because the
  // reader's count of axes changes as it goes.
  std::map<std::string, std::string> fields;
  int declaredDimension = 0;  // the "dimension" field
  int axesInForce = 0;        // vtkNrrdReader's count when it reads a per-axis field
  std::vector<long long> sizes;
  std::vector<double> spacing; // per axis, from spacings or space directions
  bool spacingIsDirections = false;
  std::istringstream lines(header);
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
      problem = "the field '" + name + "' appears twice.";
      return check;
    }
    fields[name] = value;
    if (name == "dimension")
    {
      long long d = 0;
      if (!ParseInteger(value, &d) || d < 1 || d > 4)
      {
        problem = "dimension is " + Quote(value) +
          "; VTK's NRRD reader reads 1 to 4 axes (up to 3 in space and one of values per voxel).";
        return check;
      }
      declaredDimension = axesInForce = static_cast<int>(d);
    }
    else if (name == "space")
    {
      // vtkNrrdReader takes any space to mean 3 axes (and refuses time).
      if (value.find("time") != std::string::npos)
      {
        problem = "space " + Quote(value) + " has a time axis, which VTK's NRRD reader refuses.";
        return check;
      }
      axesInForce = 3;
    }
    else if (name == "space dimension")
    {
      long long d = 0;
      if (!ParseInteger(value, &d) || d < 1 || d > 4)
      {
        problem = "space dimension is " + Quote(value) + ", not 1 to 4.";
        return check;
      }
      axesInForce = static_cast<int>(d);
    }
    else if (name == "sizes" || name == "spacings" || name == "space directions")
    {
      if (declaredDimension == 0)
      {
        problem = "'" + name + "' comes before 'dimension', which gives its length.";
        return check;
      }
      // vtkNrrdReader sizes "sizes" and "spacings" by its axis count at that point, which a
      // "space" field before them sets to 3; "space directions" it takes as written.
      if (name != "space directions" && declaredDimension != axesInForce)
      {
        problem = "'" + name + "' follows a 'space' field that makes VTK's NRRD reader take " +
          std::to_string(axesInForce) + " axes, but dimension is " +
          std::to_string(declaredDimension) + ": it would drop or invent axes (write " + name +
          " before the space field).";
        return check;
      }
      const std::vector<std::string> words = Split(value);
      if (static_cast<int>(words.size()) != declaredDimension)
      {
        problem = "'" + name + "' " + Quote(value) + " has " + std::to_string(words.size()) +
          " entries but dimension is " + std::to_string(declaredDimension) + ".";
        return check;
      }
      if (name == "sizes")
      {
        for (const std::string& word : words)
        {
          long long size = 0;
          if (!ParseInteger(word, &size) || size < 1 || size > INT_MAX)
          {
            problem = "sizes " + Quote(value) + " is not a list of positive sizes.";
            return check;
          }
          sizes.push_back(size);
        }
        continue;
      }
      if (!spacing.empty())
      {
        problem = "the header has both 'spacings' and 'space directions'.";
        return check;
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
            problem = "spacings " + Quote(value) + " holds " + Quote(word) + ", not a number.";
            return check;
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
          problem = "space directions entry " + Quote(word) +
            " is not a vector like (1,0,0) (no spaces inside the parentheses).";
          return check;
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
            problem = "space directions entry " + Quote(word) + " holds " + Quote(part) +
              ", not a finite number.";
            return check;
          }
          sumOfSquares += c * c;
          ++components;
        }
        if (components == 0)
        {
          problem = "space directions entry " + Quote(word) + " is empty.";
          return check;
        }
        spacing.push_back(std::sqrt(sumOfSquares));
      }
    }
    else if (name == "space origin")
    {
      // vtkNrrdReader reads "(x,y,z)" and keeps up to three numbers.
      if (value.size() < 2 || value.front() != '(' || value.back() != ')')
      {
        problem = "space origin " + Quote(value) + " is not a vector like (0,0,0).";
        return check;
      }
      std::stringstream parts(value.substr(1, value.size() - 2));
      std::string part;
      int i = 0;
      while (std::getline(parts, part, ','))
      {
        double c = 0;
        if (!ParseReal(Trim(part), &c))
        {
          problem = "space origin " + Quote(value) + " holds " + Quote(part) + ", not a number.";
          return check;
        }
        if (i < 3)
        {
          check.Layout.Origin[i] = c;
        }
        ++i;
      }
    }
  }

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
    { { "signed char", "int8", "int8_t" }, 1, { NumberKind::Integer, -128, 127 } },
    { { "uchar", "unsigned char", "uint8", "uint8_t" }, 1, { NumberKind::Integer, 0, 255 } },
    { { "short", "short int", "signed short", "signed short int", "int16", "int16_t" }, 2,
      { NumberKind::Integer, -32768, 32767 } },
    { { "ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t" }, 2,
      { NumberKind::Integer, 0, 65535 } },
    { { "int", "signed int", "int32", "int32_t" }, 4,
      { NumberKind::Integer, -2147483648.0, 2147483647.0 } },
    { { "uint", "unsigned int", "uint32", "uint32_t" }, 4,
      { NumberKind::Integer, 0, 4294967295.0 } },
    { { "longlong", "long long", "long long int", "signed long long", "signed long long int",
        "int64", "int64_t" },
      8, { NumberKind::Integer, -4.6e18, 4.6e18 } },
    { { "ulonglong", "unsigned long long", "unsigned long long int", "uint64", "uint64_t" }, 8,
      { NumberKind::Integer, 0, 4.6e18 } },
    { { "float" }, 4, { NumberKind::Real, -3.4e38, 3.4e38 } },
    { { "double" }, 8, { NumberKind::Real, -1.7e308, 1.7e308 } },
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
      msg << "the gzip data file " << dataName << " (" << available
          << " bytes) is larger than the " << promised
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

//------------------------------------------------------------------------------
// NIfTI-1 and -2 (and Analyze 7.5), as vtkNIFTIImageReader reads a single .nii file.
HeaderCheck CheckNiftiHeader(const std::string& path)
{
  HeaderCheck check;
  check.Encoding = "raw";
  std::string& problem = check.Problem;
  const long long fileBytes = FileBytes(path);
  if (fileBytes < 0)
  {
    problem = "the file cannot be opened.";
    return check;
  }
  constexpr std::size_t kNifti2Bytes = 540;
  std::string bytes = ReadBytes(path, 0, kNifti2Bytes);
  const bool gzip = IsGzip(bytes); // gzopen reads anything else as is
  if (gzip)
  {
    check.Encoding = "gzip";
    const InflateResult r = Inflate(ReadBytes(path, 0,
                                      static_cast<std::size_t>(std::min<long long>(fileBytes,
                                        static_cast<long long>(kInflateCheckBytes) + (1 << 16)))),
      kNifti2Bytes, false);
    if (r.Status == InflateStatus::Corrupt)
    {
      problem = "its gzip data is corrupt (" + r.Why + ").";
      return check;
    }
    bytes.assign(r.Output.begin(), r.Output.end());
  }
  if (bytes.size() < 348)
  {
    problem = "truncated: shorter than the 348-byte NIfTI-1 header.";
    return check;
  }
  const auto* h = reinterpret_cast<const std::uint8_t*>(bytes.data());

  // Version, as vtkNIFTIImageReader::CheckNIFTIVersion: NIfTI-2's magic is where NIfTI-1
  // keeps data_type.
  int version = 0;
  if (h[4] == 'n' && (h[5] == '+' || h[5] == 'i') && h[6] >= '2' && h[6] <= '9' && h[7] == 0)
  {
    if (h[8] != '\r' || h[9] != '\n' || h[10] != 032 || h[11] != '\n')
    {
      problem = "the NIfTI-2 header was damaged by a newline conversion.";
      return check;
    }
    if (h[6] != '2')
    {
      problem = "NIfTI version " + std::string(1, static_cast<char>(h[6])) + " is not supported.";
      return check;
    }
    version = 2;
  }
  else if (h[344] == 'n' && (h[345] == '+' || h[345] == 'i') && h[346] == '1' && h[347] == 0)
  {
    version = 1;
  }
  if (version == 2 && bytes.size() < kNifti2Bytes)
  {
    problem = "truncated: shorter than the 540-byte NIfTI-2 header.";
    return check;
  }
  const long long headerSize = version == 2 ? 540 : 348;
  if (version == 1 && h[345] == 'i')
  {
    problem = "its magic 'ni1' says the voxels are in a separate .img file; this reader opens "
              "single-file .nii volumes.";
    return check;
  }

  // Byte order: the reader swaps when dim[0] is outside 0..7.
  auto read = [&](int offset, int size, bool swap) {
    std::uint64_t v = 0;
    for (int i = 0; i < size; ++i)
    {
      const int k = swap ? size - 1 - i : i;
      v |= static_cast<std::uint64_t>(h[offset + k]) << (8 * i);
    }
    return v;
  };
  const int dimOffset = version == 2 ? 16 : 40;
  const int dimSize = version == 2 ? 8 : 2;
  auto signedValue = [&](int offset, int size, bool swap) -> long long {
    const std::uint64_t v = read(offset, size, swap);
    if (size == 2)
      return static_cast<std::int16_t>(v);
    if (size == 4)
      return static_cast<std::int32_t>(v);
    return static_cast<std::int64_t>(v);
  };
  const long long dim0 = signedValue(dimOffset, dimSize, false);
  const bool swap = dim0 < 0 || dim0 > 7;
  const long long sizeofHdr = signedValue(0, 4, swap);
  if (sizeofHdr != headerSize)
  {
    problem = "not a NIfTI header (sizeof_hdr is " + std::to_string(sizeofHdr) + ", not " +
      std::to_string(headerSize) + ", in either byte order).";
    return check;
  }
  const long long ndim = signedValue(dimOffset, dimSize, swap);
  if (ndim < 1 || ndim > 7)
  {
    problem = "dim[0] (the number of axes) is " + std::to_string(ndim) + ", not 1 to 7.";
    return check;
  }
  long long dims[8] = { ndim, 1, 1, 1, 1, 1, 1, 1 };
  long long voxels = 1;
  for (int i = 1; i <= ndim; ++i)
  {
    dims[i] = signedValue(dimOffset + dimSize * i, dimSize, swap);
    if (dims[i] < 1 || dims[i] > INT_MAX)
    {
      problem = "dim[" + std::to_string(i) + "] is " + std::to_string(dims[i]) +
        ", not a positive size.";
      return check;
    }
    voxels = Times(voxels, dims[i]);
  }

  // The datatypes vtkNIFTIImageReader maps (any other crashes VTK 9.1's reader).
  struct NiftiType
  {
    int Code;
    int Bits;
    int Components;
  };
  static const NiftiType types[] = { { 2, 8, 1 }, { 4, 16, 1 }, { 8, 32, 1 }, { 16, 32, 1 },
    { 32, 64, 2 }, { 64, 64, 1 }, { 128, 24, 3 }, { 256, 8, 1 }, { 512, 16, 1 },
    { 768, 32, 1 }, { 1024, 64, 1 }, { 1280, 64, 1 }, { 1792, 128, 2 }, { 2304, 32, 4 } };
  const int typeOffset = version == 2 ? 12 : 70;
  const long long datatype = signedValue(typeOffset, 2, swap);
  const long long bitpix = signedValue(typeOffset + 2, 2, swap);
  const NiftiType* type = nullptr;
  for (const NiftiType& t : types)
  {
    if (t.Code == datatype)
    {
      type = &t;
    }
  }
  if (!type)
  {
    problem = "datatype " + std::to_string(datatype) +
      " is not one VTK's NIfTI reader reads (2, 4, 8, 16, 32, 64, 128, 256, 512, 768, 1024, "
      "1280, 1792, 2304).";
    return check;
  }
  if (bitpix != type->Bits)
  {
    problem = "bitpix is " + std::to_string(bitpix) + " but datatype " +
      std::to_string(datatype) + " has " + std::to_string(type->Bits) + " bits per voxel.";
    return check;
  }
  // A 5th axis holds values per voxel; a 4th (time) and the 6th and 7th are read as their
  // first frame.
  const long long components = type->Components * (ndim >= 5 ? dims[5] : 1);
  if (components > kMaxComponents)
  {
    problem = ComponentsProblem(components,
      "datatype " + std::to_string(datatype) + " with dim[5] = " + std::to_string(dims[5]));
    return check;
  }
  check.Layout.Components = static_cast<int>(components);

  // pixdim[1..3] is the spacing; the reader replaces 0 by 1, which is right only for an
  // axis the image does not have.
  const int pixdimOffset = version == 2 ? 104 : 76;
  for (int i = 1; i <= 3; ++i)
  {
    double s = 0;
    if (version == 2)
    {
      const std::uint64_t bits = read(pixdimOffset + 8 * i, 8, swap);
      std::memcpy(&s, &bits, 8);
    }
    else
    {
      const auto bits = static_cast<std::uint32_t>(read(pixdimOffset + 4 * i, 4, swap));
      float f = 0;
      std::memcpy(&f, &bits, 4);
      s = f;
    }
    if (s == 0 && i > ndim)
    {
      s = 1;
    }
    check.Layout.Dimensions[i - 1] = static_cast<int>(dims[i]);
    check.Layout.Spacing[i - 1] = s;
  }
  // The origin is 0: the NIfTI offset belongs to the qform/sform matrices, which this
  // reader does not apply.
  problem = CheckLayout(check.Layout);
  if (!problem.empty())
  {
    return check;
  }

  double voxOffset = 0;
  if (version == 2)
  {
    voxOffset = static_cast<double>(signedValue(168, 8, swap));
  }
  else
  {
    const auto bits = static_cast<std::uint32_t>(read(108, 4, swap));
    float f = 0;
    std::memcpy(&f, &bits, 4);
    voxOffset = f;
  }
  if (!std::isfinite(voxOffset) || voxOffset < headerSize || voxOffset > 1e15)
  {
    problem = "vox_offset is " + Number(voxOffset) + ", not a byte offset past the " +
      std::to_string(headerSize) + "-byte header.";
    return check;
  }
  const long long dataStart = static_cast<long long>(voxOffset); // the reader truncates too
  const long long promised = Times(voxels, type->Bits / 8);
  const long long expected = promised < 0 ? -1 : dataStart + promised;
  if (promised < 0 || expected > kMaxVoxelBytes)
  {
    problem = "its dimensions make an absurdly large volume.";
    return check;
  }
  if (!gzip)
  {
    if (fileBytes < expected)
    {
      problem = Shortfall(expected, fileBytes, "the file");
    }
    return check;
  }
  // .nii.gz: header and voxels are one gzip stream; decode it as far as the check goes.
  problem = CheckCompressedFile(path, 0, fileBytes, expected, false, "gzip data");
  return check;
}
}
