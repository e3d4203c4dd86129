// The contract one scene text must keep, shared by the fuzz target and its regression tests.
#pragma once

#include <string>
#include <string_view>

namespace mdrsim::test {

struct SceneCheck {
  enum class Outcome {
    refused,  ///< bad input: SceneError, as docs wants (exit code 2)
    ran,      ///< a run to a status with finite numbers
    broken,   ///< anything else: another exception, or a number that is not finite
  };
  Outcome outcome;
  std::string why;  ///< for broken: what happened
};

/// Builds the scene text with the built-in parts and runs it as `mdrsim run` would, with the
/// run's length capped (springs, steps and rtol: see scene_check.cpp). Never throws.
SceneCheck check_scene_text(std::string_view text);

}  // namespace mdrsim::test
