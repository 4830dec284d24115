// The raw deflate decoder (RFC 1951) behind ScattererInflate.h. Modelled on zlib's
// reference decoder "puff": canonical Huffman codes decoded bit by bit, which is slow but
// short and needs no tables; the header checks decode at most kInflateCheckBytes with it.
#include "ScattererInflate.h"

#include <array>

namespace scatterer_io
{
namespace header_check
{
namespace
{
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
  Inflater(
    const std::uint8_t* in, std::size_t size, std::size_t limit, std::vector<std::uint8_t>& out)
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
    static const std::uint16_t lengthBase[29] = { 3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23,
      27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258 };
    static const std::uint8_t lengthExtra[29] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3,
      3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0 };
    static const std::uint16_t distanceBase[30] = { 1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97,
      129, 193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577 };
    static const std::uint8_t distanceExtra[30] = { 0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6,
      7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13 };
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
    static const std::uint8_t order[19] = { 16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2,
      14, 1, 15 };
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
}

InflateStatus InflateDeflateStream(const std::uint8_t* in, std::size_t size, std::size_t limit,
  std::vector<std::uint8_t>& out, std::string& why, std::size_t& consumed)
{
  Inflater inflater(in, size, limit, out);
  const InflateStatus status = inflater.Run(why);
  consumed = inflater.Consumed();
  return status;
}
}
}
