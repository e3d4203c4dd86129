// What is zero in a run: the force, displacement and work below which a value is rounding.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/base/hess_scale.hpp"

namespace mdrsim {

/// A run's sums (of up to 2^25 springs) round at 1e-16 to 1e-13 of their terms; the values
/// rounding makes appear on real paths (a "peak" of -1e-21 N, a critical point at
/// -2.2e-22 N, both on paths of 1e-3 N) lie at 1e-18 of the scale and below. A genuine fold
/// 2.4e-6 of the glued radius of an 85 degree cone lies at 2e-11 of it: above this.
inline constexpr double kRoundingShare = 1e-12;

/// Values below these are zero: decided once per run, from the scene alone (never from the
/// path, so that every row of a resolution sequence draws the line at the same place).
struct ZeroScale {
  double force = 0.0;         ///< [N]
  double displacement = 0.0;  ///< [m]
  double work = 0.0;          ///< [J]
  /// The contact's own force, of which `force` is the rounding: what a finite force is
  /// measured against (loss_status.hpp) [N].
  double contact_force = 0.0;

  bool zero_force(double f) const { return std::abs(f) <= force; }
  bool zero_displacement(double d) const { return std::abs(d) <= displacement; }
  bool zero_work(double w) const { return std::abs(w) <= work; }
};

/// The scale of a contact of radius `radius` [m] (the glued radius, or the largest one a
/// program reaches) on E* [Pa]: its depth D the larger of `image` (g at that radius [m]) and
/// the Hess length 2 pi dgamma / E* [m], its force the larger of E* a D (half a flat punch of
/// radius a pressed to D) and `held_force` [N] (a preload or held load), its work force times
/// D. Each times kRoundingShare, and the force itself as `contact_force`.
inline ZeroScale zero_scale(double effective_modulus, double radius, double image,
                            double work_of_adhesion, double held_force = 0.0) {
  const double hess = hess_scale(work_of_adhesion, effective_modulus);
  const double depth = std::max(std::abs(image), hess);
  const double force = std::max(effective_modulus * radius * depth, std::abs(held_force));
  const auto finite = [](double v) { return std::isfinite(v) ? v : 0.0; };
  return {finite(kRoundingShare * force), finite(kRoundingShare * depth),
          finite(kRoundingShare * force * depth), finite(force)};
}

}  // namespace mdrsim
