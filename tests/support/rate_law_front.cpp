// The rate-law retraction of an elastic parabola under fixed grips, integrated apart from the
// engine (rate_law_front.hpp gives the equations and scales).
#include "tests/support/rate_law_front.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
// Odeint's steppers copy their scratch arrays, unset until the first step, when the controlled
// stepper is built; GCC at -O3 sees the copy of the unset std::array.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

namespace mdrsim::test {
namespace {

constexpr double kPi = std::numbers::pi;
// Three numbers ride along: in the tau walk (alpha, dissipated, work), in the alpha walk
// (tau, dissipated, work).
using RateLawVector = std::array<double, 3>;
using RateLawStepper = boost::numeric::odeint::runge_kutta_fehlberg78<RateLawVector>;

struct RateLawProblem {
  double beta;
  double exponent;
  double delta0;

  double delta_at(double tau) const { return delta0 - beta * tau; }
  static double release_over_threshold(double alpha, double delta) {
    const double e = delta - alpha * alpha;
    return e * e / (2.0 * kPi * alpha);
  }
  static double force(double alpha, double delta) {
    return 2.0 * (delta * alpha - alpha * alpha * alpha / 3.0);
  }
  /// -d alpha / d tau
  double front_speed(double alpha, double delta) const {
    const double excess = release_over_threshold(alpha, delta) - 1.0;
    return excess > 0.0 ? std::pow(excess, 1.0 / exponent) : 0.0;
  }
  /// d f / d tau / 2: negative while the tension grows.
  double force_slope(double alpha, double delta) const {
    return -beta * alpha - front_speed(alpha, delta) * (delta - alpha * alpha);
  }
  // In tau: y = (alpha, dissipated, work).
  void in_time(const RateLawVector& y, RateLawVector& dy, double tau) const {
    const double alpha = std::max(y[0], 0.0);
    const double delta = delta_at(tau);
    const double speed = front_speed(alpha, delta);
    dy[0] = -speed;
    dy[1] = (release_over_threshold(alpha, delta) - 1.0) * 2.0 * kPi * alpha * speed;
    dy[2] = -beta * force(alpha, delta);
  }
  // In alpha (decreasing): y = (tau, dissipated, work); (G/dgamma - 1) 2 pi alpha written as
  // e^2 - 2 pi alpha, finite at alpha = 0.
  void in_radius(const RateLawVector& y, RateLawVector& dy, double alpha) const {
    const double delta = delta_at(y[0]);
    const double e = delta - alpha * alpha;
    const double excess_times = e * e - 2.0 * kPi * alpha;
    const double inverse_speed =
        alpha > 0.0 ? std::pow(2.0 * kPi * alpha / excess_times, 1.0 / exponent) : 0.0;
    dy[0] = -inverse_speed;
    dy[1] = -excess_times;
    dy[2] = beta * force(alpha, delta) * inverse_speed;
  }
};

RateLawState state_in_time(const RateLawProblem& p, const RateLawVector& y, double tau) {
  const double delta = p.delta_at(tau);
  return {tau, y[0], delta, RateLawProblem::force(y[0], delta), y[1], y[2]};
}
RateLawState state_in_radius(const RateLawProblem& p, const RateLawVector& y, double alpha) {
  const double delta = p.delta_at(y[0]);
  return {y[0], alpha, delta, RateLawProblem::force(alpha, delta), y[1], y[2]};
}

// Walks x from x0 by controlled steps while `go_on(state)` holds; where `slope(state)` turns from
// negative to non-negative within a step, that step is redone by the plain stepper with its
// length root-found (TOMS 748), and the state there is kept as the peak.
template <class System, class ToState, class GoOn>
RateLawVector walk(const System& system, RateLawVector y, double& x, double step, double rtol,
                   const ToState& to_state, const GoOn& go_on, const RateLawProblem& p,
                   bool& peak_found, RateLawState& peak) {
  namespace odeint = boost::numeric::odeint;
  auto controlled = odeint::make_controlled(rtol, rtol, RateLawStepper());
  RateLawStepper plain;
  const auto slope_of = [&](const RateLawState& s) { return p.force_slope(s.alpha, s.delta); };
  for (int steps = 0; steps < 10'000'000; ++steps) {
    const RateLawVector before = y;
    const double x_before = x;
    double tried = step;
    while (controlled.try_step(system, y, x, tried) == odeint::fail) {
    }
    const double taken = x - x_before;
    step = tried;
    const RateLawState now = to_state(y, x);
    if (!peak_found && slope_of(to_state(before, x_before)) < 0.0 && slope_of(now) >= 0.0) {
      const auto redo = [&](double h) {
        RateLawVector z = before;
        if (h != 0.0) plain.do_step(system, z, x_before, h);
        return z;
      };
      const auto slope_after = [&](double h) { return slope_of(to_state(redo(h), x_before + h)); };
      std::uintmax_t iterations = 200;
      const double lo = std::min(0.0, taken);
      const double hi = std::max(0.0, taken);
      const double scale = std::abs(taken);
      const auto bracket = boost::math::tools::toms748_solve(
          slope_after, lo, hi, slope_after(lo), slope_after(hi),
          [scale](double a, double b) { return std::abs(b - a) <= 1e-14 * scale; }, iterations);
      const double h = 0.5 * (bracket.first + bracket.second);
      peak = to_state(redo(h), x_before + h);
      peak_found = true;
    }
    if (!go_on(now, step)) return y;
  }
  throw std::runtime_error("rate_law_retraction: the walk took ten million steps");
}

}  // namespace

RateLawRetraction rate_law_retraction(double beta, double exponent, double rtol) {
  const double alpha0 = std::cbrt(4.5 * kPi);
  const double delta0 = alpha0 * alpha0 - std::sqrt(2.0 * kPi * alpha0);
  const RateLawProblem p{beta, exponent, delta0};
  RateLawRetraction out;
  out.start = {0.0, alpha0, delta0, RateLawProblem::force(alpha0, delta0), 0.0, 0.0};
  bool peak_found = false;

  // In time while the front is slower than v*.
  const auto in_time = [&](const RateLawVector& y, RateLawVector& dy, double tau) {
    p.in_time(y, dy, tau);
  };
  double tau = 0.0;
  // A first step of 1e-3 of the time the grips take to move by delta0 (or of L / v*).
  const double first_step = 1e-3 * std::min(1.0, std::abs(delta0) / beta);
  RateLawVector y = walk(
      in_time, RateLawVector{alpha0, 0.0, 0.0}, tau, first_step, rtol,
      [&](const RateLawVector& z, double t) { return state_in_time(p, z, t); },
      [&](const RateLawState& s, double& next) {
        // The walk in alpha needs G to grow all the way to alpha = 0: so the front runs
        // (G >= 2 dgamma), the grips are in tension (delta < 0), and 3 alpha^2 < -delta
        // (where G at fixed delta grows as alpha falls).
        if (p.front_speed(s.alpha, s.delta) >= 1.0 && 3.0 * s.alpha * s.alpha < -s.delta) {
          return false;
        }
        // The walk in tau must not step past alpha = 0 before the switch.
        next = std::min(next, 0.5 * s.alpha / std::max(p.front_speed(s.alpha, s.delta), 1e-300));
        return true;
      },
      p, peak_found, out.peak);

  // In alpha from the switch down to 0.
  const auto in_radius = [&](const RateLawVector& z, RateLawVector& dz, double alpha) {
    p.in_radius(z, dz, alpha);
  };
  double alpha = y[0];
  RateLawVector z{tau, y[1], y[2]};
  z = walk(
      in_radius, z, alpha, -1e-3 * alpha, rtol,
      [&](const RateLawVector& v, double a) { return state_in_radius(p, v, a); },
      [&](const RateLawState& s, double& next) {
        if (s.alpha <= 0.0) return false;
        if (s.alpha + next < 0.0) next = -s.alpha;  // land on alpha = 0 exactly
        return true;
      },
      p, peak_found, out.peak);
  out.lost = state_in_radius(p, z, 0.0);
  if (!peak_found) throw std::runtime_error("rate_law_retraction: no peak tension");
  return out;
}

RateLawScales rate_law_scales(double effective_modulus, double radius, double work_of_adhesion,
                              double front_speed) {
  const double length = std::cbrt(work_of_adhesion * radius * radius / effective_modulus);
  return {length, length * length / radius, length / front_speed, work_of_adhesion * radius,
          work_of_adhesion * length * length};
}

double jkr_fixed_grips_peak_force() { return -1.5 * kPi; }

double jkr_fixed_grips_pull_off_indentation() {
  const double alpha_c = std::cbrt(kPi / 8.0);
  return alpha_c * alpha_c - std::sqrt(2.0 * kPi * alpha_c);
}

}  // namespace mdrsim::test
