// discretization.rtol: rows zoomed onto the critical point and refined until their estimate meets
// rtol.
#pragma once

#include <optional>
#include <vector>

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Runs the scene to relative accuracy `rtol` of the critical normal force (and of the peak
/// adhesive force), with an a posteriori estimate from the rows actually run.
///
/// 1. Zoom. A pilot row of 512 springs across the glued radius finds the critical spring
///    n_c. The rows' error scales with their spacing, so wherever that gains at least 1.5x a
///    new row of 512 springs is glued at the radius of spring min(top, n_c + max(4, n_c/8)) of the
///    last row, where `top` is the first equilibrium of the unbroken run of single let-gos
///    that ends at the critical point. On the irreversible path this is exact: the springs
///    outside have let go and carry nothing, and the state of a contact of radius a depends
///    only on the springs inside it and the held values. Each zoom gains up to 100x, so a
///    fold at 1e-9 of the glued radius takes five rows of 512 springs. A row whose critical
///    point is its own first let-go was cut inside the jump; it is refused and the zoom
///    widened. A smooth peel is followed down to 1e-12 of the glued radius.
/// 2. Refinement. Rows of 2N, 4N, ... springs across the zoom radius (RowSequence); after
///    four rows (each estimate then has its guard term) the route is chosen: the plain row or
///    Richardson, whichever is predicted to meet rtol with fewer springs (`route` forces one). Rows
///    are added until the chosen route's estimate is within rtol, or the row would pass 2^25
///    springs (DiscretizationOptions::max_row_springs): then the result says so (Accuracy::rtol_met
///    and a warning).
/// 3. The peak adhesive force takes the critical point's rows where it lies inside them,
///    else its own zoom and refinement.
/// Observers see the preload events of the pilot and the detachments of the finest row.
/// Where `glued_rows` is given, the rows run across the whole glued radius (the pilot, and the
/// refinement's where no zoom gains) record their paths and are kept there, for the shorthand's
/// path rows to take rather than run again (shorthand_accuracy.hpp).
RunResult run_adaptive(const Scene& scene, double rtol, std::optional<Accuracy::Route> route,
                       const ObserverList& observers, std::vector<RunResult>* glued_rows = nullptr);

}  // namespace mdrsim
