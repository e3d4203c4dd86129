// Declared parameters of a pluggable part and the checked values a scene gives them.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace mdrsim {

/// One end of the interval a numeric parameter must lie in.
struct Bound {
  double value;
  bool inclusive;
};

enum class ParameterKind {
  number,       ///< a finite real
  integer,      ///< a whole number
  number_list,  ///< an array of finite reals
  text,         ///< a string
  path,         ///< a string naming a file, resolved against the scene file's folder
};

/// What a part reads from its scene table; the scene loader checks values against it.
struct ParameterSpec {
  std::string key;
  ParameterKind kind = ParameterKind::number;
  std::string help;  ///< one line with the unit, for listings and messages
  bool required = true;
  std::optional<double> default_value;  ///< numbers only, used when absent and not required
  std::optional<Bound> lower;
  std::optional<Bound> upper;
  /// Numbers only: a value that makes a working part in the tests' JKR scene (R = 1 cm,
  /// E = 1 MPa, dgamma = 0.05 J/m^2), so that tests over every registered part build each
  /// one from its declaration, with no switch on part names (engine/reference/part_examples).
  std::optional<double> example;
};

using ParameterValue = std::variant<double, std::vector<double>, std::string>;

/// The values of a part's declared parameters, checked against their specs.
class ParameterValues {
 public:
  void set(std::string key, ParameterValue value) { values_[std::move(key)] = std::move(value); }
  bool has(std::string_view key) const { return values_.find(key) != values_.end(); }
  double number(std::string_view key) const { return std::get<double>(at(key)); }
  const std::vector<double>& numbers(std::string_view key) const {
    return std::get<std::vector<double>>(at(key));
  }
  const std::string& text(std::string_view key) const { return std::get<std::string>(at(key)); }

 private:
  const ParameterValue& at(std::string_view key) const {
    const auto it = values_.find(key);
    if (it == values_.end()) {
      throw std::logic_error("parameter '" + std::string(key) + "' was not declared or given");
    }
    return it->second;
  }
  std::map<std::string, ParameterValue, std::less<>> values_;
};

/// Thrown by a part's factory when values that passed their own checks do not fit together;
/// the scene loader adds the file, line and key path.
class ParameterError : public std::invalid_argument {
 public:
  ParameterError(std::string key, const std::string& message)
      : std::invalid_argument(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

}  // namespace mdrsim
