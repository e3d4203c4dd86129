// The status of a lost contact: one rule on the run's force scale and on whether the control
// turned.
#include "engine/result/loss_status.hpp"

#include <gtest/gtest.h>

namespace mdrsim {
namespace {

// A last spring's tension against the run's scale, 1e-3 of it the line (kNegligibleForce).
TEST(LossStatus, LastSpringAgainstTheRunsForceScale) {
  const LossCascade below{
      .changes = 1, .springs_before = 1, .force_before = -0.9e-3, .force_scale = 1.0};
  const LossCascade above{
      .changes = 1, .springs_before = 1, .force_before = -1.1e-3, .force_scale = 1.0};
  EXPECT_EQ(loss_status(below), RunStatus::no_instability);
  EXPECT_EQ(loss_status(above), RunStatus::instability);
  // Two springs left when one lets go: the other still holds, whatever its force.
  LossCascade two = below;
  two.springs_before = 2;
  EXPECT_EQ(loss_status(two), RunStatus::instability);
}

// Springs going together: a jump where the control turned, a smooth peel where each was due
// only to rounding (flat), a shear-off where the cascade began by shear either way.
TEST(LossStatus, ACascadeIsAJumpUnlessItsControlStayedFlat) {
  LossCascade c{.changes = 40, .springs_before = 40, .force_before = -0.5, .force_scale = 1.0};
  EXPECT_EQ(loss_status(c), RunStatus::instability);
  c.flat = true;
  EXPECT_EQ(loss_status(c), RunStatus::no_instability);
  c.second_by_shear = true;
  EXPECT_EQ(loss_status(c), RunStatus::shear_off);
}

}  // namespace
}  // namespace mdrsim
