// The small pieces of message text every folder writes: names joined, a count with its noun,
// one line, a system error's reason, blanks trimmed.
#pragma once

#include <fmt/format.h>

#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mdrsim {

/// "a, b, c" ("" for none).
std::string join_names(const std::vector<std::string>& names);

/// "'a', 'b', 'c'": each name in single quotes, joined ("" for none).
std::string quoted_names(const std::vector<std::string>& names);

/// "1 stage", "3 stages": the count and its noun, with an s unless the count is 1.
template <std::integral Count>
std::string counted(Count count, std::string_view noun) {
  return fmt::format("{} {}{}", count, noun, count == 1 ? "" : "s");
}

/// The text on one line, as every message is: trailing line ends dropped, inner ones spaces.
std::string one_line(std::string text);

/// The text with its first letter in lower case, as messages continue after a location.
std::string lowercase_first(std::string text);

/// What the system says of error number `error` (strerror), as a message continues it.
std::string system_reason(int error);

/// The text without the spaces and tabs at either end.
std::string_view trim_blanks(std::string_view text);

/// Reads all of `text` as a whole number >= 0 into `out`; false (out unspecified) for an empty
/// text, a sign, anything after the digits or a number beyond 64 bits.
bool read_whole_number(std::string_view text, std::uint64_t& out);

}  // namespace mdrsim
