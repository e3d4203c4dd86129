// The rows of a sweep: the product of its --vary axes (a --link key riding along with its
// axis), or a random or Latin hypercube design over them, kept where every --where holds;
// in a fixed order, and its shards.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/sweep/sweep_design.hpp"
#include "engine/sweep/sweep_where.hpp"
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

/// The rows of a sweep. The keys form axes: each --vary key starts one, each --link key joins
/// the axis before it (same index in a grid, same draw in a random design). A grid's
/// candidates are the product of the axes as nested loops, the first outermost and the last
/// varying fastest; a random or Latin design's are its samples in order. The rows are the
/// candidates every --where condition holds for, numbered from 0 in candidate order, so that a
/// row's number depends on the flags alone (what --resume and --shard rely on).
class SweepGrid {
 public:
  static constexpr std::uint64_t kMaxRows = 1'000'000'000;
  /// The most candidates --where looks at (it marks each one, a bit each, once).
  static constexpr std::uint64_t kMaxFiltered = 100'000'000;

  /// Throws UsageError for a key varied twice, a --link whose axis has lists of other
  /// lengths, a --where that is not about the varied numbers, no row left, or too many rows.
  explicit SweepGrid(std::vector<VarySpec> keys, std::vector<std::string> where = {},
                     SweepDesign design = {});

  const std::vector<VarySpec>& keys() const { return keys_; }
  const SweepDesign& design() const { return design_; }
  std::uint64_t rows() const { return rows_; }
  /// Each key's value at `row`, in the order of keys().
  std::vector<VaryValue> values(std::uint64_t row) const;
  /// A grid's index into each key's values at `row` (a linked key has its axis' index).
  std::vector<std::size_t> indices(std::uint64_t row) const;
  /// The rows a sweep builds before any run, in order: of a grid, for every probe of every key
  /// (VarySpec::probes), the first row with that value; of a random design, for each axis the
  /// rows of its smallest and largest draw and the first row of each value of a list.
  std::vector<std::uint64_t> probe_rows() const;
  /// The candidates a --where looked at (rows() without a --where).
  std::uint64_t candidates() const { return candidates_; }
  /// FNV-1a of every key and its values as the CSV writes them (docs/sweeps.md: the identity
  /// line), then of the --where conditions and the design where there are any.
  std::uint64_t hash() const;

 private:
  struct Axis {
    std::size_t first = 0;    ///< its first key in keys_
    std::uint64_t count = 0;  ///< a grid's values per key; a random design's list length, or 0
  };

  std::uint64_t candidate(std::uint64_t row) const;
  /// A grid's index into each axis' values at `candidate`.
  std::vector<std::size_t> grid_indices(std::uint64_t candidate) const;
  std::vector<VaryValue> candidate_values(std::uint64_t candidate) const;
  std::vector<double> candidate_numbers(std::uint64_t candidate) const;
  void select(const std::vector<WhereCondition>& where);

  std::vector<VarySpec> keys_;
  std::vector<Axis> axes_;
  std::vector<std::size_t> axis_of_;  ///< each key's axis
  std::vector<WhereCondition> where_;
  SweepDesign design_;
  DesignDraws draws_;
  std::uint64_t candidates_ = 1;
  std::uint64_t rows_ = 1;
  std::vector<std::uint64_t> kept_;    ///< with --where: one bit per candidate, 1 = a row
  std::vector<std::uint64_t> before_;  ///< rows in the words before each word of kept_
};

/// 64-bit FNV-1a of `bytes`, continuing from `hash`.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ULL);

}  // namespace mdrsim::cli
