// The depth of a viscoelastic row held by a force or a machine spring between events, as an
// exponential sum in time, and the arms' response to such a motion.
#pragma once

#include <cstdint>
#include <span>

#include "engine/base/material.hpp"
#include "engine/model/prony_root.hpp"

namespace mdrsim {

/// s -> f(s0 + s): the same sum seen from s0 [s] on.
ExponentialSum shifted(const ExponentialSum& f, double s0);

/// The lowest and highest values f can take over [0, h]: each part (the line and every decay)
/// is monotone, so its ends bound it. Loose, never wrong: what an event search skips with.
struct ExponentialSumBounds {
  double lo;
  double hi;
};
ExponentialSumBounds bounds_over(const ExponentialSum& f, double h);

/// int_0^h f(s) g(s) ds, in closed form.
double integral_of_product(const ExponentialSum& f, const ExponentialSum& g, double h);

/// An arm's stress sigma(s) [N/m] while its stretch follows `motion` w(s) = c + b s + sum_k a_k
/// exp(-s / theta_k), from `stress` at s = 0: d sigma/ds = E_i w' - sigma / tau_i solved exactly,
///   sigma(s) = E_i b tau_i + sum_k A_k exp(-s / theta_k) + K exp(-s / tau_i),
///   A_k = E_i a_k tau_i / (tau_i - theta_k), K = stress - E_i b tau_i - sum_k A_k.
/// Every theta_k must differ from tau_i (the depth below has its rates strictly between the
/// arms' 1 / tau).
ExponentialSum arm_stress_under(double stress, const PronyTerm& term, const ExponentialSum& motion);

/// What holds the row's normal axis, the affine constraint a_u d + a_F F = h(t) (fixed load:
/// a_u = 0; a machine spring of stiffness k: a_u = 1, a_F = 1 / k), written per unit length of
/// one half of the row (F = 2 dx q_total): kappa d + q_total = phi(s), kappa = a_u / (2 dx a_F),
/// phi = h / (2 dx a_F).
struct RowHeldAxis {
  double stiffness;  ///< kappa [N/m^2]: 0 under a fixed load
  double held;       ///< phi at s = 0 [N/m]
  double rate;       ///< phi' [N/(m s)]

  /// The same axis `elapsed` [s] later (phi moved on).
  RowHeldAxis after(double elapsed) const { return {stiffness, held + rate * elapsed, rate}; }
};

/// The machine's work on a held axis over the next h [s] of `motion` (the axis's displacement
/// from now, depth_under_held_axis's sum) [J/m]: int phi du under a fixed load (the machine
/// moves with the indenter), int q dh under a machine spring (its end h moving at phi' / kappa,
/// its load q = phi - kappa u).
double held_axis_work(const RowHeldAxis& axis, const ExponentialSum& motion, double h);

/// The pressed springs between events: n of them, sum g_i, and the sums S_j of their arms'
/// stresses per term.
struct PressedSprings {
  std::int64_t count;
  double images;                     ///< sum_i g(x_i) [m]
  std::span<const double> arm_sums;  ///< S_j [N/m] per term
};

/// The depth d(s) [m] of a row of relaxed modulus E* and Prony terms whose pressed springs are
/// `pressed`, held by `axis`: with q_total = E* (n d - sum g) + sum_j S_j and dS_j/ds = E_j n d' -
/// S_j / tau_j, the constraint gives (E_0 n + kappa) d' = phi' + sum_j S_j / tau_j, one linear ODE
/// in the S_j with constant coefficients. Its rates mu_k are the roots of the secular equation
/// 1 = sum_g w_g r_g / (r_g - mu), w_g = n E_g / (E_0 n + kappa), r_g = 1 / tau_g over the terms
/// grouped by relaxation time (one root in (0, r_1), one between each pair of ascending r_g),
/// so d(s) = a + b s + sum_k c_k exp(-mu_k s), with b = phi' / (E* n + kappa) and the algebraic
/// constraint giving d(0). Without a pressed spring the depth is phi / kappa under a machine
/// spring and `depth` (it does not move) under a fixed load.
ExponentialSum depth_under_held_axis(double relaxed_modulus, std::span<const PronyTerm> terms,
                                     const PressedSprings& pressed, const RowHeldAxis& axis,
                                     double depth);

}  // namespace mdrsim
