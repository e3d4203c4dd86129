// The integrals of a Maxwell arm's stress over a piece of constant drive rate, written so that
// they keep their digits as the piece shortens: with x = h / tau, the rise 1 - exp(-s / tau)
// and its integrals are O(x) and higher, and taking them as differences of O(1) terms (h less
// tau (1 - exp(-x)), say) would leave eps / x of them.
#pragma once

namespace mdrsim {

/// 1 - exp(-x) for x >= 0 to about an ulp: by its Taylor series on short pieces (x < 2^-7, an
/// event's usual step against a relaxation time: no call), by expm1 beyond.
double relaxed_part(double x);

/// Over [0, h] [s] with E(s) = exp(-s / tau) and D(s) = 1 - E(s), each [s]:
struct DecayIntegrals {
  double decay;          ///< int E = tau (1 - exp(-x))
  double decay_squared;  ///< int E^2 = tau (1 - exp(-2x)) / 2
  double rise;           ///< int D = tau (x - 1 + exp(-x))
  double rise_decay;     ///< int D E = tau (1 - exp(-x))^2 / 2
  double rise_squared;   ///< int D^2 = tau (x - 2 (1 - exp(-x)) + (1 - exp(-2x)) / 2)
};

/// The integrals over a piece of h [s] at relaxation time tau [s], each to a few eps of itself
/// at any h / tau >= 0 (the rise's by their Taylor series below h / tau = 1).
DecayIntegrals decay_integrals(double h, double tau);
/// The same where the caller has `fall` = 1 - exp(-h / tau) (by expm1) already.
DecayIntegrals decay_integrals(double h, double tau, double fall);

/// The integrals of an arm's stress sigma(s) = sigma0 E(s) + c D(s) (c = E_j w' tau, its steady
/// value) over [0, h] [N s / m], of its square [N^2 s / m^2] and of sigma E [N s / m].
struct ArmStressIntegrals {
  double stress;
  double square;
  double with_decay;
};
ArmStressIntegrals arm_stress_integrals(const DecayIntegrals& i, double sigma0, double steady);

}  // namespace mdrsim
