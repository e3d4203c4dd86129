// The rate law of the receding edge (detachment.front_speed_law): how fast the front recedes
// when its energy release rate exceeds the threshold toughness (docs/rate_law.md).
#pragma once

#include <cmath>

namespace mdrsim {

/// v = v* (G / dgamma - 1)^(1/n) while G > dgamma, else 0 (Gent-Schultz, Maugis-Barquins).
struct FrontSpeedLaw {
  double speed = 0.0;     ///< v* [m/s] > 0
  double exponent = 1.0;  ///< n in (0, 1]

  /// The receding front's speed [m/s] at G / dgamma = `release_ratio` [1].
  double front_speed(double release_ratio) const {
    const double excess = release_ratio - 1.0;
    return excess > 0.0 ? speed * std::pow(excess, 1.0 / exponent) : 0.0;
  }
};

}  // namespace mdrsim
