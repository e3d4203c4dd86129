// A scene file as parsed TOML plus command-line overrides; builds the Scene it describes.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

struct SceneOverride;

class SceneDocument {
 public:
  /// Reads and parses a scene file; throws SceneError naming the file (and line).
  static SceneDocument from_file(const std::filesystem::path& path);
  /// Parses scene text; `source_name` stands for the file in messages.
  static SceneDocument from_text(std::string_view text, const std::string& source_name,
                                 const std::filesystem::path& base_dir = ".");

  SceneDocument(const SceneDocument& other);
  SceneDocument& operator=(const SceneDocument& other);
  SceneDocument(SceneDocument&&) noexcept;
  SceneDocument& operator=(SceneDocument&&) noexcept;
  ~SceneDocument();

  /// `--set KEY=VALUE`: VALUE is a TOML value; a bare word is taken as a string.
  void set_value(std::string_view dotted_key, std::string_view value_text);
  /// `--vary`: sets a number at a dotted key; `origin` names the flag in messages.
  void set_number(std::string_view dotted_key, double value, std::string_view origin);

  /// Checks every key and value and creates the parts; throws SceneError on bad input.
  Scene build(const Registries& registries) const;

  const std::string& source_name() const;

 private:
  struct Impl;
  explicit SceneDocument(std::unique_ptr<Impl> impl);
  void remember(const SceneOverride& override_value);
  std::unique_ptr<Impl> impl_;
};

}  // namespace mdrsim
