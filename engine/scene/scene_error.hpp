// Bad input: one line naming the file, line, key and what was expected (exit code 2).
#pragma once

#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace mdrsim {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// User text (a key, a string value) as it may appear inside a one-line message: control
/// characters escaped, long text cut short.
inline std::string printable(std::string_view text, std::size_t max_chars = 80) {
  std::string out;
  for (const char c : text) {
    if (out.size() >= max_chars) return out + "...";
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace mdrsim
