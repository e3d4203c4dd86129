// Equilibrium of the glued contact from running sums, and removal of the boundary spring.
#include "engine/model/contact.hpp"

namespace mdrsim {

Contact::Contact(const SpringFoundation& foundation, const Material& material,
                 AffineConstraint normal, AffineConstraint tangential)
    : foundation_(&foundation),
      material_(material),
      normal_(normal),
      tangential_(tangential),
      state_{foundation.springs(), {}, 0.0, 0.0, foundation.image(foundation.springs())} {
  state_.image_sum.add(foundation.total_image());
}

LinearResponse Contact::normal_response() const {
  if (foundation_->graded()) {
    return {foundation_->graded_stiffness_to(state_.springs_in_contact), state_.image_sum.value()};
  }
  const double per_spring = 2.0 * material_.effective_modulus * foundation_->spacing();
  return {per_spring * static_cast<double>(state_.springs_in_contact),
          per_spring * state_.image_sum.value()};
}

LinearResponse Contact::tangential_response() const {
  const double per_spring = 2.0 * material_.effective_shear_modulus * foundation_->spacing();
  return {per_spring * static_cast<double>(state_.springs_in_contact), 0.0};
}

double Contact::indentation() const {
  return displacement_under(normal_, normal_response(), state_.normal_control);
}

double Contact::tangential_displacement() const {
  return displacement_under(tangential_, tangential_response(), state_.tangential_held);
}

double Contact::contact_radius() const { return foundation_->position(state_.springs_in_contact); }

double Contact::normal_control_at(double indentation) const {
  return held_value_at(normal_, normal_response(), indentation);
}

double Contact::normal_force_of(const State& state) const { return normal_state_of(state).second; }

std::pair<double, double> Contact::normal_state_of(const State& state) const {
  const double per_spring = 2.0 * material_.effective_modulus * foundation_->spacing();
  const LinearResponse r =
      foundation_->graded()
          ? LinearResponse{foundation_->graded_stiffness_to(state.springs_in_contact),
                           state.image_sum.value()}
          : LinearResponse{per_spring * static_cast<double>(state.springs_in_contact),
                           per_spring * state.image_sum.value()};
  const double d = displacement_under(normal_, r, state.normal_control);
  return {d, r.stiffness * d - r.offset};
}

double Contact::tangential_displacement_at_radius(double a) const {
  const LinearResponse r{2.0 * material_.effective_shear_modulus * a, 0.0};
  return displacement_under(tangential_, r, state_.tangential_held);
}

void Contact::detach_boundary_spring() {
  // Graded: the sum weighs each image by its spring's stiffness (spring_foundation.hpp).
  state_.image_sum.add(foundation_->graded()
                           ? -foundation_->graded_stiffness(state_.springs_in_contact) *
                                 state_.boundary_image
                           : -state_.boundary_image);
  --state_.springs_in_contact;
  state_.boundary_image =
      state_.springs_in_contact > 0 ? foundation_->image(state_.springs_in_contact) : 0.0;
}

ContactSnapshot Contact::snapshot_of(const State& state) const {
  Contact copy = *this;
  copy.restore(state);
  return copy.snapshot();
}

ContactSnapshot Contact::snapshot() const {
  ContactSnapshot s;
  s.normal_control = state_.normal_control;
  s.springs_in_contact = state_.springs_in_contact;
  if (state_.springs_in_contact == 0) return s;
  const LinearResponse normal = normal_response();
  const LinearResponse tangential = tangential_response();
  s.indentation = displacement_under(normal_, normal, state_.normal_control);
  s.normal_force = normal.stiffness * s.indentation - normal.offset;
  s.contact_radius = contact_radius();
  s.tangential_displacement = displacement_under(tangential_, tangential, state_.tangential_held);
  s.tangential_force = tangential.stiffness * s.tangential_displacement;
  return s;
}

}  // namespace mdrsim
