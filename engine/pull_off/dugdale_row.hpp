// The spring row's pull-off with finite-range adhesion (Maugis-Dugdale): let-go events of the
// contact edge with the cohesive zone's line load, then the zone's own branch once it closes.
//
// The discrete model (docs/maugis_row.md "The spring row"). Springs i = 1..N at x_i = i dx,
// dx = a_g / N (SpringFoundation), k_z = E* dx each on one half; spring i stands for the cell
// (x_{i-1}, x_i], so that the n springs in contact cover (0, a] with a = x_n exactly.
// - Contact springs, i <= n, follow the indenter: their force is k_z (d - g(x_i)).
// - Zone springs, a < x < c, carry the line load -2 sigma_0 sqrt(c^2 - x^2) over their cells
//   (the spring across c over the part of its cell inside c). Summed, the load of (a, c] is the
//   closed form -sigma_0 (c^2 t - a s) per half, t = arccos(a/c), s = sqrt(c^2 - a^2): O(1) for
//   any c, where the springs' point values sqrt(c^2 - x_i^2) dx would cost O(c/dx) whenever c
//   moves. So F = 2 k_z sum_{i<=n} (d - g_i) - 2 sigma_0 (c^2 t - a s).
// - The edge a: the boundary spring n lets go when its tension exceeds the zone's pull at its
//   place, k_z (g_n - d) >= 2 sigma_0 sqrt(c^2 - x_n^2) dx, i.e. d <= g(a) - (2 sigma_0/E*) s:
//   the continuum's "no singularity at a", at a = x_n.
// - The edge c: the opening (2/pi) [J(a, c) - d t - (2 sigma_0/E*)(c - a)] = h0, with
//   J = int_a^c g / sqrt(c^2 - x^2) dx. The zone's springs carry a load fixed by c, not by their
//   stretch, so the opening is the indenter's image and the line load's own, and the row takes
//   both exactly: the line load's part in closed form, g's by Profile::dugdale_gap_integral
//   (closed for parabola and cone, Gauss-Kronrod otherwise). Springs' gaps weighted by the
//   cells' arcsine weights would add an O(dx^{3/2}) error (the weight's root at c) and O(c/dx)
//   work to each evaluation.
// At spring n's let-go both edge conditions hold at a = x_n: the event is the continuum's state
// at a = x_n in (a, c, d), and its force differs by the contact's right-point sum only,
// E* dx (g(0) - g(a)) + O(dx^2), a smooth first-order error that Richardson removes.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "controllers/controller.hpp"
#include "engine/model/dugdale_zone.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// One equilibrium of the row.
struct DugdaleRowState {
  std::int64_t springs_in_contact = 0;  ///< n (0 on the no-contact branch)
  double contact_radius = 0.0;          ///< a [m]
  double cohesive_radius = 0.0;         ///< c [m]
  double indentation = 0.0;             ///< d [m]
  double normal_force = 0.0;            ///< F [N], both halves
};

struct DugdaleRowSpec {
  std::int64_t springs = 0;   ///< N across the glued radius
  double glued_radius = 0.0;  ///< a_g [m]: the preload's contact radius
  /// The machine: a_u d + a_F F held and falling (fixed grips (1, 0), fixed load (0, 1),
  /// compliant (1, 1/k)).
  AffineConstraint normal{1.0, 0.0};
  bool record_path = false;  ///< keep every let-go's equilibrium and the zone's branch
  /// solver.max_events: the row stops at this many let-gos with its contact still in place.
  std::int64_t max_events = std::numeric_limits<std::int64_t>::max();
};

struct DugdaleRowCounts {
  std::int64_t events = 0;               ///< let-gos of a contact spring
  std::int64_t opening_evaluations = 0;  ///< of the opening condition, warm-started ones
  std::int64_t bracketed_solves = 0;     ///< events solved from scratch (the first, or a fallback)
};

struct DugdaleRowResult {
  /// The last equilibrium before the jump, located between springs where the row's control
  /// folds on the contact branch; with no jump, the state where the zone shrinks to nothing.
  DugdaleRowState critical;
  bool instability = true;
  /// The row met spec.max_events before its contact was lost: `critical` is the last let-go's
  /// equilibrium and no jump is known.
  bool event_limit = false;
  /// The most tensile force on the path up to the critical point, between springs likewise.
  DugdaleRowState peak;
  /// The first let-go's equilibrium (n = N): where the path starts.
  DugdaleRowState first;
  /// The machine's work int F dp along the path by trapezoids between its equilibria [J], p the
  /// driving point (the held value through a spring, else d; machine_work.hpp): from the first
  /// let-go to the critical point, or to the no-contact branch's start where the path reaches
  /// it (that branch's part is the caller's, in closed form in c).
  double work = 0.0;
  /// c0 where the path joined the no-contact branch [m]; 0 where it did not.
  double no_contact_start = 0.0;
  /// With record_path: the equilibrium at each let-go (n = N down), then the no-contact
  /// branch's start and end where the path reaches it.
  std::vector<DugdaleRowState> path;
  DugdaleRowCounts counts;
};

/// Peels the row from the contact glued at a_g (pinned there while the control falls with the
/// zone pulling) spring by spring: each let-go is O(1) (a running image sum, and the zone's c
/// from the last one's by a secant step or two), a cascade (the next let-go due at the held
/// value) is the jump. Where the last spring lets go the path joins the no-contact branch
/// d(c) = f(c) - 4 sigma_0 c/(pi E*) - h0, F = -pi sigma_0 c^2, which it follows as c shrinks
/// until the control folds there (a jump) or c reaches 0 (no instability).
/// Throws std::invalid_argument for a row of no springs or a law without a positive stress,
/// and std::domain_error where the zone would reach beyond the profile's outer radius.
DugdaleRowResult run_dugdale_row(const Profile& profile, const DugdaleLaw& law,
                                 const DugdaleRowSpec& spec);

}  // namespace mdrsim
