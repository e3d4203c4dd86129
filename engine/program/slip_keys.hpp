// The slip keys of a row's sticking springs: the first to slip along +x and along -x, flat.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/base/large_pages.hpp"

namespace mdrsim {

/// A key of one spring: where the indenter's p+ (p-) makes it slip [m].
struct SlipKey {
  double value;
  std::int64_t spring;  ///< i, 1-based; 0 when the set is empty
};

/// Springs i >= 1, each with a forward and a backward key; gives the smallest forward key and
/// the largest backward key (ties: the smaller i forward, the larger i backward, as ordered sets
/// of (key, i) pairs give them) in O(1).
///
/// Springs touch, slip and stick in runs of neighbours whose keys rise or fall with i (a
/// parabola's row under Cattaneo-Mindlin or fretting: the keys o_i -+ r g_i are monotone in i
/// over each run, because g is monotone and the offsets are set run by run). Each side keeps
/// its members as such runs, a run's least key at one of its ends: a change at a run's end, or
/// a spring joining a run as its next neighbour, costs O(log R) for R runs and allocates
/// nothing. Where the keys are in no such order (more than `max_runs` runs on a side) that side
/// becomes a tournament tree over i, O(log m) per change, until it is empty. Memory: a key per
/// spring and side, a run's two ends, and the tree's two indices per spring only where used.
class SlipKeys {
 public:
  explicit SlipKeys(std::size_t max_runs = 64) : forward_(1, max_runs), backward_(-1, max_runs) {}

  bool empty() const { return forward_.size() == 0; }
  std::int64_t size() const { return forward_.size(); }
  bool contains(std::int64_t i) const { return forward_.contains(i); }
  /// Room for springs 1..n without reallocation.
  void reserve(std::int64_t n) {
    forward_.reserve(n);
    backward_.reserve(n);
  }
  /// Puts spring i (not in the set: std::logic_error if it is) in with its keys.
  void insert(std::int64_t i, double forward, double backward);
  /// Takes spring i out; nothing when it is not in.
  void erase(std::int64_t i);
  /// The smallest forward key (value +inf, spring 0 when empty).
  SlipKey forward_first() const;
  /// The largest backward key (value -inf, spring 0 when empty).
  SlipKey backward_last() const;
  /// Member i's forward key.
  double forward_key(std::int64_t i) const { return forward_.key(i); }

 private:
  /// One side: the least (key, tie i) of its members.
  class Side {
   public:
    Side(int tie, std::size_t max_runs) : tie_(tie), max_runs_(max_runs) {}
    std::int64_t size() const { return size_; }
    void reserve(std::int64_t n) { keys_.reserve(static_cast<std::size_t>(n)); }
    bool contains(std::int64_t i) const;
    void insert(std::int64_t i, double key);
    void erase(std::int64_t i);
    std::int64_t least() const { return least_; }  ///< 0 when empty
    double key(std::int64_t i) const { return keys_[static_cast<std::size_t>(i - 1)]; }

   private:
    /// Springs first..last, all members, their (key, tie i) rising with i (order +1), falling
    /// (-1), or one spring (0).
    struct Run {
      std::int64_t first;
      std::int64_t last;
      int order;
    };
    bool less(std::int64_t i, std::int64_t j) const {
      const double a = key(i);
      const double b = key(j);
      return a < b || (a == b && tie_ * i < tie_ * j);
    }
    std::int64_t better(std::int64_t i, std::int64_t j) const {
      if (i == 0) return j;
      if (j == 0) return i;
      return less(j, i) ? j : i;
    }
    static std::int64_t least_of(const Run& run) { return run.order < 0 ? run.last : run.first; }
    /// The first run whose first spring is past i.
    std::vector<Run>::iterator run_after(std::int64_t i);
    std::vector<Run>::const_iterator run_after(std::int64_t i) const;
    void insert_in_runs(std::int64_t i);
    void erase_from_runs(std::int64_t i);
    void build_tree(std::int64_t top);
    void update_tree(std::int64_t i, std::int64_t value);

    int tie_;  ///< +1: ties go to the smaller i; -1: to the larger
    std::size_t max_runs_;
    /// By i - 1; a member's key. In large pages: a row of 1e6 springs writes 8 MB per side.
    std::vector<double, LargePageAllocator<double>> keys_;
    std::vector<Run> runs_;   ///< ordered by first, disjoint
    bool tree_ = false;       ///< the tree holds the members, runs_ is empty
    std::size_t leaves_ = 0;  ///< a power of 2; node 1 the root, i's leaf at leaves_ + i - 1
    std::vector<std::int64_t> nodes_;  ///< the least member below each node; 0: none
    std::int64_t least_ = 0;
    std::int64_t size_ = 0;
  };

  Side forward_;   ///< keys o - r g
  Side backward_;  ///< keys -(o + r g): its least is the largest backward key
};

}  // namespace mdrsim
