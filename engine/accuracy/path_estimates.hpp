// Stage ends, jumps and works combined across rows of doubling springs, with their estimates:
// one rule for programs (program_resolution.hpp) and the shorthand (run_scene.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "controllers/controller.hpp"
#include "engine/base/zero_scale.hpp"
#include "engine/pull_off/pull_off.hpp"

namespace mdrsim {

/// The reported states a combination takes: a program's all (stage ends, jumps, the critical
/// point, the peak); the shorthand's path only (stage ends, jumps), as its critical point and
/// peak are combined by RowSequence (row_sequence.hpp).
/// `critical_elsewhere`: a program's all, with the critical point's force resolved on zoomed
/// rows of its own (program_zoom.hpp); `critical_and_peak_elsewhere`: the peak's too.
enum class PathStates { all, path, critical_elsewhere, critical_and_peak_elsewhere };

/// Whether rows end alike, so that they can be compared state by state: the status, the
/// stages, every jump, the critical point and the peak.
bool end_alike(const RunResult& a, const RunResult& b);

/// Whether `state` of `row` is the row's critical point (its last equilibrium before the loss).
bool is_critical_state(const RunResult& row, const ContactSnapshot& state);

/// Where the first two of the rows (springs, result) that end differently part, in one short
/// phrase: a long program's rows list hundreds of jumps, most of them alike.
std::string first_difference(const std::vector<std::pair<std::int64_t, const RunResult*>>& rows);

/// Where the critical point is resolved on zoomed rows of its own (the shorthand's, a
/// program's last stage), the path's rows stop here or at 4x the critical point's finest row,
/// if larger: a held tangential force's stage work converges as a sawtooth, and refining it to
/// rtol 1e-6 takes rows of 2^24 springs (0.84 s against 0.01 s for the critical point); past
/// the cap the path's values carry their estimates and a warning instead.
inline constexpr std::int64_t kPathRowCap = std::int64_t{1} << 17;

/// One state's value and estimates as the last three or four rows give it.
struct StateChoice {
  ContactSnapshot value;
  double normal_error;
  double tangential_error;
  bool extrapolated;
  /// PathStates::path and critical_elsewhere: the state is the rows' critical point (a stage end or
  /// a jump's start there), whose normal force RowSequence resolves on its own zoomed rows: the
  /// shorthand writes that value and estimate in its place, and rtol does not wait for the
  /// path's rows to reach it (they are not refined near the fold).
  bool at_critical = false;
  /// PathStates::critical_and_peak_elsewhere: the state is the rows' peak, likewise.
  bool at_peak = false;
};

/// Every state's choice from the last three or four rows (which end alike): Richardson where
/// every row located the state between springs and `extrapolation` allows it (automatic:
/// where its estimate is the smaller), else the finest row's own value with the plain estimate
/// (error_estimate.hpp) plus the edge spring's force, which bounds the front's place between
/// two springs (two rows can put it alike by chance: a stage end at a let-go front gave
/// 0.238017, 0.237967, 0.238015 F0 at 16000, 64000, 256000 springs against 0.238026).
std::vector<StateChoice> choose_states(std::vector<RunResult>& rows,
                                       DiscretizationOptions::Extrapolation extrapolation,
                                       PathStates which);

/// Whether `state` of `row` is the row's peak adhesive force.
bool is_peak_state(const RunResult& row, const ContactSnapshot& state);

/// The states at the peak take `value` and its estimate [N], as take_critical.
void take_peak(const ContactSnapshot& value, double estimate, std::vector<StateChoice>& choices);

/// The states at the critical point take `value` and its normal force's `estimate` [N], which
/// rows of their own resolved (one number for one state); the tangential estimate stays.
void take_critical(const ContactSnapshot& value, double estimate,
                   std::vector<StateChoice>& choices);

/// Writes the choices into the row. Returns whether any was extrapolated, and the states
/// that were not though rows locate them (for the richardson route's warning).
struct WrittenStates {
  bool extrapolated = false;
  std::vector<std::string> plain;
};
WrittenStates write_states(RunResult& r, const std::vector<StateChoice>& choices, PathStates which);

/// One work's value and estimate from the last three or four rows (which end alike).
struct WorkChoice {
  double value;
  double error;
  /// The rows' differences grow geometrically: the work depends on the spring count, not
  /// through a discretization error (a fixed load's flight after the last spring): no rtol
  /// covers it, and a warning says so.
  bool diverges = false;
};

/// The constraints a stage's axes hold (engine/model/machine_work.hpp's driving points): by
/// them choose_works carries each row's stage work to the stage's end located between springs.
struct StageControl {
  AffineConstraint normal{1.0, 0.0};
  AffineConstraint tangential{1.0, 0.0};
};

/// Every work (each stage's per axis, then the total's) chosen as a state's force: the
/// finest row's own with the plain estimate, or Richardson 2 W_j - W_j-1 with its estimate,
/// where `extrapolation` allows it (automatic: where its estimate is the smaller). The work
/// is a sum of exact trapezoids between the rows' changes, so its error is that of the
/// changes' places: O(dx), smooth where the states are (the reversible cycle: -1.73e-3,
/// -8.82e-4, -4.43e-4, -2.23e-4 relative on 256 ... 2048 springs).
/// Not where a row's stage ends off its located end: one that ends at a fold ends at the row's
/// last equilibrium, a fraction of a spacing before the fold that varies with the spring count,
/// and one that ends at a held force has its front on a spring. Under a fixed load the depth
/// moves along the branch between the two, so the work's error holds F dd, a sawtooth O(dx)
/// that Richardson keeps (Fig. 3a's fixed-load pull-off work on rows of 5000 to 20000 springs:
/// 1.6e-12 J off, 700 times the rows' estimate; the sphere's 6.5e-6 relative at 131072).
/// So each row's stage work is first carried on to the stage's located end (refined_end) by
/// the trapezoid between the driving points of `controls[s]` (machine_work.hpp; the force is
/// at its extremum there under a fixed load, the depth at its own under fixed grips: good to
/// O(dx^3)), and the next stage starts there: every row's work ends at the same point, and only
/// the smooth part of the error is left. A stage beyond `controls` is not carried, nor is a
/// jump inside a stage (the shorthand's rows do not locate those; the wavy sphere's pull-off
/// through one stays within its estimate: 4.6e-16 J off, estimate 4.1e-14 J).
/// Nor where a stage starts with its front pinned off the row's springs (a peeling front
/// reloaded): that stage's normal work and the program's are a sawtooth in the spacing, and
/// take the plain value with a bound on the pinned strip's work added to the estimate. Only
/// the stages need to match across rows.
std::vector<WorkChoice> choose_works(const std::vector<RunResult>& rows,
                                     DiscretizationOptions::Extrapolation extrapolation,
                                     const std::vector<StageControl>& controls);

/// Writes the works' choices into the row: values, each stage's estimate, the total's.
void write_works(RunResult& r, const std::vector<WorkChoice>& choices);

/// What the estimates cover (Accuracy::covers): the forces, and the works unless one of them
/// diverges, which the warning returned names (empty if none).
std::string set_covers(RunResult& r, const std::vector<WorkChoice>& works_chosen);

/// Whether every choice's estimate is within rtol of its force, and every work's of its
/// work. A force (a work) below 1e-6 of the path's largest is held to that absolutely, and
/// nothing to less than what is zero on the rows (zero_scale.hpp): a non-adhesive cycle's
/// total work is rounding of its stages' (6e-21 J of 6.4e-9 J).
bool within(const std::vector<StateChoice>& choices, const std::vector<WorkChoice>& work_choices,
            const ZeroScale& zero, double rtol);

/// The rows refine_path compares: four, so that each estimate compares two differences (a
/// plain row's sawtooth can make two rows alike by chance).
inline constexpr std::size_t kRowsKept = 4;

/// What refine_path found.
struct PathRefinement {
  std::vector<RunResult> rows;        ///< the last kRowsKept rows run, coarsest first
  std::vector<std::int64_t> springs;  ///< the springs of every row run
  RunCounts counts;                   ///< of every row run
  std::vector<StateChoice> choices;   ///< empty where the last rows end differently
  std::vector<WorkChoice> work_choices;
  bool met = false;
  std::string why;  ///< why rtol is not met
  /// The springs of the rows the choices come from (the last kRowsKept), finest last.
  std::vector<std::int64_t> rows_used() const;
};

/// Rows of `first`, 2 `first`, ... springs, each run by `run` (without observers), until the
/// last kRowsKept rows end alike and every state's and work's estimate over them meets rtol
/// (within above), or the next row would have more than `max_springs`.
PathRefinement refine_path(std::int64_t first, std::int64_t max_springs,
                           const std::function<RunResult(std::int64_t)>& run,
                           DiscretizationOptions::Extrapolation extrapolation, PathStates which,
                           const std::vector<StageControl>& controls, const ZeroScale& zero,
                           double rtol);

}  // namespace mdrsim
