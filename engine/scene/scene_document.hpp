// A scene file as parsed TOML plus command-line overrides; builds the Scene it describes.
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

struct SceneOverride;

class SceneDocument {
 public:
  /// Reads and parses a scene file, TOML or JSON (from_scene_text); throws SceneError naming
  /// the file (and line).
  static SceneDocument from_file(const std::filesystem::path& path);
  /// Reads a scene from an open stream (standard input) up to its end, as from_file.
  static SceneDocument from_stream(std::FILE* stream, const std::string& source_name,
                                   const std::filesystem::path& base_dir = ".");
  /// Parses TOML scene text; `source_name` stands for the file in messages.
  static SceneDocument from_text(std::string_view text, const std::string& source_name,
                                 const std::filesystem::path& base_dir = ".");
  /// TOML, or JSON when the text starts with '{': a scene as an object, or a result of
  /// `mdrsim run --json`, whose `scene` member is read (engine/scene/json_scene.hpp).
  static SceneDocument from_scene_text(std::string_view text, const std::string& source_name,
                                       const std::filesystem::path& base_dir = ".");

  SceneDocument(const SceneDocument& other);
  SceneDocument& operator=(const SceneDocument& other);
  SceneDocument(SceneDocument&&) noexcept;
  SceneDocument& operator=(SceneDocument&&) noexcept;
  ~SceneDocument();

  /// `--set KEY=VALUE`: VALUE is a TOML value; a bare word is taken as a string. A key of a
  /// group of exclusive keys (springs or rtol, the preload's depth, force or contact_radius,
  /// ...: docs/scene.md "Changing values from the command line") removes the others of its table.
  void set_value(std::string_view dotted_key, std::string_view value_text);
  /// `--vary`: sets a number at a dotted key; `origin` names the flag in messages.
  void set_number(std::string_view dotted_key, double value, std::string_view origin);

  /// Checks every key and value and creates the parts; throws SceneError on bad input.
  Scene build(const Registries& registries) const;

  const std::string& source_name() const;
  /// The scene's values as TOML text, overrides applied: what from_text reads back to the same
  /// scene (comments and layout are not kept).
  std::string to_toml() const;

 private:
  struct Impl;
  explicit SceneDocument(std::unique_ptr<Impl> impl);
  void remember(const SceneOverride& override_value);
  std::unique_ptr<Impl> impl_;
};

/// The message for a --set value that opens an inline table or array and is not one, as the
/// shell leaves an unquoted value it has split at spaces; nullopt for any other value.
std::optional<std::string> split_value_message(std::string_view dotted_key,
                                               std::string_view value_text);

}  // namespace mdrsim
