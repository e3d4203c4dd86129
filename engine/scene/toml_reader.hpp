// A typed reader over one TOML table: range-checked reads, file:line:col in every message,
// and keys never read reported as unknown.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/base/parameters.hpp"

namespace mdrsim {

class TomlReader {
 public:
  /// `path` is the dotted key of the table ("" for the root); `file` names the document;
  /// `base_dir` resolves relative file paths.
  TomlReader(const toml::table& table, std::string path, std::string file,
             std::filesystem::path base_dir);

  bool has(std::string_view key) const { return table_->contains(key); }

  /// Reads a declared parameter; absent and not required gives its default or nullopt.
  std::optional<ParameterValue> read(const ParameterSpec& spec);
  /// Reads every declared parameter of a part.
  ParameterValues read_all(const std::vector<ParameterSpec>& specs);

  double number(const ParameterSpec& spec);
  std::optional<double> optional_number(const ParameterSpec& spec);
  std::int64_t integer(const ParameterSpec& spec);
  std::optional<std::string> optional_text(std::string_view key);
  /// A name from `known`; `fallback` when absent (nullopt makes it required).
  std::string name(std::string_view key, const std::vector<std::string>& known,
                   std::optional<std::string> fallback = std::nullopt);

  TomlReader table(std::string_view key);
  std::optional<TomlReader> optional_table(std::string_view key);

  /// Declares every key this table may hold and fails on the first other key (in file order),
  /// so that a typo is reported before any value is checked.
  /// `explain` may give a better message than "unknown key" for a key it recognises.
  void check_keys(const std::vector<std::string>& known,
                  const std::function<std::optional<std::string>(std::string_view)>& explain = {});
  /// Fails on the first key (in file order) that no read asked for.
  void finish() const;

  [[noreturn]] void fail_at(std::string_view key, const std::string& message) const;
  [[noreturn]] void fail_range(std::string_view key, const std::string& message) const;
  [[noreturn]] void fail(const std::string& message) const;
  std::string key_path(std::string_view key) const;

 private:
  const toml::node* find(std::string_view key);
  /// The first key in file order that is not in `keys`, with its value.
  std::optional<std::pair<const toml::key*, const toml::node*>> first_key_outside(
      const std::set<std::string, std::less<>>& keys) const;
  std::string where(const toml::source_region& source) const;
  std::string where(const toml::node& node) const { return where(node.source()); }
  /// The table itself: its header, or the file alone for the root table.
  std::string where_table() const;
  [[noreturn]] void fail_unknown(const toml::key& key, const toml::node& node) const;
  /// `shown` names the value in messages: the key, or key[i] for an array element.
  double checked_number(const std::string& shown, const toml::node& node,
                        const ParameterSpec& spec) const;

  const toml::table* table_;
  std::string path_;
  std::string file_;
  std::filesystem::path base_dir_;
  std::set<std::string, std::less<>> read_;   ///< keys present and read
  std::set<std::string, std::less<>> asked_;  ///< keys asked for, present or not
  std::set<std::string, std::less<>> known_;  ///< keys declared by check_keys
};

}  // namespace mdrsim
