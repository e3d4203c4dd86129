// The power-law graded half-space E(z) = E0 (z / z0)^k solved apart from the engine's closed
// forms: a point force by its Hankel-transformed equations integrated numerically, a flat
// punch's deflection by a quadrature of the point-force kernel.
//
// Point force. With u_z = int U(xi, z) J0(xi r) xi dxi, u_r = int V J1 xi dxi, sigma_zz =
// int S J0 xi dxi, tau_rz = int T J1 xi dxi and lambda(z), mu(z) both proportional to z^k,
// the equilibrium and Hooke's law become, for each xi, (' = d/dz)
//   U' = (S - lambda xi V) / (lambda + 2 mu),   V' = T / mu + xi U,
//   S' = -xi T,   T' = lambda xi (xi V + U') + 2 mu xi^2 V,
// with S(0) = -P / (2 pi) (the point force's transform), T(0) = 0 and decay as z -> infinity.
// Scaling z by 1/xi gives U(xi, 0) = U1 P xi^(k-1) / (2 pi m), m = E0 z0^(-k), U1 the surface
// value at xi = 1, m = 1, S(0) = -1; and int_0^inf s^k J0(s) ds = 2^k Gamma((1+k)/2) /
// Gamma((1-k)/2) turns it into u_z(r, 0) = M P / r^(1+k) with
//   M m = U1 2^k Gamma((1+k)/2) / (2 pi Gamma((1-k)/2)).
// U1: the two solutions that decay into the body are integrated from z = 60 up to the surface
// (the growing ones die there by e^-60 against them), in t with z = t^(N/(1-k)), which makes
// the equations smooth at the surface where the modulus vanishes (for k = j / (j + N) with
// whole j, N); then the combination with S(0) = -1, T(0) = 0.
#pragma once

namespace mdrsim::test {

/// M [m^(2+k) / N] of the point force on E(z) = E0 (z/z0)^k with Poisson's ratio nu < 1/2,
/// by the integration above (to about 1e-12).
double graded_point_force_compliance_by_hankel(double exponent, double youngs_modulus, double depth,
                                               double poisson_ratio);

/// The surface deflection [m] at radius r < a [m] under the pressure p(r) = (a^2 - r^2)^((k-1)/2)
/// [Pa, for a in metres] on the disk r < a, by a quadrature of the point-force kernel
/// M / rho^(1+k) for the given M [m^(2+k) / N] over the disk (polar coordinates about the point).
double graded_punch_deflection(double exponent, double compliance, double a, double r);

/// The same pressure's surface deflection [m] at radius r > a [m], outside the disk: the rays
/// from the point that cross the disk, sin(phi) = (a / r) sin(psi), each chord by
/// rho = mid + half u with the pressure's edge factor (1 - u^2)^((k-1)/2) kept whole.
double graded_punch_deflection_outside(double exponent, double compliance, double a, double r);

}  // namespace mdrsim::test
