// Optimal string alignment distance in two rows of the table plus the one before them.
#include "engine/base/nearest_name.hpp"

#include <algorithm>
#include <cstddef>

namespace mdrsim {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t replace = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, replace});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        current[j] = std::min(current[j], before[j - 2] + 1);
      }
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::optional<std::string> nearest_name(std::string_view given,
                                        const std::vector<std::string>& known) {
  if (std::find(known.begin(), known.end(), given) != known.end()) return std::nullopt;
  const std::size_t limit = std::max<std::size_t>(1, given.size() / 3);
  const std::string* best = nullptr;
  std::size_t best_distance = limit + 1;
  for (const std::string& name : known) {
    const std::size_t d = edit_distance(given, name);
    if (d < best_distance) {
      best = &name;
      best_distance = d;
    }
  }
  if (best) return *best;
  if (given.size() < 3) return std::nullopt;
  const std::string* prefixed = nullptr;
  for (const std::string& name : known) {
    if (name.size() > given.size() && name.compare(0, given.size(), given) == 0) {
      if (prefixed) return std::nullopt;  // two names begin so: neither is the one
      prefixed = &name;
    }
  }
  if (prefixed) return *prefixed;
  return std::nullopt;
}

std::string did_you_mean(std::string_view given, const std::vector<std::string>& known) {
  const auto name = nearest_name(given, known);
  return name ? "; did you mean '" + *name + "'?" : std::string();
}

}  // namespace mdrsim
