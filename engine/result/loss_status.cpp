// The status of a lost contact: smooth peel, instability or shear-off.
#include "engine/result/loss_status.hpp"

#include <cmath>

namespace mdrsim {

bool peels_smoothly(const LossCascade& c) {
  if (c.changes >= 2) return c.flat;
  return c.springs_before <= 1 && std::abs(c.force_before) <= kNegligibleForce * c.force_scale;
}

RunStatus loss_status(const LossCascade& c) {
  const bool by_shear = c.changes >= 2 ? c.second_by_shear : c.first_by_shear;
  if (by_shear) return RunStatus::shear_off;
  return peels_smoothly(c) ? RunStatus::no_instability : RunStatus::instability;
}

}  // namespace mdrsim
