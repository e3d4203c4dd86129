// The Dugdale law of a material with finite-range adhesion, and Maugis' parameter lambda of a
// parabolic tip (docs/maugis.md).
#pragma once

#include <cmath>
#include <numbers>

#include "engine/base/material.hpp"
#include "engine/model/dugdale_zone.hpp"

namespace mdrsim {

/// sigma_0, dgamma and E* of `m` (m.finite_range() for a law with a range).
inline DugdaleLaw dugdale_law(const Material& m) {
  return {.adhesive_stress = m.adhesive_stress,
          .work_of_adhesion = m.work_of_adhesion,
          .effective_modulus = m.effective_modulus};
}

/// (pi dgamma K^2 / R)^(1/3) [Pa] with K = 4 E*/3: the stress that lambda measures sigma_0 in,
/// lambda = 2 sigma_0 / that (Maugis 1992).
inline double maugis_stress_unit(double work_of_adhesion, double effective_modulus, double radius) {
  const double k = 4.0 * effective_modulus / 3.0;
  return std::cbrt(std::numbers::pi * work_of_adhesion * k * k / radius);
}

/// sigma_0 [Pa] from Maugis' lambda of a tip of radius R [m].
inline double adhesive_stress_of_maugis_parameter(double lambda, double work_of_adhesion,
                                                  double effective_modulus, double radius) {
  return 0.5 * lambda * maugis_stress_unit(work_of_adhesion, effective_modulus, radius);
}

/// Maugis' lambda [1] of sigma_0 [Pa] on a tip of radius R [m].
inline double maugis_parameter_of(double adhesive_stress, double work_of_adhesion,
                                  double effective_modulus, double radius) {
  return 2.0 * adhesive_stress / maugis_stress_unit(work_of_adhesion, effective_modulus, radius);
}

}  // namespace mdrsim
