// The paper's closed forms for the parabola, in dimensionless units (paper eqs. 16-35).
#pragma once

namespace mdrsim::parabolic_reference {

// a, d, u, F below are a/a0, d/d0, u_x/d0, F/F0; gamma = G*/E* (paper eq. 9).

/// Indentation on the equilibrium branch, eq. 25 (eq. 18 at u = 0).
double indentation(double a, double u = 0.0, double gamma = 1.0);
/// Normal force on the equilibrium branch, eq. 26 with eq. 25 (eq. 19 at u = 0).
double normal_force(double a, double u = 0.0, double gamma = 1.0);
/// Tangential force of a fixed tangential displacement, eq. 27.
double tangential_force(double a, double u, double gamma = 1.0);
/// d(indentation)/da and d(normal_force)/da on the branch.
double indentation_slope(double a, double u = 0.0, double gamma = 1.0);
double normal_force_slope(double a, double u = 0.0, double gamma = 1.0);

struct CriticalPoint {
  double contact_radius;
  double indentation;
  double normal_force;
  double tangential_force;
  double tangential_displacement;
};

/// Fixed grips on both axes: eq. 31 for the radius, eqs. 32-33 for the forces.
CriticalPoint fixed_grips_critical(double u, double gamma = 1.0);
/// Fixed load normally, fixed grips tangentially: eq. 29 with eqs. 25-27.
CriticalPoint fixed_load_critical(double u, double gamma = 1.0);
/// A compliant normal machine of dimensionless stiffness k d0/F0 (fixed grips tangentially):
/// the fold of w = d + F/k, where dF/da + k dd/da = 0, between the two limits above.
CriticalPoint compliant_critical(double stiffness, double u = 0.0, double gamma = 1.0);
/// The fixed-grips master curve F_z(F_x), eq. 34 (eq. 35 at gamma = 1).
double fixed_grips_master_curve(double tangential_force, double gamma = 1.0);

// Beyond the paper: the tangential force F_x held (fixed load tangentially) instead of the
// displacement. Eq. 27 gives u = 2 F_x/(gamma a), which changes as the contact shrinks; with
// q = F_x^2/gamma the branch is d = 3 a^2 - sqrt(16 a - 4 q/a^2), F_z = a^3 - (a/2) sqrt(...).
// The derivation of the folds is in parabolic_reference.cpp.

/// Indentation and normal force on that branch (eqs. 25-26 with u = 2 F_x/(gamma a)).
double indentation_at_tangential_force(double a, double fx, double gamma = 1.0);
double normal_force_at_tangential_force(double a, double fx, double gamma = 1.0);
/// The radius below which the held force alone breaks the glue, a^3 = F_x^2/(4 gamma)
/// (F_x^2 = 8 pi G* a^3 dgamma in SI units): the shear-off limit.
double shear_off_radius(double fx, double gamma = 1.0);
/// Fixed grips normally: t = a^3 is the one positive root of
/// 36 t^3 - (9 q + 4) t^2 - 4 q t - q^2 = 0, and F_z = t - 2/3 - q/(3 t).
CriticalPoint fixed_grips_critical_at_tangential_force(double fx, double gamma = 1.0);
/// Fixed load normally: a^3 = 1 + q/4 and F_z = q/4 - 1, in closed form.
CriticalPoint fixed_load_critical_at_tangential_force(double fx, double gamma = 1.0);
/// The master curves F_z(F_x) of the two normal controls with F_x held.
double fixed_grips_master_curve_at_tangential_force(double fx, double gamma = 1.0);
double fixed_load_master_curve_at_tangential_force(double fx, double gamma = 1.0);

}  // namespace mdrsim::parabolic_reference
