// The end of the spring model's discrete branch, located between springs: fold, shear-off, peak.
#pragma once

#include <optional>

#include "detachment/criterion.hpp"
#include "engine/model/contact.hpp"

namespace mdrsim {

/// The vertex in [-1, 1] of the parabola through q(-1) = inner, q(0) = at, q(1) = outer, or
/// nothing where it does not open upwards.
/// The quadratic through q(-1) = inner, q(0) = at, q(1) = outer, at s.
double quadratic_through(double inner, double at, double outer, double s);

std::optional<double> parabola_vertex(double inner, double at, double outer);

/// Every field of a snapshot on the parabola through q(-1) = inner, q(0) = at, q(1) = outer,
/// evaluated at s (springs in contact decided by `at`).
ContactSnapshot interpolate_snapshots(const ContactSnapshot& inner, const ContactSnapshot& at,
                                      const ContactSnapshot& outer, double s);

/// The instability of the spring row starts at the spring n_c whose let-go control value
/// lambda(n) is smallest, so the critical point jumps by one spring as the resolution
/// changes: a sawtooth of O(dx) under fixed grips, where the force still varies along the
/// branch at the fold. The branch lambda(n), Q(n) of the row's own equilibria is smooth in n,
/// so the parabola through lambda at n_c + 1, n_c and the virtual next equilibrium n_c - 1
/// locates the fold between springs, and every quantity Q is interpolated there. What is
/// left is the row's smooth O(dx) error, which extrapolation across resolutions removes.
///
/// `outer` and `critical` are the saved equilibria at n_c + 1 and n_c springs; returns
/// nothing where the branch is not smooth there (a jump just before, a shear-driven
/// let-go next, fewer than two springs).
std::optional<ContactSnapshot> refine_fold(const Contact& contact,
                                           const DetachmentCriterion& criterion,
                                           const Contact::State& outer,
                                           const Contact::State& critical);

/// A cascade started by shear: below some radius a_s the criterion breaks the boundary spring
/// even unstretched (margin < 0 at zero elongation), so the branch ends at a_s, between the
/// critical spring n_c and the next one. a_s is the root of that margin in a (with u_x(a) of
/// the tangential constraint), and the branch through the equilibria at n_c + 2, n_c + 1 and
/// n_c is extended to it by a parabola. Returns nothing without three such equilibria or
/// without a sign change of the margin.
std::optional<ContactSnapshot> refine_shear_off(const Contact& contact,
                                                const DetachmentCriterion& criterion,
                                                const Contact::State& outer2,
                                                const Contact::State& outer,
                                                const Contact::State& critical);

/// The most tensile equilibrium between springs: the vertex of the parabola through the
/// normal forces of the equilibria at n + 1, n and n - 1 around the row's smallest one.
ContactSnapshot refine_peak(const Contact& contact, const Contact::State& outer,
                            const Contact::State& at, const Contact::State& inner);

}  // namespace mdrsim
