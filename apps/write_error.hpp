// An output the command could not write (a full disk, a reader that closed the pipe): exit
// code 1 with one line naming the flag and the reason, not an internal error.
#pragma once

#include <stdexcept>

namespace mdrsim::cli {

class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mdrsim::cli
