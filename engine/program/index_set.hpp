// A set of spring indices with its smallest member: a bitset with a summary bit per word.
#pragma once

#include <cstdint>
#include <vector>

namespace mdrsim {

/// Indices i >= 1; insert, erase and the smallest member in O(log_64 m) with no allocation per
/// member (one bit each, and a bit per 64 of them at each level above).
class IndexSet {
 public:
  bool empty() const { return size_ == 0; }
  std::int64_t size() const { return size_; }
  bool contains(std::int64_t i) const;
  void insert(std::int64_t i);
  void erase(std::int64_t i);                    ///< nothing when i is not in
  std::int64_t first() const { return first_; }  ///< the smallest member; 0 when empty

 private:
  void grow(std::int64_t i);
  std::int64_t search_first() const;

  /// levels_[0] holds bit i for member i; bit w of levels_[l + 1] is set where word w of
  /// levels_[l] is not 0; the last level is one word.
  std::vector<std::vector<std::uint64_t>> levels_;
  std::int64_t size_ = 0;
  std::int64_t first_ = 0;
};

}  // namespace mdrsim
