// Bad input: one line naming the file, line, key and what was expected (exit code 2).
#pragma once

#include <stdexcept>

namespace mdrsim {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mdrsim
