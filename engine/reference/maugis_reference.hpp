// Maugis' classical solution of the adhesive parabola with a Dugdale zone, in his own variables:
// the independent yardstick of finite-range adhesion (written apart from any MDR code).
#pragma once

namespace mdrsim::maugis_reference {

// Maugis (J. Colloid Interface Sci. 150, 1992), for the parabola f(r) = r^2/(2R) on E* with a
// Dugdale stress sigma_0 acting over the gap h0 = w / sigma_0 (w the work of adhesion):
//   K = 4 E*/3, lambda = 2 sigma_0 (R / (pi w K^2))^(1/3),
//   a = A (pi w R^2 / K)^(1/3), c = m a, delta = D (pi^2 w^2 R / K^2)^(1/3), F = P pi w R,
// and with t = arctan sqrt(m^2 - 1) (so m = 1/cos t, sqrt(m^2 - 1) = tan t):
//   (lambda A^2/2) [tan t + (m^2 - 2) t] + (4 lambda^2 A/3) [t tan t - m + 1] = 1   (the
//   opening of the zone at c is h0),
//   P = A^3 - lambda A^2 [tan t + m^2 t],     D = A^2 - (4/3) A lambda tan t.
// As A -> 0 the contact closes while the zone still pulls: with C = c (K / (pi w R^2))^(1/3),
// the disk of radius C alone gives P = -(pi lambda/2) C^2 and
// D = C^2/2 - (8 lambda/(3 pi)) C - 2/(pi lambda) (the no-contact branch; the contact branch
// meets it at C0, the root of (pi lambda/4) C^2 + (4 lambda^2/3)(pi/2 - 1) C = 1).

/// Maugis' scales in SI units for a parabola of radius R [m] on E* [Pa] with work of adhesion
/// w [J/m^2], and the Dugdale stress sigma_0 [Pa] of a given lambda.
struct MaugisScales {
  double radius = 0.0;   ///< R [m]
  double modulus = 0.0;  ///< E* [Pa]
  double work = 0.0;     ///< w [J/m^2]

  double length() const;                        ///< (pi w R^2 / K)^(1/3) [m], K = 4 E*/3
  double depth() const;                         ///< length^2 / R [m]
  double force() const;                         ///< pi w R [N]
  double adhesive_stress(double lambda) const;  ///< (lambda/2) (pi w K^2 / R)^(1/3) [Pa]
};

/// One equilibrium on the contact branch (A > 0) or the no-contact branch (A = 0).
struct MaugisState {
  double contact_radius = 0.0;   ///< A
  double cohesive_radius = 0.0;  ///< C = m A on the contact branch
  double indentation = 0.0;      ///< D
  double force = 0.0;            ///< P
};

/// The contact branch at A > 0: solves the opening condition for m.
MaugisState contact_branch(double lambda, double contact_radius);
/// The no-contact branch at the zone's radius C > 0.
MaugisState no_contact_branch(double lambda, double cohesive_radius);
/// C0: where the contact branch ends at A = 0 on the no-contact branch.
double closing_cohesive_radius(double lambda);

/// Fixed load: the most tensile force on the path (the pull-off), and where it is.
MaugisState fixed_load_pull_off(double lambda);
/// The lambda below which the contact closes before D folds under fixed grips: where C0 = 8
/// lambda / (3 pi), the no-contact branch's fold, i.e. lambda^3 = 9 pi / (16 (pi - 1)),
/// lambda = 0.9379475...
double grips_threshold();
/// Fixed grips: the last equilibrium before the jump out, retracting from a large contact:
/// the first fold of D going down the contact branch, or, where the contact closes first
/// (lambda <= grips_threshold()), the fold of the no-contact branch at C = 8 lambda / (3 pi).
MaugisState fixed_grips_jump(double lambda);

}  // namespace mdrsim::maugis_reference
