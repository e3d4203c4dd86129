// Strict parsing of --vary: every part must be a whole, finite number of the right kind.
#include "apps/vary_spec.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "apps/usage_error.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim::cli {
namespace {

constexpr std::int64_t kMaxCount = 1'000'000;

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

/// The whole of `text` as a T; from_chars takes no leading '+', a user may write one.
template <class T>
bool parse_whole(std::string_view text, T& out) {
  text = trim(text);
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return r.ec == std::errc() && r.ptr == end;
}

}  // namespace

VarySpec parse_vary(const std::string& text) {
  const auto eq = text.find('=');
  const std::string_view key = trim(std::string_view(text).substr(0, eq));
  const std::string_view range =
      eq == std::string::npos ? std::string_view() : std::string_view(text).substr(eq + 1);
  const auto c1 = range.find(':');
  const auto c2 = c1 == range.npos ? range.npos : range.find(':', c1 + 1);
  if (eq == std::string::npos || key.empty() || c2 == range.npos ||
      range.find(':', c2 + 1) != range.npos) {
    throw UsageError(fmt::format("--vary: '{}' is not KEY=FROM:TO:COUNT", printable(text)));
  }
  const auto fail = [&](const char* part, std::string_view given, const char* expected) {
    throw UsageError(fmt::format("--vary: {}: {} '{}' is not {}", printable(key), part,
                                 printable(trim(given)), expected));
  };
  const std::string_view from_text = range.substr(0, c1);
  const std::string_view to_text = range.substr(c1 + 1, c2 - c1 - 1);
  const std::string_view count_text = range.substr(c2 + 1);
  double from = 0.0, to = 0.0;
  std::int64_t count = 0;
  if (!parse_whole(from_text, from) || !std::isfinite(from)) {
    fail("FROM", from_text, "a finite number");
  }
  if (!parse_whole(to_text, to) || !std::isfinite(to)) fail("TO", to_text, "a finite number");
  if (!parse_whole(count_text, count) || count < 1 || count > kMaxCount) {
    fail("COUNT", count_text, "a whole number from 1 to 1000000");
  }
  VarySpec spec{std::string(key), {}};
  spec.values.reserve(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) {
    // from + (to - from) t overflows for from and to near opposite ends of the doubles.
    const double t = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
    const double value = count == 1 ? from : i == count - 1 ? to : (1.0 - t) * from + t * to;
    spec.values.push_back(value);
  }
  return spec;
}

}  // namespace mdrsim::cli
