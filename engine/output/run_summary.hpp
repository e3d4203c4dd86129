// The human summary of `mdrsim run`: one line each for the status, stages, jumps, accuracy,
// critical point, peak and counts, printed when no --json is asked for.
#pragma once

#include <cstdio>

#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim::cli {

/// Prints the summary of `r` to `out` (the command puts it on standard error when standard
/// output carries the trajectory CSV).
void print_summary(std::FILE* out, const Scene& scene, const RunResult& r);

}  // namespace mdrsim::cli
