// The known name a mistyped one most likely meant: the "did you mean" of unknown-key messages.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mdrsim {

/// Edits (insert, delete, replace one character, or swap two neighbours) that turn `a` into
/// `b`: the optimal string alignment distance.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The name of `known` nearest to `given`: the fewest edits, at most a third of `given`'s
/// length (and at least 1), the first in `known` on a tie; else the one name `given` begins
/// (3 characters or more: "poisson" for "poisson_ratio"). nullopt when none is near, or for
/// a name that is known itself.
std::optional<std::string> nearest_name(std::string_view given,
                                        const std::vector<std::string>& known);

/// The suffix of an unknown-name message: "; did you mean 'NAME'?", or "" when none is near.
std::string did_you_mean(std::string_view given, const std::vector<std::string>& known);

}  // namespace mdrsim
