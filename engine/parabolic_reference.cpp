// Closed forms and their critical points; roots by TOMS 748 to full double precision.
#include "engine/parabolic_reference.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace mdrsim::parabolic_reference {
namespace {

template <class Fn>
double root_between(Fn fn, double lo, double hi) {
  std::uintmax_t iterations = 300;
  const auto r = boost::math::tools::toms748_solve(
      fn, lo, hi,
      boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 1),
      iterations);
  return 0.5 * (r.first + r.second);
}

/// sqrt(16 a - gamma u^2), the boundary elongation of eq. 25 in units of d0.
double stretch(double a, double u, double gamma) { return std::sqrt(16.0 * a - gamma * u * u); }

CriticalPoint point_at(double a, double u, double gamma) {
  return {a, indentation(a, u, gamma), normal_force(a, u, gamma), tangential_force(a, u, gamma)};
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
  const double a = root_between(eq31, 0.0, upper_bracket(eq31, 1.0));
  return point_at(a, u, gamma);
}

// Eq. 29 on a > gamma u^2 / 16 (where eq. 25 is real); negative at that end.
CriticalPoint fixed_load_critical(double u, double gamma) {
  const double a_min = gamma * u * u / 16.0;
  const auto eq29 = [&](double a) {
    return a * a * std::sqrt(a - a_min) - a + gamma * u * u / 24.0;
  };
  const double lo = a_min > 0.0 ? a_min : 1e-12;
  const double a = root_between(eq29, lo, upper_bracket(eq29, std::max(1.0, 2.0 * lo)));
  return point_at(a, u, gamma);
}

CriticalPoint compliant_critical(double stiffness, double u, double gamma) {
  if (!(stiffness > 0.0)) throw std::invalid_argument("stiffness must be positive");
  const double lo = fixed_grips_critical(u, gamma).contact_radius;
  const double hi = fixed_load_critical(u, gamma).contact_radius;
  const auto fold = [&](double a) {
    return normal_force_slope(a, u, gamma) + stiffness * indentation_slope(a, u, gamma);
  };
  return point_at(root_between(fold, lo, hi), u, gamma);
}

double fixed_grips_master_curve(double fx, double gamma) {
  return fx * fx / (4.0 * gamma) - 5.0 / 9.0;
}

}  // namespace mdrsim::parabolic_reference
