// The work a run did, counted by the methods: detachments, steps, halvings, root iterations.
#pragma once

#include <cstdint>

namespace mdrsim {

struct RunCounts {
  std::int64_t events = 0;           ///< springs detached
  std::int64_t steps = 0;            ///< stepping increments taken
  std::int64_t halvings = 0;         ///< stepping increments halved
  std::int64_t root_iterations = 0;  ///< iterations of let-go root searches

  RunCounts& operator+=(const RunCounts& more) {
    events += more.events;
    steps += more.steps;
    halvings += more.halvings;
    root_iterations += more.root_iterations;
    return *this;
  }
};

}  // namespace mdrsim
