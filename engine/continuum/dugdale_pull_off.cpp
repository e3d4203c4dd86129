// The continuum route's pull-off with finite-range adhesion: folds of F(a), d(a) and d(c).
#include "engine/continuum/dugdale_pull_off.hpp"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "engine/base/bracketed_root.hpp"

namespace mdrsim {
namespace {

/// Samples of the contact branch from a_g down: a_k = a_g (k/K)^2, denser near the closing
/// point, where the DMT side's folds sit (a fold at 1e-2 of a_g is 13 samples above a = 0).
constexpr int kSamples = 512;

double sample_radius(double glued_radius, int k) {
  const double s = static_cast<double>(k) / kSamples;
  return glued_radius * s * s;
}

/// The first local minimum of value(a) going down from a_g over the samples, refined by Brent
/// (its place to sqrt(eps), its value, quadratic there, to the last bits); nullopt where value
/// falls all the way to the smallest sample.
template <class Value>
std::optional<double> first_minimum_going_down(double glued_radius, Value value) {
  double above = value(glued_radius);
  for (int k = kSamples - 1; k >= 1; --k) {
    const double here = value(sample_radius(glued_radius, k));
    if (here >= above) {
      const double lo = sample_radius(glued_radius, k);
      const double width = sample_radius(glued_radius, std::min(kSamples, k + 2)) - lo;
      // Over the bracket's unit interval: Brent's tolerance has an absolute part (a quarter of
      // its relative one) that in metres would stop it 1e-5 of a radius off the minimum.
      const double s =
          boost::math::tools::brent_find_minima([&](double u) { return value(lo + u * width); },
                                                0.0, 1.0, std::numeric_limits<double>::digits)
              .first;
      return lo + s * width;
    }
    above = here;
  }
  return std::nullopt;
}

}  // namespace

DugdalePullOff dugdale_fixed_load_pull_off(const Profile& profile, const DugdaleLaw& law,
                                           double glued_radius) {
  const auto force = [&](double a) { return dugdale_contact_state(profile, law, a).normal_force; };
  if (const auto a = first_minimum_going_down(glued_radius, force)) {
    return {dugdale_contact_state(profile, law, *a), true};
  }
  return {dugdale_free_state(profile, law, dugdale_closing_radius(profile, law)), true};
}

DugdalePullOff dugdale_fixed_grips_pull_off(const Profile& profile, const DugdaleLaw& law,
                                            double glued_radius) {
  const auto depth = [&](double a) { return dugdale_contact_state(profile, law, a).indentation; };
  if (const auto a = first_minimum_going_down(glued_radius, depth)) {
    return {dugdale_contact_state(profile, law, *a), true};
  }
  // The contact closed: d(c) on the no-contact branch from c0 down, with d'(c) = f'(c) - p.
  const double c0 = dugdale_closing_radius(profile, law);
  const double pull = 4.0 * law.adhesive_stress / (std::numbers::pi * law.effective_modulus);
  const auto slope = [&](double c) {
    const double h = 1e-6 * c;  // f' by a central difference: f is smooth away from r = 0
    return (profile.shape(c + h) - profile.shape(c - h)) / (2.0 * h) - pull;
  };
  if (!(slope(c0) > 0.0)) return {dugdale_free_state(profile, law, c0), true};
  // Going down from c0 while d'(c) > 0: the first c where it turns, on a geometric scan (the
  // parabola's fold c = 4 sigma_0 R/(pi E*) lies at 1e-3 of c0 at lambda = 0.01) down to
  // 1e-12 of c0, below which the zone carries nothing a force could show.
  double above = c0;
  for (int k = 1; k <= 8 * 40; ++k) {
    const double c = c0 * std::exp2(-k / 8.0);
    if (!(slope(c) > 0.0)) {
      const double at = bracketed_root(slope, c, above);
      return {dugdale_free_state(profile, law, at), true};
    }
    above = c;
  }
  return {dugdale_free_state(profile, law, 0.0), false};
}

}  // namespace mdrsim
