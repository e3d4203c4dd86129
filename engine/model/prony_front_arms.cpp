// The glued arms' sums with their squares, advanced exactly along a linear drive, and the line
// load at a front between springs.
#include "engine/model/prony_front_arms.hpp"

#include <algorithm>
#include <cmath>

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

DrivenArmPiece DrivenArmSums::advance(double rate, double duration) {
  DrivenArmPiece piece;
  if (!(duration > 0.0)) return piece;
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    const PronyTerm& term = terms_[j];
    // sigma_i(s) = A + (B + c_i) e(s), e = exp(-s / tau), A = E r tau, B = H(0) - A: the sums
    // are W A + (W B + C) e and W A^2 + 2 A (W B + C) e + (W B^2 + 2 B C + D) e^2.
    const double steady = term.modulus * rate * term.time;
    const double b = history_[j] - steady;
    const double c = decaying_[j];
    const double once = -std::expm1(-duration / term.time) * term.time;               // int e ds
    const double twice = -std::expm1(-2.0 * duration / term.time) * 0.5 * term.time;  // int e^2
    piece.force_time += weight_ * steady * duration + (weight_ * b + c) * once;
    const double squares = weight_ * steady * steady * duration +
                           2.0 * steady * (weight_ * b + c) * once +
                           (weight_ * b * b + 2.0 * b * c + squares_[j]) * twice;
    piece.dissipated += squares / (term.modulus * term.time);
    history_[j] = maxwell_arm_after(history_[j], term, rate, duration);
    const double decay = std::exp(-duration / term.time);
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

ExponentialSum FrontLineLoad::at_image(double image) const {
  ExponentialSum q = boundary;
  const double shift = image - boundary_image;
  q.constant -= relaxed_modulus * shift;
  for (const PronyTerm& term : terms) {
    q.decays.push_back({-term.modulus * shift * std::exp(-boundary_age / term.time), term.time});
  }
  return q;
}

}  // namespace mdrsim
