// How the mapper's helpers tell whether something they keep between frames is stale.
//
// Everything kept (the templates, their packing and upload, the transport volume's
// tables, a label-map mask's visible opacity, the scan for unassigned voxels, the
// shader texts that failed to compile) is remembered with a key: the values and
// modification times it was made from, written as text. A frame writes the key of
// what it needs and compares. Keys of values rather than one timestamp, because each
// product depends on its own few settings (a slider that only feeds a uniform must not
// regenerate the templates) and on objects outside the mapper (transfer functions,
// derived materials). The mapper's public GetIlluminationMTime() is not part of this:
// it tells users when a setting last changed.
#ifndef ScattererChangeKey_h
#define ScattererChangeKey_h

#include <set>
#include <sstream>
#include <string>

namespace scatterer_render
{
/** Writes a key: values streamed in, doubles at full precision (17 digits). */
class KeyWriter
{
public:
  KeyWriter() { this->Stream.precision(17); }

  template <typename T>
  KeyWriter& operator<<(const T& value)
  {
    this->Stream << value;
    return *this;
  }

  std::string Key() const { return this->Stream.str(); }

private:
  std::ostringstream Stream;
};

/** The key something kept was last made from ("": not made yet, or dropped). */
class ChangeKey
{
public:
  /** True when @p key differs from the one recorded. */
  bool Differs(const std::string& key) const { return key != this->Last; }
  /** Records @p key as what the kept thing is now made from. */
  void Record(const std::string& key) { this->Last = key; }
  /** Forgets the key: the next comparison differs (the kept thing was released). */
  void Clear() { this->Last.clear(); }
  const std::string& Get() const { return this->Last; }

private:
  std::string Last;
};

/** Keys remembered for good (e.g. shader texts that failed to compile here). */
class KeySet
{
public:
  bool Contains(const std::string& key) const { return this->Keys.count(key) != 0; }
  void Insert(const std::string& key) { this->Keys.insert(key); }

private:
  std::set<std::string> Keys;
};
}

#endif
