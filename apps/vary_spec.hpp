// The --vary KEY=FROM:TO:COUNT of a sweep: a key and its evenly spaced values.
#pragma once

#include <string>
#include <vector>

namespace mdrsim::cli {

struct VarySpec {
  std::string key;
  std::vector<double> values;
};

/// Parses KEY=FROM:TO:COUNT; COUNT values from FROM to TO inclusive. Throws UsageError.
VarySpec parse_vary(const std::string& text);

}  // namespace mdrsim::cli
