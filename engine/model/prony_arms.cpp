// The exact exponential update of Maxwell arms under a linear stretch.
#include "engine/model/prony_arms.hpp"

#include <cmath>

namespace mdrsim {

double maxwell_arm_after(double stress, const PronyTerm& term, double rate, double duration) {
  // 1 - exp(-h / tau) by expm1: exact for h far below tau, where the difference would cancel.
  const double relaxed_part = -std::expm1(-duration / term.time);
  return stress + (term.modulus * rate * term.time - stress) * relaxed_part;
}

void advance_arms(std::span<double> stresses, std::span<const PronyTerm> terms, double rate,
                  double duration) {
  for (std::size_t j = 0; j < terms.size(); ++j) {
    stresses[j] = maxwell_arm_after(stresses[j], terms[j], rate, duration);
  }
}

ExponentialSum line_load_over(double relaxed_modulus, std::span<const PronyTerm> terms,
                              double stretch, std::span<const double> stresses, double rate) {
  ExponentialSum load;
  line_load_over(load, relaxed_modulus, terms, stretch, stresses, rate);
  return load;
}

void line_load_over(ExponentialSum& load, double relaxed_modulus, std::span<const PronyTerm> terms,
                    double stretch, std::span<const double> stresses, double rate) {
  load.constant = relaxed_modulus * stretch;
  load.slope = relaxed_modulus * rate;
  load.decays.clear();
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const double steady = terms[j].modulus * rate * terms[j].time;
    load.constant += steady;
    load.decays.push_back({stresses[j] - steady, terms[j].time});
  }
}

}  // namespace mdrsim
