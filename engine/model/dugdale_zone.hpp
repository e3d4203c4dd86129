// Finite-range adhesion in the MDR (Maugis-Dugdale): the equilibria of a contact of radius a
// with a cohesive zone out to c, and of the zone alone once the contact has closed.
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "profiles/profile.hpp"

namespace mdrsim {

/// The Dugdale interaction: a constant stress sigma_0 over the gap h0 = dgamma / sigma_0.
struct DugdaleLaw {
  double adhesive_stress = 0.0;    ///< sigma_0 [Pa]
  double work_of_adhesion = 0.0;   ///< dgamma [J/m^2]
  double effective_modulus = 0.0;  ///< E* [Pa]

  double range() const { return work_of_adhesion / adhesive_stress; }  ///< h0 [m]
  /// 2 sigma_0 / E* [1]: a zone spring at x stretches by that times sqrt(c^2 - x^2).
  double zone_strain() const { return 2.0 * adhesive_stress / effective_modulus; }
};

/// One equilibrium: the springs |x| < a follow the indenter, those of a < |x| < c carry the
/// line load -2 sigma_0 sqrt(c^2 - x^2), no stress singularity at a, the gap h0 at c.
struct DugdaleState {
  double contact_radius = 0.0;   ///< a [m] (0 on the no-contact branch)
  double cohesive_radius = 0.0;  ///< c [m]
  double angle = 0.0;            ///< t = arccos(a/c) [rad] (pi/2 on the no-contact branch)
  double indentation = 0.0;      ///< d [m]
  double normal_force = 0.0;     ///< F [N]
};

/// The contact branch's state of a zone already solved: a contact of radius a [m] whose zone
/// reaches c [m] at the angle t = arccos(a/c) [rad] with half-chord s = sqrt(c^2 - a^2) [m]
/// (each as its solver knows it to full precision): d = g(a) - (2 sigma_0/E*) s and F = E*
/// nf(a) - 2 sigma_0 (a s + c^2 t).
DugdaleState dugdale_contact_state_of_zone(const Profile& profile, const DugdaleLaw& law, double a,
                                           double s, double c, double t);

/// The contact branch at a > 0: the zone's opening (2/pi)[int_a^c (g - g(a))/sqrt(c^2 - x^2) dx
/// + (2 sigma_0/E*)(s t - (c - a))] = h0 solved for t (it rises with t from -h0 at t = 0), then
/// d = g(a) - (2 sigma_0/E*) s and F = E* nf(a) - 2 sigma_0 (a s + c^2 t), s = sqrt(c^2 - a^2).
/// Throws std::domain_error where the zone would reach beyond the profile's outer radius.
DugdaleState dugdale_contact_state(const Profile& profile, const DugdaleLaw& law, double a);

/// The same state from a first guess of its half-chord sqrt(c^2 - a^2) [m] (a neighbour's
/// zone): Newton's steps start there, one or two where the guess is close.
DugdaleState dugdale_contact_state(const Profile& profile, const DugdaleLaw& law, double a,
                                   double half_chord_guess);

/// The contact branch's slopes at one of its states: zero where a control folds (fixed grips:
/// dd/da, fixed load: dF/da), for a fold search to root.
struct DugdaleSlopes {
  double indentation = 0.0;   ///< dd/da [1]
  double normal_force = 0.0;  ///< dF/da [N/m]
  double half_chord = 0.0;    ///< ds/da of the zone's half-chord s = sqrt(c^2 - a^2) [1]
};

/// dd/da and dF/da along the contact branch at `state` (from dugdale_contact_state), by implicit
/// differentiation of the opening condition O(a, s) = 0 in the half-chord s = sqrt(c^2 - a^2):
/// ds/da = -O_a/O_s. O_a holds -g'(a) t + (dJ/dt) a^2/(c^2 s), which cancel to O(t^3) where
/// the zone is thin: relative accuracy about eps g'(a)/((2 sigma_0/E*) t) there.
DugdaleSlopes dugdale_contact_slopes(const Profile& profile, const DugdaleLaw& law,
                                     const DugdaleState& state);

/// The same slopes at the zone (a, s, c, t) [m, m, m, rad] from its gap integral `gap` there: those
/// of dugdale_contact_slopes at a solved zone, off by about the distance to it at a Newton
/// iterate next to the root (no gap integral of their own).
DugdaleSlopes dugdale_slopes_at_zone(const Profile& profile, const DugdaleLaw& law, double a,
                                     double s, double c, double t, const DugdaleGap& gap);

/// A contact state with the slopes its solve read on the way: those at the last Newton iterate,
/// whose gap integral the steps have already taken, `offset` [m] of the half-chord away from the
/// state's (the last step, about the iterate's distance from the root: a rounding-sized offset
/// where the guess was the root). Infinite where the solve ended by bisection (no slopes).
struct DugdaleSlopedState {
  DugdaleState state;
  DugdaleSlopes slopes;
  double offset = 0.0;
  double half_chord = 0.0;  ///< the state's sqrt(c^2 - a^2) [m], as its solver knows it
};

/// Whether a caller is content with a solve's iterate: its slopes and the zone (a, c, t) one
/// Newton step on, whose d and F it is not shown (a scan that reads only a slope's sign stops
/// there, a Newton step short of the root, and gains that state).
using SlopedEnough = std::function<bool(const DugdaleSlopedState&)>;

/// dugdale_contact_state from a half-chord guess (none: <= 0) with the slopes at its last iterate:
/// one gap integral fewer than the state and dugdale_contact_slopes, at slopes off by about
/// `offset` over the half-chord of their terms. Where `enough` is given and content with an
/// iterate, the solve stops there: its state one Newton step on, not converged.
DugdaleSlopedState dugdale_sloped_contact_state(const Profile& profile, const DugdaleLaw& law,
                                                double a, double half_chord_guess,
                                                const SlopedEnough& enough = {});

/// A walk's guess of its next solve: the cubic Hermite through the last two (x, y) it added where
/// both came with their slopes dy/dx, else the cubic through the last four (Neville's scheme),
/// the line through two, the one value of one; none (0) before. Within the curve's fourth
/// derivative times the step^4: on close points, inside a Newton solve's own tolerance; the
/// Hermite's from the two nearest, where a scan's far samples would bend Neville's cubic.
class ContinuedGuess {
 public:
  /// y at x, or 0 where nothing is known (or the scheme's value is not a finite positive).
  double at(double x) const;
  /// Adds a solved (x, y), with its slope dy/dx where known (else NaN); an x equal to the newest
  /// one is not added (the scheme would divide by zero).
  void add(double x, double y, double slope = std::numeric_limits<double>::quiet_NaN());
  void clear() { known_ = 0; }

 private:
  static constexpr int kFit = 4;
  std::array<double, kFit> x_{}, y_{}, slope_{};  ///< the newest first
  int known_ = 0;
};

/// The contact branch at each of `contact_radii` (a > 0 [m]), in their order: each solve
/// starts from the two zones before with their slopes ds/da (their cubic Hermite), so that a
/// force curve of close radii costs one Newton step a point where it is smooth instead of five. The
/// same states as dugdale_contact_state, to its convergence (the last steps agree to 1e-9 of the
/// half-chord, the root to its rounding).
std::vector<DugdaleState> dugdale_contact_states(const Profile& profile, const DugdaleLaw& law,
                                                 std::span<const double> contact_radii);

/// The no-contact branch at c > 0: the zone's disk alone pulls, d = f(c) - 4 sigma_0 c/(pi E*)
/// - h0 and F = -pi sigma_0 c^2.
DugdaleState dugdale_free_state(const Profile& profile, const DugdaleLaw& law, double c);

/// c0 [m]: where the contact branch closes (a -> 0) onto the no-contact branch, the root of
/// f(c) - g(0) + (2 sigma_0/E*)(1 - 2/pi) c = h0.
double dugdale_closing_radius(const Profile& profile, const DugdaleLaw& law);

}  // namespace mdrsim
