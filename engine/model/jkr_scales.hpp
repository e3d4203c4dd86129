// The JKR scales of a parabolic contact, F0, a0, d0 (paper eq. 17), for dimensionless output (eq.
// 16).
#pragma once

#include <cmath>
#include <numbers>
#include <optional>

namespace mdrsim {

struct JkrScales {
  double force;   ///< F0 = 1.5 pi R dgamma [N]
  double radius;  ///< a0 = (9 pi R^2 dgamma / (8 E*))^(1/3) [m]
  double depth;   ///< d0 = (3 pi^2 R dgamma^2 / (64 E*^2))^(1/3) [m]

  /// Scales for tip radius R [m], E* [Pa] and dgamma [J/m^2]; none without adhesion.
  static std::optional<JkrScales> of(double tip_radius, double effective_modulus,
                                     double work_of_adhesion) {
    if (!(work_of_adhesion > 0.0)) return std::nullopt;
    constexpr double pi = std::numbers::pi;
    const double r = tip_radius, e = effective_modulus, w = work_of_adhesion;
    // Cube roots taken factor by factor, so that w^2 or R^2 cannot underflow or overflow.
    const double ratio = std::cbrt(w / e);
    const double scales[] = {1.5 * pi * r * w,
                             std::cbrt(9.0 * pi / 8.0) * std::cbrt(r) * std::cbrt(r) * ratio,
                             std::cbrt(3.0 * pi * pi / 64.0) * std::cbrt(r) * ratio * ratio};
    for (const double s : scales) {
      if (!(s > 0.0) || !std::isfinite(s)) return std::nullopt;
    }
    return JkrScales{scales[0], scales[1], scales[2]};
  }
};

}  // namespace mdrsim
