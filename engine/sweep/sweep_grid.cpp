// Row order, shards and the grid's fingerprint: what lets shards and resumed sweeps agree.
#include "engine/sweep/sweep_grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <unordered_set>
#include <utility>

#include "engine/base/text.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

constexpr std::uint64_t kMaxShards = 1'000'000;
constexpr std::uint64_t kNone = std::numeric_limits<std::uint64_t>::max();

/// The position of the `n`-th (from 0) set bit of `word`.
unsigned nth_bit(std::uint64_t word, std::uint64_t n) {
  for (; n > 0; --n) word &= word - 1;
  return static_cast<unsigned>(std::countr_zero(word));
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  Shard shard;
  if (slash == std::string::npos ||
      !read_whole_number(std::string_view(text).substr(0, slash), shard.index) ||
      !read_whole_number(std::string_view(text).substr(slash + 1), shard.count) ||
      shard.count < 1 || shard.count > kMaxShards || shard.index >= shard.count) {
    throw UsageError(
        fmt::format("--shard: '{}' is not I/N with 0 <= I < N <= {}", printable(text), kMaxShards));
  }
  return shard;
}

SweepGrid::SweepGrid(std::vector<VarySpec> keys, std::vector<std::string> where, SweepDesign design)
    : keys_(std::move(keys)), design_(design) {
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    const VarySpec& spec = keys_[k];
    const char* flag = spec.linked ? "--link" : "--vary";
    for (std::size_t j = 0; j < k; ++j) {
      if (keys_[j].key == spec.key) {
        throw UsageError(fmt::format("{}: {} is varied twice", flag, printable(spec.key)));
      }
    }
    if (spec.drawn() && !design_.drawn()) {
      throw UsageError(
          fmt::format("{}: {}: a grid needs FROM:TO:COUNT (FROM:TO draws from a "
                      "range: --design random or latin)",
                      flag, printable(spec.key)));
    }
    if (!spec.linked || axes_.empty()) {
      if (spec.linked) {
        throw UsageError(fmt::format(
            "--link: {} follows no --vary (a linked key varies with the --vary before it)",
            printable(spec.key)));
      }
      axes_.push_back({k, 0});
    }
    Axis& axis = axes_.back();
    axis_of_.push_back(axes_.size() - 1);
    if (spec.drawn()) continue;
    // Every list of an axis has as many values: its keys are zipped, not multiplied.
    if (axis.count != 0 && spec.values.size() != axis.count) {
      std::size_t listed = axis.first;  // the axis' first list, which set its count
      while (keys_[listed].drawn()) ++listed;
      const VarySpec& other = keys_[listed];
      throw UsageError(fmt::format(
          "--link: {} has {} values, {} has {} (a linked key needs as many as the key it "
          "varies with)",
          printable(spec.key), spec.values.size(), printable(other.key), axis.count));
    }
    axis.count = spec.values.size();
  }
  if (design_.drawn()) {
    draws_ = DesignDraws(design_, axes_.size());
    candidates_ = design_.samples;
  } else {
    for (const Axis& axis : axes_) {
      if (axis.count == 0 || candidates_ > kMaxRows / axis.count) {
        throw UsageError(fmt::format("--vary: the grid has more than {} rows", kMaxRows));
      }
      candidates_ *= axis.count;
    }
  }
  rows_ = candidates_;
  for (const std::string& text : where) where_.push_back(parse_where(text, keys_));
  if (!where_.empty()) select(where_);
}

void SweepGrid::select(const std::vector<WhereCondition>& where) {
  if (candidates_ > kMaxFiltered) {
    throw UsageError(fmt::format("--where: filters at most {} rows, not the {} of this {}",
                                 kMaxFiltered, candidates_, to_string(design_.kind)));
  }
  kept_.assign((candidates_ + 63) / 64, 0);
  before_.assign(kept_.size(), 0);
  rows_ = 0;
  for (std::uint64_t c = 0; c < candidates_; ++c) {
    const std::vector<double> numbers = candidate_numbers(c);
    if (std::all_of(where.begin(), where.end(),
                    [&](const WhereCondition& w) { return w.holds(numbers); })) {
      kept_[c / 64] |= std::uint64_t{1} << (c % 64);
      ++rows_;
    }
  }
  std::uint64_t count = 0;
  for (std::size_t w = 0; w < kept_.size(); ++w) {
    before_[w] = count;
    count += static_cast<std::uint64_t>(std::popcount(kept_[w]));
  }
  if (rows_ == 0) {
    std::string conditions;
    for (const WhereCondition& w : where) {
      conditions += (conditions.empty() ? "" : ", ") + w.text(keys_);
    }
    throw UsageError(
        fmt::format("--where: no row of the {} candidates passes {}", candidates_, conditions));
  }
}

std::uint64_t SweepGrid::candidate(std::uint64_t row) const {
  if (kept_.empty()) return row;
  // The last word with fewer rows before it than `row` + 1 holds the row.
  const auto word = static_cast<std::size_t>(std::upper_bound(before_.begin(), before_.end(), row) -
                                             before_.begin() - 1);
  return word * 64 + nth_bit(kept_[word], row - before_[word]);
}

std::vector<std::size_t> SweepGrid::grid_indices(std::uint64_t candidate) const {
  std::vector<std::size_t> out(axes_.size());
  for (std::size_t a = axes_.size(); a-- > 0;) {
    out[a] = static_cast<std::size_t>(candidate % axes_[a].count);
    candidate /= axes_[a].count;
  }
  return out;
}

std::vector<VaryValue> SweepGrid::candidate_values(std::uint64_t candidate) const {
  std::vector<VaryValue> out;
  out.reserve(keys_.size());
  if (design_.drawn()) {
    std::vector<double> t(axes_.size());
    for (std::size_t a = 0; a < axes_.size(); ++a) t[a] = draws_.draw(candidate, a);
    for (std::size_t k = 0; k < keys_.size(); ++k) out.push_back(keys_[k].at(t[axis_of_[k]]));
    return out;
  }
  const std::vector<std::size_t> index = grid_indices(candidate);
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    out.push_back(keys_[k].values[index[axis_of_[k]]]);
  }
  return out;
}

std::vector<double> SweepGrid::candidate_numbers(std::uint64_t candidate) const {
  // As candidate_values, without the text: --where looks at every candidate.
  std::vector<double> out(keys_.size());
  if (design_.drawn()) {
    std::vector<double> t(axes_.size());
    for (std::size_t a = 0; a < axes_.size(); ++a) t[a] = draws_.draw(candidate, a);
    for (std::size_t k = 0; k < keys_.size(); ++k) out[k] = keys_[k].number_at(t[axis_of_[k]]);
    return out;
  }
  const std::vector<std::size_t> index = grid_indices(candidate);
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    out[k] = keys_[k].values[index[axis_of_[k]]].number.value_or(
        std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

std::vector<VaryValue> SweepGrid::values(std::uint64_t row) const {
  return candidate_values(candidate(row));
}

std::vector<std::size_t> SweepGrid::indices(std::uint64_t row) const {
  const std::vector<std::size_t> index = grid_indices(candidate(row));
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < keys_.size(); ++k) out.push_back(index[axis_of_[k]]);
  return out;
}

std::vector<std::uint64_t> SweepGrid::probe_rows() const {
  // For each axis, the first row with each value to probe: of a grid, its keys' probes; of a
  // random design, each value of a list and the smallest and largest draw.
  std::vector<std::vector<std::uint64_t>> first(axes_.size());
  for (std::size_t a = 0; a < axes_.size(); ++a) first[a].assign(axes_[a].count, kNone);
  std::vector<std::pair<double, std::uint64_t>> lowest(axes_.size(), {2.0, kNone});
  std::vector<std::pair<double, std::uint64_t>> highest(axes_.size(), {-1.0, kNone});
  if (!design_.drawn() && kept_.empty()) {
    // Without --where the first row with index p of an axis has every other axis at 0.
    std::uint64_t stride = 1;
    for (std::size_t a = axes_.size(); a-- > 0;) {
      for (std::uint64_t p = 0; p < axes_[a].count; ++p) first[a][p] = p * stride;
      stride *= axes_[a].count;
    }
  } else {
    std::uint64_t row = 0;
    for (std::uint64_t c = 0; c < candidates_; ++c) {
      if (!kept_.empty() && ((kept_[c / 64] >> (c % 64)) & 1U) == 0) continue;
      if (design_.drawn()) {
        for (std::size_t a = 0; a < axes_.size(); ++a) {
          const double t = draws_.draw(c, a);
          if (t < lowest[a].first) lowest[a] = {t, row};
          if (t > highest[a].first) highest[a] = {t, row};
          if (axes_[a].count == 0) continue;
          const auto i = std::min<std::uint64_t>(
              axes_[a].count - 1,
              static_cast<std::uint64_t>(t * static_cast<double>(axes_[a].count)));
          if (first[a][i] == kNone) first[a][i] = row;
        }
      } else {
        const std::vector<std::size_t> index = grid_indices(c);
        for (std::size_t a = 0; a < axes_.size(); ++a) {
          if (first[a][index[a]] == kNone) first[a][index[a]] = row;
        }
      }
      ++row;
    }
  }
  // Key by key, as the keys were given, so that of two bad values the first key's is named.
  std::vector<std::uint64_t> out;
  std::unordered_set<std::uint64_t> seen;
  const auto add = [&](std::uint64_t row) {
    if (row != kNone && seen.insert(row).second) out.push_back(row);
  };
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    const std::size_t a = axis_of_[k];
    if (design_.drawn()) {
      for (const std::uint64_t row : first[a]) add(row);
      add(lowest[a].second);
      add(highest[a].second);
    } else {
      for (const std::size_t p : keys_[k].probes()) add(first[a][p]);
    }
  }
  return out;
}

std::uint64_t SweepGrid::hash() const {
  std::uint64_t h = fnv1a("");
  if (design_.drawn()) {
    h = fnv1a(fmt::format("design {} samples {} seed {}\n", to_string(design_.kind),
                          design_.samples, design_.seed),
              h);
  }
  for (const VarySpec& spec : keys_) {
    if (spec.linked) h = fnv1a("&", h);
    h = fnv1a(spec.key, h);
    if (spec.drawn()) {
      h = fnv1a(fmt::format("={}:{}{}", number_field(spec.from), number_field(spec.to),
                            spec.form == VarySpec::Form::log ? ":log" : ""),
                h);
    }
    for (std::size_t i = 0; i < spec.values.size(); ++i) {
      h = fnv1a(i == 0 ? "=" : ",", h);
      h = fnv1a(spec.values[i].text, h);
    }
    h = fnv1a("\n", h);
  }
  for (const WhereCondition& w : where_) h = fnv1a("where " + w.text(keys_) + "\n", h);
  return h;
}

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace mdrsim::cli
