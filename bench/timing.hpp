// Wall time of one run, robust to noise: the best of three batches of repeated runs.
#pragma once

#include <chrono>

namespace mdrsim::bench {

/// Seconds per call of `run`: each batch repeats it until 20 ms have passed (at least
/// once), and the fastest of three batches is returned; one call only when it takes > 0.2 s.
template <class Run>
double seconds_per_run(Run&& run) {
  using clock = std::chrono::steady_clock;
  double best = 1e300;
  for (int batch = 0; batch < 3; ++batch) {
    const auto start = clock::now();
    int calls = 0;
    double elapsed = 0.0;
    do {
      run();
      ++calls;
      elapsed = std::chrono::duration<double>(clock::now() - start).count();
    } while (elapsed < 0.02);
    best = std::min(best, elapsed / calls);
    if (elapsed > 0.2) break;
  }
  return best;
}

}  // namespace mdrsim::bench
