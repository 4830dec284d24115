// Internal: the merge lattice. Maps a position to its cell (cube of edge `cell`,
// centred on multiples of `cell`, so the template centre is a cell centre) and the cell
// to the index of the photon stored there. Open addressing with linear probing: no
// per-insert allocation and no iteration-order dependence.
#pragma once

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace scatterer {
namespace detail {

class Lattice {
public:
  explicit Lattice(double cell) : invCell_(1.0 / cell), keys_(256, 0), values_(256, -1) {}

  // Cell indices fit in 21 bits: |p| < 1 and cell >= 1e-4 give |i| <= 10001 < 2^20.
  // The offset keeps every field positive, so key 0 never occurs and marks empty slots.
  // Ordering keys orders cells by x, then y, then z.
  std::uint64_t key(const glm::dvec3& p) const
  {
    const auto field = [this](double v) {
      const auto i = static_cast<std::int64_t>(std::floor(v * invCell_ + 0.5));
      return static_cast<std::uint64_t>(i + (std::int64_t(1) << 20));
    };
    return (field(p.x) << 42u) | (field(p.y) << 21u) | field(p.z);
  }

  int find(std::uint64_t key) const
  {
    for (std::size_t i = slot(key);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == key) {
        return values_[i];
      }
      if (keys_[i] == 0) {
        return -1;
      }
    }
  }

  void insert(std::uint64_t key, int value)
  {
    if (2 * (count_ + 1) > keys_.size()) {
      grow();
    }
    place(key, value);
    ++count_;
  }

private:
  std::size_t slot(std::uint64_t key) const
  {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32u) & (keys_.size() - 1);
  }

  void place(std::uint64_t key, int value)
  {
    std::size_t i = slot(key);
    while (keys_[i] != 0) {
      i = (i + 1) & (keys_.size() - 1);
    }
    keys_[i] = key;
    values_[i] = value;
  }

  void grow()
  {
    std::vector<std::uint64_t> oldKeys(keys_.size() * 2, 0);
    std::vector<int> oldValues(values_.size() * 2, -1);
    oldKeys.swap(keys_);
    oldValues.swap(values_);
    for (std::size_t i = 0; i < oldKeys.size(); ++i) {
      if (oldKeys[i] != 0) {
        place(oldKeys[i], oldValues[i]);
      }
    }
  }

  double invCell_;
  std::vector<std::uint64_t> keys_;
  std::vector<int> values_;
  std::size_t count_ = 0;
};

} // namespace detail
} // namespace scatterer
