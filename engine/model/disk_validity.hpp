// Whether an MDR state is one contact disk: the gap outside it and the pressure inside it.
#pragma once

#include <optional>

#include "profiles/profile.hpp"

namespace mdrsim {

/// What the check found at one state (contact radius a, indentation d).
struct DiskValidity {
  enum class Violation { none, gap, pressure };
  bool valid = true;
  Violation violation = Violation::none;
  /// Where the check found its worst value: the most negative gap (r > a) or pressure
  /// (r < a, springs not glued) [m]; nothing where every value is positive.
  std::optional<double> worst_radius;
  double worst = 0.0;  ///< that gap [m] or pressure [Pa]; 0 where nothing was negative
  /// What counted as zero at this state: a gap [m] or a pressure [Pa] below -zero is
  /// negative; 0 where nothing was negative.
  double zero = 0.0;
};

/// The MDR surface displacement outside a contact of radius a at indentation d,
///   w(r) = (2/pi) int_0^a (d - g(x)) / sqrt(r^2 - x^2) dx   (r > a) [m],
/// integrated as (2/pi) int_0^asin(a/r) (d - g(r sin t)) dt, smooth up to r = a.
double mdr_surface_displacement(const Profile& profile, double contact_radius, double indentation,
                                double radius);

/// The MDR pressure inside the contact, at r < a, for springs out to a that are compressed
/// at the edge (d >= g(a)):
///   p(r) = (E*/pi) [(d - g(a)) / sqrt(a^2 - r^2) + int_r^a g'(x) / sqrt(x^2 - r^2) dx] [Pa],
/// the integral as int_0^acosh(a/r) g'(r cosh u) du (r = 0 is taken at 1e-9 a).
double mdr_pressure(const Profile& profile, double effective_modulus, double contact_radius,
                    double indentation, double radius);

/// The check of one state: the gap h(r) = w(r) + f(r) - d >= 0 for a < r <= min(10 a, the
/// profile's outer radius), and the pressure >= 0 for `unglued_from` < r < a where springs
/// in contact are not glued (a when all are glued: no pressure check). A value counts as
/// negative below -1e-9 of the state's depth scale max(|d|, g(a)) (a gap) or of E* times it
/// over a (a pressure), one zero scale per state: the quadrature's accuracy is far inside
/// that. The gap is sampled at about 115 radii crowded towards a, filled in at 4 per shortest
/// feature of the profile (Profile::shortest_feature) wherever a bound from the samples does
/// not keep it positive, and every local minimum of the samples is refined by a bracketed
/// minimum search: a dip narrower than the samples' spacing is found between samples that
/// stand above it.
DiskValidity check_disk(const Profile& profile, double effective_modulus, double contact_radius,
                        double indentation, double unglued_from);

}  // namespace mdrsim
