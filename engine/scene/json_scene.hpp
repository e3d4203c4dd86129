// A scene written as JSON: the `scene` of a result of `mdrsim run --json`, or a scene itself.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace mdrsim {

/// Whether scene text is JSON: its first non-blank character opens an object, which no TOML
/// document can start with.
bool is_json_text(std::string_view text);

/// The scene table of a JSON document: its `scene` member when it has one (a result), else the
/// document itself. Objects become tables, arrays of objects arrays of tables ([[...]]), and
/// numbers keep their kind (1000 a whole number, 1000.0 a real). Throws SceneError naming
/// `source_name`; its nodes carry no line, so messages name the file alone.
toml::table json_scene_table(std::string_view text, const std::string& source_name);

}  // namespace mdrsim
