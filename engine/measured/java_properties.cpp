// Java .properties text (JPK's headers) to a key -> value map.
#include "engine/measured/java_properties.hpp"

#include <charconv>
#include <cstdint>
#include <vector>

namespace mdrsim::measured {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f'; }

/// The logical lines: physical lines joined where one ends in an odd run of backslashes,
/// the continuation's leading blanks dropped.
std::vector<std::string> logical_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::string current;
  bool continuing = false;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    if (continuing) {
      while (!line.empty() && is_blank(line.front())) line.remove_prefix(1);
    }
    std::size_t backslashes = 0;
    while (backslashes < line.size() && line[line.size() - 1 - backslashes] == '\\') ++backslashes;
    const bool continues = backslashes % 2 == 1;
    if (continues) line.remove_suffix(1);
    current.append(line);
    continuing = continues;
    if (!continues) {
      lines.push_back(std::move(current));
      current.clear();
    }
    if (end == text.size()) break;
    pos = end + 1;
    if (text[end] == '\r' && pos < text.size() && text[pos] == '\n') ++pos;
  }
  if (!current.empty()) lines.push_back(std::move(current));
  return lines;
}

void append_utf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xc0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3f));
  } else {
    out += static_cast<char>(0xe0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (code & 0x3f));
  }
}

/// Reads one escaped character at text[pos] (after the backslash) into out; returns the
/// position after it.
std::size_t unescape_one(std::string_view text, std::size_t pos, std::string& out) {
  if (pos >= text.size()) return pos;
  const char c = text[pos];
  switch (c) {
    case 't':
      out += '\t';
      return pos + 1;
    case 'n':
      out += '\n';
      return pos + 1;
    case 'r':
      out += '\r';
      return pos + 1;
    case 'f':
      out += '\f';
      return pos + 1;
    case 'u': {
      std::uint32_t code = 0;
      if (pos + 5 <= text.size() &&
          std::from_chars(text.data() + pos + 1, text.data() + pos + 5, code, 16).ptr ==
              text.data() + pos + 5) {
        append_utf8(out, code);
        return pos + 5;
      }
      out += 'u';
      return pos + 1;
    }
    default:
      out += c;
      return pos + 1;
  }
}

}  // namespace

Properties parse_properties(std::string_view text) {
  Properties properties;
  for (const std::string& line : logical_lines(text)) {
    std::size_t pos = 0;
    while (pos < line.size() && is_blank(line[pos])) ++pos;
    if (pos == line.size() || line[pos] == '#' || line[pos] == '!') continue;
    std::string key;
    while (pos < line.size()) {
      const char c = line[pos];
      if (c == '\\') {
        pos = unescape_one(line, pos + 1, key);
        continue;
      }
      if (c == '=' || c == ':' || is_blank(c)) break;
      key += c;
      ++pos;
    }
    while (pos < line.size() && is_blank(line[pos])) ++pos;
    if (pos < line.size() && (line[pos] == '=' || line[pos] == ':')) ++pos;
    while (pos < line.size() && is_blank(line[pos])) ++pos;
    std::string value;
    while (pos < line.size()) {
      if (line[pos] == '\\') {
        pos = unescape_one(line, pos + 1, value);
      } else {
        value += line[pos++];
      }
    }
    properties[std::move(key)] = std::move(value);
  }
  return properties;
}

std::optional<double> property_number(const Properties& properties, std::string_view key) {
  const auto found = properties.find(key);
  if (found == properties.end()) return std::nullopt;
  const std::string& text = found->second;
  double value = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, error] = std::from_chars(first, last, value);
  if (error != std::errc{} || ptr != last || first == last) return std::nullopt;
  return value;
}

std::optional<std::string> property_text(const Properties& properties, std::string_view key) {
  const auto found = properties.find(key);
  if (found == properties.end()) return std::nullopt;
  return found->second;
}

}  // namespace mdrsim::measured
