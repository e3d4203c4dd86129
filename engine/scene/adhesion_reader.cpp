// A work of adhesion from the scene: its three forms, each point checked where it stands.
#include "engine/scene/adhesion_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/scene/embedded_table.hpp"
#include "profiles/two_column_file.hpp"

namespace mdrsim {
namespace {

/// Out to this many wavelengths past the tables' last points a sinusoid is compared with the
/// other work of adhesion (64 points per wavelength).
constexpr double kComparedWavelengths = 64.0;

/// The table of dgamma(r) from arrays r and value, or from file.
std::shared_ptr<const RadialAdhesion> read_table(TomlReader& w) {
  RadialAdhesion::Table table;
  std::vector<std::size_t> lines;  // of a file's rows
  std::string file;
  if (w.has("file")) {
    if (w.has("r") || w.has("value"))
      w.fail_at("file", "give file or the arrays r and value, not both");
    file = std::get<std::string>(*w.read({.key = "file",
                                          .kind = ParameterKind::path,
                                          .help = "CSV file with columns r [m], value [J/m^2]"}));
    try {
      TwoColumnFile columns = read_two_column_file(file, "r", "value");
      // The result carries the table, so that it reruns without the file.
      w.record("table", adhesion_table_record(file, columns));
      table.radii = std::move(columns.first);
      table.values = std::move(columns.second);
      lines = std::move(columns.lines);
    } catch (const std::invalid_argument& e) {
      w.fail_at("file", e.what());
    }
  } else {
    for (const char* key : {"r", "value"}) {
      if (!w.has(key)) {
        w.fail_at(key,
                  "missing: expected r = [...] [m] and value = [...] [J/m^2], or "
                  "file = \"w.csv\", or mean, amplitude and wavelength");
      }
    }
    table.radii = std::get<std::vector<double>>(*w.read(
        {.key = "r", .kind = ParameterKind::number_list, .help = "radii r_i [m], increasing"}));
    table.values = std::get<std::vector<double>>(*w.read(
        {.key = "value", .kind = ParameterKind::number_list, .help = "dgamma(r_i) [J/m^2], >= 0"}));
  }
  if (const auto problem = find_adhesion_table_problem(table)) {
    if (file.empty()) w.fail_at(problem->column, problem->message);
    // In a file: the line of the point the message names.
    const bool located = problem->point && *problem->point < lines.size();
    w.fail_at("file", located ? fmt::format("line {} of '{}': {}", lines[*problem->point], file,
                                            problem->message)
                              : fmt::format("'{}': {}", file, problem->message));
  }
  return std::make_shared<const RadialAdhesion>(std::move(table));
}

std::shared_ptr<const RadialAdhesion> read_sinusoid(TomlReader& w) {
  const double mean = w.number(
      {.key = "mean", .help = "mean work of adhesion [J/m^2], >= 0", .lower = Bound{0.0, true}});
  const double amplitude = w.number({.key = "amplitude",
                                     .help = "relative amplitude in [0, 1]",
                                     .lower = Bound{0.0, true},
                                     .upper = Bound{1.0, true}});
  const double wavelength =
      w.number({.key = "wavelength", .help = "wavelength [m], > 0", .lower = Bound{0.0, false}});
  return std::make_shared<const RadialAdhesion>(
      RadialAdhesion::Sinusoid{mean, amplitude, wavelength});
}

}  // namespace

ReadAdhesion read_adhesion(TomlReader& t, std::string_view key, const char* help,
                           std::optional<double> fallback) {
  if (!t.holds_table(key)) {
    // One named spec, not a temporary in each arm of a ?: (clang 14 destroys such a
    // temporary twice when its arm throws: a double free under ASan).
    ParameterSpec spec{.key = std::string(key), .help = help, .lower = Bound{0.0, true}};
    if (!fallback) return {t.number(spec), nullptr};
    spec.default_value = *fallback;
    return {t.optional_number(spec).value_or(*fallback), nullptr};
  }
  TomlReader w = t.table(key);
  w.check_keys({"r", "value", "file", "mean", "amplitude", "wavelength"});
  const bool sinusoid = w.has("mean") || w.has("amplitude") || w.has("wavelength");
  const bool table = w.has("r") || w.has("value") || w.has("file");
  if (sinusoid && table) {
    w.fail_at(w.has("mean") ? "mean" : (w.has("amplitude") ? "amplitude" : "wavelength"),
              "give a table (r and value, or file) or a sinusoid (mean, amplitude, wavelength), "
              "not both");
  }
  if (!sinusoid && !table) {
    w.fail(
        "empty: expected r = [...] and value = [...], file = \"w.csv\", or mean, amplitude "
        "and wavelength");
  }
  auto by_radius = sinusoid ? read_sinusoid(w) : read_table(w);
  w.finish();
  return {by_radius->scale_value(), std::move(by_radius)};
}

void apply_adhesion(TomlReader& t, const ReadAdhesion& receding, const ReadAdhesion& approach,
                    Material& m) {
  m.work_of_adhesion = receding.scale_value;
  m.approach_work_of_adhesion = approach.scale_value;
  m.work_of_adhesion_by_radius = receding.by_radius;
  m.approach_work_of_adhesion_by_radius = approach.by_radius;
  if (!receding.by_radius && !approach.by_radius) {
    if (approach.scale_value > receding.scale_value) {
      t.fail_range("approach_work_of_adhesion",
                   fmt::format("= {} is above work_of_adhesion = {} (0 <= dgamma_a <= dgamma)",
                               approach.scale_value, receding.scale_value));
    }
    return;
  }
  const auto as_function = [](const ReadAdhesion& a) {
    return a.by_radius ? *a.by_radius
                       : RadialAdhesion(RadialAdhesion::Table{{0.0}, {a.scale_value}});
  };
  const RadialAdhesion w = as_function(receding);
  const RadialAdhesion w_a = as_function(approach);
  // Beyond the tables' last points only sinusoids vary: a few of their longest waves past
  // the last point show where one exceeds the other.
  double last_point = 0.0, longest_wave = 0.0;
  for (const RadialAdhesion* a : {&w, &w_a}) {
    if (!a->breakpoints().empty()) last_point = std::max(last_point, a->breakpoints().back());
    if (const auto* s = a->sinusoid()) longest_wave = std::max(longest_wave, s->wavelength);
  }
  const double reach = last_point + kComparedWavelengths * longest_wave;
  if (const auto r = first_radius_where_approach_exceeds(w_a, w, reach)) {
    t.fail_at("approach_work_of_adhesion",
              fmt::format("dgamma_a = {} is above work_of_adhesion's dgamma = {} at r = {} m "
                          "(0 <= dgamma_a <= dgamma at every radius)",
                          w_a.at(*r), w.at(*r), *r));
  }
}

}  // namespace mdrsim
