// Dawson's function, Lee-Radok's and Ting's forces and their quadrature checks (lee_radok.hpp
// derives them).
#include "tests/support/lee_radok.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace mdrsim::test {
namespace {

// The Maclaurin series sum_{n >= first} (-1)^n 2^n x^(2n+1) / (2n+1)!!: below |x| = 1 its
// terms never exceed about 3 |D(x)|, so it keeps double precision.
double dawson_series(double x, int first) {
  const double minus_two_x2 = -2.0 * x * x;
  double term = x;
  for (int n = 0; n < first; ++n) {
    term *= minus_two_x2 / (2 * n + 3);
  }
  double sum = 0.0;
  for (int n = first; n < 200; ++n) {
    sum += term;
    if (std::abs(term) <= 1e-18 * std::abs(sum)) {
      break;
    }
    term *= minus_two_x2 / (2 * n + 3);
  }
  return sum;
}

// Rybicki: D(x) = lim_{h -> 0} pi^(-1/2) sum_{n odd} exp(-(x - n h)^2) / n, with an error of
// about exp(-(pi / 2h)^2) ~ 1e-27 at h = 0.2; terms with |x - n h| > 7 are below 1e-21 of the sum.
double dawson_rybicki(double x) {
  constexpr double kStep = 0.2;
  constexpr double kReach = 7.0;
  const auto lowest = static_cast<std::int64_t>(std::floor((x - kReach) / kStep));
  const auto highest = static_cast<std::int64_t>(std::ceil((x + kReach) / kStep));
  long double sum = 0.0L;
  for (std::int64_t n = lowest; n <= highest; ++n) {
    if (n % 2 == 0) {
      continue;
    }
    const long double offset = static_cast<long double>(x) - n * static_cast<long double>(kStep);
    sum += std::exp(-offset * offset) / static_cast<long double>(n);
  }
  return static_cast<double>(sum / std::sqrt(std::numbers::pi_v<long double>));
}

// 1/(2x) sum_n (2n - 1)!! / (2 x^2)^n: at x > 50 the sixth term is below 1e-20.
double dawson_asymptotic(double x) {
  const double inverse_2x2 = 0.5 / (x * x);
  double term = 1.0, sum = 0.0;
  for (int n = 0; n < 8; ++n) {
    sum += term;
    term *= (2 * n + 1) * inverse_2x2;
  }
  return sum / (2.0 * x);
}

// The integrands are smooth (entire in the variable): the 61-point rule alone reaches a few ulps,
// and roundoff keeps the error estimate above 1e-14 of the integral, so the bisections stop at a
// depth that costs little.
constexpr double kQuadratureTolerance = 1e-14;
constexpr unsigned kQuadratureDepth = 6;

// A root in [low, high] of a function that changes sign there, to a few ulps.
template <class F>
double bracketed_root_of(F f, double low, double high) {
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      f, low, high, boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (a + b);
}

}  // namespace

double dawson(double x) {
  const double ax = std::abs(x);
  const double value = ax < 1.0    ? dawson_series(ax, 0)
                       : ax < 50.0 ? dawson_rybicki(ax)
                                   : dawson_asymptotic(ax);
  return std::copysign(value, x);
}

double dawson_complement(double z) {
  return std::abs(z) < 1.0 ? -dawson_series(z, 1) : z - dawson(z);
}

double StandardLinearSolid::relaxation(double t) const {
  return relaxed_modulus + arm_modulus * std::exp(-t / relaxation_time);
}

double StandardLinearSolid::relaxation_integral(double t) const {
  return relaxed_modulus * t - arm_modulus * relaxation_time * std::expm1(-t / relaxation_time);
}

double ParabolaRamp::indentation(double t) const {
  return t <= turn_time ? speed * t : speed * (2.0 * turn_time - t);
}

double hertz_force(double modulus, double radius, double indentation) {
  return indentation <= 0.0
             ? 0.0
             : 4.0 / 3.0 * modulus * std::sqrt(radius) * indentation * std::sqrt(indentation);
}

namespace {

// (4 sqrt(R) / 3) V^(3/2) [E*_inf t_1^(3/2) + (3/2) E*_1 tau^(3/2) exp(-(t - t_1)/tau)
// (sqrt(x_1) - D(sqrt(x_1)))]: Ting's force with matching time t_1, Lee-Radok's at t_1 = t.
double force_from_matching_time(const StandardLinearSolid& solid, const ParabolaRamp& ramp,
                                double t, double t1) {
  const double tau = solid.relaxation_time;
  const double relaxed = solid.relaxed_modulus * t1 * std::sqrt(t1);
  const double arm = 1.5 * solid.arm_modulus * tau * std::sqrt(tau) * std::exp(-(t - t1) / tau) *
                     dawson_complement(std::sqrt(t1 / tau));
  return 4.0 / 3.0 * std::sqrt(ramp.radius) * ramp.speed * std::sqrt(ramp.speed) * (relaxed + arm);
}

}  // namespace

double lee_radok_force(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t) {
  return force_from_matching_time(solid, ramp, t, t);
}

double lee_radok_force_by_quadrature(const StandardLinearSolid& solid, const ParabolaRamp& ramp,
                                     double t) {
  // s = u^2: E*(t - u^2) 2 sqrt(R) V^(3/2) u 2u du, smooth on [0, sqrt(t)].
  const double scale = 2.0 * std::sqrt(ramp.radius) * ramp.speed * std::sqrt(ramp.speed);
  const auto integrand = [&](double u) { return solid.relaxation(t - u * u) * 2.0 * u * u; };
  return scale * boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                     integrand, 0.0, std::sqrt(t), kQuadratureDepth, kQuadratureTolerance);
}

double ting_separation_time(const StandardLinearSolid& solid, const ParabolaRamp& ramp) {
  const double tm = ramp.turn_time;
  const auto balance = [&](double t) {
    return solid.relaxation_integral(t) - 2.0 * solid.relaxation_integral(t - tm);
  };
  if (balance(2.0 * tm) >= 0.0) {
    return 2.0 * tm;  // an elastic solid: psi linear
  }
  return bracketed_root_of(balance, tm, 2.0 * tm);
}

double ting_matching_time(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t) {
  const double tm = ramp.turn_time;
  if (t <= tm) {
    return t;
  }
  const double unloaded = 2.0 * solid.relaxation_integral(t - tm);
  if (solid.relaxation_integral(t) <= unloaded) {
    return 0.0;
  }
  return bracketed_root_of([&](double t1) { return solid.relaxation_integral(t - t1) - unloaded; },
                           0.0, tm);
}

double ting_contact_radius(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t) {
  return std::sqrt(ramp.radius * ramp.speed * ting_matching_time(solid, ramp, t));
}

double ting_force(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t) {
  const double t1 = ting_matching_time(solid, ramp, t);
  return t1 <= 0.0 ? 0.0 : force_from_matching_time(solid, ramp, t, t1);
}

double ting_force_by_springs(const StandardLinearSolid& solid, const ParabolaRamp& ramp, double t) {
  const double a = ting_contact_radius(solid, ramp, t);
  if (a <= 0.0) {
    return 0.0;
  }
  const double rv = ramp.radius * ramp.speed;
  const double unloaded =
      t <= ramp.turn_time ? 0.0 : 2.0 * solid.relaxation_integral(t - ramp.turn_time);
  const auto line_load = [&](double x) {
    return ramp.speed * (solid.relaxation_integral(t - x * x / rv) - unloaded);
  };
  return 2.0 * boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                   line_load, 0.0, a, kQuadratureDepth, kQuadratureTolerance);
}

}  // namespace mdrsim::test
