// A CSV file of two named numeric columns: the tabulated profile's r,f and a dgamma(r) table.
#include "profiles/two_column_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace mdrsim {
namespace {

constexpr std::uintmax_t kLargestFile = 64u << 20;

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::optional<double> parse_number(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || error != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) {
    return std::nullopt;
  }
  return v;
}

}  // namespace

TwoColumnFile read_two_column_file(const std::string& path, std::string_view first,
                                   std::string_view second) {
  const std::string shown = std::filesystem::path(path).lexically_normal().string();
  std::error_code ec;
  std::ifstream file(path, std::ios::binary);
  if (!file || std::filesystem::is_directory(path, ec)) {
    throw std::invalid_argument(fmt::format(
        "cannot read '{}': {}", shown,
        std::filesystem::is_directory(path, ec) ? "it is a directory" : std::strerror(errno)));
  }
  // Read through a capped buffer, not by the file's size: a device or a pipe has none.
  std::string content;
  std::vector<char> chunk(1 << 16);
  while (file.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || file.gcount() > 0) {
    content.append(chunk.data(), static_cast<std::size_t>(file.gcount()));
    if (content.size() > kLargestFile) {
      throw std::invalid_argument(
          fmt::format("'{}' is larger than {} MiB", shown, kLargestFile >> 20));
    }
  }
  if (file.bad()) throw std::invalid_argument(fmt::format("cannot read '{}'", shown));
  std::istringstream in(content);
  TwoColumnFile table;
  std::string line;
  bool header_allowed = true;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const auto comma = text.find(',');
    const bool header = header_allowed && comma != std::string_view::npos &&
                        trim(text.substr(0, comma)) == first &&
                        trim(text.substr(comma + 1)) == second;
    header_allowed = false;
    if (header) continue;
    const auto r =
        comma == std::string_view::npos ? std::nullopt : parse_number(text.substr(0, comma));
    const auto f =
        comma == std::string_view::npos ? std::nullopt : parse_number(text.substr(comma + 1));
    if (!r || !f) {
      std::string quoted(text.substr(0, 60));
      if (text.size() > 60) quoted += "...";
      throw std::invalid_argument(
          fmt::format("line {} of '{}': expected two numbers {},{}, got \"{}\"", number, shown,
                      first, second, quoted));
    }
    table.first.push_back(*r);
    table.second.push_back(*f);
    table.lines.push_back(number);
  }
  return table;
}

}  // namespace mdrsim
