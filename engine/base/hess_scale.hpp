// The Hess scale 2 pi dgamma / E* [m]: the one place it is spelled, for the engine and the parts.
#pragma once

#include <numbers>

namespace mdrsim {

/// 2 pi dgamma / E* [m] (paper eq. 12: a spring at radius a lets go at the elongation
/// sqrt(a times this)), for a work of adhesion dgamma [J/m^2] (or dgamma_a) and E* [Pa].
/// dgamma / E* first: 2 pi dgamma alone overflows for dgamma near the largest double. Every
/// caller keeps this order, so that a value computed here and one computed elsewhere agree
/// to the bit.
inline double hess_scale(double work_of_adhesion, double effective_modulus) {
  return 2.0 * std::numbers::pi * (work_of_adhesion / effective_modulus);
}

}  // namespace mdrsim
