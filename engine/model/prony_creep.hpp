// A free viscoelastic spring (it carries no load: lifted, or let go) creeping back to its rest
// length, and the time the withdrawing or returning indenter meets it again.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/base/material.hpp"
#include "engine/model/prony_root.hpp"

namespace mdrsim {

/// With q = E* w + sum_j sigma_j = 0 held, the arm strains y_j = sigma_j / E_j obey
///   (D + E E^T / E*) y' = -D Lambda y,  D = diag(E_j), Lambda = diag(1 / tau_j),
/// a symmetric pencil: y(t) = sum_k alpha_k v_k exp(-mu_k t), the retardation rates mu_k the
/// roots of E* = mu sum_j E_j / (1/tau_j - mu) (one in (0, 1/tau_1), one between each pair of
/// the ascending 1/tau_j), v_kj = 1 / (1/tau_j - mu_k), and alpha_k by the pencil's D + E E^T / E*
/// orthogonality. One term: mu = E* / (tau E_0*), the inverse retardation time. Terms with one
/// relaxation time act as one arm; their differences from the shares of the sum decay at 1/tau.
class RetardationModes {
 public:
  RetardationModes(double relaxed_modulus, std::span<const PronyTerm> terms);

  double relaxed_modulus() const { return relaxed_modulus_; }
  std::span<const PronyTerm> terms() const { return terms_; }
  /// The retardation rates mu_k [1/s], ascending.
  std::span<const double> rates() const { return rates_; }
  /// The arms with distinct relaxation times (terms with one tau merged, moduli summed).
  std::span<const PronyTerm> groups() const { return groups_; }
  /// The group of term j.
  std::size_t group_of(std::size_t j) const { return group_of_[j]; }
  /// v_kg = 1 / (1/tau_g - mu_k), the strain of group g in mode k.
  double mode(std::size_t k, std::size_t g) const { return modes_[k][g]; }
  /// -sum_g E_g v_kg: E* times the stretch of mode k at unit amplitude.
  double stretch_amplitude(std::size_t k) const { return stretch_amplitudes_[k]; }
  /// stretch_amplitude(k) / E*: the stretch of mode k at unit amplitude [m].
  double stretch_of_mode(std::size_t k) const { return stretch_of_modes_[k]; }
  /// E_g v_kg: group g's stress in mode k at unit amplitude.
  double stress_of_mode(std::size_t k, std::size_t g) const {
    return stress_of_modes_[k * groups_.size() + g];
  }
  /// E_j / E_g(j): term j's share of its group's stress.
  double share_of_group(std::size_t j) const { return shares_[j]; }
  /// <v_k, v_k> / 2: what mode k stores at unit amplitude. A free spring stores
  /// E* w^2 / 2 + sum_g E_g y_g^2 / 2 = <y, y> / 2 in the pencil's inner product, in which the
  /// modes are orthogonal: sum_k <v_k, v_k> / 2 (alpha_k exp(-mu_k t))^2 (its residuals aside).
  double stored_of_mode(std::size_t k) const { return 0.5 * mode_norms_[k]; }
  /// alpha_k of group stresses sigma_g [N/m]: y = sum_k alpha_k v_k at the release.
  FewValues<double> amplitudes(std::span<const double> group_stresses) const;
  /// The same into `alpha` (one per mode), no temporaries: a row releases a spring an event.
  void amplitudes(std::span<const double> group_stresses, std::span<double> alpha) const;

 private:
  double relaxed_modulus_;
  std::vector<PronyTerm> terms_;
  std::vector<std::size_t> group_of_;
  std::vector<PronyTerm> groups_;
  std::vector<double> rates_;
  std::vector<std::vector<double>> modes_;
  std::vector<double> stretch_amplitudes_;
  std::vector<double> mode_norms_;  ///< <v_k, v_k> in the pencil's inner product
  /// alpha_k = sum_g projections_[k groups + g] sigma_g: the pencil's projection per unit stress.
  std::vector<double> projections_;
  std::vector<double> stretch_of_modes_;
  std::vector<double> stress_of_modes_;  ///< E_g v_kg, row k
  std::vector<double> shares_;           ///< E_j / E_g(j)
};

/// A free spring's numbers held elsewhere (a row's flat per-spring store), read in place: its
/// modes' amplitudes alpha_k and its terms' residuals, the modes the material's.
class FreeSpringCreepRef {
 public:
  FreeSpringCreepRef(const RetardationModes& modes, std::span<const double> amplitudes,
                     std::span<const double> residuals)
      : modes_(&modes), amplitudes_(amplitudes), residuals_(residuals) {}

  /// The stretch w(t) [m] at t [s] after the release.
  double stretch(double t) const;
  /// The arm stresses sigma_j(t) [N/m].
  FewValues<double> stresses(double t) const;
  /// stretch(t) and stresses(t), the same numbers, each mode's decay read once for both.
  FewValues<double> stresses(double t, double& stretch) const;
  /// What the spring stores at t [J/m]: E* w^2 / 2 + sum_j sigma_j^2 / (2 E_j), as a sum of
  /// squares: each mode's (stored_of_mode), and each residual's r_j^2 exp(-2 t / tau_j) / (2 E_j)
  /// (a group's residuals sum to zero, so they are orthogonal to its share of the modes).
  double stored(double t) const;
  /// w(t0 + s) as an exponential sum in s [s].
  ExponentialSum stretch_from(double t0) const;
  /// The same into `w` (its decays' storage reused).
  void stretch_from(double t0, ExponentialSum& w) const;
  /// The retardation rates mu_k [1/s], ascending.
  std::span<const double> rates() const { return modes_->rates(); }
  /// Mode k's part of the stretch at t [m] (stretch_from(t)'s decay k at 0).
  double mode_stretch(std::size_t k, double t) const;

 private:
  /// The arm stresses at t from each mode's decay exp(-mu_k t).
  FewValues<double> stresses_from_decays(double t, std::span<const double> decays) const;

  const RetardationModes* modes_;
  std::span<const double> amplitudes_;
  std::span<const double> residuals_;
};

/// The numbers of a spring free from now with arm stresses sigma_j [N/m]: its modes' amplitudes
/// (one per retardation rate) into `amplitudes`, its terms' residuals into `residuals`.
void free_spring_numbers(const RetardationModes& modes, std::span<const double> stresses,
                         std::span<double> amplitudes, std::span<double> residuals);

/// One free spring: O(1) per term (its modes' amplitudes and its terms' residuals), the modes
/// shared by every spring of the material.
class FreeSpringCreep {
 public:
  /// The spring is free from now (t = 0) with arm stresses sigma_j [N/m]; its stretch is then
  /// w = -sum_j sigma_j / E*.
  FreeSpringCreep(std::shared_ptr<const RetardationModes> modes, std::span<const double> stresses);
  /// The same with modes of its own.
  FreeSpringCreep(double relaxed_modulus, std::span<const PronyTerm> terms,
                  std::span<const double> stresses);

  /// The stretch w(t) [m] at t [s] after the release.
  double stretch(double t) const { return numbers().stretch(t); }
  /// The arm stresses sigma_j(t) [N/m].
  FewValues<double> stresses(double t) const { return numbers().stresses(t); }
  /// w(t0 + s) as an exponential sum in s [s].
  ExponentialSum stretch_from(double t0) const { return numbers().stretch_from(t0); }
  /// The same into `w` (its decays' storage reused).
  void stretch_from(double t0, ExponentialSum& w) const { numbers().stretch_from(t0, w); }
  /// The retardation rates mu_k [1/s], ascending.
  std::span<const double> rates() const { return modes_->rates(); }
  /// Its numbers, read in place.
  FreeSpringCreepRef numbers() const { return {*modes_, amplitudes_, residuals_}; }

 private:
  std::shared_ptr<const RetardationModes> modes_;
  FewValues<double> amplitudes_;  ///< alpha_k
  FewValues<double> residuals_;   ///< sigma_j - (E_j / E_group) sigma_group at 0 [N/m]
};

/// The first s in (0, span] [s] at which the indenter, whose surface at the spring stands at
/// stretch `indenter_stretch` [m] at s = 0 and moves at `rate` [m/s] (d(t) - g(x) under the
/// indentation), meets the free spring t0 [s] after its release: E* w_free = E* w_indenter,
/// reached from the side of no contact.
std::optional<double> touch_time(const FreeSpringCreep& creep, double t0, double indenter_stretch,
                                 double rate, double span);

}  // namespace mdrsim
