// A free spring's creep by the retardation modes of its arms, and its touch with the indenter.
#include "engine/model/prony_creep.hpp"

#include <algorithm>
#include <cmath>

#include "engine/base/bracketed_root.hpp"

namespace mdrsim {

RetardationModes::RetardationModes(double relaxed_modulus, std::span<const PronyTerm> terms)
    : relaxed_modulus_(relaxed_modulus), terms_(terms.begin(), terms.end()) {
  // Group the terms by relaxation time, ascending rate 1/tau.
  std::vector<std::size_t> order(terms_.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return terms_[a].time > terms_[b].time; });
  group_of_.resize(terms_.size());
  for (const std::size_t j : order) {
    if (groups_.empty() || groups_.back().time != terms_[j].time) {
      groups_.push_back({0.0, terms_[j].time});
    }
    groups_.back().modulus += terms_[j].modulus;
    group_of_[j] = groups_.size() - 1;
  }
  // The retardation rates: E* = mu sum_g E_g / (lambda_g - mu), one root per interval.
  const auto secular = [&](double mu) {
    double sum = 0.0;
    for (const PronyTerm& group : groups_) sum += group.modulus / (1.0 / group.time - mu);
    return mu * sum - relaxed_modulus_;
  };
  const std::size_t count = groups_.size();
  for (std::size_t k = 0; k < count; ++k) {
    const double lo = k == 0 ? 0.0 : std::nextafter(1.0 / groups_[k - 1].time, HUGE_VAL);
    const double hi = std::nextafter(1.0 / groups_[k].time, 0.0);
    rates_.push_back(bracketed_root(secular, lo, hi));
    std::vector<double> mode(count);
    for (std::size_t g = 0; g < count; ++g) mode[g] = 1.0 / (1.0 / groups_[g].time - rates_[k]);
    modes_.push_back(std::move(mode));
  }
  for (std::size_t k = 0; k < count; ++k) {
    double diagonal = 0.0, weighted = 0.0;
    for (std::size_t g = 0; g < count; ++g) {
      diagonal += groups_[g].modulus * modes_[k][g] * modes_[k][g];
      weighted += groups_[g].modulus * modes_[k][g];
    }
    mode_norms_.push_back(diagonal + weighted * weighted / relaxed_modulus_);
    double amplitude = 0.0;
    for (std::size_t g = 0; g < count; ++g) amplitude -= groups_[g].modulus * modes_[k][g];
    stretch_amplitudes_.push_back(amplitude);
    stretch_of_modes_.push_back(amplitude / relaxed_modulus_);
  }
  // alpha_k = <v_k, y0> / <v_k, v_k>, <u, v> = sum_g E_g u_g v_g + (sum E_g u_g)(sum E_g v_g) / E*,
  // with y0_g = sigma_g / E_g (E_g y0_g = sigma_g): linear in sigma_g, its coefficients once here.
  for (std::size_t k = 0; k < count; ++k) {
    double weighted = 0.0;
    for (std::size_t g = 0; g < count; ++g) weighted += groups_[g].modulus * modes_[k][g];
    for (std::size_t g = 0; g < count; ++g) {
      projections_.push_back((modes_[k][g] + weighted / relaxed_modulus_) / mode_norms_[k]);
      stress_of_modes_.push_back(groups_[g].modulus * modes_[k][g]);
    }
  }
  for (std::size_t j = 0; j < terms_.size(); ++j) {
    shares_.push_back(terms_[j].modulus / groups_[group_of_[j]].modulus);
  }
}

FewValues<double> RetardationModes::amplitudes(std::span<const double> group_stresses) const {
  FewValues<double> alpha(rates_.size());
  amplitudes(group_stresses, alpha);
  return alpha;
}

void RetardationModes::amplitudes(std::span<const double> group_stresses,
                                  std::span<double> alpha) const {
  const std::size_t count = groups_.size();
  for (std::size_t k = 0; k < rates_.size(); ++k) {
    double sum = 0.0;
    for (std::size_t g = 0; g < count; ++g) sum += projections_[k * count + g] * group_stresses[g];
    alpha[k] = sum;
  }
}

void free_spring_numbers(const RetardationModes& modes, std::span<const double> stresses,
                         std::span<double> amplitudes, std::span<double> residuals) {
  const std::span<const PronyTerm> terms = modes.terms();
  if (terms.size() == 1) {
    // One term, one group, one mode, no residual (a release an event: no temporaries).
    modes.amplitudes(stresses, amplitudes);
    residuals[0] = 0.0;
    return;
  }
  if (modes.groups().size() == terms.size()) {
    // Each term its own group (distinct relaxation times, the usual case): the terms are the
    // groups, reordered, and no term has a residual.
    FewValues<double> group_stresses(terms.size());
    for (std::size_t j = 0; j < terms.size(); ++j) group_stresses[modes.group_of(j)] = stresses[j];
    modes.amplitudes(group_stresses, amplitudes);
    std::fill(residuals.begin(), residuals.end(), 0.0);
    return;
  }
  FewValues<double> group_stresses(modes.groups().size(), 0.0);
  for (std::size_t j = 0; j < terms.size(); ++j) group_stresses[modes.group_of(j)] += stresses[j];
  modes.amplitudes(group_stresses, amplitudes);
  for (std::size_t j = 0; j < terms.size(); ++j) {
    residuals[j] = stresses[j] - modes.share_of_group(j) * group_stresses[modes.group_of(j)];
  }
}

FreeSpringCreep::FreeSpringCreep(std::shared_ptr<const RetardationModes> modes,
                                 std::span<const double> stresses)
    : modes_(std::move(modes)),
      amplitudes_(modes_->rates().size()),
      residuals_(modes_->terms().size()) {
  free_spring_numbers(*modes_, stresses, amplitudes_, residuals_);
}

FreeSpringCreep::FreeSpringCreep(double relaxed_modulus, std::span<const PronyTerm> terms,
                                 std::span<const double> stresses)
    : FreeSpringCreep(std::make_shared<const RetardationModes>(relaxed_modulus, terms), stresses) {}

FewValues<double> FreeSpringCreepRef::stresses(double t) const {
  FewValues<double> decays(amplitudes_.size());
  for (std::size_t k = 0; k < decays.size(); ++k) decays[k] = std::exp(-modes_->rates()[k] * t);
  return stresses_from_decays(t, decays);
}

FewValues<double> FreeSpringCreepRef::stresses(double t, double& stretch) const {
  FewValues<double> decays(amplitudes_.size());
  stretch = 0.0;
  for (std::size_t k = 0; k < decays.size(); ++k) {
    // exp(-mu 0) is 1 exactly, as mode_stretch and stresses(t) read it.
    decays[k] = t == 0.0 ? 1.0 : std::exp(-modes_->rates()[k] * t);
    stretch += modes_->stretch_of_mode(k) * amplitudes_[k] * decays[k];
  }
  return stresses_from_decays(t, decays);
}

double FreeSpringCreepRef::stored(double t) const {
  double e = 0.0;
  for (std::size_t k = 0; k < amplitudes_.size(); ++k) {
    // exp(-mu 0) is 1 exactly, as stresses(t) reads it.
    const double part =
        t == 0.0 ? amplitudes_[k] : amplitudes_[k] * std::exp(-modes_->rates()[k] * t);
    e += modes_->stored_of_mode(k) * part * part;
  }
  const std::span<const PronyTerm> terms = modes_->terms();
  for (std::size_t j = 0; j < terms.size(); ++j) {
    if (residuals_[j] == 0.0) continue;  // a term alone in its group
    const double residual = residuals_[j] * std::exp(-t / terms[j].time);
    e += 0.5 * residual * residual / terms[j].modulus;
  }
  return e;
}

FewValues<double> FreeSpringCreepRef::stresses_from_decays(double t,
                                                           std::span<const double> decays) const {
  const std::span<const PronyTerm> groups = modes_->groups();
  FewValues<double> group_stress(groups.size(), 0.0);
  for (std::size_t k = 0; k < amplitudes_.size(); ++k) {
    const double decay = amplitudes_[k] * decays[k];
    for (std::size_t g = 0; g < groups.size(); ++g) {
      group_stress[g] += modes_->stress_of_mode(k, g) * decay;
    }
  }
  const std::span<const PronyTerm> terms = modes_->terms();
  FewValues<double> out(terms.size());
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const std::size_t g = modes_->group_of(j);
    // A term alone in its group has no residual (zero times its decay, which need not be read).
    const double residual =
        residuals_[j] == 0.0 ? residuals_[j] : residuals_[j] * std::exp(-t / terms[j].time);
    out[j] = modes_->share_of_group(j) * group_stress[g] + residual;
  }
  return out;
}

ExponentialSum FreeSpringCreepRef::stretch_from(double t0) const {
  // w = -sum_g sigma_g / E* (the residuals of a group sum to zero).
  ExponentialSum w;
  stretch_from(t0, w);
  return w;
}

void FreeSpringCreepRef::stretch_from(double t0, ExponentialSum& w) const {
  w.constant = 0.0;
  w.slope = 0.0;
  w.decays.clear();
  for (std::size_t k = 0; k < amplitudes_.size(); ++k) {
    w.decays.push_back({mode_stretch(k, t0), 1.0 / modes_->rates()[k]});
  }
}

double FreeSpringCreepRef::mode_stretch(std::size_t k, double t) const {
  const double at_release = modes_->stretch_of_mode(k) * amplitudes_[k];
  // exp(-mu 0) is 1 exactly: a spring read as it is released needs no call.
  return t == 0.0 ? at_release : at_release * std::exp(-modes_->rates()[k] * t);
}

double FreeSpringCreepRef::stretch(double t) const {
  // stretch_from(t) at 0, summed as ExponentialSum::at sums it (each decay times exp(0) = 1).
  double w = 0.0;
  for (std::size_t k = 0; k < amplitudes_.size(); ++k) w += mode_stretch(k, t);
  return w;
}

std::optional<double> touch_time(const FreeSpringCreep& creep, double t0, double indenter_stretch,
                                 double rate, double span) {
  // The indenter's stretch less the free surface's: negative while apart, zero at the touch.
  ExponentialSum overlap = creep.stretch_from(t0);
  for (ExponentialDecay& decay : overlap.decays) decay.amplitude = -decay.amplitude;
  overlap.constant = indenter_stretch;
  overlap.slope = rate;
  return first_crossing(overlap, 0.0, span);
}

}  // namespace mdrsim
