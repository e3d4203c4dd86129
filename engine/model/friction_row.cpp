// The springs in contact under Coulomb friction: their tangential force, slip events and frictional
// work.
#include "engine/model/friction_row.hpp"

#include <stdexcept>

namespace mdrsim {

FrictionRow::FrictionRow(const Material& material, const FrictionSettings& settings, double spacing)
    : settings_(settings),
      normal_stiffness_(material.effective_modulus * spacing),
      tangential_stiffness_(material.effective_shear_modulus * spacing),
      spacing_(spacing) {}

SpringGeometry FrictionRow::geometry(std::int64_t i) const {
  return {normal_stiffness_, tangential_stiffness_, springs_[index(i)].image};
}

std::optional<CoulombLaw> FrictionRow::law(std::int64_t i) const {
  if (i > glued_) return CoulombLaw{settings_.coefficient, 0.0};
  if (settings_.glued == GluedLaw::unlimited) return std::nullopt;
  return CoulombLaw{settings_.coefficient, settings_.shear_strength * spacing_};
}

void FrictionRow::touch(double image, double tangential) {
  springs_.push_back({CoulombSpring{tangential, 0}, image});
}

void FrictionRow::lift_outer() {
  if (in_contact() <= glued_) throw std::logic_error("FrictionRow::lift_outer: spring m is glued");
  springs_.pop_back();
}

void FrictionRow::glue_next() {
  if (glued_ >= in_contact()) throw std::logic_error("FrictionRow::glue_next: no spring k+1");
  // A sliding spring glues only once it sticks (docs/friction.md).
  if (springs_[index(glued_ + 1)].state.sliding != 0)
    throw std::logic_error("FrictionRow::glue_next: spring k+1 slides");
  ++glued_;
}

double FrictionRow::let_go_boundary(double indentation, double tangential) {
  if (glued_ == 0) throw std::logic_error("FrictionRow::let_go_boundary: nothing glued");
  const std::int64_t i = glued_--;
  return 2.0 *
         slip_to_limit(springs_[index(i)].state, *law(i), geometry(i), indentation, tangential);
}

double FrictionRow::tangential_force(double indentation, double tangential) const {
  double sum = 0.0;
  for (std::int64_t i = 1; i <= in_contact(); ++i) {
    const CoulombSpring& state = springs_[index(i)].state;
    if (state.sliding == 0) {
      sum += tangential_stiffness_ * (tangential - state.offset);
    } else {
      sum += spring_tangential_force(state, *law(i), geometry(i), indentation, tangential);
    }
  }
  return 2.0 * sum;
}

std::int64_t FrictionRow::springs_sliding() const {
  std::int64_t count = 0;
  for (const Spring& s : springs_) count += s.state.sliding != 0 ? 1 : 0;
  return count;
}

double FrictionRow::stick_radius() const {
  for (std::int64_t i = 1; i <= in_contact(); ++i)
    if (springs_[index(i)].state.sliding != 0) return position(i - 1);
  return position(in_contact());
}

std::optional<RowFrictionEvent> FrictionRow::next_event(const LinearMotion& motion,
                                                        double end) const {
  std::optional<RowFrictionEvent> first;
  for (std::int64_t i = 1; i <= in_contact(); ++i) {
    const auto spring_law = law(i);
    if (!spring_law) continue;
    const double until = first ? first->event.at : end;
    const auto event =
        next_friction_event(springs_[index(i)].state, *spring_law, geometry(i), motion, until);
    if (event && (!first || event->at < first->event.at)) first = RowFrictionEvent{i, *event};
  }
  return first;
}

double FrictionRow::advance(const LinearMotion& motion, double t) {
  double dissipated = 0.0;
  for (std::int64_t i = 1; i <= in_contact(); ++i) {
    Spring& s = springs_[index(i)];
    if (s.state.sliding == 0) continue;
    dissipated += advance_spring(s.state, *law(i), geometry(i), motion, t);
  }
  return 2.0 * dissipated;
}

void FrictionRow::apply(const RowFrictionEvent& event) {
  apply_friction_event(springs_[index(event.spring)].state, event.event);
}

}  // namespace mdrsim
