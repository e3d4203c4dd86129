// Force curves in text tables: the AFM Workshop export and SPEC's CSV/TSV columns.
#include "engine/measured/table_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/base/text.hpp"
#include "engine/measured/measured_error.hpp"

namespace mdrsim::measured {
namespace {

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    pos = end + 1;
  }
  return lines;
}

std::vector<std::string_view> split_fields(std::string_view line, char delimiter) {
  std::vector<std::string_view> fields;
  std::size_t pos = 0;
  while (true) {
    const std::size_t end = line.find(delimiter, pos);
    fields.push_back(
        trim_blanks(line.substr(pos, end == std::string_view::npos ? end : end - pos)));
    if (end == std::string_view::npos) break;
    pos = end + 1;
  }
  return fields;
}

std::optional<double> parse_number(std::string_view text) {
  text = trim_blanks(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [ptr, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

/// Reads the data rows below the header line: each a number in every column.
std::vector<std::vector<double>> read_rows(const std::filesystem::path& path,
                                           const std::vector<std::string_view>& lines,
                                           std::size_t first, std::size_t columns, char delimiter,
                                           const std::vector<bool>& text_columns = {}) {
  std::vector<std::vector<double>> values(columns);
  for (std::size_t l = first; l < lines.size(); ++l) {
    if (trim_blanks(lines[l]).empty()) continue;
    const auto fields = split_fields(lines[l], delimiter);
    if (fields.size() != columns) {
      refuse(path, "line {}: {} fields, the header has {}", l + 1, fields.size(), columns);
    }
    for (std::size_t c = 0; c < columns; ++c) {
      if (c < text_columns.size() && text_columns[c]) {
        values[c].push_back(0.0);
        continue;
      }
      const auto number = parse_number(fields[c]);
      if (!number) refuse(path, "line {}: '{}' is not a number", l + 1, printable(fields[c], 40));
      values[c].push_back(*number);
    }
  }
  return values;
}

std::vector<double> scaled(const std::vector<double>& values, double factor) {
  std::vector<double> out(values.size());
  std::transform(values.begin(), values.end(), out.begin(), [&](double v) { return v * factor; });
  return out;
}

/// The AFM Workshop export: "Key: value" lines, then "Extend Z-Sense(nm),Extend Force(nN),
/// Retract Z-Sense(nm),Retract Force(nN)" (or T-B(V) for the deflection in volts).
MeasuredFile read_afm_workshop(const std::filesystem::path& path,
                               const std::vector<std::string_view>& lines,
                               const CalibrationOverride& overrides) {
  ForceCurve curve;
  std::optional<double> x, y;
  long point = 0;
  std::size_t header = lines.size();
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const std::string_view line = lines[l];
    if (std::count(line.begin(), line.end(), ',') >= 3) {
      header = l;
      break;
    }
    const std::size_t colon = line.rfind(':');
    if (colon == std::string_view::npos) continue;
    const std::string_view key = trim_blanks(line.substr(0, colon));
    const auto value = parse_number(line.substr(colon + 1));
    if (!value) continue;
    if (key == "X, um") x = *value * 1e-6;
    if (key == "Y, um") y = *value * 1e-6;
    if (key == "Point" && std::abs(*value) < 1e9) point = std::lround(*value);
    // The instrument writes 1 for a gain or a constant nobody set.
    if (key == "Light Lever Gain, mV/nm" && *value != 1.0) {
      curve.calibration.sensitivity = Calibrated{1.0 / (*value * 1e-3 / 1e-9), std::string(key)};
    }
    if (key == "Force Constant, nN/nm" && *value != 1.0) {
      curve.calibration.spring_constant = Calibrated{*value, std::string(key)};
    }
  }
  if (header == lines.size()) refuse(path, "no column header line (Extend Z-Sense(nm),...)");
  if (overrides.sensitivity)
    curve.calibration.sensitivity = Calibrated{*overrides.sensitivity, "override"};
  if (overrides.spring_constant) {
    curve.calibration.spring_constant = Calibrated{*overrides.spring_constant, "override"};
  }
  if (x && y) curve.position = MapPosition{*x, *y, point};
  const auto names = split_fields(lines[header], ',');
  const auto values = read_rows(path, lines, header + 1, names.size(), ',');
  Segment approach{.name = "extend", .kind = SegmentKind::approach};
  Segment retract{.name = "retract", .kind = SegmentKind::retract};
  for (std::size_t c = 0; c < names.size(); ++c) {
    const std::string_view name = names[c];
    Segment& segment = name.starts_with("Extend") ? approach : retract;
    if (!name.starts_with("Extend") && !name.starts_with("Retract")) {
      refuse(path, "unknown column '{}' (known: Extend/Retract Z-Sense(nm), Force(nN), T-B(V))",
             printable(name, 40));
    }
    if (name.ends_with("Z-Sense(nm)")) {
      segment.measured_height = scaled(values[c], -1e-9);  // the sensor's height grows downwards
    } else if (name.ends_with("Force(nN)")) {
      segment.force = scaled(values[c], 1e-9);
    } else if (name.ends_with("T-B(V)")) {
      if (!curve.calibration.sensitivity) {
        refuse(path,
               "column '{}' is in volts and the file gives no sensitivity "
               "(Light Lever Gain, mV/nm)",
               printable(name, 40));
      }
      segment.deflection = scaled(values[c], curve.calibration.sensitivity->value);
    } else {
      refuse(path, "unknown column '{}' (known: Extend/Retract Z-Sense(nm), Force(nN), T-B(V))",
             printable(name, 40));
    }
  }
  curve.segments = {std::move(approach), std::move(retract)};
  MeasuredFile result{.path = path, .format = "afm-workshop"};
  result.curves.push_back(std::move(curve));
  return result;
}

/// SPEC's table: "# key: value" calibration lines, a header row of column names (an optional
/// "[unit]" after each, which must be the SI one), then the rows, comma- or tab-separated.
MeasuredFile read_spec_table(const std::filesystem::path& path,
                             const std::vector<std::string_view>& lines,
                             const CalibrationOverride& overrides) {
  static const std::map<std::string_view, std::string_view> kColumns = {
      {"time", "s"},       {"piezo_height", "m"}, {"measured_height", "m"}, {"tip_position", "m"},
      {"deflection", "m"}, {"force", "N"},        {"segment", ""}};
  static const std::map<std::string_view, std::string_view> kCalibration = {
      {"sensitivity", "m/V"},
      {"spring_constant", "N/m"},
      {"approach_speed", "m/s"},
      {"retract_speed", "m/s"}};
  ForceCurve curve;
  std::size_t header = lines.size();
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const std::string_view line = trim_blanks(lines[l]);
    if (line.empty()) continue;
    if (line.front() != '#') {
      header = l;
      break;
    }
    const std::string_view entry = trim_blanks(line.substr(1));
    const std::size_t separator = entry.find_first_of(":=");
    if (separator == std::string_view::npos) continue;
    const std::string_view key = trim_blanks(entry.substr(0, separator));
    if (!kCalibration.contains(key)) continue;
    const auto value = parse_number(entry.substr(separator + 1));
    if (!value || !(*value > 0.0)) {
      refuse(path, "line {}: {} must be a number > 0", l + 1, key);
    }
    Calibrated calibrated{*value, "line " + std::to_string(l + 1)};
    if (key == "sensitivity") curve.calibration.sensitivity = calibrated;
    if (key == "spring_constant") curve.calibration.spring_constant = calibrated;
    if (key == "approach_speed") curve.calibration.approach_speed = calibrated;
    if (key == "retract_speed") curve.calibration.retract_speed = calibrated;
  }
  if (header == lines.size()) refuse(path, "no header row of column names");
  if (overrides.sensitivity)
    curve.calibration.sensitivity = Calibrated{*overrides.sensitivity, "override"};
  if (overrides.spring_constant) {
    curve.calibration.spring_constant = Calibrated{*overrides.spring_constant, "override"};
  }
  const char delimiter = lines[header].find('\t') != std::string_view::npos ? '\t' : ',';
  const auto fields = split_fields(lines[header], delimiter);
  std::vector<std::string> names;
  for (const std::string_view field : fields) {
    std::string_view name = field;
    std::string_view unit;
    if (const std::size_t open = field.find('[');
        open != std::string_view::npos && field.ends_with(']')) {
      name = trim_blanks(field.substr(0, open));
      unit = field.substr(open + 1, field.size() - open - 2);
    }
    const auto known = kColumns.find(name);
    if (known == kColumns.end()) {
      refuse(path,
             "line {}: unknown column '{}' (known: deflection, force, measured_height, "
             "piezo_height, segment, time, tip_position)",
             header + 1, printable(name, 40));
    }
    if (!unit.empty() && unit != known->second) {
      refuse(path, "line {}: column {} is in [{}], not [{}]", header + 1, name, printable(unit, 20),
             known->second);
    }
    if (std::find(names.begin(), names.end(), name) != names.end()) {
      refuse(path, "line {}: column {} given twice", header + 1, name);
    }
    names.emplace_back(name);
  }
  const auto column = [&](std::string_view name) -> std::optional<std::size_t> {
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) return std::nullopt;
    return static_cast<std::size_t>(found - names.begin());
  };
  // The segment column is text (approach, retract, pause) or numbers (0 the approach, the
  // highest the retract, any between them pauses, as afmformats numbers them).
  std::vector<bool> text_columns(names.size(), false);
  const auto segment_column = column("segment");
  if (segment_column) text_columns[*segment_column] = true;
  const auto values = read_rows(path, lines, header + 1, names.size(), delimiter, text_columns);
  std::vector<std::string> segment_names;
  if (segment_column) {
    for (std::size_t l = header + 1; l < lines.size(); ++l) {
      if (trim_blanks(lines[l]).empty()) continue;
      segment_names.emplace_back(split_fields(lines[l], delimiter)[*segment_column]);
    }
  } else {
    segment_names.assign(values.front().size(), "approach");
  }
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < segment_names.size(); ++i) {
    if (i == 0 || segment_names[i] != segment_names[i - 1]) starts.push_back(i);
  }
  starts.push_back(segment_names.size());
  const std::size_t segments = starts.size() - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    const std::string& name = segment_names[starts[s]];
    Segment segment;
    segment.name = name;
    if (name == "approach" || name == "extend") {
      segment.kind = SegmentKind::approach;
    } else if (name == "retract") {
      segment.kind = SegmentKind::retract;
    } else if (name == "pause") {
      segment.kind = SegmentKind::pause;
    } else if (parse_number(name)) {
      segment.kind = s == 0              ? SegmentKind::approach
                     : s + 1 == segments ? SegmentKind::retract
                                         : SegmentKind::pause;
      segment.name = segment_kind_name(segment.kind);
    } else {
      refuse(path, "segment '{}' is unknown (known: approach, retract, pause, or numbers)",
             printable(name, 40));
    }
    const auto take = [&](std::string_view column_name) {
      const auto c = column(column_name);
      if (!c) return std::vector<double>{};
      return std::vector<double>(values[*c].begin() + static_cast<std::ptrdiff_t>(starts[s]),
                                 values[*c].begin() + static_cast<std::ptrdiff_t>(starts[s + 1]));
    };
    segment.time = take("time");
    segment.piezo_height = take("piezo_height");
    segment.measured_height = take("measured_height");
    segment.tip_position = take("tip_position");
    segment.deflection = take("deflection");
    segment.force = take("force");
    curve.segments.push_back(std::move(segment));
  }
  MeasuredFile result{.path = path, .format = "table"};
  result.curves.push_back(std::move(curve));
  return result;
}

}  // namespace

MeasuredFile read_table(const std::filesystem::path& path, const CalibrationOverride& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(path, "cannot be opened ({})", system_reason(errno));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (text.find('\0') != std::string::npos) refuse(path, "binary data, not a text table");
  const std::vector<std::string_view> lines = split_lines(text);
  if (!lines.empty() && lines.front().find("Force-Distance Curve") != std::string_view::npos) {
    return read_afm_workshop(path, lines, overrides);
  }
  return read_spec_table(path, lines, overrides);
}

}  // namespace mdrsim::measured
