// Parsing scene files and applying --set / --vary overrides at dotted keys.
#include "engine/scene/scene_document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "engine/base/text.hpp"
#include "engine/scene/json_scene.hpp"
#include "engine/scene/number_underflow.hpp"
#include "engine/scene/scene_document_impl.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

/// Scene files are small; the cap keeps /dev/zero or a mistyped data file from eating memory.
constexpr std::size_t kMaxSceneBytes = 16u << 20;

std::vector<std::string> split_key(std::string_view origin, std::string_view dotted) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = dotted.find('.', start);
    const std::string_view part =
        dotted.substr(start, dot == std::string_view::npos ? dotted.npos : dot - start);
    if (part.empty()) {
      throw SceneError(fmt::format("{}: '{}' is not a dotted scene key like material.poisson_ratio",
                                   origin, printable(dotted)));
    }
    parts.emplace_back(part);
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

std::string join_key(const std::vector<std::string>& parts) {
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : ".") + p;
  return out;
}

/// The dotted key of the first `count` parts.
std::string key_prefix(const std::vector<std::string>& parts, std::size_t count) {
  return join_key(std::vector<std::string>(parts.begin(), parts.begin() + count));
}

/// An element number as loading.stage.N writes it: digits only.
bool is_element_number(std::string_view part) {
  return !part.empty() && std::all_of(part.begin(), part.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
}

/// An array that a dotted key may index by element number: an array of tables, such as
/// [[loading.stage]] (an empty one, so that the message can say it has none).
bool is_indexable(const toml::node& node) {
  const auto* array = node.as_array();
  return array != nullptr && (array->empty() || array->is_array_of_tables());
}

/// The index of the element that parts[i] names (N from 1) in the array at parts[0..i).
std::size_t element_index(const toml::array& array, const std::vector<std::string>& parts,
                          std::size_t i, std::string_view origin) {
  const std::string array_key = printable(key_prefix(parts, i));
  const auto fail = [&](const std::string& why) {
    throw SceneError(fmt::format("{}: {}: {}", origin, printable(join_key(parts)), why));
  };
  if (array.empty()) fail(fmt::format("the scene has no [[{}]]", array_key));
  const std::size_t count = array.size();
  const std::string range = count == 1 ? fmt::format("{}.1", array_key)
                                       : fmt::format("{}.1 to {}.{}", array_key, array_key, count);
  const std::string has =
      fmt::format("the scene has {} ({})", counted(count, printable(parts[i - 1])), range);
  const std::string& part = parts[i];
  if (!is_element_number(part)) {
    fail(fmt::format("'{}' is not a {} number; {}", printable(part), printable(parts[i - 1]), has));
  }
  std::size_t number = 0;
  const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), number);
  if (error != std::errc{} || end != part.data() + part.size() || number < 1 || number > count) {
    fail(has);
  }
  return number - 1;
}

/// Walks to the node that holds the last part of a dotted key: a table, or an array of tables
/// when the last part is an element number. With `create`, missing tables are inserted;
/// without, the walk only checks, so that a refused key leaves the document unchanged.
toml::node* walk_to_parent(toml::table& root, const std::vector<std::string>& parts,
                           std::string_view origin, bool create) {
  toml::node* node = &root;  // nullptr below a table that is not there yet
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* next = nullptr;
    if (auto* array = node ? node->as_array() : nullptr) {
      next = array->get(element_index(*array, parts, i, origin));
    } else if (node) {
      next = node->as_table()->get(parts[i]);
    }
    if (!next) {
      // A table made at a key followed by a number would hide a missing [[key]].
      if (is_element_number(parts[i + 1])) {
        throw SceneError(fmt::format("{}: {}: the scene has no [[{}]]", origin,
                                     printable(join_key(parts)),
                                     printable(key_prefix(parts, i + 1))));
      }
      if (create) next = &node->as_table()->insert_or_assign(parts[i], toml::table{}).first->second;
    }
    if (next && !next->is_table() && !is_indexable(*next)) {
      throw SceneError(fmt::format("{}: {}: '{}' is not a table", origin,
                                   printable(join_key(parts)), printable(parts[i])));
    }
    node = next;
  }
  return node;
}

/// Parses "v = VALUE" with `origin` as the source of its nodes; throws toml::parse_error.
toml::table parse_value(const std::string& value_toml, const std::string& origin) {
  return toml::parse("v = " + value_toml, origin);
}

/// Keys of one table that exclude each other: setting a key of one group from the command line
/// removes the keys of the table's other groups (docs/scene.md "Changing values from the command
/// line"). In `table`, "N" stands for a stage number.
struct ExclusiveKeys {
  std::string_view table;
  std::vector<std::vector<std::string_view>> groups;
};

const std::vector<ExclusiveKeys>& exclusive_keys() {
  static const std::vector<ExclusiveKeys> table{
      {"material",
       {{"youngs_modulus", "poisson_ratio"}, {"effective_modulus", "effective_shear_modulus"}}},
      {"material", {{"adhesive_stress"}, {"maugis_parameter"}}},
      {"profile", {{"file"}, {"r", "f"}}},
      {"loading.preload", {{"depth"}, {"force"}, {"contact_radius"}}},
      {"loading.tangential", {{"displacement"}, {"force"}}},
      {"loading.stage.N.normal", {{"to"}, {"by"}}},
      {"loading.stage.N.tangential", {{"to"}, {"by"}}},
      {"loading.stage.N", {{"duration"}, {"speed"}}},
      {"discretization", {{"springs"}, {"rtol"}}},
  };
  return table;
}

/// Whether the first `count` parts of a dotted key spell `pattern`, "N" matching a number.
bool names_table(const std::vector<std::string>& parts, std::size_t count,
                 std::string_view pattern) {
  std::size_t i = 0;
  for (; i < count; ++i) {
    const std::size_t dot = pattern.find('.');
    const std::string_view head = pattern.substr(0, dot);
    if (!(head == parts[i] || (head == "N" && is_element_number(parts[i])))) return false;
    if (dot == std::string_view::npos) return i + 1 == count;
    pattern.remove_prefix(dot + 1);
  }
  return false;
}

/// Removes from `table` the keys that exclude the key `parts.back()`.
void drop_exclusive_siblings(toml::table& table, const std::vector<std::string>& parts) {
  const std::string& key = parts.back();
  for (const ExclusiveKeys& entry : exclusive_keys()) {
    if (!names_table(parts, parts.size() - 1, entry.table)) continue;
    const auto own = std::find_if(entry.groups.begin(), entry.groups.end(), [&](const auto& g) {
      return std::find(g.begin(), g.end(), key) != g.end();
    });
    if (own == entry.groups.end()) continue;
    for (auto group = entry.groups.begin(); group != entry.groups.end(); ++group) {
      if (group == own) continue;
      for (const std::string_view other : *group) table.erase(other);
    }
  }
}

void apply(toml::table& root, const SceneOverride& o) {
  walk_to_parent(root, o.parts, o.origin, false);
  toml::node& parent = *walk_to_parent(root, o.parts, o.origin, true);
  if (auto* table = parent.as_table()) drop_exclusive_siblings(*table, o.parts);
  toml::table parsed = parse_value(o.value_toml, o.origin);
  // Moved, not copied: a moved node keeps its source, so messages name the flag.
  if (auto* array = parent.as_array()) {
    const auto index = element_index(*array, o.parts, o.parts.size() - 1, o.origin);
    parsed.get("v")->visit([&](auto&& node) {
      array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(index), std::move(node));
    });
  } else {
    parsed.get("v")->visit(
        [&](auto&& node) { parent.as_table()->insert_or_assign(o.parts.back(), std::move(node)); });
  }
}

/// " = 1e400 is beyond the range of a double (...)" where `literal` is a TOML number too large
/// for a double or a whole number too large for 64 bits, which toml++ refuses without naming the
/// key ("could not be interpreted as a value"); else nullopt.
std::optional<std::string> beyond_range(std::string_view literal) {
  std::string digits;
  for (const char c : literal) {
    if (c != '_') digits += c;
  }
  if (digits.empty() || digits.find_first_not_of("0123456789+-.eE") != std::string::npos) {
    return std::nullopt;
  }
  const std::string shown = printable(literal);
  if (digits.find_first_not_of("0123456789+-") == std::string::npos) {
    std::int64_t whole = 0;
    const char* first = digits.c_str() + (digits.front() == '+' ? 1 : 0);
    const auto [end, error] = std::from_chars(first, digits.c_str() + digits.size(), whole);
    if (error != std::errc::result_out_of_range) return std::nullopt;
    return fmt::format(" = {} is beyond the range of a 64-bit whole number", shown);
  }
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(digits.c_str(), &end);
  if (end != digits.c_str() + digits.size() || errno != ERANGE || std::isfinite(value)) {
    return std::nullopt;
  }
  return fmt::format(" = {} is beyond the range of a double (largest 1.8e308)", shown);
}

/// The dotted key of the value that begins at `at` under `node` (at `path`), as the reader
/// names it: tables of an array of tables .N from 1, other array elements [i] from 0.
std::optional<std::string> key_at(const toml::node& node, const toml::source_position& at,
                                  const std::string& path) {
  if (node.source().begin == at && !node.is_table() && !node.is_array()) return path;
  const auto join = [&](const std::string& key) { return path.empty() ? key : path + "." + key; };
  if (const auto* table = node.as_table()) {
    for (const auto& [key, value] : *table) {
      if (auto found = key_at(value, at, join(std::string(key.str())))) return found;
    }
  } else if (const auto* array = node.as_array()) {
    for (std::size_t i = 0; i < array->size(); ++i) {
      const toml::node& element = *array->get(i);
      const std::string shown =
          element.is_table() ? fmt::format("{}.{}", path, i + 1) : fmt::format("{}[{}]", path, i);
      if (auto found = key_at(element, at, shown)) return found;
    }
  }
  return std::nullopt;
}

/// A number TOML refused for its size alone: where it begins, its key and what is wrong.
struct NumberBeyondRange {
  toml::source_position at;
  std::string key;
  std::string message;  ///< " = 1e400 is beyond ..."
};

/// For a parse error at a number beyond range (beyond_range): its key, found by parsing the
/// text again with such numbers read as inf. nullopt for any other parse error.
std::optional<NumberBeyondRange> number_beyond_range(std::string text,
                                                     const std::string& source_name,
                                                     toml::source_position error) {
  const auto number_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '+' ||
           c == '-';
  };
  std::optional<NumberBeyondRange> first;
  // Each number beyond range becomes inf (a later one in the same text too), until TOML reads it.
  for (int replaced = 0; replaced < 64 && error.line != 0; ++replaced) {
    std::size_t line_start = 0;
    for (std::size_t line = 1; line < error.line && line_start != std::string::npos; ++line) {
      line_start = text.find('\n', line_start);
      if (line_start != std::string::npos) ++line_start;
    }
    if (line_start == std::string::npos) return std::nullopt;
    const std::size_t line_end = std::min(text.find('\n', line_start), text.size());
    std::size_t begin = std::min(line_start + error.column - 1, line_end);
    while (begin > line_start && number_char(text[begin - 1])) --begin;
    std::size_t end = begin;
    while (end < line_end && number_char(text[end])) ++end;
    const std::string literal = text.substr(begin, end - begin);
    std::optional<std::string> message = beyond_range(literal);
    if (!message) return std::nullopt;
    if (!first) {
      first =
          NumberBeyondRange{{error.line, static_cast<toml::source_index>(begin - line_start + 1)},
                            "",
                            std::move(*message)};
    }
    text.replace(begin, end - begin, literal.front() == '-' ? "-inf" : "inf");
    try {
      const toml::table root = toml::parse(text, source_name);
      std::optional<std::string> key = key_at(root, first->at, "");
      if (!key) return std::nullopt;
      first->key = std::move(*key);
      return first;
    } catch (const toml::parse_error& e) {
      error = e.source().begin;
    }
  }
  return std::nullopt;
}

toml::table parse_scene(const std::string& text, const std::string& source_name) {
  try {
    toml::table root = toml::parse(text, source_name);
    if (const auto under = find_number_underflow(root, text)) {
      throw SceneError(fmt::format("{}:{}:{}: {}{}", source_name, under->at.line, under->at.column,
                                   printable(under->key), under->message));
    }
    return root;
  } catch (const toml::parse_error& e) {
    if (const auto beyond = number_beyond_range(text, source_name, e.source().begin)) {
      throw SceneError(fmt::format("{}:{}:{}: {}{}", source_name, beyond->at.line,
                                   beyond->at.column, printable(beyond->key), beyond->message));
    }
    const auto& begin = e.source().begin;
    const std::string where = begin.line == 0
                                  ? source_name + ":"
                                  : fmt::format("{}:{}:{}:", source_name, begin.line, begin.column);
    throw SceneError(fmt::format("{} malformed TOML: {}", where,
                                 printable(lowercase_first(std::string(e.description())), 200)));
  }
}

toml::table parse_document(const std::string& text, const std::string& source_name, bool json) {
  return json ? json_scene_table(text, source_name) : parse_scene(text, source_name);
}

/// Reads `file` to its end, within the size cap; `fail` throws with the reason.
template <class Fail>
std::string read_capped(std::FILE* file, const Fail& fail) {
  std::string text;
  char buffer[1 << 16];
  while (true) {
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, file);
    text.append(buffer, n);
    if (text.size() > kMaxSceneBytes) fail("it is larger than 16 MiB");
    if (n < sizeof buffer) break;
  }
  if (std::ferror(file)) fail(system_reason(errno));
  return text;
}

/// Whether TOML reads `value` as one value.
bool is_toml_value(std::string_view value, const std::string& origin) {
  try {
    parse_value(std::string(value), origin);
    return true;
  } catch (const toml::parse_error&) {
    return false;
  }
}

/// "name=": the start of one key-value pair of an inline table, which no scene value has.
bool starts_with_pair(std::string_view value) {
  const auto eq = value.find('=');
  return eq != std::string_view::npos && eq > 0 &&
         std::all_of(value.begin(), value.begin() + static_cast<std::ptrdiff_t>(eq), [](char c) {
           return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
         });
}

}  // namespace

std::optional<std::string> split_value_message(std::string_view dotted_key,
                                               std::string_view value_text) {
  const std::string_view value = trim_blanks(value_text);
  if (value.empty() || is_toml_value(value, "--set")) return std::nullopt;
  std::string what;
  if (value.front() == '{' || value.front() == '[') {
    what = fmt::format("is not a whole TOML {}", value.front() == '{' ? "inline table" : "array");
  } else if (starts_with_pair(value)) {
    what = "is a piece of an inline table";
  } else {
    return std::nullopt;
  }
  const std::string key = printable(trim_blanks(dotted_key));
  return fmt::format(
      "--set: {}: '{}' {}: unquoted, the shell splits a value at spaces, expands {{a,b}} and "
      "drops quotes; quote the whole KEY=VALUE, as in --set '{}={{ ... }}'",
      key, printable(value), what, key);
}

SceneDocument::SceneDocument(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

// toml++ does not copy source regions, so a copy re-parses the text and replays the
// overrides: messages from a copy still name the line or the flag.
SceneDocument::SceneDocument(const SceneDocument& other) : impl_(std::make_unique<Impl>()) {
  impl_->text = other.impl_->text;
  impl_->json = other.impl_->json;
  impl_->source_name = other.impl_->source_name;
  impl_->base_dir = other.impl_->base_dir;
  impl_->overrides = other.impl_->overrides;
  impl_->root = parse_document(impl_->text, impl_->source_name, impl_->json);
  for (const auto& o : impl_->overrides) apply(impl_->root, o);
}

SceneDocument& SceneDocument::operator=(const SceneDocument& other) {
  if (this != &other) *this = SceneDocument(other);
  return *this;
}
SceneDocument::SceneDocument(SceneDocument&&) noexcept = default;
SceneDocument& SceneDocument::operator=(SceneDocument&&) noexcept = default;
SceneDocument::~SceneDocument() = default;

const std::string& SceneDocument::source_name() const { return impl_->source_name; }

std::string SceneDocument::to_toml() const {
  std::ostringstream out;
  out << toml::toml_formatter(impl_->root);
  out << '\n';
  return out.str();
}

SceneDocument SceneDocument::from_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  const auto fail = [&](const std::string& why) {
    throw SceneError(fmt::format("{}: cannot read the scene file ({})", name, why));
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail("it is a directory");
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) fail(system_reason(errno));
  const std::string text = read_capped(file.get(), fail);
  return from_scene_text(text, name, path.parent_path().empty() ? "." : path.parent_path());
}

SceneDocument SceneDocument::from_stream(std::FILE* stream, const std::string& source_name,
                                         const std::filesystem::path& base_dir) {
  const auto fail = [&](const std::string& why) {
    throw SceneError(fmt::format("{}: cannot read the scene ({})", source_name, why));
  };
  return from_scene_text(read_capped(stream, fail), source_name, base_dir);
}

SceneDocument SceneDocument::from_scene_text(std::string_view text, const std::string& source_name,
                                             const std::filesystem::path& base_dir) {
  if (!is_json_text(text)) return from_text(text, source_name, base_dir);
  auto impl = std::make_unique<Impl>();
  impl->text = std::string(text);
  impl->json = true;
  impl->source_name = source_name;
  impl->base_dir = base_dir;
  impl->root = json_scene_table(impl->text, source_name);
  return SceneDocument(std::move(impl));
}

SceneDocument SceneDocument::from_text(std::string_view text, const std::string& source_name,
                                       const std::filesystem::path& base_dir) {
  auto impl = std::make_unique<Impl>();
  impl->text = std::string(text);
  impl->source_name = source_name;
  impl->base_dir = base_dir;
  impl->root = parse_scene(impl->text, source_name);
  return SceneDocument(std::move(impl));
}

void SceneDocument::set_value(std::string_view dotted_key, std::string_view value_text) {
  const std::string origin = "--set";
  const auto parts = split_key(origin, trim_blanks(dotted_key));
  const std::string key = printable(join_key(parts));
  const std::string_view value = trim_blanks(value_text);
  if (value.empty()) throw SceneError(fmt::format("{}: {}: the value is empty", origin, key));
  if (std::any_of(value.begin(), value.end(), [](char c) {
        return (static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f;
      })) {
    throw SceneError(fmt::format("{}: {}: the value must be one line of text", origin, key));
  }
  std::string value_toml(value);
  try {
    parse_value(value_toml, origin);
  } catch (const toml::parse_error& e) {
    // A number too large, also inside an inline table: "v" is the key.
    if (const auto beyond = number_beyond_range("v = " + value_toml, origin, e.source().begin)) {
      throw SceneError(fmt::format("{}: {}{}{}", origin, key, printable(beyond->key.substr(1)),
                                   beyond->message));
    }
  }
  if (const auto split = split_value_message(key, value)) throw SceneError(*split);
  try {
    const toml::table parsed = parse_value(value_toml, origin);
    if (parsed.size() != 1) throw SceneError(fmt::format("{}: {}: not one value", origin, key));
    if (const auto under = find_number_underflow(parsed, "v = " + value_toml)) {
      throw SceneError(
          fmt::format("{}: {}{}{}", origin, key, printable(under->key.substr(1)), under->message));
    }
  } catch (const toml::parse_error&) {
    // A bare word such as fixed-load: read it as a TOML string.
    std::string quoted(1, '"');
    for (const char c : value) {
      if (c == '"' || c == '\\') quoted += '\\';
      quoted += c;
    }
    quoted += '"';
    value_toml = std::move(quoted);
    try {
      parse_value(value_toml, origin);
    } catch (const toml::parse_error& e) {
      throw SceneError(fmt::format("{}: {}: cannot read value '{}' ({})", origin, key,
                                   printable(value), printable(std::string(e.description()))));
    }
  }
  const SceneOverride o{origin, parts, value_toml};
  apply(impl_->root, o);
  remember(o);
}

void SceneDocument::set_number(std::string_view dotted_key, double value, std::string_view origin) {
  const std::string from(origin);
  if (!std::isfinite(value)) {
    throw SceneError(
        fmt::format("{}: {} = {} is not a finite number", from, printable(dotted_key), value));
  }
  const SceneOverride o{from, split_key(from, trim_blanks(dotted_key)),
                        fmt::format("{:.17g}", value)};
  apply(impl_->root, o);
  remember(o);
}

void SceneDocument::remember(const SceneOverride& o) {
  // A later value at the same key replaces an earlier one, so a sweep's copies stay small.
  auto& list = impl_->overrides;
  list.erase(std::remove_if(list.begin(), list.end(),
                            [&](const SceneOverride& x) { return x.parts == o.parts; }),
             list.end());
  list.push_back(o);
}

Scene SceneDocument::build(const Registries& registries) const {
  return build_scene(impl_->root, impl_->source_name, impl_->base_dir, registries);
}

}  // namespace mdrsim
