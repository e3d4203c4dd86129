// The shorthand's pull-off path with finite-range adhesion: the pinned phase, the contact branch
// and the no-contact branch as one curve of one parameter, and its folds under any control.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "controllers/controller.hpp"
#include "engine/model/contact_snapshot.hpp"
#include "engine/model/dugdale_zone.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// The path from the preload, s in [0, 4] (docs/maugis.md "The path"): the contact branch from
/// a_p, where its depth is the preload depth d_p (the zone pulls the contact pressed to d_p out
/// from a_g to a_p >= a_g at fixed grips), down to the closing point, then the no-contact branch:
/// [0, 1] a = a_p - s (a_p - a_g), from a_p down to a_g;
/// [1, 2] a from a_g down to a_t, where the zone's angle t = arccos(a/c) reaches pi/3 (a_g if
///   it is beyond already), a_g - a = (a_g - a_t)(s - 1)(3 - s);
/// [2, 3] t = pi/2 - (pi/2 - t_t)(3 - s)^2 up to the closing point (a = 0, c = c0), in t where
///   a radius would round c;
/// [3, 4] the no-contact branch, c = c0 2^(-40 (s - 3)) from c0 down to 1e-12 of it.
class DugdalePath {
 public:
  static constexpr double kClosing = 3.0;  ///< s at the closing point
  static constexpr double kEnd = 4.0;

  DugdalePath(const Profile& profile, const DugdaleLaw& law, double glued_radius,
              double preload_depth);

  /// The equilibrium at s.
  DugdaleState at(double s) const;
  /// The equilibria at each of `places` (a force curve's s, in order), each solve started from
  /// the cubic through the last four of its phase (their half-chords in a on the branch's radii,
  /// their radii in t on its angles): one Newton step a point where the curve is smooth. The
  /// same states as at(), to its solvers' convergence (the root to its rounding).
  std::vector<DugdaleState> states(std::span<const double> places) const;
  /// The equilibrium at s, its solve started from `walk`'s guess, which then gains it: a walk
  /// through nearby places of one phase (a scan, a root search) costs one or two Newton steps
  /// a place. Keep one walk per phase (its variable is the radius in [0, 2), the angle in [2, 3)).
  DugdaleState walk_to(double s, ContinuedGuess& walk) const;
  /// walk_to in the zone's angle (s in (2, 3)) with the slopes at its solve's last iterate
  /// (dugdale_sloped_contact_state): one gap integral fewer than the state and its slopes.
  /// Elsewhere walk_to's state with no slopes (an infinite offset). `enough`: as
  /// dugdale_sloped_contact_state's (a scan's sign read, a step short of the root).
  DugdaleSlopedState sloped_walk_to(double s, ContinuedGuess& walk,
                                    const SlopedEnough& enough = {}) const;
  /// d'(s) [m]: a fourth-order central difference on s's own phase, its formula continued.
  double depth_slope(double s) const;

  double preload_radius() const { return preload_radius_; }  ///< a_p [m]
  double glued_radius() const { return glued_radius_; }      ///< a_g [m]
  /// The branch's state at a_t, where phase [1, 2] ends and [2, 3] begins.
  const DugdaleState& angle_state() const { return angle_state_; }
  const Profile& profile() const { return profile_; }
  const DugdaleLaw& law() const { return law_; }
  double closing_radius() const { return closing_radius_; }  ///< c0 [m]

 private:
  /// The state at s by the formula of `phase`, continued beyond its ends; `guess` starts its
  /// solve (the half-chord in phases 0 and 1, the radius in phase 2; 0: the solver's own).
  DugdaleState in_phase(int phase, double s, double guess = 0.0) const;

  const Profile& profile_;
  DugdaleLaw law_;
  double glued_radius_;
  DugdaleState glued_state_;
  DugdaleState angle_state_;  ///< at a_t
  double preload_radius_ = 0.0;
  double closing_radius_;
};

/// The state the path does not take (docs/maugis.md "Why the contact is not held at a_g"): the
/// contact held at radius a [m] at the depth d [m], its zone's c from the opening condition
/// with a stress singularity at a, F = 2 E* (a d - int_0^a g dx) - 2 sigma_0 (c^2 t - a s).
/// For d above the branch's d(a) that singularity is compressive: the surface just outside a
/// would pass through the indenter.
DugdaleState dugdale_held_state(const Profile& profile, const DugdaleLaw& law, double a,
                                double depth);

/// A fold of the control value v = a_u d + a_F F along the path: where it stops falling.
struct DugdaleFold {
  double s = 0.0;
  DugdaleState state;
  double force_error = 0.0;  ///< a bound on the error of state.normal_force from locating s [N]
};

/// The first fold of v going along the path from s = 0, or nullopt where v falls to the end
/// (no instability). On the contact branch ([0, 3)) a fold is a root of dv/da = a_u dd/da +
/// a_F dF/da (dugdale_contact_slopes) after a scan of its sign, in a where the path runs in a
/// and in s where it runs in the zone's angle; on the no-contact branch a root of dv/dc after a
/// scan of v; a fold at a corner (the start, the closing point) is that corner exactly.
std::optional<DugdaleFold> first_fold(const DugdalePath& path, const AffineConstraint& control);

/// The most tensile state on [0, s_end] (Brent about the most tensile sample), with its error.
DugdaleFold most_tensile(const DugdalePath& path, double s_end);

/// A Dugdale state as the results carry it, with the control `normal` holds there.
ContactSnapshot dugdale_snapshot(const DugdaleState& s, const AffineConstraint& normal);

/// The machine's work int F dd along [s0, s1] [J] (the pinned phase exactly linear in d, the
/// branches by Gauss-Kronrod on F d'(s)); `error` gains its bound.
double path_work(const DugdalePath& path, double s0, double s1, double& error);

}  // namespace mdrsim
