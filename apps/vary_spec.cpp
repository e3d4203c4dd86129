// Strict parsing of --vary: every part must be a whole, finite number of the right kind.
#include "apps/vary_spec.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>

#include "apps/usage_error.hpp"

namespace mdrsim::cli {
namespace {

template <class T>
bool parse_whole(std::string_view text, T& out) {
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return r.ec == std::errc() && r.ptr == end;
}

}  // namespace

VarySpec parse_vary(const std::string& text) {
  const auto fail = [&](const char* why) -> VarySpec {
    throw UsageError(fmt::format("--vary: '{}' {}; expected KEY=FROM:TO:COUNT", text, why));
  };
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) return fail("has no KEY=");
  const std::string_view range = std::string_view(text).substr(eq + 1);
  const auto c1 = range.find(':');
  const auto c2 = c1 == range.npos ? range.npos : range.find(':', c1 + 1);
  if (c2 == range.npos || range.find(':', c2 + 1) != range.npos)
    return fail("is not FROM:TO:COUNT");
  double from = 0.0, to = 0.0;
  std::int64_t count = 0;
  if (!parse_whole(range.substr(0, c1), from) || !std::isfinite(from))
    return fail("has a bad FROM");
  if (!parse_whole(range.substr(c1 + 1, c2 - c1 - 1), to) || !std::isfinite(to)) {
    return fail("has a bad TO");
  }
  if (!parse_whole(range.substr(c2 + 1), count) || count < 1 || count > 1000000) {
    return fail("has a bad COUNT (a whole number from 1 to 1000000)");
  }
  VarySpec spec{text.substr(0, eq), {}};
  spec.values.reserve(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) {
    spec.values.push_back(count == 1       ? from
                          : i == count - 1 ? to
                                           : from + (to - from) * static_cast<double>(i) /
                                                        static_cast<double>(count - 1));
  }
  return spec;
}

}  // namespace mdrsim::cli
