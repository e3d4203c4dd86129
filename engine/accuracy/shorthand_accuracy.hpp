// The shorthand's stages, jumps and works estimated as a program's (path_estimates.hpp): from
// its Richardson rows, or refined across the glued radius under rtol.
#pragma once

#include <vector>

#include "engine/base/zero_scale.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Richardson's rows of N/2, N and 2N springs across the glued radius, each with its path
/// recorded (RowSpec::record_path), combined into `result` (the finest row, its critical
/// point and peak already combined by RowSequence): every stage end, jump and work by the
/// rule programs use, with its estimate, and `covers` listing them. Rows that end differently
/// along the path leave the finest row's values without estimates, and a warning says so.
/// `scene`: its controllers, by which each row's works are carried to the located ends.
void combine_shorthand_path(const Scene& scene, std::vector<RunResult> rows, RunResult& result);

/// Under rtol: rows of 512, 1024, ... springs across the glued radius with their paths
/// recorded, doubled until every stage end's, jump's and work's estimate meets rtol (the
/// critical point and peak stay as the zoom refined them); their values and estimates go into
/// `result`. Where they do not meet it, a warning says which and `covers` leaves them out.
/// `ran`: rows across the glued radius with their paths recorded that the critical point's
/// refinement already ran (run_adaptive's glued_rows): a path row of the same springs is taken
/// from them rather than run again.
void refine_shorthand_path(const Scene& scene, double rtol, RunResult& result,
                           std::vector<RunResult> ran = {});

}  // namespace mdrsim
