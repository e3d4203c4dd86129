// The rows of a sweep as scenes.
#include "engine/output/sweep_rows.hpp"

#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "engine/output/finite_result.hpp"
#include "engine/output/result_json.hpp"
#include "engine/output/sweep_csv.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/run_label.hpp"

namespace mdrsim::cli {
namespace {

/// A name's value goes in through set_value, whose messages say --set: they say --vary here.
std::string as_vary_message(const std::string& message, const SweepGrid& grid,
                            const std::vector<VaryValue>& values) {
  constexpr std::string_view set = "--set: ";
  if (message.rfind(set, 0) != 0) return message;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const VarySpec& spec = grid.keys()[k];
    if (values[k].number) continue;
    const std::string& key = spec.key;
    const std::size_t after = set.size() + key.size();
    if (message.compare(set.size(), key.size(), key) == 0 && after < message.size() &&
        (message[after] == ':' || message[after] == ' ')) {
      return (spec.linked ? "--link: " : "--vary: ") + message.substr(set.size());
    }
  }
  return message;
}

/// "row R of M (key=value, ...)".
std::string row_label(const SweepGrid& grid, std::uint64_t row,
                      const std::vector<VaryValue>& values) {
  std::string label = fmt::format("row {} of {} (", row, grid.rows());
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k > 0) label += ", ";
    label += grid.keys()[k].key + "=" + values[k].text;
  }
  return label + ")";
}

}  // namespace

Scene build_row(SceneDocument& document, const SweepGrid& grid,
                const std::vector<VaryValue>& values, const Registries& registries) {
  try {
    for (std::size_t k = 0; k < values.size(); ++k) {
      const VarySpec& spec = grid.keys()[k];
      const VaryValue& value = values[k];
      if (value.number) {
        document.set_number(spec.key, *value.number, spec.linked ? "--link" : "--vary");
      } else {
        document.set_value(spec.key, value.text);
      }
    }
    return document.build(registries);
  } catch (const SceneError& e) {
    throw SceneError(as_vary_message(e.what(), grid, values));
  }
}

SweepColumns check_values(const SceneDocument& base, const SweepGrid& grid,
                          const Registries& registries) {
  SceneDocument document = base;
  SweepColumns columns;
  for (const std::uint64_t row : grid.probe_rows()) {
    const Scene scene = build_row(document, grid, grid.values(row), registries);
    columns.dimensionless = columns.dimensionless || dimensionless_scales(scene).has_value();
    columns.friction = columns.friction || scene.friction.has_value();
    columns.work = columns.work || scene.program.has_value();
    columns.bulk = columns.bulk || scene.material.relaxes();
    columns.front = columns.front || scene.front_speed_law.has_value();
  }
  return columns;
}

std::string run_row(SceneDocument& document, const SweepGrid& grid, std::uint64_t row,
                    const Registries& registries, SweepColumns columns) {
  const std::vector<VaryValue> values = grid.values(row);
  const ScopedRunLabel label(row_label(grid, row, values));
  const Scene scene = build_row(document, grid, values, registries);
  const RunResult result = run_scene(scene, ObserverList{});
  require_finite(scene, result);
  return csv_row(values, scene, result, columns);
}

}  // namespace mdrsim::cli
