// One viscoelastic spring's Maxwell arms: the exact update of an arm's stress under a stretch
// that moves linearly in time, and the spring's line load over such a motion as an exponential
// sum (whose crossings engine/model/prony_root locates).
#pragma once

#include <span>
#include <vector>

#include "engine/base/material.hpp"
#include "engine/model/prony_root.hpp"

namespace mdrsim {

/// An arm's stress sigma [N/m, a line load] after `duration` [s] of a stretch moving at `rate`
/// [m/s]: d sigma/dt = E_i w' - sigma / tau_i solved exactly,
///   sigma(h) = sigma(0) exp(-h / tau_i) + E_i w' tau_i (1 - exp(-h / tau_i)).
double maxwell_arm_after(double stress, const PronyTerm& term, double rate, double duration);

/// The same for every arm of a spring, in place (stresses[j] belongs to terms[j]).
void advance_arms(std::span<double> stresses, std::span<const PronyTerm> terms, double rate,
                  double duration);

/// The line load q = E* w + sum_j sigma_j [N/m] of a spring whose stretch is w [m] and arm
/// stresses sigma_j now, over a motion of the stretch at `rate` [m/s]:
///   q(s) = (E* w + sum_j E_j rate tau_j) + E* rate s + sum_j (sigma_j - E_j rate tau_j) exp(-s /
///   tau_j).
ExponentialSum line_load_over(double relaxed_modulus, std::span<const PronyTerm> terms,
                              double stretch, std::span<const double> stresses, double rate);
/// The same into `load` (its decays' storage reused: a row builds one at every event).
void line_load_over(ExponentialSum& load, double relaxed_modulus, std::span<const PronyTerm> terms,
                    double stretch, std::span<const double> stresses, double rate);

}  // namespace mdrsim
