// Strict parsing of --vary: every part must be a whole, finite number of the right kind.
#include "engine/sweep/vary_spec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "engine/base/text.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

constexpr std::int64_t kMaxCount = 1'000'000;
constexpr const char* kForms = "KEY=FROM:TO:COUNT, KEY=FROM:TO:COUNT:log or KEY=V1,V2,...";
constexpr const char* kDrawnForms = "KEY=FROM:TO, KEY=FROM:TO:log or KEY=V1,V2,...";

/// `text` without a '+' that from_chars does not take (a user may write one).
std::string_view without_plus(std::string_view text) {
  text = trim_blanks(text);
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  return text;
}

/// The whole of `text` as a T.
template <class T>
bool parse_whole(std::string_view text, T& out) {
  text = without_plus(text);
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return r.ec == std::errc() && r.ptr == end;
}

/// Whether the whole of `text` is written as a number, in range or not (1e999, nan, inf).
bool looks_like_a_number(std::string_view text) {
  text = without_plus(text);
  double ignored = 0.0;
  const char* end = text.data() + text.size();
  return !text.empty() && std::from_chars(text.data(), end, ignored).ptr == end;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  while (true) {
    const auto at = text.find(separator);
    parts.push_back(text.substr(0, at));
    if (at == text.npos) return parts;
    text.remove_prefix(at + 1);
  }
}

VaryValue number_value(double value) { return {value, number_field(value)}; }

/// A value inside a range as a person writes it: the shortest decimal of at most 15
/// significant digits within `noise` (the rounding error of the range's formula) of the
/// computed value, so that 0:0.4:5 gives 0.3, not 0.30000000000000004, and 1e7:1.7e7:8 whole
/// numbers, not 11000000.000000002, and -2e-3:1e-3:4 a zero, not -1e-19 (no digit count of
/// -1e-19 reaches 0, so zero is decided on the noise first); else the computed value.
double tidy(double value, double noise) {
  if (std::abs(value) <= noise) return 0.0;
  const auto rounded = [value](int digits) {
    const std::string text = fmt::format("{:.{}e}", value, digits - 1);
    double near = value;
    std::from_chars(text.data(), text.data() + text.size(), near);
    return near;
  };
  const auto close = [&](int digits) { return std::abs(rounded(digits) - value) <= noise; };
  // Rounded to more digits is never farther: the fewest that are close, by bisection.
  if (!close(15)) return value;
  int lo = 0, hi = 15;  // lo digits are not close (0: none), hi are
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (close(mid) ? hi : lo) = mid;
  }
  return rounded(hi);
}

}  // namespace

std::string number_field(double value) { return fmt::format("{}", value); }

std::vector<std::size_t> VarySpec::probes() const {
  std::vector<std::size_t> out;
  if (form == Form::list || values.size() <= kAllProbed) {
    for (std::size_t i = 0; i < values.size(); ++i) out.push_back(i);
  } else {
    out = {0, 1, values.size() - 1};
  }
  return out;
}

VaryValue VarySpec::at(double t) const {
  if (!drawn()) {
    const auto size = static_cast<double>(values.size());
    return values[std::min(values.size() - 1, static_cast<std::size_t>(t * size))];
  }
  return number_value(number_at(t));
}

double VarySpec::number_at(double t) const {
  if (!drawn()) return at(t).number.value_or(std::numeric_limits<double>::quiet_NaN());
  const double value =
      form == Form::log ? from * std::pow(to / from, t) : (1.0 - t) * from + t * to;
  return std::clamp(value, std::min(from, to), std::max(from, to));
}

VarySpec parse_vary(const std::string& text, bool drawn, const std::string& flag) {
  const char* forms = drawn ? kDrawnForms : kForms;
  const auto eq = text.find('=');
  const std::string_view key = trim_blanks(std::string_view(text).substr(0, eq));
  const std::string_view given =
      eq == std::string::npos ? std::string_view() : std::string_view(text).substr(eq + 1);
  if (eq == std::string::npos || key.empty() || trim_blanks(given).empty()) {
    throw UsageError(fmt::format("{}: '{}' is not {}", flag, printable(text), forms));
  }
  const auto fail = [&](const std::string& why) {
    throw UsageError(fmt::format("{}: {}: {}", flag, printable(key), why));
  };
  VarySpec spec{std::string(key), VarySpec::Form::list, {}};

  if (given.find(':') == given.npos) {
    const auto items = split(given, ',');
    if (items.size() > static_cast<std::size_t>(kMaxCount)) {
      fail(fmt::format("{} values are more than {}", items.size(), kMaxCount));
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
      const std::string_view item = trim_blanks(items[i]);
      if (item.empty()) fail(fmt::format("value {} of '{}' is empty", i + 1, printable(given)));
      if (looks_like_a_number(item)) {
        double value = 0.0;
        if (!parse_whole(item, value) || !std::isfinite(value)) {
          fail(fmt::format("'{}' is not a finite number", printable(item)));
        }
        spec.values.push_back(number_value(value));
        continue;
      }
      // A name goes into a CSV field unquoted and into the scene as --set reads it.
      if (std::any_of(item.begin(), item.end(), [](char c) {
            return c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
          })) {
        fail(fmt::format("'{}' is not a name (no quotes, backslashes or control characters)",
                         printable(item)));
      }
      spec.values.push_back({std::nullopt, std::string(item)});
    }
    return spec;
  }

  const auto parts = split(given, ':');
  if (drawn) {
    // A random design draws from the range: a COUNT there is a grid's, not this design's.
    if (parts.size() == 3 && trim_blanks(parts[2]) != "log") {
      fail(fmt::format("a random design draws from FROM:TO or FROM:TO:log, not a COUNT ('{}')",
                       printable(trim_blanks(parts[2]))));
    }
    if (parts.size() != 2 && parts.size() != 3) {
      throw UsageError(fmt::format("{}: '{}' is not {}", flag, printable(text), forms));
    }
  } else if (parts.size() != 3 && parts.size() != 4) {
    throw UsageError(fmt::format("{}: '{}' is not {}", flag, printable(text), forms));
  }
  const std::size_t log_part = drawn ? 2 : 3;
  const bool log = parts.size() == log_part + 1;
  if (log && trim_blanks(parts[log_part]) != "log") {
    fail(fmt::format("'{}' is not log ({})", printable(trim_blanks(parts[log_part])),
                     drawn ? "FROM:TO:log" : "FROM:TO:COUNT:log"));
  }
  const auto part_fail = [&](const char* part, std::string_view value, const char* expected) {
    fail(fmt::format("{} '{}' is not {}", part, printable(trim_blanks(value)), expected));
  };
  double from = 0.0, to = 0.0;
  std::int64_t count = 0;
  if (!parse_whole(parts[0], from) || !std::isfinite(from)) {
    part_fail("FROM", parts[0], "a finite number");
  }
  if (!parse_whole(parts[1], to) || !std::isfinite(to)) {
    part_fail("TO", parts[1], "a finite number");
  }
  if (!drawn && (!parse_whole(parts[2], count) || count < 1 || count > kMaxCount)) {
    part_fail("COUNT", parts[2], "a whole number from 1 to 1000000");
  }
  if (!drawn && count == 1 && from != to) {
    fail(
        fmt::format("COUNT 1 gives one value, but FROM {} and TO {} differ (give a COUNT of 2 or "
                    "more, or one value)",
                    number_field(from), number_field(to)));
  }
  double ratio = 1.0;
  if (log) {
    if (from == 0.0 || to == 0.0 || (from < 0.0) != (to < 0.0)) {
      fail(fmt::format("a log range needs FROM and TO of the same sign and not zero, not {} and {}",
                       number_field(from), number_field(to)));
    }
    ratio = to / from;
    if (!std::isfinite(ratio) || ratio == 0.0) {
      fail(fmt::format("TO/FROM = {}/{} is beyond a double", number_field(to), number_field(from)));
    }
  }
  spec.form = log ? VarySpec::Form::log : VarySpec::Form::linear;
  spec.from = from;
  spec.to = to;
  if (drawn) return spec;
  spec.values.reserve(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) {
    // The ends are exact. Linear: from + (to - from) t overflows for from and to near opposite
    // ends of the doubles; (1 - t) from + t to does not.
    const double t = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
    double value = to;
    if (i == 0) {
      value = from;
    } else if (i < count - 1) {
      value = log ? from * std::pow(ratio, t) : (1.0 - t) * from + t * to;
      // The formula's rounding error: two ulps of the larger end (linear); of the value, and
      // the error ln(ratio) dt that t's rounding dt makes in pow (log).
      constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
      const double noise = log ? kEpsilon * std::abs(value) * (2.0 + std::abs(std::log(ratio)))
                               : 2.0 * kEpsilon * std::max(std::abs(from), std::abs(to));
      value = tidy(value, noise);
    }
    spec.values.push_back(number_value(value));
  }
  return spec;
}

}  // namespace mdrsim::cli
