// Row order, shards and the grid's fingerprint: what lets shards and resumed sweeps agree.
#include "engine/sweep/sweep_grid.hpp"

#include <fmt/format.h>

#include <charconv>

#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

constexpr std::uint64_t kMaxShards = 1'000'000;

bool parse_count(std::string_view text, std::uint64_t& out) {
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return !text.empty() && r.ec == std::errc() && r.ptr == end;
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  Shard shard;
  if (slash == std::string::npos ||
      !parse_count(std::string_view(text).substr(0, slash), shard.index) ||
      !parse_count(std::string_view(text).substr(slash + 1), shard.count) || shard.count < 1 ||
      shard.count > kMaxShards || shard.index >= shard.count) {
    throw UsageError(
        fmt::format("--shard: '{}' is not I/N with 0 <= I < N <= {}", printable(text), kMaxShards));
  }
  return shard;
}

SweepGrid::SweepGrid(std::vector<VarySpec> keys) : keys_(std::move(keys)) {
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      if (keys_[j].key == keys_[k].key) {
        throw UsageError(fmt::format("--vary: {} is varied twice", printable(keys_[k].key)));
      }
    }
    const std::uint64_t count = keys_[k].values.size();
    if (count == 0 || rows_ > kMaxRows / count) {
      throw UsageError(fmt::format("--vary: the grid has more than {} rows", kMaxRows));
    }
    rows_ *= count;
  }
}

std::vector<std::size_t> SweepGrid::indices(std::uint64_t row) const {
  std::vector<std::size_t> out(keys_.size());
  for (std::size_t k = keys_.size(); k-- > 0;) {
    const std::uint64_t count = keys_[k].values.size();
    out[k] = static_cast<std::size_t>(row % count);
    row /= count;
  }
  return out;
}

std::uint64_t SweepGrid::hash() const {
  std::uint64_t h = fnv1a("");
  for (const VarySpec& spec : keys_) {
    h = fnv1a(spec.key, h);
    for (std::size_t i = 0; i < spec.values.size(); ++i) {
      h = fnv1a(i == 0 ? "=" : ",", h);
      h = fnv1a(spec.values[i].text, h);
    }
    h = fnv1a("\n", h);
  }
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
