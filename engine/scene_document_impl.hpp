// The parsed TOML behind a SceneDocument, shared by the document and the scene builder.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <string>

#include "engine/registries.hpp"
#include "engine/scene.hpp"
#include "engine/scene_document.hpp"

namespace mdrsim {

struct SceneDocument::Impl {
  toml::table root;
  std::string source_name;
  std::filesystem::path base_dir;
};

/// Reads the whole scene out of the table (scene_builder.cpp).
Scene build_scene(const toml::table& root, const std::string& source_name,
                  const std::filesystem::path& base_dir, const Registries& registries);

}  // namespace mdrsim
