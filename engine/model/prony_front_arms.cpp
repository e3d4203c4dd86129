// The glued arms' sums with their squares, advanced exactly along a linear drive, and the line
// load at a front between springs.
#include "engine/model/prony_front_arms.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>

#include "engine/model/prony_arms.hpp"

namespace mdrsim {

double relaxation_modulus(double relaxed_modulus, std::span<const PronyTerm> terms, double t) {
  double sum = relaxed_modulus;
  for (const PronyTerm& term : terms) sum += term.modulus * std::exp(-t / term.time);
  return sum;
}

DrivenArmSums::DrivenArmSums(std::vector<PronyTerm> terms)
    : terms_(std::move(terms)),
      history_(terms_.size(), 0.0),
      decaying_(terms_.size(), 0.0),
      squares_(terms_.size(), 0.0) {}

namespace {

/// x - (1 - exp(-x)) and x - 2 (1 - exp(-x)) + (1 - exp(-2x)) / 2, by their series where the
/// differences would cancel (x below 1/2: 20 terms leave 1e-24).
struct DrivenArmMoments {
  double ramp;     ///< int_0^x (1 - e) = x - (1 - exp(-x))
  double ramp_sq;  ///< int_0^x (1 - e)^2
};
DrivenArmMoments driven_arm_moments(double x) {
  if (x >= 0.5) {
    const double once = -std::expm1(-x);
    const double twice = -std::expm1(-2.0 * x);
    return {x - once, x - 2.0 * once + 0.5 * twice};
  }
  // e^-x - 1 + x = sum_{k >= 2} (-x)^k / k!, and the second sum_{k >= 3} (-x)^k (2 - 2^(k-1)) / k!.
  DrivenArmMoments m{0.0, 0.0};
  double power = -x;  // (-x)^k / k!
  double doubled = 1.0;
  for (int k = 2; k <= 22; ++k) {
    power *= -x / static_cast<double>(k);
    doubled *= 2.0;  // 2^(k-1)
    m.ramp += power;
    m.ramp_sq += power * (2.0 - doubled);
  }
  return m;
}

}  // namespace

DrivenArmPiece DrivenArmSums::advance(double rate, double duration) {
  DrivenArmPiece piece;
  if (!(duration > 0.0)) return piece;
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    const PronyTerm& term = terms_[j];
    // sigma_i(s) = beta_i e + A (1 - e), e = exp(-s / tau), A = E r tau, beta_i the member's
    // stress now; with x = h / tau, u1 = 1 - exp(-x), u2 = 1 - exp(-2x):
    //   int sum_i w_i sigma_i = tau (S u1 + W A ramp),
    //   int sum_i w_i sigma_i^2 = tau (Q u2 / 2 + A S u1^2 + W A^2 ramp_sq),
    // S = W H + C and Q = W H^2 + 2 H C + D the sums now. Written so that neither a slow arm
    // (A far above the stresses) nor a fast one cancels.
    const double x = duration / term.time;
    const double u1 = -std::expm1(-x);
    const double u2 = -std::expm1(-2.0 * x);
    const DrivenArmMoments moments = driven_arm_moments(x);
    const double steady = term.modulus * rate * term.time;
    const double h = history_[j];
    const double sum = weight_ * h + decaying_[j];
    const double squares = weight_ * h * h + 2.0 * h * decaying_[j] + squares_[j];
    piece.force_time += term.time * (sum * u1 + weight_ * steady * moments.ramp);
    piece.dissipated += (0.5 * squares * u2 + steady * sum * u1 * u1 +
                         weight_ * steady * steady * moments.ramp_sq) /
                        term.modulus;
    history_[j] = maxwell_arm_after(h, term, rate, duration);
    const double decay = std::exp(-x);
    decaying_[j] *= decay;
    squares_[j] *= decay * decay;
  }
  time_ += duration;
  return piece;
}

DrivenArmMember DrivenArmSums::enter(std::span<const double> stresses, double weight) {
  DrivenArmMember member{time_, FewValues<double>(terms_.size()), weight};
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    member.offsets[j] = stresses[j] - history_[j];
    decaying_[j] += weight * member.offsets[j];
    squares_[j] += weight * member.offsets[j] * member.offsets[j];
  }
  weight_ += weight;
  ++members_;
  return member;
}

double DrivenArmSums::stress(const DrivenArmMember& member, std::size_t j) const {
  return history_[j] + member.offsets[j] * std::exp(-(time_ - member.entry_time) / terms_[j].time);
}

FewValues<double> DrivenArmSums::leave(const DrivenArmMember& member) {
  FewValues<double> stresses(terms_.size());
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    stresses[j] = stress(member, j);
    const double own = stresses[j] - history_[j];
    decaying_[j] -= member.weight * own;
    squares_[j] -= member.weight * own * own;
  }
  weight_ -= member.weight;
  if (--members_ == 0) {
    // An empty set sums to zero exactly, not to the roundoff of its additions and removals.
    weight_ = 0.0;
    std::fill(decaying_.begin(), decaying_.end(), 0.0);
    std::fill(squares_.begin(), squares_.end(), 0.0);
  }
  return stresses;
}

double DrivenArmSums::arm_force() const {
  double sum = 0.0;
  for (std::size_t j = 0; j < terms_.size(); ++j) sum += weight_ * history_[j] + decaying_[j];
  return sum;
}

double DrivenArmSums::stored() const {
  double sum = 0.0;
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    const double h = history_[j];
    sum += (weight_ * h * h + 2.0 * h * decaying_[j] + squares_[j]) / (2.0 * terms_[j].modulus);
  }
  return sum;
}

double FrontLineLoad::at(double image, double s) const {
  double q = relaxed_modulus * (stretch + rate * s);
  const double shift = image - boundary_image;
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const PronyTerm& term = terms[j];
    const double decay = std::exp(-s / term.time);
    q += stresses[j] * decay - term.modulus * rate * term.time * std::expm1(-s / term.time);
    q -= shift * term.modulus * std::exp(-(boundary_age + s) / term.time);
  }
  return q - shift * relaxed_modulus;
}

ExponentialSum FrontLineLoad::slope(double image) const {
  ExponentialSum d;
  d.constant = relaxed_modulus * rate;
  const double shift = image - boundary_image;
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const PronyTerm& term = terms[j];
    d.decays.push_back({term.modulus * rate - stresses[j] / term.time +
                            shift * term.modulus / term.time * std::exp(-boundary_age / term.time),
                        term.time});
  }
  return d;
}

std::optional<double> FrontLineLoad::first_reach(double image, double level, double span) const {
  if (!(span > 0.0)) return std::nullopt;
  // The slope's zeros in (0, span): at most one per term.
  const ExponentialSum d = slope(image);
  std::vector<double> points{0.0};
  ExponentialSum shifted = d;
  for (std::size_t k = 0; k <= terms.size(); ++k) {
    const double from = points.back();
    for (std::size_t j = 0; j < d.decays.size(); ++j) {
      shifted.decays[j].amplitude = d.decays[j].amplitude * std::exp(-from / d.decays[j].time);
    }
    const std::optional<double> zero = first_crossing(shifted, 0.0, span - from);
    if (!zero || !(from + *zero < span)) break;
    points.push_back(from + *zero);
  }
  points.push_back(span);
  const auto g = [&](double s) { return at(image, s) - level; };
  double side = g(0.0);
  std::size_t first = 0;
  if (side == 0.0) {
    side = g(points[1]);
    if (side == 0.0) return std::nullopt;
    first = 1;
  }
  double g_lo = g(points[first]);
  for (std::size_t i = first; i + 1 < points.size(); ++i) {
    const double lo = points[i];
    const double hi = points[i + 1];
    const double g_hi = g(hi);
    if (g_hi == 0.0) return hi;
    if ((g_hi < 0.0) != (side < 0.0)) {
      if (g_lo == 0.0) return lo;
      std::uintmax_t iterations = 200;
      const double width = hi - lo;
      const auto root = boost::math::tools::toms748_solve(
          g, lo, hi, g_lo, g_hi,
          [width](double a, double b) { return std::abs(b - a) <= 1e-15 * width; }, iterations);
      return 0.5 * (root.first + root.second);
    }
    g_lo = g_hi;
  }
  return std::nullopt;
}

}  // namespace mdrsim
