// The scene from a file or standard input, and its --set KEY=VALUE overrides, checked like the
// file itself once the scene is built.
#include "apps/scene_input.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {

SceneDocument load_scene_document(const std::string& path, const std::vector<std::string>& sets) {
  if (path.empty()) throw UsageError("mdrsim: the scene file path is empty");
  SceneDocument document = path == "-" ? SceneDocument::from_stream(stdin, kStandardInputName, ".")
                                       : SceneDocument::from_file(path);
  for (const std::string& set : sets) {
    const auto eq = set.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw UsageError(fmt::format("--set: '{}' is not KEY=VALUE", set));
    }
    document.set_value(std::string_view(set).substr(0, eq), std::string_view(set).substr(eq + 1));
  }
  return document;
}

}  // namespace mdrsim::cli
