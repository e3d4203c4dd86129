// A sweep's --where condition: a comparison between varied keys (and numbers) that a row must
// pass to be run, such as `material.approach_work_of_adhesion <= material.work_of_adhesion`.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "engine/sweep/vary_spec.hpp"

namespace mdrsim::cli {

struct WhereCondition {
  enum class Op { less_equal, less, greater_equal, greater, equal, not_equal };

  /// NUMBER, KEY or NUMBER*KEY: factor times the key's value, or the number alone.
  struct Term {
    double factor = 1.0;
    std::optional<std::size_t> key;  ///< an index into the sweep's keys
  };

  Term left;
  Op op = Op::less_equal;
  Term right;

  /// Whether it holds for the keys' values `numbers` (by key index), compared as doubles.
  bool holds(const std::vector<double>& numbers) const;
  /// The condition as written back: `0.5*a.b <= c`, each number in its shortest form.
  std::string text(const std::vector<VarySpec>& keys) const;
};

/// Parses `A OP B`, OP one of <= < >= > == !=, A and B each a number, a varied key or
/// NUMBER*KEY; a key must be one of `keys` and take numbers only, and one side at least must
/// name a key. Throws UsageError naming --where.
WhereCondition parse_where(const std::string& text, const std::vector<VarySpec>& keys);

}  // namespace mdrsim::cli
