// Reads a CSV file of two named numeric columns (r,f of a profile; r,value of a dgamma(r) table).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace mdrsim {

/// The columns of a two-column CSV file and the line of each row.
struct TwoColumnFile {
  std::vector<double> first;
  std::vector<double> second;
  std::vector<std::size_t> lines;  ///< the file's line of row i
};

/// Reads `path`: one row of two numbers per line, an optional header line "first,second",
/// blank lines and lines starting with '#' skipped, at most 64 MiB. Throws
/// std::invalid_argument with "line N of 'file': ..." for a malformed line, or naming the file
/// when it cannot be read.
TwoColumnFile read_two_column_file(const std::string& path, std::string_view first,
                                   std::string_view second);

}  // namespace mdrsim
