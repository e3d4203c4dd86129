// The viscoelastic row's let-go loads and glue gaps, spring by spring, from the glassy criterion.
#include "engine/model/viscoelastic_edge.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "detachment/let_go.hpp"
#include "engine/base/hess_scale.hpp"

namespace mdrsim {

Material glassy_material(const Material& material) {
  Material glassy = material;
  const double e0 = material.glassy_modulus();
  glassy.effective_shear_modulus =
      material.effective_shear_modulus * (e0 / material.effective_modulus);
  glassy.effective_modulus = e0;
  return glassy;
}

ViscoelasticEdge viscoelastic_edge(const DetachmentCriterion& glassy_criterion,
                                   const Material& material, double spacing, std::size_t springs,
                                   bool rebinding) {
  ViscoelasticEdge edge;
  edge.glassy_modulus = material.glassy_modulus();
  edge.rebinding = rebinding;
  edge.glassy_shear_modulus = glassy_material(material).effective_shear_modulus;
  edge.criterion = &glassy_criterion;
  edge.let_go_loads.reserve(springs);
  edge.glue_gaps.reserve(springs);
  edge.surface_energies.reserve(springs);
  for (std::size_t i = 1; i <= springs; ++i) {
    const double x = spacing * static_cast<double>(i);
    const double dgamma = material.work_of_adhesion_at(x);
    const double hess = std::sqrt(hess_scale(dgamma, edge.glassy_modulus) * x);
    double load = 0.0;
    if (hess > 0.0) {
      const LetGo let_go = locate_let_go(glassy_criterion, x, 0.0, hess);
      if (let_go.kind == LetGo::Kind::at_elongation) {
        load = edge.glassy_modulus * let_go.elongation;
      } else if (let_go.kind == LetGo::Kind::never) {
        load = std::numeric_limits<double>::infinity();
      }
    }
    edge.let_go_loads.push_back(load);
    edge.glue_gaps.push_back(
        std::sqrt(hess_scale(material.approach_work_of_adhesion_at(x), edge.glassy_modulus) * x));
    edge.surface_energies.push_back(std::numbers::pi * x * dgamma);
  }
  return edge;
}

std::optional<double> reach_time(const FreeSpringCreepRef& creep, double t0, double reach,
                                 double rate, double span, bool on_level) {
  // The reach less the free surface: negative while apart, zero where they meet.
  ExponentialSum apart = creep.stretch_from(t0);
  for (ExponentialDecay& decay : apart.decays) decay.amplitude = -decay.amplitude;
  apart.constant = reach - apart.constant;
  apart.slope = rate - apart.slope;
  // On the level: the level where the difference stands, to the bit, so that its side is
  // read from where it goes.
  return first_crossing(apart, on_level ? apart.at(0.0) : 0.0, span);
}

std::optional<double> reach_time(const FreeSpringCreep& creep, double t0, double reach, double rate,
                                 double span, bool on_level) {
  return reach_time(creep.numbers(), t0, reach, rate, span, on_level);
}

void glassy_step(std::span<double> stresses, std::span<const PronyTerm> terms, double step) {
  for (std::size_t j = 0; j < terms.size(); ++j) stresses[j] += terms[j].modulus * step;
}

}  // namespace mdrsim
