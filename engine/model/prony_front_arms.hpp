// The glued springs of a rate-law row on a relaxing bulk: their arms' per-term sums (force, stored
// energy and dashpot dissipation in O(1) per term), and the line load at a front that lies
// between two springs.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "engine/base/material.hpp"
#include "engine/model/prony_root.hpp"

namespace mdrsim {

/// E(t) = E* + sum_j E_j exp(-t / tau_j) [Pa]: the relaxation modulus t [s] after a step.
double relaxation_modulus(double relaxed_modulus, std::span<const PronyTerm> terms, double t);

/// What a glued spring keeps: its arm stress per term is sigma_j(t) = H_j(t) + offset_j
/// exp(-(t - entry_time) / tau_j), O(1) per term.
struct DrivenArmMember {
  double entry_time = 0.0;    ///< [s] on the sums' clock
  FewValues<double> offsets;  ///< [N/m] per term
  double weight = 0.0;        ///< dx [m]
};

/// What the dashpots and the arms' line loads did over one piece of a linear drive.
struct DrivenArmPiece {
  double force_time = 0.0;  ///< int sum_ij w_i sigma_ij ds over the piece [N s]
  double dissipated = 0.0;  ///< sum_j int sum_i w_i sigma_ij^2 / (E_j tau_j) ds [J]
};

/// Arms whose springs' stretches all move at one rate (the glued springs follow the grips), as
/// engine/model/prony_shared_drive's sums, with the weighted sums of squares as well: per term
/// S_j = W H_j + C_j and Q_j = sum_i w_i sigma_ij^2 = W H_j^2 + 2 H_j C_j + D_j, with C_j =
/// sum_i w_i c_ij (decaying at 1 / tau_j) and D_j = sum_i w_i c_ij^2 (at 2 / tau_j), c_ij the
/// member's own decaying part. The stored energy sum_j Q_j / (2 E_j) and the dissipation
/// int sum_j Q_j / (E_j tau_j) follow in closed form.
class DrivenArmSums {
 public:
  explicit DrivenArmSums(std::vector<PronyTerm> terms);

  /// The drive moves at `rate` [m/s] for `duration` [s]: the sums advance exactly, and the
  /// piece's integrals are returned.
  DrivenArmPiece advance(double rate, double duration);
  /// A spring joins now with arm stresses `stresses` [N/m] and weight dx [m].
  DrivenArmMember enter(std::span<const double> stresses, double weight);
  /// A member leaves now; its arm stresses then [N/m] are returned.
  FewValues<double> leave(const DrivenArmMember& member);
  /// A member's arm stress of term j now [N/m].
  double stress(const DrivenArmMember& member, std::size_t j) const;
  /// sum_ij w_i sigma_ij [N].
  double arm_force() const;
  /// sum_ij w_i sigma_ij^2 / (2 E_j) [J]: the arms' energy, one half of the row.
  double stored() const;
  double time() const { return time_; }
  std::span<const PronyTerm> terms() const { return terms_; }

 private:
  std::vector<PronyTerm> terms_;
  std::vector<double> history_;   ///< H_j [N/m]
  std::vector<double> decaying_;  ///< C_j [N]
  std::vector<double> squares_;   ///< D_j [N^2/m]
  double weight_ = 0.0;
  std::size_t members_ = 0;
  double time_ = 0.0;
};

/// The line load q(a, t) [N/m] at a front at radius a between the outermost glued spring m and
/// the next: spring m's load shifted by the image's difference through the relaxation function,
///   q(a, t) = q_m(t) - E(t - t_m) (g(a) - g_m),
/// exact for a spring at a glued when m glued from the same (relaxed) rest, since the two
/// stretches then differ by g(a) - g_m at every time since. Spring m's load over its linear
/// stretch w + r s is E* (w + r s) + sum_j [sigma_j exp(-s / tau_j) + E_j r tau_j (1 -
/// exp(-s / tau_j))], kept in that form: as a constant plus decays (prony_arms' line_load_over)
/// a slow arm's E_j r tau_j would cancel against its decay and leave the load's ulp far above
/// its threshold's.
struct FrontLineLoad {
  double stretch = 0.0;          ///< w_m at t0 [m]
  double rate = 0.0;             ///< dw_m / dt [m/s]
  FewValues<double> stresses;    ///< sigma_mj at t0 [N/m]
  double boundary_age = 0.0;     ///< t0 - t_m [s]
  double boundary_image = 0.0;   ///< g_m [m]
  double relaxed_modulus = 0.0;  ///< E* [Pa]
  std::span<const PronyTerm> terms;

  /// q at radius image g(a) = `image` [m], s [s] after t0.
  double at(double image, double s) const;
  /// dq/ds at `image` as a constant plus decays in s [N/(m s)].
  ExponentialSum slope(double image) const;
  /// The first s in (0, span] [s] at which q at `image` reaches `level` [N/m] from the side it
  /// is on just after 0 (the load split where it is monotone, at the zeros of its slope, and the
  /// first piece that straddles the level solved by TOMS 748); nullopt where it does not.
  std::optional<double> first_reach(double image, double level, double span) const;
};

}  // namespace mdrsim
