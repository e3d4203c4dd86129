// The --vary KEY=VALUES of a sweep: a key and its values (a range, a log range or a list), or
// the range a random design draws from.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace mdrsim::cli {

/// One value of a varied key.
struct VaryValue {
  std::optional<double> number;  ///< set as a number when present; else `text` as --set reads it
  std::string text;              ///< the CSV field: the number's shortest form, or the name

  bool operator==(const VaryValue&) const = default;
};

struct VarySpec {
  enum class Form { linear, log, list };

  std::string key;
  Form form = Form::list;
  std::vector<VaryValue> values;  ///< empty for a drawn range (a random design's FROM:TO)
  bool linked = false;            ///< --link: varies with the key before it, not as a product
  double from = 0.0;              ///< a range's ends (FROM and TO as given)
  double to = 0.0;

  /// A random design's FROM:TO or FROM:TO:log: a value is drawn, not listed.
  bool drawn() const { return form != Form::list && values.empty(); }
  /// The value at `t` in [0, 1) of a drawn range: (1 - t) FROM + t TO or FROM (TO/FROM)^t,
  /// kept between the ends; of a list, value floor(t * size).
  VaryValue at(double t) const;
  /// at(t)'s number, without its text (NaN for a name).
  double number_at(double t) const;

  /// The values a sweep builds before any run, so that a bad value fails before the CSV
  /// exists: all of them for a list or a range of up to kAllProbed values, else the first,
  /// second and last of the range (the scene's checks are intervals and whole numbers,
  /// which those three decide for an evenly or log spaced range).
  std::vector<std::size_t> probes() const;

  static constexpr std::size_t kAllProbed = 64;
};

/// Parses KEY=FROM:TO:COUNT (evenly spaced), KEY=FROM:TO:COUNT:log (log spaced) or
/// KEY=V1,V2,... (numbers or names); with `drawn` (a random design) KEY=FROM:TO or
/// KEY=FROM:TO:log in place of the ranges. `flag` names the flag in messages (--vary, --link).
/// Throws UsageError.
VarySpec parse_vary(const std::string& text, bool drawn = false,
                    const std::string& flag = "--vary");

/// The value of a number as a sweep's CSV writes it: the shortest text that reads back
/// as the same double.
std::string number_field(double value);

}  // namespace mdrsim::cli
