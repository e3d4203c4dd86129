// A set of spring indices with its smallest member: a bitset with a summary bit per word.
#include "engine/program/index_set.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <utility>

namespace mdrsim {

namespace {
constexpr std::uint64_t bit(std::uint64_t i) { return std::uint64_t{1} << (i & 63U); }
}  // namespace

bool IndexSet::contains(std::int64_t i) const {
  if (i < 0 || levels_.empty()) return false;
  const auto w = static_cast<std::size_t>(i) >> 6U;
  return w < levels_[0].size() && (levels_[0][w] & bit(static_cast<std::uint64_t>(i))) != 0;
}

void IndexSet::grow(std::int64_t i) {
  // Words for bits 0..i at level 0, then a summary level until one word holds them all.
  std::size_t words = (static_cast<std::size_t>(i) >> 6U) + 1;
  words = std::max(words, levels_.empty() ? std::size_t{1} : 2 * levels_[0].size());
  std::vector<std::vector<std::uint64_t>> levels;
  levels.emplace_back(words, 0);
  if (!levels_.empty()) std::copy(levels_[0].begin(), levels_[0].end(), levels[0].begin());
  while (levels.back().size() > 1) {
    const std::vector<std::uint64_t>& below = levels.back();
    std::vector<std::uint64_t> above((below.size() + 63) / 64, 0);
    for (std::size_t w = 0; w < below.size(); ++w)
      if (below[w] != 0) above[w >> 6U] |= bit(w);
    levels.push_back(std::move(above));
  }
  levels_ = std::move(levels);
}

void IndexSet::insert(std::int64_t i) {
  if (i < 1) throw std::logic_error("IndexSet::insert: index below 1");
  if (contains(i)) return;
  if (levels_.empty() || (static_cast<std::size_t>(i) >> 6U) >= levels_[0].size()) grow(i);
  ++size_;
  if (first_ == 0 || i < first_) first_ = i;
  auto k = static_cast<std::uint64_t>(i);
  for (auto& level : levels_) {
    std::uint64_t& word = level[k >> 6U];
    const bool was_empty = word == 0;
    word |= bit(k);
    if (!was_empty) return;
    k >>= 6U;
  }
}

void IndexSet::erase(std::int64_t i) {
  if (!contains(i)) return;
  --size_;
  auto k = static_cast<std::uint64_t>(i);
  for (auto& level : levels_) {
    std::uint64_t& word = level[k >> 6U];
    word &= ~bit(k);
    if (word != 0) break;
    k >>= 6U;
  }
  if (i == first_) first_ = search_first();
}

std::int64_t IndexSet::search_first() const {
  if (size_ == 0) return 0;
  std::uint64_t k = 0;
  for (auto level = levels_.rbegin(); level != levels_.rend(); ++level)
    k = (k << 6U) + static_cast<std::uint64_t>(std::countr_zero((*level)[k]));
  return static_cast<std::int64_t>(k);
}

}  // namespace mdrsim
