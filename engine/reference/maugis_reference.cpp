// Maugis' classical solution of the adhesive parabola with a Dugdale zone, in his own variables.
#include "engine/reference/maugis_reference.hpp"

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace mdrsim::maugis_reference {
namespace {

constexpr double kPi = std::numbers::pi;

/// tan t - t, by its series below t = 0.1 where the difference cancels (terms to t^13: the
/// next is below 1e-14 of the sum there).
double tan_minus_angle(double t) {
  if (t >= 0.1) return std::tan(t) - t;
  const double t2 = t * t;
  return t * t2 *
         (1.0 / 3.0 +
          t2 * (2.0 / 15.0 +
                t2 * (17.0 / 315.0 +
                      t2 * (62.0 / 2835.0 + t2 * (1382.0 / 155925.0 + t2 * 21844.0 / 6081075.0)))));
}

/// The opening condition's left side less 1, at t = arctan sqrt(m^2 - 1).
double opening(double lambda, double a, double t) {
  const double tan_t = std::tan(t);
  // tan t + (m^2 - 2) t = (tan t - t) + t tan^2 t.
  const double first = tan_minus_angle(t) + t * tan_t * tan_t;
  // t tan t - (m - 1), with m - 1 = 2 sin^2(t/2) / cos t.
  const double half = std::sin(0.5 * t);
  const double second = t * tan_t - 2.0 * half * half / std::cos(t);
  return 0.5 * lambda * a * a * first + 4.0 * lambda * lambda * a / 3.0 * second - 1.0;
}

double root(auto f, double lo, double hi) {
  std::uintmax_t iterations = 300;
  const auto tol = boost::math::tools::eps_tolerance<double>(52);
  const auto r = boost::math::tools::toms748_solve(f, lo, hi, tol, iterations);
  return 0.5 * (r.first + r.second);
}

/// The minimum of f on [lo, hi] sampled at `samples` points and refined by Brent's method;
/// the first local minimum from `from_high` when asked (else the global one).
template <class F>
double sampled_minimum(F f, double lo, double hi, int samples) {
  double best = lo;
  double best_value = f(lo);
  for (int i = 1; i <= samples; ++i) {
    const double x = lo + (hi - lo) * i / samples;
    const double v = f(x);
    if (v < best_value) best = x, best_value = v;
  }
  const double step = (hi - lo) / samples;
  const double left = std::max(lo, best - step), right = std::min(hi, best + step);
  const auto m = boost::math::tools::brent_find_minima(f, left, right, 60);
  return m.second < best_value ? m.first : best;
}

}  // namespace

double MaugisScales::length() const {
  return std::cbrt(kPi * work * radius * radius / (4.0 * modulus / 3.0));
}

double MaugisScales::depth() const { return length() * length() / radius; }

double MaugisScales::force() const { return kPi * work * radius; }

double MaugisScales::adhesive_stress(double lambda) const {
  const double k = 4.0 * modulus / 3.0;
  return 0.5 * lambda * std::cbrt(kPi * work * k * k / radius);
}

MaugisState contact_branch(double lambda, double contact_radius) {
  if (!(lambda > 0.0) || !(contact_radius > 0.0)) {
    throw std::invalid_argument("maugis_reference: lambda and A must be > 0");
  }
  const double a = contact_radius;
  const double top = 0.5 * kPi * (1.0 - std::numeric_limits<double>::epsilon());
  const double t = root([&](double x) { return opening(lambda, a, x); }, 0.0, top);
  const double tan_t = std::tan(t), m = 1.0 / std::cos(t);
  return {.contact_radius = a,
          .cohesive_radius = m * a,
          .indentation = a * a - 4.0 / 3.0 * a * lambda * tan_t,
          .force = a * a * a - lambda * a * a * (tan_t + m * m * t)};
}

MaugisState no_contact_branch(double lambda, double cohesive_radius) {
  const double c = cohesive_radius;
  return {.contact_radius = 0.0,
          .cohesive_radius = c,
          .indentation = 0.5 * c * c - 8.0 * lambda / (3.0 * kPi) * c - 2.0 / (kPi * lambda),
          .force = -0.5 * kPi * lambda * c * c};
}

double closing_cohesive_radius(double lambda) {
  // (pi lambda/4) C^2 + (4 lambda^2/3)(pi/2 - 1) C - 1 = 0, the positive root in stable form.
  const double qa = 0.25 * kPi * lambda, qb = 4.0 * lambda * lambda / 3.0 * (0.5 * kPi - 1.0);
  return 2.0 / (qb + std::sqrt(qb * qb + 4.0 * qa));
}

MaugisState fixed_load_pull_off(double lambda) {
  const MaugisState closed = no_contact_branch(lambda, closing_cohesive_radius(lambda));
  const auto force = [&](double a) {
    return a > 0.0 ? contact_branch(lambda, a).force : closed.force;
  };
  const double a = sampled_minimum(force, 0.0, 4.0, 800);
  return a > 0.0 ? contact_branch(lambda, a) : closed;
}

double grips_threshold() { return std::cbrt(9.0 * kPi / (16.0 * (kPi - 1.0))); }

MaugisState fixed_grips_jump(double lambda) {
  // The contact closes first: the no-contact branch folds at C = 8 lambda / (3 pi) <= C0.
  if (lambda <= grips_threshold()) {
    return no_contact_branch(lambda, 8.0 * lambda / (3.0 * kPi));
  }
  // Down the contact branch from A = 4 (far beyond any fold) while D falls with A: evenly to
  // A = 1e-3, then geometrically, since near the threshold the fold sits just above A = 0
  // (D - D(0) grows like A^2 with a factor that vanishes there).
  constexpr int kSamples = 4000;
  constexpr double kTop = 4.0;
  const auto depth = [&](double x) { return contact_branch(lambda, x).indentation; };
  std::vector<double> radii;
  for (int i = kSamples; i >= 1; --i) radii.push_back(kTop * i / kSamples);
  for (double a = kTop / kSamples * 0.9; a > 1e-7; a *= 0.9) radii.push_back(a);
  double previous = depth(radii[0]);
  for (std::size_t i = 1; i < radii.size(); ++i) {
    const double d = depth(radii[i]);
    if (d >= previous) {  // D turned between radii[i] and radii[i - 2]: refine its minimum
      const double upper = radii[i >= 2 ? i - 2 : 0];
      return contact_branch(
          lambda, boost::math::tools::brent_find_minima(depth, radii[i], upper, 60).first);
    }
    previous = d;
  }
  throw std::logic_error("maugis_reference: no fold of D above the threshold");
}

}  // namespace mdrsim::maugis_reference
