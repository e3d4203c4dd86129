// Messages follow docs: "scene.toml:7:16: material.poisson_ratio = 0.7 is outside (-1, 0.5]".
#include "engine/scene/toml_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <system_error>
#include <type_traits>
#include <variant>

#include "engine/base/nearest_name.hpp"
#include "engine/base/text.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

std::string interval(const ParameterSpec& s) {
  const std::string lo = s.lower
                             ? fmt::format("{}{}", s.lower->inclusive ? "[" : "(", s.lower->value)
                             : std::string("(-inf");
  const std::string hi = s.upper
                             ? fmt::format("{}{}", s.upper->value, s.upper->inclusive ? "]" : ")")
                             : std::string("inf)");
  return lo + ", " + hi;
}

bool inside(const ParameterSpec& s, double v) {
  if (s.lower && (s.lower->inclusive ? v < s.lower->value : v <= s.lower->value)) return false;
  if (s.upper && (s.upper->inclusive ? v > s.upper->value : v >= s.upper->value)) return false;
  return true;
}

std::string describe(const toml::node& node) {
  if (const auto* s = node.as_string()) return fmt::format("string \"{}\"", printable(s->get()));
  if (node.is_table()) return "a table";
  if (node.is_array()) return "an array";
  if (node.is_boolean()) return node.as_boolean()->get() ? "true" : "false";
  if (node.is_integer()) return fmt::format("{}", node.as_integer()->get());
  if (node.is_floating_point()) return fmt::format("{}", node.as_floating_point()->get());
  return "a date or time";
}

bool before(const toml::source_position& a, const toml::source_position& b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

const char* expected(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::number:
      return "a number";
    case ParameterKind::integer:
      return "a whole number";
    case ParameterKind::number_list:
      return "an array of numbers";
    case ParameterKind::text:
      return "a string";
    case ParameterKind::path:
      return "a file path string";
  }
  return "?";
}

/// A file path as the resolved scene gives it: absolute, so that it reads the same from anywhere.
std::string absolute_path(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  return ec ? path : absolute.lexically_normal().string();
}

}  // namespace

TomlReader::TomlReader(const toml::table& table, std::string path, std::string file,
                       std::filesystem::path base_dir, nlohmann::json* resolved)
    : table_(&table),
      path_(std::move(path)),
      file_(std::move(file)),
      base_dir_(std::move(base_dir)),
      resolved_(resolved) {}

void TomlReader::record(std::string_view key, nlohmann::json value) {
  if (resolved_) (*resolved_)[std::string(key)] = std::move(value);
}

nlohmann::json* TomlReader::resolved_child(std::string_view key, nlohmann::json empty) {
  if (!resolved_) return nullptr;
  nlohmann::json& child = (*resolved_)[std::string(key)];
  child = std::move(empty);
  return &child;
}

std::string TomlReader::key_path(std::string_view key) const {
  const std::string shown = printable(key);
  return path_.empty() ? shown : path_ + "." + shown;
}

std::string TomlReader::where(const toml::source_region& src) const {
  // Values given on the command line carry the flag as their source.
  if (src.path && (*src.path == "--set" || *src.path == "--vary")) return *src.path + ":";
  if (src.begin.line == 0) return file_ + ":";
  return fmt::format("{}:{}:{}:", file_, src.begin.line, src.begin.column);
}

std::string TomlReader::where_table() const {
  // The root table "begins" at 1:1, which points at nothing in particular.
  if (path_.empty()) return file_ + ":";
  return where(*table_);
}

void TomlReader::fail(const std::string& message) const {
  throw SceneError(
      fmt::format("{} {}: {}", where_table(), path_.empty() ? "scene" : path_, message));
}

std::string TomlReader::message_at(std::string_view key, const std::string& message) const {
  const toml::node* node = table_->get(key);
  return fmt::format("{} {}: {}", node ? where(*node) : where_table(), key_path(key), message);
}

void TomlReader::fail_at(std::string_view key, const std::string& message) const {
  throw SceneError(message_at(key, message));
}

void TomlReader::fail_range(std::string_view key, const std::string& message) const {
  const toml::node* node = table_->get(key);
  throw SceneError(
      fmt::format("{} {} {}", node ? where(*node) : where_table(), key_path(key), message));
}

void TomlReader::fail_unknown(const toml::key& key, const toml::node& node) const {
  std::set<std::string, std::less<>> known = known_;
  known.insert(asked_.begin(), asked_.end());
  // A key inserted by --set has no source of its own; its value does.
  const std::string location = key.source().begin.line != 0 ? where(key.source()) : where(node);
  const std::vector<std::string> names(known.begin(), known.end());
  throw SceneError(fmt::format(
      "{} {}: unknown key{}{}", location, key_path(key.str()), did_you_mean(key.str(), names),
      names.empty() ? std::string() : fmt::format(" (known: {})", join_names(names))));
}

const toml::node* TomlReader::find(std::string_view key) {
  const toml::node* node = table_->get(key);
  asked_.emplace(key);
  if (node) read_.emplace(key);
  return node;
}

double TomlReader::checked_number(const std::string& shown, const toml::node& node,
                                  const ParameterSpec& spec) const {
  const auto fail_here = [&](const std::string& message) {
    throw SceneError(fmt::format("{} {}{}", where(node), shown, message));
  };
  double v = 0.0;
  if (const auto* i = node.as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    v = f->get();
  } else {
    fail_here(fmt::format(": expected {}, got {}",
                          spec.kind == ParameterKind::integer ? "a whole number" : "a number",
                          describe(node)));
  }
  if (!std::isfinite(v)) fail_here(fmt::format(" = {} is not a finite number", v));
  if (!inside(spec, v)) fail_here(fmt::format(" = {} is outside {}", v, interval(spec)));
  if (spec.kind == ParameterKind::integer && v != std::floor(v)) {
    fail_here(fmt::format(" = {} is not a whole number", v));
  }
  return v;
}

std::optional<ParameterValue> TomlReader::read(const ParameterSpec& spec) {
  std::optional<ParameterValue> value = read_value(spec);
  if (value) {
    std::visit(
        [&](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<V, double>) {
            if (spec.kind == ParameterKind::integer) {
              record(spec.key, static_cast<std::int64_t>(v));
            } else {
              record(spec.key, v);
            }
          } else if constexpr (std::is_same_v<V, std::string>) {
            record(spec.key, spec.kind == ParameterKind::path ? absolute_path(v) : v);
          } else {
            record(spec.key, v);
          }
        },
        *value);
  }
  return value;
}

std::optional<ParameterValue> TomlReader::read_value(const ParameterSpec& spec) {
  const toml::node* node = find(spec.key);
  if (!node) {
    if (spec.required) {
      fail_at(spec.key, fmt::format("missing, expected {} ({})", expected(spec.kind), spec.help));
    }
    if (spec.default_value) return ParameterValue{*spec.default_value};
    return std::nullopt;
  }
  switch (spec.kind) {
    case ParameterKind::number:
    case ParameterKind::integer:
      return ParameterValue{checked_number(key_path(spec.key), *node, spec)};
    case ParameterKind::number_list: {
      const auto* array = node->as_array();
      if (!array)
        fail_at(spec.key, fmt::format("expected an array of numbers, got {}", describe(*node)));
      std::vector<double> values;
      values.reserve(array->size());
      for (std::size_t i = 0; i < array->size(); ++i) {
        values.push_back(
            checked_number(fmt::format("{}[{}]", key_path(spec.key), i), *array->get(i), spec));
      }
      return ParameterValue{std::move(values)};
    }
    case ParameterKind::text:
    case ParameterKind::path: {
      const auto* s = node->as_string();
      if (!s)
        fail_at(spec.key, fmt::format("expected {}, got {}", expected(spec.kind), describe(*node)));
      if (spec.kind == ParameterKind::text) return ParameterValue{s->get()};
      // A path typed on the command line is relative to where it was typed, not to the scene.
      const std::filesystem::path p(s->get());
      const bool typed = from_command_line(spec.key);
      return ParameterValue{(p.is_absolute() || typed ? p : base_dir_ / p).string()};
    }
  }
  return std::nullopt;
}

ParameterValues TomlReader::read_all(const std::vector<ParameterSpec>& specs) {
  ParameterValues values;
  for (const ParameterSpec& spec : specs) {
    if (auto v = read(spec)) values.set(spec.key, std::move(*v));
  }
  return values;
}

double TomlReader::number(const ParameterSpec& spec) {
  ParameterSpec required = spec;
  required.required = true;
  return std::get<double>(*read(required));
}

std::optional<double> TomlReader::optional_number(const ParameterSpec& spec) {
  ParameterSpec optional = spec;
  optional.required = false;
  const auto v = read(optional);
  if (!v) return std::nullopt;
  return std::get<double>(*v);
}

std::int64_t TomlReader::integer(const ParameterSpec& spec) {
  ParameterSpec whole = spec;
  whole.kind = ParameterKind::integer;
  whole.required = true;
  const auto v = read(whole);
  return static_cast<std::int64_t>(std::get<double>(*v));
}

std::optional<std::string> TomlReader::optional_text(std::string_view key) {
  const auto v = read({.key = std::string(key), .kind = ParameterKind::text, .required = false});
  if (!v) return std::nullopt;
  return std::get<std::string>(*v);
}

std::optional<bool> TomlReader::optional_boolean(std::string_view key) {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  const auto* flag = node->as_boolean();
  if (!flag) fail_at(key, fmt::format("expected true or false, got {}", describe(*node)));
  record(key, flag->get());
  return flag->get();
}

std::string TomlReader::name(std::string_view key, const std::vector<std::string>& known,
                             std::optional<std::string> fallback) {
  const auto v = read({.key = std::string(key),
                       .kind = ParameterKind::text,
                       .help = "one of: " + join_names(known),
                       .required = !fallback.has_value()});
  if (!v) {
    record(key, *fallback);
    return *fallback;
  }
  const std::string& given = std::get<std::string>(*v);
  if (std::find(known.begin(), known.end(), given) == known.end()) {
    fail_at(key, fmt::format("unknown '{}'{} (known: {})", printable(given),
                             did_you_mean(given, known), join_names(known)));
  }
  return given;
}

TomlReader TomlReader::table(std::string_view key) {
  auto t = optional_table(key);
  if (!t) fail_at(key, "missing, expected a table");
  return std::move(*t);
}

std::optional<TomlReader> TomlReader::optional_table(std::string_view key) {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  const auto* t = node->as_table();
  if (!t) fail_at(key, fmt::format("expected a table, got {}", describe(*node)));
  return TomlReader(*t, key_path(key), file_, base_dir_,
                    resolved_child(key, nlohmann::json::object()));
}

std::optional<std::vector<TomlReader>> TomlReader::optional_table_array(std::string_view key,
                                                                        std::size_t max_size) {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  const std::string shown = key_path(key);
  const auto* array = node->as_array();
  if (!array) {
    fail_at(key,
            fmt::format("expected an array of tables ([[{}]]), got {}", shown, describe(*node)));
  }
  if (array->empty()) {
    fail_at(key, fmt::format("expected at least one [[{}]] table, got an empty array", shown));
  }
  if (array->size() > max_size) {
    fail_at(key, fmt::format("has {} tables, at most {}", array->size(), max_size));
  }
  std::vector<TomlReader> tables;
  tables.reserve(array->size());
  // Sized before any element is taken: the readers keep pointers into it.
  nlohmann::json* resolved =
      resolved_child(key, nlohmann::json::array_t(array->size(), nlohmann::json::object()));
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    const std::string element_path = fmt::format("{}.{}", shown, i + 1);
    const auto* table = element.as_table();
    if (!table) {
      throw SceneError(fmt::format("{} {}: expected a table, got {}", where(element), element_path,
                                   describe(element)));
    }
    tables.emplace_back(*table, element_path, file_, base_dir_,
                        resolved ? &(*resolved)[i] : nullptr);
  }
  return tables;
}

std::optional<std::pair<const toml::key*, const toml::node*>> TomlReader::first_key_outside(
    const std::set<std::string, std::less<>>& keys) const {
  std::optional<std::pair<const toml::key*, const toml::node*>> first;
  for (auto&& [key, node] : *table_) {
    if (keys.count(key.str()) != 0) continue;
    if (!first || before(key.source().begin, first->first->source().begin)) first = {&key, &node};
  }
  return first;
}

void TomlReader::check_keys(
    const std::vector<std::string>& known,
    const std::function<std::optional<std::string>(std::string_view)>& explain) {
  known_.insert(known.begin(), known.end());
  const auto first = first_key_outside(known_);
  if (!first) return;
  if (explain) {
    if (const auto message = explain(first->first->str())) fail_at(first->first->str(), *message);
  }
  fail_unknown(*first->first, *first->second);
}

void TomlReader::finish() const {
  const auto first = first_key_outside(read_);
  if (!first) return;
  if (known_.count(first->first->str()) == 0) fail_unknown(*first->first, *first->second);
  // A declared key that these settings never read: a safety net, the builder says why first.
  fail_at(first->first->str(), "does not apply with these settings");
}

bool TomlReader::from_command_line(std::string_view key) const {
  const toml::node* node = table_->get(key);
  if (!node) return false;
  const auto& path = node->source().path;
  return path && (*path == "--set" || *path == "--vary");
}

std::vector<std::string> TomlReader::keys_from_scene() const {
  std::vector<std::string> keys;
  for (auto&& [key, node] : *table_) {
    if (!from_command_line(key.str())) keys.emplace_back(key.str());
  }
  return keys;
}

void TomlReader::ignore(std::string_view key) { read_.emplace(key); }

}  // namespace mdrsim
