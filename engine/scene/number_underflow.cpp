// Refusing a number a scene writes as nonzero that a double reads as zero (1e-400).
#include "engine/scene/number_underflow.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstddef>
#include <vector>

#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

/// The literal that begins at `at` in `text` (a TOML number: digits, signs, '.', 'e', '_').
std::string_view literal_at(std::string_view text, const toml::source_position& at) {
  std::size_t start = 0;
  for (toml::source_index line = 1; line < at.line; ++line) {
    start = text.find('\n', start);
    if (start == std::string_view::npos) return {};
    ++start;
  }
  start += at.column - 1;
  if (start >= text.size()) return {};
  std::size_t end = start;
  while (end < text.size() &&
         (std::isalnum(static_cast<unsigned char>(text[end])) != 0 || text[end] == '_' ||
          text[end] == '.' || text[end] == '+' || text[end] == '-')) {
    ++end;
  }
  return text.substr(start, end - start);
}

void find_underflow(const toml::node& node, std::string_view text, const std::string& path,
                    std::optional<NumberUnderflow>& found) {
  if (found) return;
  const auto join = [&](std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
  };
  if (const auto* table = node.as_table()) {
    for (const auto& [key, value] : *table) find_underflow(value, text, join(key.str()), found);
  } else if (const auto* array = node.as_array()) {
    for (std::size_t i = 0; i < array->size(); ++i) {
      const toml::node& element = *array->get(i);
      find_underflow(
          element, text,
          element.is_table() ? fmt::format("{}.{}", path, i + 1) : fmt::format("{}[{}]", path, i),
          found);
    }
  } else if (const auto* number = node.as_floating_point();
             number != nullptr && number->get() == 0.0) {
    const toml::source_position at = node.source().begin;
    if (auto message = underflow_message(literal_at(text, at))) {
      found = NumberUnderflow{at, path, std::move(*message)};
    }
  }
}

}  // namespace

std::optional<std::string> underflow_message(std::string_view literal) {
  // The mantissa is the part before the exponent; a nonzero digit there means "not zero".
  for (const char c : literal) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') {
      return fmt::format(
          " = {} is too small for a double (it would read as 0; the smallest is 4.9e-324)",
          printable(literal));
    }
  }
  return std::nullopt;
}

std::optional<NumberUnderflow> find_number_underflow(const toml::table& root,
                                                     std::string_view text) {
  std::optional<NumberUnderflow> found;
  find_underflow(root, text, "", found);
  return found;
}

}  // namespace mdrsim
