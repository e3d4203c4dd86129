// A free spring's creep by the retardation modes of its arms, and its touch with the indenter.
#include "engine/model/prony_creep.hpp"

#include <algorithm>
#include <cmath>

#include "engine/base/bracketed_root.hpp"

namespace mdrsim {

FreeSpringCreep::FreeSpringCreep(double relaxed_modulus, std::span<const PronyTerm> terms,
                                 std::span<const double> stresses)
    : relaxed_modulus_(relaxed_modulus), terms_(terms.begin(), terms.end()) {
  // Group the terms by relaxation time, ascending rate 1/tau.
  std::vector<std::size_t> order(terms_.size());
  for (std::size_t j = 0; j < order.size(); ++j) {
    order[j] = j;
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return terms_[a].time > terms_[b].time; });
  group_of_.resize(terms_.size());
  std::vector<double> group_stress;
  for (const std::size_t j : order) {
    if (groups_.empty() || groups_.back().time != terms_[j].time) {
      groups_.push_back({0.0, terms_[j].time});
      group_stress.push_back(0.0);
    }
    groups_.back().modulus += terms_[j].modulus;
    group_stress.back() += stresses[j];
    group_of_[j] = groups_.size() - 1;
  }
  residuals_.resize(terms_.size());
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    const PronyTerm& group = groups_[group_of_[j]];
    residuals_[j] = stresses[j] - terms_[j].modulus / group.modulus * group_stress[group_of_[j]];
  }

  // The retardation rates: E* = mu sum_g E_g / (lambda_g - mu), one root per interval.
  const std::size_t count = groups_.size();
  const auto secular = [&](double mu) {
    double sum = 0.0;
    for (const PronyTerm& group : groups_) {
      sum += group.modulus / (1.0 / group.time - mu);
    }
    return mu * sum - relaxed_modulus_;
  };
  for (std::size_t k = 0; k < count; ++k) {
    const double lo = k == 0 ? 0.0 : std::nextafter(1.0 / groups_[k - 1].time, HUGE_VAL);
    const double hi = std::nextafter(1.0 / groups_[k].time, 0.0);
    rates_.push_back(bracketed_root(secular, lo, hi));
  }

  // alpha_k = <v_k, y0> / <v_k, v_k> in <u, v> = sum_g E_g u_g v_g + (sum E_g u_g)(sum E_g v_g) /
  // E*.
  const auto inner = [&](const std::vector<double>& u, const std::vector<double>& v) {
    double diagonal = 0.0, eu = 0.0, ev = 0.0;
    for (std::size_t g = 0; g < count; ++g) {
      diagonal += groups_[g].modulus * u[g] * v[g];
      eu += groups_[g].modulus * u[g];
      ev += groups_[g].modulus * v[g];
    }
    return diagonal + eu * ev / relaxed_modulus_;
  };
  std::vector<double> initial(count);
  for (std::size_t g = 0; g < count; ++g) {
    initial[g] = group_stress[g] / groups_[g].modulus;
  }
  for (std::size_t k = 0; k < count; ++k) {
    std::vector<double> mode(count);
    for (std::size_t g = 0; g < count; ++g) {
      mode[g] = 1.0 / (1.0 / groups_[g].time - rates_[k]);
    }
    const double alpha = inner(mode, initial) / inner(mode, mode);
    for (double& v : mode) {
      v *= alpha;
    }
    strains_.push_back(std::move(mode));
  }
}

std::vector<double> FreeSpringCreep::stresses(double t) const {
  std::vector<double> group_stress(groups_.size(), 0.0);
  for (std::size_t k = 0; k < rates_.size(); ++k) {
    const double decay = std::exp(-rates_[k] * t);
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      group_stress[g] += groups_[g].modulus * strains_[k][g] * decay;
    }
  }
  std::vector<double> out(terms_.size());
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    const PronyTerm& group = groups_[group_of_[j]];
    out[j] = terms_[j].modulus / group.modulus * group_stress[group_of_[j]] +
             residuals_[j] * std::exp(-t / terms_[j].time);
  }
  return out;
}

ExponentialSum FreeSpringCreep::stretch_from(double t0) const {
  // w = -sum_g sigma_g / E* (the residuals of a group sum to zero).
  ExponentialSum w;
  for (std::size_t k = 0; k < rates_.size(); ++k) {
    double amplitude = 0.0;
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      amplitude -= groups_[g].modulus * strains_[k][g];
    }
    w.decays.push_back({amplitude / relaxed_modulus_ * std::exp(-rates_[k] * t0), 1.0 / rates_[k]});
  }
  return w;
}

double FreeSpringCreep::stretch(double t) const { return stretch_from(t).at(0.0); }

std::optional<double> touch_time(const FreeSpringCreep& creep, double t0, double indenter_stretch,
                                 double rate, double span) {
  // The indenter's stretch less the free surface's: negative while apart, zero at the touch.
  ExponentialSum overlap = creep.stretch_from(t0);
  for (ExponentialDecay& decay : overlap.decays) {
    decay.amplitude = -decay.amplitude;
  }
  overlap.constant = indenter_stretch;
  overlap.slope = rate;
  return first_crossing(overlap, 0.0, span);
}

}  // namespace mdrsim
