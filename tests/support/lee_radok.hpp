// Lee-Radok's loading and Ting's unloading of a parabola driven at constant speed into a standard
// linear solid, written apart from the engine: the references of the viscoelastic springs.
//
// Moduli. Every modulus here is a plane-strain one, E* = E / (1 - nu^2) with nu constant in time,
// as the engine's springs take material.youngs_modulus and material.relaxation: the relaxation
// function is E*(t) = E*_inf + E*_1 exp(-t / tau) and its integral psi(t) = int_0^t E*(s) ds =
// E*_inf t + E*_1 tau (1 - exp(-t / tau)). E*_0 = E*_inf + E*_1 is the glassy modulus.
//
// Path. The indentation d(t) = V t up to the turn t_m, then d(t) = V (2 t_m - t).
//
// Loading (t <= t_m, Lee and Radok 1960). With the contact radius growing, Hertz's force with a
// unit modulus, F_H(s) = (4 sqrt(R) / 3) d(s)^(3/2), is convolved with the relaxation function:
//   F(t) = int_0^t E*(t - s) dF_H/ds ds,  dF_H/ds = 2 sqrt(R) V^(3/2) s^(1/2).
// The arm's part, int_0^t exp(-(t - s) / tau) s^(1/2) ds, is with s = tau v^2 and x = t / tau
//   2 tau^(3/2) exp(-x) int_0^sqrt(x) v^2 exp(v^2) dv = tau^(3/2) (sqrt(x) - D(sqrt(x)))
// (by parts: int v^2 e^(v^2) = v e^(v^2) / 2 - int e^(v^2) / 2; D(z) = exp(-z^2) int_0^z
// exp(v^2) dv is Dawson's function), so
//   F(t) = (4 sqrt(R) / 3) V^(3/2) [E*_inf t^(3/2) + (3/2) E*_1 tau^(3/2) (sqrt(x) - D(sqrt(x)))].
//
// Unloading (t > t_m, Ting 1966). In the MDR's picture each spring at x is touched when d =
// x^2 / R, at t_in(x) = x^2 / (R V), and its line load from then on is
//   q(x, t) = int_t_in^t E*(t - s) d'(s) ds = V [psi(t - t_in) - 2 psi(t - t_m)]   (t > t_m),
// the same for every spring up to its t_in. q falls with t_in, so the springs still pressed are
// those touched before t_1(t), the contact's edge carrying q = 0:
//   psi(t - t_1) = 2 psi(t - t_m),   a(t) = sqrt(R V t_1(t))
// (Ting's condition: the radius now is the radius the loading had at t_1). Differentiating,
// dt_1/dt = 1 - 2 E*(t - t_m) / E*(t - t_1) <= -1, so the contact shrinks monotonically, as
// Ting's solution needs, and a spring leaves as its load reaches zero. The force is
//   F(t) = 2 int_0^a q dx = V sqrt(R V) int_0^t_1 [psi(t - s) - 2 psi(t - t_m)] s^(-1/2) ds
//        = 2 sqrt(R) V^(3/2) int_0^t_1 E*(t - s) s^(1/2) ds          (by parts; q(t_1) = 0)
//        = (4 sqrt(R) / 3) V^(3/2) [E*_inf t_1^(3/2)
//            + (3/2) E*_1 tau^(3/2) exp(-(t - t_1) / tau) (sqrt(x_1) - D(sqrt(x_1)))],
// x_1 = t_1 / tau: Ting's F(t) = (4 / (3 R)) int_0^t_1 E*(t - s) d(a^3)/ds ds, which at t_1 = t
// is Lee-Radok's. The contact is lost when t_1 reaches 0: psi(t_s) = 2 psi(t_s - t_m), in
// (t_m, 2 t_m] since psi is concave (2 t_m for an elastic solid). A spring that has left carries
// no load and creeps back; the solution assumes the indenter, withdrawing, never meets it again.
#pragma once

namespace mdrsim::test {

/// Dawson's function D(x) = exp(-x^2) int_0^x exp(t^2) dt, to about 1e-15 relative: its
/// Maclaurin series below |x| = 1, Rybicki's sum (h = 0.2, error ~ exp(-(pi / 2h)^2)) above,
/// the asymptotic series 1/(2x) (1 + 1/(2x^2) + ...) beyond |x| = 50.
double dawson(double x);
/// z - D(z) without the cancellation at small z (its series from z^3 on below z = 1).
double dawson_complement(double z);

/// E*(t) = E*_inf + E*_1 exp(-t / tau), plane-strain moduli.
struct StandardLinearSolid {
  double relaxed_modulus;  ///< E*_inf [Pa]
  double arm_modulus;      ///< E*_1 [Pa]
  double relaxation_time;  ///< tau [s]

  /// E*(t) [Pa].
  double relaxation(double t) const;
  /// psi(t) = int_0^t E*(s) ds [Pa s].
  double relaxation_integral(double t) const;
  /// E*_0 = E*_inf + E*_1 [Pa].
  double glassy_modulus() const { return relaxed_modulus + arm_modulus; }
};

/// A parabola f = r^2 / (2R) pressed at speed V up to t_m and withdrawn at the same speed.
struct ParabolaRamp {
  double radius;     ///< R [m]
  double speed;      ///< V [m/s] > 0
  double turn_time;  ///< t_m [s]

  /// d(t) [m].
  double indentation(double t) const;
};

/// Hertz's force (4/3) E* sqrt(R) d^(3/2) [N] (0 for d <= 0).
double hertz_force(double modulus, double radius, double indentation);

/// Lee-Radok's force [N] at t <= t_m by the closed form above.
double lee_radok_force(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t);
/// The same by a quadrature of int_0^t E*(t - s) dF_H/ds ds (s = u^2, Gauss-Kronrod to 1e-14).
double lee_radok_force_by_quadrature(const StandardLinearSolid& solid, const ParabolaRamp& ramp,
                                     double t);

/// Ting's t_1(t) [s]: t itself up to t_m, then the root of psi(t - t_1) = 2 psi(t - t_m) in
/// [0, t_m]; 0 once the contact is lost.
double ting_matching_time(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t);
/// The contact radius a(t) = sqrt(R V t_1(t)) [m].
double ting_contact_radius(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t);
/// The force [N] at any t >= 0 (Lee-Radok's up to t_m, Ting's after, 0 once separated).
double ting_force(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t);
/// The same by the springs' sum 2 V int_0^a [psi(t - x^2/(RV)) - 2 psi(t - t_m)] dx (the last
/// term only after t_m; Gauss-Kronrod to 1e-14), without the integration by parts.
double ting_force_by_springs(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t);
/// The time [s] the contact is lost: psi(t_s) = 2 psi(t_s - t_m), t_m < t_s <= 2 t_m.
double ting_separation_time(const StandardLinearSolid& solid, const ParabolaRamp& ramp);

}  // namespace mdrsim::test
