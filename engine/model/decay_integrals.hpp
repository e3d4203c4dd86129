// The integrals of a Maxwell arm's stress over a piece of constant drive rate, written so that
// they keep their digits as the piece shortens: with x = h / tau, the rise 1 - exp(-s / tau)
// and its integrals are O(x) and higher, and taking them as differences of O(1) terms (h less
// tau (1 - exp(-x)), say) would leave eps / x of them.
#pragma once

namespace mdrsim {

/// Below it a piece is short (x = h / tau < 2^-7, an event's usual step against a relaxation
/// time): its numbers are polynomials in x, inline here, with no call and no loop.
inline constexpr double kShortPiece = 0x1p-7;

/// -expm1(-x), out of line.
double relaxed_part_long(double x);

/// 1 - exp(-x) for x >= 0 to about an ulp: by its Taylor series on short pieces (through x^7 /
/// 7!: the next term is below 2^-53 of the sum at x < 2^-7, and the terms fall by at least 2^-8
/// each, so Horner's rounding stays within an ulp), by expm1 beyond.
inline double relaxed_part(double x) {
  if (!(x < kShortPiece)) return relaxed_part_long(x);
  return x * (1.0 + x * (-1.0 / 2.0 +
                         x * (1.0 / 6.0 +
                              x * (-1.0 / 24.0 +
                                   x * (1.0 / 120.0 + x * (-1.0 / 720.0 + x * (1.0 / 5040.0)))))));
}

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
/// The same beyond a short piece, out of line, where the caller has `fall` = 1 - exp(-h / tau).
DecayIntegrals decay_integrals_long(double h, double tau, double fall);

/// The same where the caller has x = h / tau and `fall` = relaxed_part(x) already. A short
/// piece's rise integrals are polynomials: x - 1 + exp(-x) = sum_{n >= 2} (-x)^n / n! through
/// n = 8, and x - 2 (1 - exp(-x)) + (1 - exp(-2x)) / 2 = sum_{n >= 3} (-1)^(n+1) (2^(n-1) - 2)
/// x^n / n! through n = 10 (each next term below 2^-53 of the sum at x < 2^-7).
inline DecayIntegrals decay_integrals_at(double x, double tau, double fall) {
  if (!(x < kShortPiece)) return decay_integrals_long(x * tau, tau, fall);
  DecayIntegrals i{};
  i.decay = tau * fall;
  // 1 - exp(-2x) = (1 - exp(-x)) (1 + exp(-x)): from `fall` to a few eps.
  i.decay_squared = fall * (2.0 - fall) * tau * 0.5;
  i.rise_decay = tau * fall * fall * 0.5;
  const double x2 = x * x;
  i.rise =
      tau * x2 *
      (1.0 / 2.0 +
       x * (-1.0 / 6.0 +
            x * (1.0 / 24.0 + x * (-1.0 / 120.0 + x * (1.0 / 720.0 + x * (-1.0 / 5040.0 +
                                                                          x * (1.0 / 40320.0)))))));
  i.rise_squared =
      tau * x2 * x *
      (1.0 / 3.0 +
       x * (-1.0 / 4.0 +
            x * (7.0 / 60.0 +
                 x * (-1.0 / 24.0 +
                      x * (31.0 / 2520.0 + x * (-1.0 / 320.0 + x * (127.0 / 181440.0 +
                                                                    x * (-17.0 / 120960.0))))))));
  return i;
}

/// The same from h [s].
inline DecayIntegrals decay_integrals(double h, double tau, double fall) {
  return decay_integrals_at(h / tau, tau, fall);
}

/// The integrals of an arm's stress sigma(s) = sigma0 E(s) + c D(s) (c = E_j w' tau, its steady
/// value) over [0, h] [N s / m], of its square [N^2 s / m^2] and of sigma E [N s / m].
struct ArmStressIntegrals {
  double stress;
  double square;
  double with_decay;
};
ArmStressIntegrals arm_stress_integrals(const DecayIntegrals& i, double sigma0, double steady);

}  // namespace mdrsim
