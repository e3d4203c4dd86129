// Hutchinson-Suo toughness: the margin, free of tan, and the let-go, tabulated once per lambda.
#include "detachment/mode_dependent_criterion.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

namespace mdrsim {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

// Quarter octaves: the top 2 bits of a double's mantissa pick the piece, the other 50 are x.
constexpr int kQuarterShift = 50;
constexpr std::uint64_t kInPiece = (std::uint64_t{1} << kQuarterShift) - 1;
constexpr int kDegree = 11;  // error ~ 16^-12 on a quarter octave, whatever lambda: see fit()
constexpr int kTopLowestOctave = -30;  // 1 - t below 2^-30: the exact root, at every call
constexpr int kMaxBottomOctaves = 64;  // t below 2^-65: the series or the exact root
// A piece must match the exact root to this at its checks (the table reaches ~2e-15), or it
// is left NaN and its calls solve exactly: the tests ask for 1e-13.
constexpr double kCheckTolerance = 4e-15;

int octave_of(double v) { return static_cast<int>(std::bit_cast<std::uint64_t>(v) >> 52) - 1023; }

// Estrin's scheme: three independent cubics, so that the chain of dependent operations is short.
double evaluate(const std::array<double, 12>& a, double x) {
  const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  const double low = (a[0] + a[1] * x) + (a[2] + a[3] * x) * x2;
  const double middle = (a[4] + a[5] * x) + (a[6] + a[7] * x) * x2;
  const double high = (a[8] + a[9] * x) + (a[10] + a[11] * x) * x2;
  return low + middle * x4 + high * x8;
}

// cos(m (2k + 1) pi / 24): T_m at the 12 Chebyshev points, for the coefficients of a fit.
using ChebyshevTable = std::array<std::array<double, kDegree + 1>, kDegree + 1>;
const ChebyshevTable& chebyshev_at_points() {
  static const ChebyshevTable table = [] {
    ChebyshevTable t{};
    for (int m = 0; m <= kDegree; ++m) {
      for (int k = 0; k <= kDegree; ++k) {
        t[m][k] = std::cos(m * (2 * k + 1) * std::numbers::pi / (2 * (kDegree + 1)));
      }
    }
    return t;
  }();
  return table;
}

}  // namespace

// Writing r^2 = E* e^2 + G* ux^2, e sqrt(E*) = r cos(psi), |ux| sqrt(G*) = r sin(psi), the let-go
// r cos((1 - lambda) psi) = sqrt(2 pi a dgamma) is an equation in phi = pi/2 - psi alone:
//   cos(phi) = c sin(lambda pi/2 + (1 - lambda) phi),  c = |ux| sqrt(G* / (2 pi a dgamma)),
// and then e = sqrt(2 pi a dgamma / E*) sin(phi) / sin(lambda pi/2 + (1 - lambda) phi). phi
// (not psi) keeps both sines accurate where e -> 0. With t = c sin(lambda pi/2) in [0, 1) the
// ratio e / sqrt(2 pi a dgamma / E*) is smooth except near t = 0 (a bend at c ~ 1, i.e. t ~ lambda
// for small lambda) and t = 1 (a square root for lambda -> 1): on log-spaced pieces, of t below
// 1/2 and of 1 - t above, each bend is as far from its piece as the piece is wide, for every
// lambda.
ModeDependentCriterion::ModeDependentCriterion(const InterfaceProperties& properties, double lambda)
    : p_(properties),
      scales_(properties),
      lambda_(lambda),
      cos_at_pure_shear_(std::cos((1.0 - lambda) * kHalfPi)),
      mu_(1.0 - lambda) {
  if (!(lambda >= 0.0 && lambda <= 1.0)) {
    throw std::invalid_argument("lambda must lie in [0, 1]");
  }
  if (mu_ == 1.0 || lambda_ == 1.0) return;  // closed forms: see critical_elongation()
  // The law as margin() computes it, with 1 - lambda rounded: lambda itself for lambda >= 1/2,
  // a multiple of 2^-53 near it below (1 - mu is exact).
  const double law_lambda = 1.0 - mu_;
  half_lambda_pi_ = law_lambda * kHalfPi;
  sin_half_ = std::sin(half_lambda_pi_);
  cot_half_ = std::cos(half_lambda_pi_) / sin_half_;
  // Square roots apart, no squares: finite for dgamma near the largest double.
  const double root_work = std::sqrt(2.0 * std::numbers::pi) * std::sqrt(p_.work_of_adhesion);
  root_per_radius_ = root_work / std::sqrt(p_.effective_modulus);
  t_per_root_ = std::sqrt(p_.effective_shear_modulus) / root_work * sin_half_;
  // ratio = 1 - (1 - mu^2) c^2 / 2 + O(c^4): exact to rounding for c < 2^-20.
  series_ = law_lambda * (1.0 + mu_) / (2.0 * sin_half_) / sin_half_;
  series_end_ = std::ldexp(sin_half_, -20);
  lowest_octave_ = std::max(octave_of(series_end_), -1 - kMaxBottomOctaves);

  double angle = kHalfPi;  // each root starts Newton at the one before: phi -> pi/2 as t -> 0
  for (int octave = lowest_octave_; octave <= -2; ++octave) {
    for (int quarter = 0; quarter < 4; ++quarter) fit(false, octave, quarter, angle);
  }
  angle = 0.0;  // phi -> 0 as 1 - t -> 0
  for (int octave = kTopLowestOctave; octave <= -2; ++octave) {
    for (int quarter = 0; quarter < 4; ++quarter) fit(true, octave, quarter, angle);
  }
  fit(true, -1, 0, angle);  // 1 - t = 1/2 exactly
}

// Interpolates at the 12 Chebyshev points of the quarter octave and checks between them. A bend
// at distance ~ the piece's start from a piece 1/4 of it wide bounds the error by ~16^-12.
void ModeDependentCriterion::fit(bool top, int octave, int quarter, double& angle) {
  const double start = std::ldexp(1.0 + 0.25 * quarter, octave);
  const double half_width = std::ldexp(0.125, octave);
  const auto exact_at = [&](double x) {
    const double v = start + half_width * (1.0 + x);
    angle = top ? root_angle(1.0 - v, v, angle) : root_angle(v, 1.0 - v, angle);
    return ratio_at(angle);
  };
  constexpr int n = kDegree + 1;
  const ChebyshevTable& basis = chebyshev_at_points();
  std::array<double, n> values{}, chebyshev{};
  for (int k = n - 1; k >= 0; --k) values[k] = exact_at(basis[1][k]);  // increasing x: guesses
  for (int m = 0; m < n; ++m) {
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += values[k] * basis[m][k];
    chebyshev[m] = (m == 0 ? 1.0 : 2.0) * sum / n;
  }
  // To powers of x: T_{m+1} = 2 x T_m - T_{m-1}.
  Piece piece{};
  std::array<double, n> older{}, old{}, next{};
  older[0] = 1.0;
  old[1] = 1.0;
  piece.coefficients[0] = chebyshev[0];
  for (int j = 0; j < n; ++j) piece.coefficients[j] += chebyshev[1] * old[j];
  for (int m = 2; m < n; ++m) {
    for (int j = 0; j < n; ++j) next[j] = (j > 0 ? 2.0 * old[j - 1] : 0.0) - older[j];
    for (int j = 0; j < n; ++j) piece.coefficients[j] += chebyshev[m] * next[j];
    older = old;
    old = next;
  }
  for (const double x : {-0.97, -0.6, 0.0, 0.6, 0.97}) {
    const double exact = exact_at(x);
    if (!(std::abs(evaluate(piece.coefficients, x) - exact) <= kCheckTolerance * exact)) {
      piece.coefficients.fill(std::numeric_limits<double>::quiet_NaN());
      break;
    }
  }
  pieces_.push_back(piece);
}

// G >= Gamma_I (1 + tan^2 x) with x = (1 - lambda) psi is G cos^2 x >= Gamma_I, since
// 1 + tan^2 = 1/cos^2; tan psi = sqrt(G*/E*) ux / |uz| is the phase angle of the spring.
// At zero stretch psi is atan2(., +0) = pi/2 (or 0 without shear) to the bit, so its cosine
// is taken from the constructor: the engine asks for this margin before every let-go, and the
// library cosine there cost more than the let-go itself.
double ModeDependentCriterion::margin(const BoundarySpring& s) const {
  const double normal = p_.effective_modulus * s.elongation * s.elongation;
  const double shear =
      p_.effective_shear_modulus * s.tangential_displacement * s.tangential_displacement;
  const double c =
      normal == 0.0 ? (shear > 0.0 ? cos_at_pure_shear_ : 1.0)
                    : std::cos((1.0 - lambda_) * std::atan2(std::sqrt(shear), std::sqrt(normal)));
  return 2.0 * std::numbers::pi * s.contact_radius * p_.work_of_adhesion_at(s.contact_radius) -
         (normal + shear) * c * c;
}

std::optional<double> ModeDependentCriterion::critical_elongation(double a, double ux) const {
  if (lambda_ == 1.0) {  // mode-mixed's let-go, to the bit (paper eq. 21)
    const double squared = scales_.hess_squared(a) - scales_.shear_ratio * ux * ux;
    return squared > 0.0 ? std::sqrt(squared) : 0.0;
  }
  // 1 - lambda rounds to 1 for lambda <= 2^-54 (and 0): margin() is then normal-only's.
  if (mu_ == 1.0) return std::sqrt(scales_.hess_squared(a));
  const double root_a = std::sqrt(a);
  if (!p_.work_of_adhesion_by_radius) {
    return root_a * root_per_radius_ * let_go_ratio(std::abs(ux) / root_a * t_per_root_);
  }
  // dgamma at a: the table of the ratio is in t alone, the scales follow dgamma(a).
  const double root_work = std::sqrt(2.0 * std::numbers::pi) * std::sqrt(p_.work_of_adhesion_at(a));
  if (!(root_work > 0.0)) return 0.0;  // no glue at this radius
  const double t_per_root = std::sqrt(p_.effective_shear_modulus) / root_work * sin_half_;
  return root_a * (root_work / std::sqrt(p_.effective_modulus)) *
         let_go_ratio(std::abs(ux) / root_a * t_per_root);
}

// The let-go elongation over sqrt(2 pi a dgamma / E*), from the table.
double ModeDependentCriterion::let_go_ratio(double t) const {
  if (!(t < 1.0)) return 0.0;  // at or past the supremum of c (or 0/0 at a = 0): no stretch
  const int bottom_pieces = 4 * (-1 - lowest_octave_);
  std::uint64_t bits = 0, first = 0;
  if (t < 0.5) {
    if (t < std::ldexp(1.0, lowest_octave_)) {
      return t < series_end_ ? 1.0 - series_ * t * t : ratio_at(root_angle(t, 1.0 - t, kHalfPi));
    }
    bits = std::bit_cast<std::uint64_t>(t);
    first = static_cast<std::uint64_t>(lowest_octave_ + 1023) << 2;
  } else {
    const double s = 1.0 - t;  // exact (Sterbenz)
    if (s < std::ldexp(1.0, kTopLowestOctave)) return ratio_at(root_angle(t, s, 0.0));
    bits = std::bit_cast<std::uint64_t>(s);
    first = (static_cast<std::uint64_t>(kTopLowestOctave + 1023) << 2) - bottom_pieces;
  }
  const Piece& piece = pieces_[(bits >> kQuarterShift) - first];
  const double x = static_cast<double>(bits & kInPiece) * 0x1p-49 - 1.0;
  const double ratio = evaluate(piece.coefficients, x);
  return std::isnan(ratio) ? ratio_at(root_angle(t, 1.0 - t, 0.5 * kHalfPi)) : ratio;
}

// The root phi of cos(phi) = c sin(lambda pi/2 + (1 - lambda) phi), c = t / sin(lambda pi/2), to
// the last bits: Newton from `guess`, bisecting whenever a step leaves the bracket (the left side
// falls from s at 0 to -c cos(lambda pi/2) at pi/2); by hand, as Boost's Newton may throw and
// this also runs mid-pull-off. s = 1 - t is passed apart, exactly: the equation is written as
// s - 2 sin^2(phi/2) + 2 t sin^2(mu phi/2) - t cot(lambda pi/2) sin(mu phi) = 0, whose terms stay
// accurate near t = 1, where they nearly cancel.
double ModeDependentCriterion::root_angle(double t, double s, double guess) const {
  const double c = t / sin_half_;
  double low = 0.0, high = kHalfPi, phi = guess;
  for (int iteration = 0; iteration < 300; ++iteration) {
    const double half = std::sin(0.5 * phi), half_mu = std::sin(0.5 * mu_ * phi);
    const double f =
        s - 2.0 * half * half + 2.0 * t * half_mu * half_mu - t * cot_half_ * std::sin(mu_ * phi);
    const double slope = -std::sin(phi) - c * mu_ * std::cos(half_lambda_pi_ + mu_ * phi);
    (f > 0.0 ? low : high) = phi;
    const double next = phi - f / slope;
    if (std::abs(next - phi) <= 2.0 * std::numeric_limits<double>::epsilon() * next) return next;
    phi = next > low && next < high ? next : 0.5 * (low + high);
  }
  return phi;
}

// e / sqrt(2 pi a dgamma / E*) at the root phi.
double ModeDependentCriterion::ratio_at(double phi) const {
  return std::sin(phi) / std::sin(half_lambda_pi_ + mu_ * phi);
}

}  // namespace mdrsim
