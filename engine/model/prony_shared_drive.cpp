// The per-term sums of arms that share one drive, advanced exactly between events.
#include "engine/model/prony_shared_drive.hpp"

#include <algorithm>
#include <cmath>

#include "engine/model/prony_arms.hpp"
#include "engine/model/prony_load_drive.hpp"

namespace mdrsim {

SharedDriveArms::SharedDriveArms(std::vector<PronyTerm> terms)
    : terms_(std::move(terms)), history_(terms_.size(), 0.0), decaying_(terms_.size(), 0.0) {
  for (const PronyTerm& term : terms_) rates_.push_back(1.0 / term.time);
}

void SharedDriveArms::advance(double rate, double duration) {
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    history_[j] = maxwell_arm_after(history_[j], terms_[j], rate, duration);
    decaying_[j] *= std::exp(-duration / terms_[j].time);
  }
  time_ += duration;
}

void SharedDriveArms::advance(double rate, double duration, std::span<const double> relaxed_parts) {
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    const double steady = terms_[j].modulus * rate * terms_[j].time;
    history_[j] += (steady - history_[j]) * relaxed_parts[j];
    // exp(-duration / tau_j) from the part given, to an eps, with no call of its own.
    decaying_[j] *= 1.0 - relaxed_parts[j];
  }
  time_ += duration;
}

void SharedDriveArms::advance_along(const ExponentialSum& motion, double duration) {
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    history_[j] = arm_stress_under(history_[j], terms_[j], motion).at(duration);
    decaying_[j] *= std::exp(-duration / terms_[j].time);
  }
  time_ += duration;
}

void SharedDriveArms::glassy_step(double step) {
  for (std::size_t j = 0; j < terms_.size(); ++j) history_[j] += terms_[j].modulus * step;
}

SharedDriveMember SharedDriveArms::enter(std::span<const double> stresses, double weight) {
  SharedDriveMember member{time_, FewValues<double>(terms_.size()), weight};
  enter(stresses, weight, member.offsets);
  return member;
}

double SharedDriveArms::enter(std::span<const double> stresses, double weight,
                              std::span<double> offsets) {
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    offsets[j] = stresses[j] - history_[j];
    decaying_[j] += weight * offsets[j];
  }
  weight_ += weight;
  ++members_;
  return time_;
}

double SharedDriveArms::stress(const SharedDriveMember& member, std::size_t j) const {
  return stress(SharedDriveMemberRef{member.entry_time, member.offsets}, j);
}

double SharedDriveArms::stress(const SharedDriveMemberRef& member, std::size_t j) const {
  const double age = time_ - member.entry_time;
  // exp(-0 / tau) is 1 exactly: a member read as it enters needs no call.
  if (age == 0.0) return history_[j] + member.offsets[j];
  return history_[j] + member.offsets[j] * std::exp(-age * rates_[j]);
}

FewValues<double> SharedDriveArms::leave(const SharedDriveMember& member) {
  FewValues<double> stresses(terms_.size());
  leave(SharedDriveMemberRef{member.entry_time, member.offsets}, member.weight, stresses);
  return stresses;
}

void SharedDriveArms::leave(const SharedDriveMemberRef& member, double weight,
                            std::span<double> stresses) {
  for (std::size_t j = 0; j < terms_.size(); ++j) stresses[j] = stress(member, j);
  leave_read(stresses, weight);
}

void SharedDriveArms::leave_read(std::span<const double> stresses, double weight) {
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    decaying_[j] -= weight * (stresses[j] - history_[j]);
  }
  weight_ -= weight;
  if (--members_ == 0) {
    // An empty set sums to zero exactly, not to the roundoff of its additions and removals.
    weight_ = 0.0;
    std::fill(decaying_.begin(), decaying_.end(), 0.0);
  }
}

double SharedDriveArms::arm_force(std::size_t j) const {
  return weight_ * history_[j] + decaying_[j];
}

double SharedDriveArms::arm_force() const {
  double sum = 0.0;
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    sum += arm_force(j);
  }
  return sum;
}

}  // namespace mdrsim
