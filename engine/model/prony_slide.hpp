// A viscoelastic spring whose load is prescribed in time (a sliding spring held at its slip
// limit): its stretch and arm stresses as exponential sums, solved exactly.
#pragma once

#include <span>
#include <vector>

#include "engine/model/prony_creep.hpp"
#include "engine/model/prony_root.hpp"

namespace mdrsim {

/// The stretch w(s) [m] and arm stresses sigma_j(s) [N/m] of a spring of relaxed modulus G and
/// Maxwell arms (G_j, tau_j) whose line load G w + sum_j sigma_j is prescribed, s from now.
struct PrescribedLoadResponse {
  ExponentialSum stretch;
  std::vector<ExponentialSum> stresses;  ///< one per term of the modes
};

/// The spring starts with arm stresses `stresses` and follows `load`, F(s) = c + b s + sum_m a_m
/// exp(-s / theta_m): a particular response to each part plus the free creep (the retardation
/// modes, `modes`) of what the arms hold beyond it. The line c + b s: w = (c - sum_j G_j tau_j
/// b / G) / G + b s / G, sigma_j = G_j tau_j b; a decay at theta equal to a relaxation time
/// tau_g: carried by that group's arms alone (shared by modulus), w unmoved; any other theta:
/// w = a / (G + sum_j G_j tau_j / (tau_j - theta)) exp(-s / theta), sigma_j = G_j tau_j / (tau_j -
/// theta) times w. theta must not be a retardation time 1 / mu_k. The stretch at s = 0 is (F(0) -
/// sum_j sigma_j) / G: continuous with the spring's where F(0) is its load.
PrescribedLoadResponse response_to_load(const RetardationModes& modes,
                                        std::span<const double> stresses,
                                        const ExponentialSum& load);

/// The free creep of arm stresses `stresses` (zero load) as sums: w(s) and sigma_j(s).
PrescribedLoadResponse free_creep_sums(const RetardationModes& modes,
                                       std::span<const double> stresses);

}  // namespace mdrsim
