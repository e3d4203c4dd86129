// A bad command line: exit code 2 with one line naming the flag.
#pragma once

#include <stdexcept>

namespace mdrsim::cli {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mdrsim::cli
