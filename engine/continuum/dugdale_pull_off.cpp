// The continuum route's pull-off with finite-range adhesion: folds of F(a), d(a) and d(c).
#include "engine/continuum/dugdale_pull_off.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "engine/base/bracketed_root.hpp"
#include "engine/continuum/dugdale_branch_walk.hpp"

namespace mdrsim {
namespace {

/// Samples of the contact branch from a_g down: a_k = a_g (k/K)^2, denser near the closing
/// point, where the DMT side's folds sit (a fold at 1e-2 of a_g lies between the last two);
/// below a_g / K^2 the scan goes on in halvings down to 2^-18 a_g, where the fixed-grips fold
/// meets the closing point (lambda = 0.938).
constexpr int kSamples = 16;
constexpr int kHalvings = 10;

std::vector<double> sample_radii(double glued_radius) {
  std::vector<double> radii;
  for (int k = kSamples; k >= 1; --k) {
    const double u = static_cast<double>(k) / kSamples;
    radii.push_back(glued_radius * u * u);
  }
  for (int k = 1; k <= kHalvings; ++k) radii.push_back(std::ldexp(radii[kSamples - 1], -k));
  return radii;
}

/// The state at the first fold going down from a_g of a control whose slope along the contact
/// branch is `slope(DugdaleSlopes)`: the first sample where that slope stops being positive,
/// then its root (dugdale_contact_slopes, exact to rounding) by TOMS 748 between that sample
/// and the one above; a_g itself where it is not positive there; nullopt where it stays positive to
/// the smallest sample. The samples are taken one at a time (most folds lie within the first few),
/// each state from its neighbours' zones.
template <class Slope>
std::optional<DugdaleState> first_fold_going_down(const Profile& profile, const DugdaleLaw& law,
                                                  double glued_radius, Slope slope) {
  DugdaleBranchWalk walk(profile, law);
  const auto slope_at = [&](double a) { return slope(walk.slopes_at(a)); };
  const std::vector<double> radii = sample_radii(glued_radius);
  for (std::size_t k = 0; k < radii.size(); ++k) {
    if (slope_at(radii[k]) > 0.0) continue;
    if (k == 0) return walk.at(glued_radius);
    // The radius to 2^-40 of itself: the value there is flat, F'' da^2 / 2 below its rounding.
    const RootBracket root = bracket_root(slope_at, radii[k], radii[k - 1], 40);
    return walk.at(0.5 * (root.lo + root.hi));  // from the search's last zones
  }
  return std::nullopt;
}

}  // namespace

DugdalePullOff dugdale_fixed_load_pull_off(const Profile& profile, const DugdaleLaw& law,
                                           double glued_radius) {
  const auto force = [](const DugdaleSlopes& s) { return s.normal_force; };
  if (const auto fold = first_fold_going_down(profile, law, glued_radius, force)) {
    return {*fold, true};
  }
  return {dugdale_free_state(profile, law, dugdale_closing_radius(profile, law)), true};
}

DugdalePullOff dugdale_fixed_grips_pull_off(const Profile& profile, const DugdaleLaw& law,
                                            double glued_radius) {
  const auto depth = [](const DugdaleSlopes& s) { return s.indentation; };
  if (const auto fold = first_fold_going_down(profile, law, glued_radius, depth)) {
    return {*fold, true};
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
