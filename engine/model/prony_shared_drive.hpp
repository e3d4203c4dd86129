// The Maxwell arms of a set of springs whose stretches all move at one rate (the springs in
// contact all follow the indentation): their weighted sums per Prony term advance in O(1)
// between events, with no loop over the springs.
#pragma once

#include <span>
#include <vector>

#include "engine/base/material.hpp"
#include "engine/model/prony_root.hpp"

namespace mdrsim {

/// What a member keeps: its arm stress per term is sigma_j(t) = H_j(t) + offset_j
/// exp(-(t - entry_time) / tau_j), H_j the drive's history below. O(1) per term.
struct SharedDriveMember {
  double entry_time = 0.0;    ///< [s] on the set's clock
  FewValues<double> offsets;  ///< [N/m] per term
  double weight = 0.0;        ///< dx [m]: the member's share of the sums
};

/// A member whose offsets are held elsewhere (a row's flat per-spring store), read in place.
struct SharedDriveMemberRef {
  double entry_time;                ///< [s] on the set's clock
  std::span<const double> offsets;  ///< [N/m] per term
};

/// Every member's stretch moves at the same rate, so each arm obeys d sigma_j/dt = E_j w' -
/// sigma_j / tau_j with one w'(t): sigma_j = H_j + a decay of the member's own, where H_j solves
/// the same equation from H_j = 0 at the clock's start. The weighted sum over the members is
/// S_j = W H_j + C_j with W the members' total weight and C_j = sum_i weight_i offset_ij
/// exp(-(t - t_i) / tau_j), which only decays: one linear ODE per term, updated exactly.
class SharedDriveArms {
 public:
  explicit SharedDriveArms(std::vector<PronyTerm> terms);

  /// The drive moves at `rate` [m/s] for `duration` [s]: the clock, H_j and C_j advance.
  void advance(double rate, double duration);
  /// The same, with 1 - exp(-duration / tau_j) given per term (`relaxed_parts`, by expm1 as
  /// maxwell_arm_after takes it: the same numbers), for a caller that needs them too.
  void advance(double rate, double duration, std::span<const double> relaxed_parts);
  /// The drive follows `motion` (its stretch as a sum in s from now, prony_load_drive.hpp) for
  /// `duration` [s].
  void advance_along(const ExponentialSum& motion, double duration);
  /// Every member's stretch steps by `step` [m] at once (a glassy response: the arms' springs
  /// take it, the dashpots do not move): each member's sigma_j gains E_j step, all through H_j.
  void glassy_step(double step);
  /// A spring joins now with arm stresses `stresses` [N/m] (zero for a fresh one) and weight dx.
  SharedDriveMember enter(std::span<const double> stresses, double weight);
  /// The same into `offsets` (one per term, held by the caller); the entry time is returned.
  double enter(std::span<const double> stresses, double weight, std::span<double> offsets);
  /// A member leaves now; its arm stresses then [N/m] are returned.
  FewValues<double> leave(const SharedDriveMember& member);
  /// The same for a member of weight `weight` held elsewhere, its stresses into `stresses`.
  void leave(const SharedDriveMemberRef& member, double weight, std::span<double> stresses);
  /// The same for a member whose stresses now, `stresses`, were just read by stress().
  void leave_read(std::span<const double> stresses, double weight);
  /// A member's arm stress of term j now [N/m].
  double stress(const SharedDriveMember& member, std::size_t j) const;
  double stress(const SharedDriveMemberRef& member, std::size_t j) const;

  /// sum_i weight_i sigma_ij over the members [N], term j.
  double arm_force(std::size_t j) const;
  /// sum_j arm_force(j) [N].
  double arm_force() const;
  /// H_j [N/m]: the stress of an arm that has followed the drive from rest at the clock's start.
  double history(std::size_t j) const { return history_[j]; }
  /// The members' total weight W [m].
  double weight() const { return weight_; }
  /// The set's clock [s].
  double time() const { return time_; }
  std::span<const PronyTerm> terms() const { return terms_; }

 private:
  std::vector<PronyTerm> terms_;
  std::vector<double> rates_;     ///< 1 / tau_j [1/s]: a member's read multiplies by it
  std::vector<double> history_;   ///< H_j [N/m]
  std::vector<double> decaying_;  ///< C_j [N]
  double weight_ = 0.0;
  std::size_t members_ = 0;
  double time_ = 0.0;
};

}  // namespace mdrsim
