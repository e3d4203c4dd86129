// Bad input from a measured file: one line naming the file and what is wrong (exit code 2).
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <string>
#include <utility>

#include "engine/scene/scene_error.hpp"

namespace mdrsim::measured {

/// A SceneError, so the command maps it to exit 2 like any other bad input.
class MeasuredFileError : public SceneError {
 public:
  using SceneError::SceneError;
};

/// "path: what" as a MeasuredFileError, the path as the caller gave it.
template <typename... Args>
[[noreturn]] void refuse(const std::filesystem::path& path, fmt::format_string<Args...> what,
                         Args&&... args) {
  throw MeasuredFileError(
      fmt::format("{}: {}", printable(path.string(), 300),
                  printable(fmt::format(what, std::forward<Args>(args)...), 300)));
}

}  // namespace mdrsim::measured
