// Refusing a number a scene writes as nonzero that a double reads as zero (1e-400).
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>

namespace mdrsim {

/// " = 1e-400 is too small for a double (it reads as 0; the smallest is 4.9e-324)" where
/// `literal` is a TOML number with a nonzero digit that reads as zero; else nullopt.
std::optional<std::string> underflow_message(std::string_view literal);

/// A number written nonzero that reads as zero: where it begins, its dotted key, what is wrong.
struct NumberUnderflow {
  toml::source_position at;
  std::string key;      ///< as the reader names it: tables of an array .N from 1, elements [i]
  std::string message;  ///< " = 1e-400 is too small ..."
};

/// The first number in `root` (parsed from `text`) written with a nonzero digit that reads as
/// zero: toml++ and strtod quietly read 1e-400 as 0, a silent default for what is most likely
/// a mistyped exponent. nullopt when there is none.
std::optional<NumberUnderflow> find_number_underflow(const toml::table& root,
                                                     std::string_view text);

}  // namespace mdrsim
