// The constants of a power-law graded half-space E(z) = E0 (z / z0)^k (docs/graded.md).
#pragma once

#include "engine/base/material.hpp"

namespace mdrsim {

/// M [m^(2+k) / N]: a point force P on the surface deflects it by M P / r^(1+k) at the
/// distance r (Giannakopoulos and Suresh 1997, Booker, Balaam and Davis 1985), for E0 [Pa] and
/// Poisson's ratio nu (< 1 / (1 + k), which every nu <= 1/2 meets). k = 0: (1 - nu^2) / (pi E0).
double graded_point_force_compliance(const Grading& grading, double youngs_modulus,
                                     double poisson_ratio);

/// C_k = 2 cos(pi k / 2) / (pi (1 + k) M) [Pa / m^k]: a flat punch of radius a pressed by d
/// carries F = C_k d a^(1+k) (k = 0: 2 E*).
double graded_punch_constant(const Grading& grading, double youngs_modulus, double poisson_ratio);

/// c_k(x) = (1 + k) C_k |x|^k / 2 [Pa]: the MDR spring's normal stiffness per unit length at
/// x [m], for the punch constant C_k [Pa / m^k].
double graded_spring_stiffness(double exponent, double punch_constant, double x);

/// Hess's rule on the graded springs: the boundary spring at radius a [m] lets go at the
/// stretch e(a) = sqrt(2 pi a dgamma / c_k(a)) = sqrt(4 pi a^(1-k) dgamma / ((1 + k) C_k)) [m]
/// (the energy its two halves store, c_k(a) e^2, is the glue's 2 pi a dgamma per unit of a).
double graded_let_go_stretch(double exponent, double punch_constant, double work_of_adhesion,
                             double a);

/// The surface displacement [m] at radius r [m] around a flat punch of radius a [m] pressed by
/// d [m]: d under the punch, and outside it the MDR's back-transform of the springs' uniform
/// stretch, (2 cos(pi k / 2) / pi) int_0^a x^k d (r^2 - x^2)^(-(1+k)/2) dx
/// = d cos(pi k / 2) B(a^2 / r^2; (1 + k) / 2, (1 - k) / 2) / pi (k = 0: (2 d / pi) asin(a / r)).
double graded_punch_surface_displacement(double exponent, double depth, double a, double r);

}  // namespace mdrsim
