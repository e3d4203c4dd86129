// Java .properties text (JPK's headers) to a key -> value map.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace mdrsim::measured {

using Properties = std::map<std::string, std::string, std::less<>>;

/// Parses the text by java.util.Properties' rules: '#' and '!' comments, '=', ':' or blanks
/// between key and value, backslash escapes (\t \n \r \f \uXXXX, any other character as
/// itself) and lines continued by an odd number of trailing backslashes. A later key
/// replaces an earlier one.
Properties parse_properties(std::string_view text);

/// The value of `key` read as a number (Java's Double.toString text, NaN included); nullopt
/// when the key is absent or its value is not a number.
std::optional<double> property_number(const Properties& properties, std::string_view key);

/// The value of `key`, nullopt when absent.
std::optional<std::string> property_text(const Properties& properties, std::string_view key);

}  // namespace mdrsim::measured
