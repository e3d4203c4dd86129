// The running total of exponential sums with shared decay times.
#include "engine/model/exponential_sum_total.hpp"

#include <cmath>

namespace mdrsim {

void ExponentialSumTotal::clear(double now) {
  time_ = now;
  total_.constant = 0.0;
  total_.slope = 0.0;
  total_.decays.clear();
}

void ExponentialSumTotal::rebase(double now) {
  const double step = now - time_;
  if (step == 0.0) return;
  total_.constant += total_.slope * step;
  for (ExponentialDecay& d : total_.decays) d.amplitude *= std::exp(-step / d.time);
  time_ = now;
}

void ExponentialSumTotal::add(const ExponentialSum& f, double since, double now, double sign) {
  rebase(now);
  const double age = now - since;
  total_.constant += sign * (f.constant + f.slope * age);
  total_.slope += sign * f.slope;
  if (total_.decays.empty()) {
    for (const ExponentialDecay& d : f.decays) total_.decays.push_back({0.0, d.time});
  }
  for (std::size_t j = 0; j < f.decays.size(); ++j) {
    const ExponentialDecay& d = f.decays[j];
    total_.decays[j].amplitude += sign * d.amplitude * std::exp(-age / d.time);
  }
}

double ExponentialSumTotal::at(double t) const { return total_.at(t - time_); }

}  // namespace mdrsim
