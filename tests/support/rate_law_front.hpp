// An elastic parabola under fixed grips, retracted at constant speed from the JKR state of zero
// force, its receding front moving by the rate law v = v* (G / dgamma - 1)^(1/n): the front's
// ODE solved apart from the engine, for the peak tension, the loss of contact and the energies.
//
// MDR of the parabola g(x) = x^2 / R with the front at a and the indentation d: the boundary
// stretch e = d - a^2 / R, the force F = 2 E* int_0^a (d - x^2 / R) dx = 2 E* (d a - a^3 / (3 R)),
// the energy release rate G = E* e^2 / (2 pi a), the stored energy U = E* int_0^a (d - g)^2 dx.
// With L = (dgamma R^2 / E*)^(1/3) the lengths a = L alpha, d = (L^2 / R) delta, the time
// t = (L / v*) tau, F = dgamma R f and energies in dgamma L^2, the problem keeps two numbers:
//   G / dgamma = (delta - alpha^2)^2 / (2 pi alpha),   f = 2 (delta alpha - alpha^3 / 3),
//   d alpha / d tau = -max(G / dgamma - 1, 0)^(1/n),   d delta / d tau = -beta,
// beta = (V / v*) (E* R / dgamma)^(1/3), and n. The start: F = 0 on JKR's branch (G = dgamma),
// alpha0^3 = 9 pi / 2 (JKR's zero-load radius a^3 = 9 pi dgamma R^2 / (2 E*)), delta0 = alpha0^2 -
// sqrt(2 pi alpha0). The peak tension is the root of df/dtau = 2 (-beta alpha + alpha' e), found
// by redoing the step that brackets it; while the front is slow the walk goes in tau, and once
// it runs (|alpha'| >= 1) in alpha down to 0 (dtau/dalpha -> 0 there, where G grows as 1/alpha).
#pragma once

namespace mdrsim::test {

/// One state of the dimensionless retraction (scales in the file's header).
struct RateLawState {
  double tau = 0.0;           ///< time / (L / v*)
  double alpha = 0.0;         ///< contact radius / L
  double delta = 0.0;         ///< indentation / (L^2 / R)
  double force = 0.0;         ///< F / (dgamma R)
  double dissipated = 0.0;    ///< int (G - dgamma) 2 pi a |da| / (dgamma L^2), from the start
  double machine_work = 0.0;  ///< int F dd / (dgamma L^2), from the start
};

struct RateLawRetraction {
  RateLawState start;  ///< JKR's zero-force state
  RateLawState peak;   ///< the largest tension
  RateLawState lost;   ///< the front reaching a = 0: the contact lost
};

/// The retraction at beta and exponent n in (0, 1], integrated by Runge-Kutta-Fehlberg 7(8)
/// with relative and absolute tolerance rtol.
RateLawRetraction rate_law_retraction(double beta, double exponent, double rtol);

/// The scales: L [m], L^2 / R [m], L / v* [s], dgamma R [N],
/// dgamma L^2 [J] for E* [Pa], R [m], dgamma [J/m^2], v* [m/s].
struct RateLawScales {
  double length;       ///< L [m]
  double indentation;  ///< L^2 / R [m]
  double time;         ///< L / v* [s]
  double force;        ///< dgamma R [N]
  double energy;       ///< dgamma L^2 [J]
};
RateLawScales rate_law_scales(double effective_modulus, double radius, double work_of_adhesion,
                              double front_speed);

/// JKR's fixed-grips path of the same parabola (the beta -> 0 limit), dimensionless: the peak
/// tension -3 pi / 2 at alpha^3 = 9 pi / 8, the loss of stability at alpha_c^3 = pi / 8 where
/// d delta / d alpha = 0 on the branch delta = alpha^2 - sqrt(2 pi alpha).
double jkr_fixed_grips_peak_force();
double jkr_fixed_grips_pull_off_indentation();

}  // namespace mdrsim::test
