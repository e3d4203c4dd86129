// How far a row's critical point lies from the line between instability and shear-off.
#pragma once

#include <array>
#include <optional>

#include "detachment/criterion.hpp"
#include "engine/model/contact.hpp"
#include "engine/result/run_result.hpp"

namespace mdrsim {

/// A fold closer to a_s than this many spacings (below) is not resolved by the row: its
/// cascade is by shear where no spring lies between the fold and a_s, and it misses a fold up
/// to 1.5 spacings above a_s.
constexpr double kStatusSpacings = 3.0;

/// How far above a_s, the radius below which the glue lets go unstretched, the row's branch
/// folds, in spacings of the row: the continuum instability of a fold above a_s and the
/// shear-off at a_s differ by that much. The let-go controls of three neighbouring springs
/// (`outer2`, `outer` and `critical` for a shear-off row; `outer`, `critical` and the next
/// spring's let-go for an instability row, virtual: the row jumped) fitted with the branch's
/// form next to a_s. Nothing where the status is plain: a_s more than a few spacings below
/// the critical spring, or no fold above it.
std::optional<double> fold_above_shear_off(const Contact& contact,
                                           const DetachmentCriterion& criterion,
                                           const std::optional<Contact::State>& outer2,
                                           const Contact::State& outer,
                                           const Contact::State& critical);

/// The fit itself: the let-go controls `controls` of three neighbouring springs at `positions`
/// (innermost first, all above a_s) with the branch's form next to a_s; the fold's height
/// above a_s in spacings `dx`, or nothing where the branch has no fold above a_s.
std::optional<double> fold_of_let_go_branch(const std::array<double, 3>& positions,
                                            const std::array<double, 3>& controls, double a_s,
                                            double dx);

/// A program row's shear-off: springs K, K + 1 and K + 2 (at `positions`, innermost first)
/// let go by their stretch at the held normal values `controls` of a stage that lowers it,
/// and spring K - 1 (at `broken_position`) broke at rest right after spring K, under the glue's
/// tangential stretch [m]. The fold of that branch above a_s in spacings, as above.
std::optional<double> program_fold_above_shear_off(
    const DetachmentCriterion& criterion, double tangential_stretch, double broken_position,
    const std::array<double, 3>& positions, const std::array<double, 3>& controls, double dx);

/// Whether a row's status is told apart from the other one (RunResult::fold_above_shear_off).
bool status_resolved(const RunResult& row);

}  // namespace mdrsim
