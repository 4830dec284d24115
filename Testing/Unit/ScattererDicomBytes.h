// Builds a DICOM Part 10 file byte by byte (explicit VR little endian elements), for
// the reader tests: the bytes come from the standard's layout (PS3.10 7.1 preamble and
// "DICM", PS3.5 7.1.2 data elements), not from the code under test.
#ifndef ScattererDicomBytes_h
#define ScattererDicomBytes_h

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace scatterer_testing
{
class DicomBytes
{
public:
  DicomBytes()
    : Bytes(128, 0)
  {
    this->Raw({ 'D', 'I', 'C', 'M' });
  }

  void Put16(uint16_t v)
  {
    this->Bytes.push_back(char(v & 0xff));
    this->Bytes.push_back(char(v >> 8));
  }
  void Put32(uint32_t v)
  {
    this->Put16(uint16_t(v & 0xffff));
    this->Put16(uint16_t(v >> 16));
  }
  void Raw(const std::vector<char>& bytes)
  {
    this->Bytes.insert(this->Bytes.end(), bytes.begin(), bytes.end());
  }
  template <typename Iterator>
  void Raw(Iterator first, Iterator last)
  {
    this->Bytes.insert(this->Bytes.end(), first, last);
  }

  /** One element with a 16-bit length; an odd value is padded with @p pad. */
  void Element(uint16_t group, uint16_t element, const char* vr, std::string value, char pad)
  {
    if (value.size() % 2)
      value += pad;
    this->Put16(group);
    this->Put16(element);
    this->Bytes.push_back(vr[0]);
    this->Bytes.push_back(vr[1]);
    this->Put16(uint16_t(value.size()));
    this->Raw(value.begin(), value.end());
  }
  void Text(uint16_t g, uint16_t e, const char* vr, const std::string& v)
  {
    this->Element(g, e, vr, v, ' ');
  }
  void Uid(uint16_t g, uint16_t e, const std::string& v) { this->Element(g, e, "UI", v, 0); }
  void UShort(uint16_t g, uint16_t e, uint16_t v)
  {
    this->Element(g, e, "US", std::string{ char(v & 0xff), char(v >> 8) }, 0);
  }

  void Write(const std::string& path) const
  {
    std::ofstream(path, std::ios::binary)
      .write(this->Bytes.data(), std::streamsize(this->Bytes.size()));
  }

private:
  std::vector<char> Bytes;
};
}

#endif
