// The work and the dissipation of the arms that share one drive over a piece where it moves at
// one rate, all members at once (O(terms) a piece, no loop over the springs).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/base/material.hpp"
#include "engine/model/prony_shared_drive.hpp"

namespace mdrsim {

/// sum_i weight_i (sigma_ij - H_j)^2 over the members of a SharedDriveArms, per term
/// [N^2/m^2 times the weights' unit]: a member's own part sigma_ij - H_j decays as
/// exp(-t / tau_j) whatever the drive, so the sum decays as exp(-2 t / tau_j) and changes
/// otherwise only as members enter or leave.
class SharedArmOwnSquares {
 public:
  /// No member, `terms` terms.
  void reset(std::size_t terms) { squares_.assign(terms, 0.0); }
  /// A member of weight `weight` with arm stresses `stresses` [N/m] joins `arms` now (before it
  /// advances again); a negative weight takes one that leaves (its stresses as it leaves).
  void change(const SharedDriveArms& arms, std::span<const double> stresses, double weight);
  /// The drive's clock moves by `duration` [s].
  void advance(std::span<const PronyTerm> terms, double duration);
  /// Term j's sum, at least 0 (its additions and removals round).
  double operator[](std::size_t j) const;

 private:
  std::vector<double> squares_;
};

/// What the members' arms do over a piece of the drive.
struct SharedArmsPiece {
  double load_integral = 0.0;  ///< sum_j int S_j dt over the piece [N s/m]
  double dissipated = 0.0;     ///< sum_j int sum_i weight_i sigma_ij^2 / (E_j tau_j) dt [J/m]
};

/// The members of `arms` (own squares `own`) over the next `duration` [s] of a drive moving at
/// `rate` [m/s]: with H_j(s) = c_j + (H_j(0) - c_j) exp(-s / tau_j), c_j = E_j rate tau_j, and
/// C_j = S_j - W H_j, sum_i weight_i sigma_ij^2 = W H_j^2 + 2 H_j C_j(0) exp(-s / tau_j) +
/// own_j exp(-2 s / tau_j), each integrated in closed form.
SharedArmsPiece shared_arms_linear_piece(const SharedDriveArms& arms,
                                         const SharedArmOwnSquares& own, double rate,
                                         double duration);

}  // namespace mdrsim
