// The rows of a sweep: the product of its --vary keys, in a fixed order, and its shards.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/sweep/vary_spec.hpp"

namespace mdrsim::cli {

/// `--shard I/N`: rows I, I + N, I + 2N, ... of the sweep's row list.
struct Shard {
  std::uint64_t index = 0;
  std::uint64_t count = 1;

  /// How many of `rows` rows are this shard's.
  std::uint64_t rows_of(std::uint64_t rows) const {
    return rows > index ? (rows - index + count - 1) / count : 0;
  }
  /// The row of the sweep that is this shard's `position`-th (from 0).
  std::uint64_t row(std::uint64_t position) const { return index + position * count; }

  bool operator==(const Shard&) const = default;
};

/// Parses I/N with 0 <= I < N <= 1000000; throws UsageError naming --shard.
Shard parse_shard(const std::string& text);

/// The product of the varied keys as nested loops, the first --vary outermost and the last
/// varying fastest: row r = sum over keys of index_k * (product of the counts after k).
class SweepGrid {
 public:
  static constexpr std::uint64_t kMaxRows = 1'000'000'000;

  /// Throws UsageError for a key varied twice or a grid of more than kMaxRows rows.
  explicit SweepGrid(std::vector<VarySpec> keys);

  const std::vector<VarySpec>& keys() const { return keys_; }
  std::uint64_t rows() const { return rows_; }
  /// The index into each key's values at `row`.
  std::vector<std::size_t> indices(std::uint64_t row) const;
  /// FNV-1a of every key and its values as the CSV writes them (docs/sweeps.md: the identity line).
  std::uint64_t hash() const;

 private:
  std::vector<VarySpec> keys_;
  std::uint64_t rows_ = 1;
};

/// 64-bit FNV-1a of `bytes`, continuing from `hash`.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ULL);

}  // namespace mdrsim::cli
