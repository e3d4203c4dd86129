// The machine's work on one axis, one rule for both engines: the force against the machine's
// driving point, an exact trapezoid while the springs stay (force and point are affine).
#pragma once

#include "controllers/controller.hpp"

namespace mdrsim {

/// The force on one axis and the displacement of the machine's driving point: the indenter
/// under fixed grips and fixed load, the machine end (the held value) under compliant.
struct AxisPoint {
  double force;    ///< [N]
  double driving;  ///< [m]
};

/// The driving point of an axis under `c` holding `held`, its displacement `displacement` [m].
inline double driving_point(const AffineConstraint& c, double held, double displacement) {
  return drives_through_spring(c) ? held : displacement;
}

/// The work [J] from `from` to `to` while the springs stay: the trapezoid, exact there.
inline double trapezoid_work(const AxisPoint& from, const AxisPoint& to) {
  return 0.5 * (from.force + to.force) * (to.driving - from.driving);
}

}  // namespace mdrsim
