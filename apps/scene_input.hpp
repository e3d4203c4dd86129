// Loading the scene named on the command line (a file, or - for standard input) and applying
// its --set overrides.
#pragma once

#include <string>
#include <vector>

#include "engine/scene/scene_document.hpp"

namespace mdrsim::cli {

/// The source name of a scene read from standard input, as messages show it.
inline constexpr const char* kStandardInputName = "<stdin>";

/// `path` "-" reads standard input (TOML or JSON; relative paths in it are relative to the
/// working directory).
SceneDocument load_scene_document(const std::string& path, const std::vector<std::string>& sets);

}  // namespace mdrsim::cli
