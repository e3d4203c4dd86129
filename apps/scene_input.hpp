// Loading the scene file named on the command line and applying its --set overrides.
#pragma once

#include <string>
#include <vector>

#include "engine/scene/scene_document.hpp"

namespace mdrsim::cli {

SceneDocument load_scene_document(const std::string& path, const std::vector<std::string>& sets);

}  // namespace mdrsim::cli
