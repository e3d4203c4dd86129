// A typed reader over one TOML table: range-checked reads, file:line:col in every message,
// and keys never read reported as unknown.
#pragma once

#include <fmt/format.h>
#include <toml++/toml.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/base/parameters.hpp"

namespace mdrsim {

class TomlReader {
 public:
  /// `path` is the dotted key of the table ("" for the root); `file` names the document;
  /// `base_dir` resolves relative file paths. With `resolved`, every value read (or its
  /// default) is also written there, at its key, and subtables into nested objects: the
  /// resolved scene of the JSON result.
  TomlReader(const toml::table& table, std::string path, std::string file,
             std::filesystem::path base_dir, nlohmann::json* resolved = nullptr);

  bool has(std::string_view key) const { return table_->contains(key); }
  /// Whether the value at `key` is a table (an inline one, { ... }, or [key]).
  bool holds_table(std::string_view key) const {
    const toml::node* node = table_->get(key);
    return node != nullptr && node->is_table();
  }

  /// Reads a declared parameter; absent and not required gives its default or nullopt.
  std::optional<ParameterValue> read(const ParameterSpec& spec);
  /// Reads every declared parameter of a part.
  ParameterValues read_all(const std::vector<ParameterSpec>& specs);

  double number(const ParameterSpec& spec);
  std::optional<double> optional_number(const ParameterSpec& spec);
  std::int64_t integer(const ParameterSpec& spec);
  std::optional<std::string> optional_text(std::string_view key);
  std::optional<bool> optional_boolean(std::string_view key);
  /// A name from `known`; `fallback` when absent (nullopt makes it required).
  std::string name(std::string_view key, const std::vector<std::string>& known,
                   std::optional<std::string> fallback = std::nullopt);

  TomlReader table(std::string_view key);
  std::optional<TomlReader> optional_table(std::string_view key);
  /// A non-empty array of tables ([[key]]) of at most `max_size` tables: a reader for each,
  /// at the path key.N with N from 1 (as --set names them); nullopt when absent.
  std::optional<std::vector<TomlReader>> optional_table_array(std::string_view key,
                                                              std::size_t max_size);

  /// Writes a value the caller applies itself (a default outside the reads) to the resolved
  /// scene.
  void record(std::string_view key, nlohmann::json value);

  /// Declares every key this table may hold and fails on the first other key (in file order),
  /// so that a typo is reported before any value is checked.
  /// `explain` may give a better message than "unknown key" for a key it recognises.
  void check_keys(const std::vector<std::string>& known,
                  const std::function<std::optional<std::string>(std::string_view)>& explain = {});
  /// Fails on the first key (in file order) that no read asked for.
  void finish() const;

  /// Whether the value at `key` was given on the command line (--set or --vary).
  bool from_command_line(std::string_view key) const;
  /// The keys of this table whose values come from the scene itself, not the command line.
  std::vector<std::string> keys_from_scene() const;
  /// Passes over a key without reading it: neither unknown nor recorded.
  void ignore(std::string_view key);

  [[noreturn]] void fail_at(std::string_view key, const std::string& message) const;
  [[noreturn]] void fail_range(std::string_view key, const std::string& message) const;
  [[noreturn]] void fail(const std::string& message) const;
  /// fail_at's message, for a warning: "file:line:col: key: message".
  std::string message_at(std::string_view key, const std::string& message) const;
  std::string key_path(std::string_view key) const;

 private:
  const toml::node* find(std::string_view key);
  /// read() without recording.
  std::optional<ParameterValue> read_value(const ParameterSpec& spec);
  /// The first key in file order that is not in `keys`, with its value.
  std::optional<std::pair<const toml::key*, const toml::node*>> first_key_outside(
      const std::set<std::string, std::less<>>& keys) const;
  std::string where(const toml::source_region& source) const;
  std::string where(const toml::node& node) const { return where(node.source()); }
  /// The table itself: its header, or the file alone for the root table.
  std::string where_table() const;
  /// A subtable's place in the resolved scene, or nullptr when nothing is recorded.
  nlohmann::json* resolved_child(std::string_view key, nlohmann::json empty);
  [[noreturn]] void fail_unknown(const toml::key& key, const toml::node& node) const;
  /// `shown` names the value in messages: the key, or key[i] for an array element.
  double checked_number(const std::string& shown, const toml::node& node,
                        const ParameterSpec& spec) const;

  const toml::table* table_;
  std::string path_;
  std::string file_;
  std::filesystem::path base_dir_;
  nlohmann::json* resolved_;                  ///< this table in the resolved scene, or nullptr
  std::set<std::string, std::less<>> read_;   ///< keys present and read
  std::set<std::string, std::less<>> asked_;  ///< keys asked for, present or not
  std::set<std::string, std::less<>> known_;  ///< keys declared by check_keys
};

/// Runs a part's factory, turning its complaints into SceneErrors at the right key.
template <class Make>
auto create_part(TomlReader& table, std::string_view name_key, Make make) {
  try {
    return make();
  } catch (const ParameterError& e) {
    table.fail_at(e.key(), e.what());
  } catch (const std::invalid_argument& e) {
    table.fail_at(name_key, e.what());
  }
}

/// The keys of a part's table: its name key and the chosen part's parameters. A key that
/// only another part declares is reported as belonging to that part.
template <class Registry>
void check_part_keys(TomlReader& t, const std::string& name_key, const std::string& chosen,
                     const Registry& registry, std::vector<std::string> extra = {}) {
  std::vector<std::string> known{name_key};
  for (const ParameterSpec& spec : registry.find(chosen)->parameters) known.push_back(spec.key);
  known.insert(known.end(), extra.begin(), extra.end());
  const auto owners_of = [&](std::string_view key) {
    std::string owners;
    for (const std::string& name : registry.names()) {
      for (const ParameterSpec& spec : registry.find(name)->parameters) {
        if (spec.key == key) owners += fmt::format("{}\"{}\"", owners.empty() ? "" : " or ", name);
      }
    }
    return owners;
  };
  // A part switched on the command line leaves the scene's keys of the part it replaces
  // behind: they are passed over, so that --set profile.type=cone needs no new table.
  if (t.from_command_line(name_key)) {
    for (const std::string& key : t.keys_from_scene()) {
      if (std::find(known.begin(), known.end(), key) == known.end() && !owners_of(key).empty()) {
        t.ignore(key);
        known.push_back(key);
      }
    }
  }
  t.check_keys(known, [&](std::string_view key) -> std::optional<std::string> {
    const std::string owners = owners_of(key);
    if (owners.empty()) return std::nullopt;
    return fmt::format("applies to {} = {} only", name_key, owners);
  });
}

}  // namespace mdrsim
