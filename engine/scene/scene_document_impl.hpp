// The parsed TOML behind a SceneDocument, shared by the document and the scene builder.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {

/// One --set or --vary value, kept so that a copy of the document can replay it.
struct SceneOverride {
  std::string origin;              ///< "--set" or "--vary", the source of its nodes
  std::vector<std::string> parts;  ///< the dotted key, split
  std::string value_toml;          ///< the value as TOML text
};

struct SceneDocument::Impl {
  std::string text;   ///< the scene file as read: copies re-parse it
  bool json = false;  ///< text is JSON (json_scene.hpp), not TOML
  std::string source_name;
  std::filesystem::path base_dir;
  std::vector<SceneOverride> overrides;
  toml::table root;  ///< nodes carry their file line:col, or --set/--vary as their path
};

/// Reads the whole scene out of the table (scene_builder.cpp).
Scene build_scene(const toml::table& root, const std::string& source_name,
                  const std::filesystem::path& base_dir, const Registries& registries);

}  // namespace mdrsim
