// Closed forms and their critical points; roots by TOMS 748 to full double precision.
#include "engine/reference/parabolic_reference.hpp"

#include "engine/base/bracketed_root.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace mdrsim::parabolic_reference {
namespace {

/// sqrt(16 a - gamma u^2), the boundary elongation of eq. 25 in units of d0.
double stretch(double a, double u, double gamma) { return std::sqrt(16.0 * a - gamma * u * u); }

CriticalPoint point_at(double a, double u, double gamma) {
  return {a, indentation(a, u, gamma), normal_force(a, u, gamma), tangential_force(a, u, gamma), u};
}

/// Smallest power of two times `start` at which fn turns positive.
template <class Fn>
double upper_bracket(Fn fn, double start) {
  double hi = start;
  while (fn(hi) <= 0.0) hi *= 2.0;
  return hi;
}

}  // namespace

double indentation(double a, double u, double gamma) { return 3.0 * a * a - stretch(a, u, gamma); }

double normal_force(double a, double u, double gamma) {
  return 0.5 * a * (indentation(a, u, gamma) - a * a);
}

double tangential_force(double a, double u, double gamma) { return 0.5 * gamma * a * u; }

double indentation_slope(double a, double u, double gamma) {
  return 6.0 * a - 8.0 / stretch(a, u, gamma);
}

// F = a^3 - a S / 2 with S = sqrt(16 a - gamma u^2), S' = 8 / S.
double normal_force_slope(double a, double u, double gamma) {
  const double s = stretch(a, u, gamma);
  return 3.0 * a * a - 0.5 * s - 4.0 * a / s;
}

// Eq. 31: a^3 - gamma/16 (u a)^2 - 1/9 = 0, negative from a = 0 up to its one positive root.
CriticalPoint fixed_grips_critical(double u, double gamma) {
  const auto eq31 = [&](double a) { return a * a * a - gamma / 16.0 * u * u * a * a - 1.0 / 9.0; };
  const double a = bracketed_root(eq31, 0.0, upper_bracket(eq31, 1.0));
  return point_at(a, u, gamma);
}

// Eq. 29 on a > gamma u^2 / 16 (where eq. 25 is real); negative at that end.
CriticalPoint fixed_load_critical(double u, double gamma) {
  const double a_min = gamma * u * u / 16.0;
  const auto eq29 = [&](double a) {
    return a * a * std::sqrt(a - a_min) - a + gamma * u * u / 24.0;
  };
  const double lo = a_min > 0.0 ? a_min : 1e-12;
  const double a = bracketed_root(eq29, lo, upper_bracket(eq29, std::max(1.0, 2.0 * lo)));
  return point_at(a, u, gamma);
}

CriticalPoint compliant_critical(double stiffness, double u, double gamma) {
  if (!(stiffness > 0.0)) throw std::invalid_argument("stiffness must be positive");
  const double lo = fixed_grips_critical(u, gamma).contact_radius;
  const double hi = fixed_load_critical(u, gamma).contact_radius;
  const auto fold = [&](double a) {
    return normal_force_slope(a, u, gamma) + stiffness * indentation_slope(a, u, gamma);
  };
  return point_at(bracketed_root(fold, lo, hi), u, gamma);
}

double fixed_grips_master_curve(double fx, double gamma) {
  return fx * fx / (4.0 * gamma) - 5.0 / 9.0;
}

// ---- Tangential force held (fixed load tangentially) ----
//
// Eq. 27 solved for u with F_x held: u = 2 F_x/(gamma a). In eq. 25 gamma u^2 = 4 q/a^2 with
// q = F_x^2/gamma, so with S = sqrt(16 a - 4 q/a^2)
//   d = 3 a^2 - S,   F_z = (a/2)(d - a^2) = a^3 - a S/2   (eq. 26),
// real while a^3 >= q/4: below that the held force alone breaks the boundary spring
// (eq. 20 with u_z = 0; in SI units F_x^2 = 8 pi G* a^3 dgamma). The force held makes u grow
// as the contact shrinks, so S' = (8 + 4 q/a^3)/S has an extra term against eq. 25's 8/S.
//
// Fixed load normally, dF_z/da = 0: 3 a^2 - S/2 - a S'/2 = 0. Times 2 S:
//   6 a^2 S = S^2 + 8 a + 4 q/a^2 = 24 a,   so S = 4/a,
// and S^2 = 16/a^2 = 16 a - 4 q/a^2 gives a^3 = 1 + q/4, then F_z = a^3 - 2 = q/4 - 1 and
// d = 3 a^2 - 4/a. So F_z = F_x^2/(4 gamma) - 1: JKR's -1 shifted by the same term as the
// paper's eq. 34 shifts -5/9. The fold lies above the shear-off radius for every q
// (1 + q/4 > q/4), so the held force never shears the contact off before it jumps.
//
// Fixed grips normally, dd/da = 0: 6 a = S', i.e. 6 a S = 8 + 4 q/a^3. Both sides are
// positive, so squaring loses nothing: 36 a^2 (16 a - 4 q/a^2) = (8 + 4 q/a^3)^2, and with
// t = a^3 (times t^2/16)
//   36 t^3 - (9 q + 4) t^2 - 4 q t - q^2 = 0.
// Its coefficients change sign once: one positive root (Descartes). Divided by t^2 it reads
// 36 t - (9 q + 4) - 4 q/t - q^2/t^2, increasing in t, and equal to -36 at the shear-off
// radius t = q/4: the root lies above it. At the fold a S = (8 + 4 q/t)/6, so
//   F_z = t - 2/3 - q/(3 t),   d = 3 a^2 - (8 + 4 q/t)/(6 a).
// Checks: q = 0 gives t = 1/9, F_z = -5/9 (eq. 33); for q -> infinity t = q/4 + 1 + O(1/q)
// and F_z -> q/4 - 1: with the force held the fixed-grips curve joins the fixed-load one.

double indentation_at_tangential_force(double a, double fx, double gamma) {
  return indentation(a, 2.0 * fx / (gamma * a), gamma);
}

double normal_force_at_tangential_force(double a, double fx, double gamma) {
  return normal_force(a, 2.0 * fx / (gamma * a), gamma);
}

double shear_off_radius(double fx, double gamma) { return std::cbrt(fx * fx / (4.0 * gamma)); }

CriticalPoint fixed_grips_critical_at_tangential_force(double fx, double gamma) {
  const double q = fx * fx / gamma;
  const auto cubic_over_t2 = [&](double t) {
    return 36.0 * t - (9.0 * q + 4.0) - 4.0 * q / t - q * q / (t * t);
  };
  const double lo = q > 0.0 ? q / 4.0 : 1.0 / 36.0;  // -36 (q > 0) and -3 (q = 0) there
  const double t = bracketed_root(cubic_over_t2, lo, upper_bracket(cubic_over_t2, lo + 1.0));
  const double a = std::cbrt(t);
  return {a, 3.0 * a * a - (8.0 + 4.0 * q / t) / (6.0 * a), t - 2.0 / 3.0 - q / (3.0 * t), fx,
          2.0 * fx / (gamma * a)};
}

CriticalPoint fixed_load_critical_at_tangential_force(double fx, double gamma) {
  const double q = fx * fx / gamma;
  const double a = std::cbrt(1.0 + q / 4.0);
  return {a, 3.0 * a * a - 4.0 / a, q / 4.0 - 1.0, fx, 2.0 * fx / (gamma * a)};
}

double fixed_grips_master_curve_at_tangential_force(double fx, double gamma) {
  return fixed_grips_critical_at_tangential_force(fx, gamma).normal_force;
}

double fixed_load_master_curve_at_tangential_force(double fx, double gamma) {
  return fx * fx / (4.0 * gamma) - 1.0;
}

}  // namespace mdrsim::parabolic_reference
