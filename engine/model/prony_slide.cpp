// The prescribed-load response of a viscoelastic spring: a particular part per piece of the load
// and the free creep of the rest.
#include "engine/model/prony_slide.hpp"

#include <cmath>

namespace mdrsim {

PrescribedLoadResponse free_creep_sums(const RetardationModes& modes,
                                       std::span<const double> stresses) {
  const std::span<const PronyTerm> terms = modes.terms();
  const std::span<const PronyTerm> groups = modes.groups();
  FewValues<double> group_stresses(groups.size(), 0.0);
  for (std::size_t j = 0; j < terms.size(); ++j) group_stresses[modes.group_of(j)] += stresses[j];
  const FewValues<double> alpha = modes.amplitudes(group_stresses);
  PrescribedLoadResponse r{{}, std::vector<ExponentialSum>(terms.size())};
  for (std::size_t k = 0; k < alpha.size(); ++k) {
    const double time = 1.0 / modes.rates()[k];
    r.stretch.decays.push_back(
        {modes.stretch_amplitude(k) * alpha[k] / modes.relaxed_modulus(), time});
    for (std::size_t j = 0; j < terms.size(); ++j) {
      const std::size_t g = modes.group_of(j);
      r.stresses[j].decays.push_back({terms[j].modulus * modes.mode(k, g) * alpha[k], time});
    }
  }
  // What a group's terms hold beyond their shares of its stress decays at their own tau.
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const std::size_t g = modes.group_of(j);
    const double residual = stresses[j] - terms[j].modulus / groups[g].modulus * group_stresses[g];
    if (residual != 0.0) r.stresses[j].decays.push_back({residual, terms[j].time});
  }
  return r;
}

PrescribedLoadResponse response_to_load(const RetardationModes& modes,
                                        std::span<const double> stresses,
                                        const ExponentialSum& load) {
  const std::span<const PronyTerm> terms = modes.terms();
  const double relaxed = modes.relaxed_modulus();
  PrescribedLoadResponse p{{}, std::vector<ExponentialSum>(terms.size())};
  // The line: the arms carry G_j tau_j b, the relaxed spring the rest.
  const double rate = load.slope / relaxed;
  double arms = 0.0;
  for (std::size_t j = 0; j < terms.size(); ++j) {
    p.stresses[j].constant = terms[j].modulus * terms[j].time * rate;
    arms += p.stresses[j].constant;
  }
  p.stretch.constant = (load.constant - arms) / relaxed;
  p.stretch.slope = rate;
  for (const ExponentialDecay& d : load.decays) {
    std::size_t group = modes.groups().size();
    for (std::size_t g = 0; g < modes.groups().size(); ++g) {
      if (modes.groups()[g].time == d.time) group = g;
    }
    if (group < modes.groups().size()) {
      // The group's arms relax at this rate on their own: the stretch stays.
      const double share = d.amplitude / modes.groups()[group].modulus;
      for (std::size_t j = 0; j < terms.size(); ++j) {
        if (modes.group_of(j) == group) {
          p.stresses[j].decays.push_back({terms[j].modulus * share, d.time});
        }
      }
      continue;
    }
    double stiffness = relaxed;
    for (const PronyTerm& term : terms) {
      stiffness += term.modulus * term.time / (term.time - d.time);
    }
    const double amplitude = d.amplitude / stiffness;
    p.stretch.decays.push_back({amplitude, d.time});
    for (std::size_t j = 0; j < terms.size(); ++j) {
      const PronyTerm& term = terms[j];
      p.stresses[j].decays.push_back(
          {term.modulus * term.time / (term.time - d.time) * amplitude, d.time});
    }
  }
  // The free creep of what the arms hold beyond the particular response at s = 0.
  FewValues<double> beyond(terms.size());
  for (std::size_t j = 0; j < terms.size(); ++j) beyond[j] = stresses[j] - p.stresses[j].at(0.0);
  const PrescribedLoadResponse h = free_creep_sums(modes, beyond);
  p.stretch.decays.insert(p.stretch.decays.end(), h.stretch.decays.begin(), h.stretch.decays.end());
  for (std::size_t j = 0; j < terms.size(); ++j) {
    p.stresses[j].decays.insert(p.stresses[j].decays.end(), h.stresses[j].decays.begin(),
                                h.stresses[j].decays.end());
  }
  return p;
}

}  // namespace mdrsim
