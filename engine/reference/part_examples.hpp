// A registered part's keys with their declared example values, for tests over every part.
#pragma once

#include <string>
#include <string_view>

namespace mdrsim::test {

/// "key = value" for each declared parameter of the built-in part `name` of `kind`
/// ("criterion", "controller" or "profile") that has an example, joined by `separator`
/// (", " inside an inline table, "\n" in a table); empty for a part without parameters.
std::string example_keys(std::string_view kind, std::string_view name, std::string_view separator);

}  // namespace mdrsim::test
