// The rigid axisymmetric indenter: its shape f(r) and its MDR image g(x) (paper eqs. 4-6).
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "engine/base/pull_off_scales.hpp"

namespace mdrsim {

/// Bounds on a logarithmic slope over x > 0 [1].
struct LogSlopeRange {
  double low;
  double high;
};

/// A closed-form integral and the sum of its terms' magnitudes, what its rounding is relative
/// to (same unit).
struct ExactIntegral {
  double value;
  double magnitude;
};

/// The Dugdale zone's gap integral J(a, t) at a fixed contact radius a and its slope in the
/// angle t = arccos(a/c) (Profile::dugdale_gap).
struct DugdaleGap {
  double integral;     ///< J [m]
  double angle_slope;  ///< dJ/dt at fixed a [m/rad]
};

/// Required operations: shape() and mdr_image(). The others have numerical defaults that
/// a profile overrides where it knows a closed form.
class Profile {
 public:
  virtual ~Profile() = default;

  /// Required: the gap f(r) [m] between indenter and undeformed surface at radius r >= 0 [m].
  virtual double shape(double radius) const = 0;

  /// Required: the MDR image g(x) [m] at x >= 0 [m] (paper eq. 4). It rises for convex
  /// profiles; a wavy or dimpled one may fall between crests (a front jumps over the dip).
  virtual double mdr_image(double x) const = 0;

  /// Optional: the slope dg/dx [1] at x > 0 [m]. Default: a fourth-order central difference
  /// with step 1e-3 x (about 1e-12 relative on smooth images).
  virtual double mdr_image_slope(double x) const;

  /// Optional: the non-adhesive contact radius [m] at indentation depth [m], the x with
  /// g(x) = depth. Default: a bracketing root search on mdr_image().
  virtual double contact_radius_at_depth(double depth) const;

  /// Optional: the non-adhesive normal force per unit E* of a contact of radius a [m],
  /// 2 * integral_0^a (g(a) - g(x)) dx [m^2]. Default: Gauss-Kronrod quadrature.
  virtual double nonadhesive_force_per_modulus(double contact_radius) const;

  /// Optional: the Dugdale zone's gap integral J = int_a^c (g(x) - g(a)) / sqrt(c^2 - x^2) dx
  /// and its slope in the angle, for 0 <= a < c [m] (finite-range adhesion: the opening at the
  /// zone's outer edge c of a contact of radius a), with t = arccos(a/c) [rad] as the caller
  /// knows it to full precision (the zone is solved for t: from a and c alone it loses digits
  /// where c is close to a). Default: dugdale_gap_quadrature; the parabola, the cone and the
  /// power laws override it in closed form.
  virtual DugdaleGap dugdale_gap(double contact_radius, double cohesive_radius, double angle) const;

  /// J alone [m]: dugdale_gap's integral.
  double dugdale_gap_integral(double contact_radius, double cohesive_radius, double angle) const {
    return dugdale_gap(contact_radius, cohesive_radius, angle).integral;
  }

  /// Optional: int_0^a (d - g(x))^2 dx [m^3] in closed form at contact radius a [m] and
  /// indentation d [m] (a power law, a table's piecewise-cubic image); nullopt: the engine
  /// integrates it by quadrature. E* times it is the energy the glued springs store.
  virtual std::optional<ExactIntegral> squared_gap_integral(double /*contact_radius*/,
                                                            double /*indentation*/) const {
    return std::nullopt;
  }

  /// Optional: a contact radius the shape fixes for any glued contact (flat punch) [m].
  virtual std::optional<double> fixed_contact_radius() const { return std::nullopt; }

  /// Optional: the largest radius the shape is defined on [m] (a sphere ends at its radius).
  virtual double outer_radius() const { return std::numeric_limits<double>::infinity(); }

  /// Optional: whether g(x) is a few arithmetic operations (a parabola, a cone, a flat punch),
  /// cheaper to compute again than to keep: a row keeps the images of other shapes
  /// (spring_foundation.hpp), whose g costs a transcendental function or a table search.
  virtual bool cheap_image() const { return false; }

  /// Optional: whether every MDR state of this shape is one contact disk (no annular
  /// re-contact outside, no separation inside), so that the disk check may be skipped: true
  /// for the convex classics (parabola, sphere, cone, power laws n >= 1, flat punch), whose
  /// non-adhesive solutions (Hertz, Sneddon) have a gap that opens outside the contact, and
  /// to which adhesion only adds the flat punch's lift dl (1 - (2/pi) asin(a/r)) >= 0.
  virtual bool always_one_disk() const { return false; }

  /// Optional: whether the shape proves every reported MDR state one contact disk, so that the
  /// disk check is skipped. Outside a contact of radius a at indentation d the gap is
  ///   h(r) = (2/pi) int_a^r (g(x) - d) / sqrt(r^2 - x^2) dx,
  /// (f is the Abel transform of g), >= 0 wherever g never falls beyond a, as d <= g(a) at a
  /// front; and the pressure of an edge pressed at d >= g(a) is >= 0 wherever g' >= 0. So a
  /// shape whose image never falls proves it: g' = int_0^(pi/2) (r f')'(x sin t) dt >= 0 where
  /// r f'(r) never falls (every convex f rising from the tip). Default: always_one_disk().
  virtual bool proves_one_disk() const { return always_one_disk(); }

  /// Optional: whether the shape's branch folds again at every crest of a ripple, more folds
  /// than the continuum route follows (it refuses the scene where it is named).
  virtual bool folds_at_every_crest() const { return false; }

  /// Optional: the CSV of points r,f (read_profile_table, profiles/tabulated_profile.hpp) the
  /// shape was read from: the result carries its points and hash, so that the scene reruns
  /// without the file. nullopt where no file was read.
  virtual std::optional<std::string> source_table_file() const { return std::nullopt; }

  /// Optional: bounds on s(x) = d ln(sqrt(x) g'(x)) / d ln x over x > 0, where the shape proves
  /// them (a power law c r^n: n - 1/2 everywhere); nullopt where unknown. sqrt(a) g'(a) is
  /// what the JKR branch's fold condition weighs against Hess's length, so its growth counts
  /// the branch's folds for every E*, dgamma and machine (docs/continuum.md "Which route rtol
  /// takes").
  virtual std::optional<LogSlopeRange> image_slope_growth() const { return std::nullopt; }

  /// Optional: the shortest length the shape varies on (a ripple's wavelength) [m]. A row whose
  /// spacing is more than a quarter of it cannot follow the shape; the scene is refused.
  virtual std::optional<double> shortest_feature() const { return std::nullopt; }

  /// Optional: the radius R of the JKR scales F0, a0, d0 (paper eq. 17), for profiles whose
  /// tip is the parabola r^2/(2R); nullopt where those scales do not apply [m].
  virtual std::optional<double> jkr_scale_radius() const { return std::nullopt; }

  /// Optional: the dimensionless output's scales where the shape's fixed-load pull-off has a
  /// closed form (cone, power law, flat punch), for E* [Pa] and dgamma [J/m^2] > 0; nullopt
  /// otherwise. A profile with jkr_scale_radius() gets the parabola's instead.
  virtual std::optional<PullOffScales> pull_off_scales(double /*effective_modulus*/,
                                                       double /*work_of_adhesion*/) const {
    return std::nullopt;
  }
};

/// Profile::dugdale_gap by quadrature for any image: in x = c cos(psi), J = int_0^t (g(x) -
/// g(a)) dpsi, integrated by parts (int_0^t c g'(x) psi sin(psi) dpsi) where t < 0.3, where the
/// difference would cancel, and dJ/dt = tan(t) int_0^t x g'(x) dpsi; Gauss-Kronrod panels
/// (10/21 points), halved where J's pair differs by more than 1e-12 of the panel's mass.
/// Relative accuracy about 1e-14 where g and g' are exact and smooth (parabola, sphere), 1e-13
/// on a table's Hermite image, that of mdr_image_slope's difference (1e-12) where it is one;
/// dJ/dt as close where g' is smooth.
DugdaleGap dugdale_gap_quadrature(const Profile& profile, double contact_radius,
                                  double cohesive_radius, double angle);

/// The non-adhesive contact radius [m] carrying normal force `force` [N] on a half-space of
/// effective modulus [Pa]: the inverse of Profile::nonadhesive_force_per_modulus.
double contact_radius_at_force(const Profile& profile, double force, double effective_modulus);

}  // namespace mdrsim
