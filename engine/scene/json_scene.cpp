// JSON scene input: parsed with nlohmann::json, converted node by node into TOML.
#include "engine/scene/json_scene.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>

#include "engine/scene/embedded_table.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

using nlohmann::json;

/// Deeper than any scene (loading.stage[i].normal.to is 4): a guard for the recursion below.
constexpr int kMaxDepth = 16;

/// The value at `key` (dotted, for messages) as a TOML node inserted by `insert`: instantiated
/// for the two inserts below only, so that nesting recurses through plain functions.
template <class Insert>
void convert(const json& value, const std::string& key, const std::string& source_name, int depth,
             Insert insert);
toml::array convert_array(const json& array, const std::string& key, const std::string& source_name,
                          int depth);
toml::table convert_object(const json& object, const std::string& key,
                           const std::string& source_name, int depth);

toml::array convert_array(const json& array, const std::string& key, const std::string& source_name,
                          int depth) {
  toml::array out;
  for (std::size_t i = 0; i < array.size(); ++i) {
    convert(array[i], fmt::format("{}[{}]", key, i), source_name, depth,
            [&](auto&& node) { out.push_back(std::forward<decltype(node)>(node)); });
  }
  return out;
}

toml::table convert_object(const json& object, const std::string& key,
                           const std::string& source_name, int depth) {
  toml::table table;
  for (const auto& item : object.items()) {
    // Not a structured binding: clang 14 cannot capture one in the lambda below.
    const std::string name = item.key();
    const json& value = item.value();
    const std::string path = key.empty() ? name : key + "." + name;
    convert(value, path, source_name, depth,
            [&](auto&& node) { table.insert_or_assign(name, std::forward<decltype(node)>(node)); });
  }
  return table;
}

template <class Insert>
void convert(const json& value, const std::string& key, const std::string& source_name, int depth,
             Insert insert) {
  const auto fail = [&](const std::string& why) {
    throw SceneError(fmt::format("{}: {}: {}", source_name, printable(key), why));
  };
  if (depth >= kMaxDepth && (value.is_object() || value.is_array())) {
    fail(fmt::format("nested deeper than {} levels", kMaxDepth));
  }
  switch (value.type()) {
    case json::value_t::object:
      insert(convert_object(value, key, source_name, depth + 1));
      return;
    case json::value_t::array:
      insert(convert_array(value, key, source_name, depth + 1));
      return;
    case json::value_t::string:
      insert(value.get<std::string>());
      return;
    case json::value_t::boolean:
      insert(value.get<bool>());
      return;
    case json::value_t::number_integer:
      insert(value.get<std::int64_t>());
      return;
    case json::value_t::number_unsigned:
      if (value.get<std::uint64_t>() >
          static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        fail(fmt::format("{} is too large a whole number", value.dump()));
      }
      insert(static_cast<std::int64_t>(value.get<std::uint64_t>()));
      return;
    case json::value_t::number_float:
      insert(value.get<double>());
      return;
    case json::value_t::null:
      fail("null is not a scene value");
      return;
    case json::value_t::binary:
    case json::value_t::discarded:
      break;
  }
  fail("not a scene value");
}

}  // namespace

bool is_json_text(std::string_view text) {
  for (const char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) == 0) return c == '{';
  }
  return false;
}

toml::table json_scene_table(std::string_view text, const std::string& source_name) {
  json document;
  try {
    document = json::parse(text);
  } catch (const json::exception& e) {
    // "[json.exception.parse_error.101] parse error at line 1, column 2: ...", or
    // "[json.exception.out_of_range.406] number overflow parsing '1e999'".
    std::string what = e.what();
    if (const auto at = what.find("] "); at != std::string::npos) what.erase(0, at + 2);
    throw SceneError(fmt::format("{}: malformed JSON: {}", source_name, printable(what, 200)));
  }
  if (!document.is_object()) {
    throw SceneError(fmt::format("{}: a JSON scene must be an object", source_name));
  }
  if (const auto scene = document.find("scene"); scene != document.end()) {
    if (!scene->is_object()) {
      throw SceneError(
          fmt::format("{}: scene: expected an object (the scene of a result)", source_name));
    }
    use_embedded_table(*scene, source_name);
    return convert_object(*scene, "", source_name, 1);
  }
  use_embedded_table(document, source_name);
  return convert_object(document, "", source_name, 1);
}

}  // namespace mdrsim
