// The work and the dissipation of the arms that share one drive over a piece where the drive
// follows an exponential sum in time (a held force's creep), all members at once.
#pragma once

#include "engine/model/prony_root.hpp"
#include "engine/model/prony_shared_energy.hpp"

namespace mdrsim {

/// The members of `arms` (own squares `own`) over the next `duration` [s] of a drive whose
/// stretch follows `motion` w(s) = c + b s + sum_k a_k exp(-s / theta_k) (every theta_k apart
/// from the arms' tau_j, as depth_under_held_axis gives it): the members' common history
/// H_j(s) follows arm_stress_under(H_j(0), term_j, motion), a member's own part decays as
/// exp(-s / tau_j), so with C_j = S_j - W H_j, sum_i weight_i sigma_ij^2 = W H_j^2 + 2 H_j C_j(0)
/// exp(-s / tau_j) + own_j exp(-2 s / tau_j), each integrated in closed form.
SharedArmsPiece shared_arms_motion_piece(const SharedDriveArms& arms,
                                         const SharedArmOwnSquares& own,
                                         const ExponentialSum& motion, double duration);

}  // namespace mdrsim
