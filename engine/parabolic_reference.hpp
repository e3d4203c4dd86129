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

}  // namespace mdrsim::parabolic_reference
