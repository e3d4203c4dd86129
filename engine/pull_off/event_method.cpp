// One detachment per advance, located exactly; O(1) work unless the criterion needs a root search.
#include "engine/pull_off/event_method.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/model/boundary_let_go.hpp"

namespace mdrsim {

AdvanceOutcome EventMethod::advance(Contact& contact, const DetachmentCriterion& criterion,
                                    const ObserverList& observers, RunCounts& counts) {
  const BoundaryLetGo go = locate_boundary_let_go(contact, criterion);
  counts.root_iterations += go.let_go.root_iterations;
  require_let_go(go.let_go, contact.contact_radius());
  AdvanceOutcome out;
  out.first_by_shear = go.let_go.kind == LetGo::Kind::now;
  const double held = contact.normal_control();
  // Already due at the held value (a cascade), up to rounding of the two control values.
  const double tolerance = 4.0 * std::numeric_limits<double>::epsilon() *
                           std::max(std::abs(held), std::abs(go.normal_control));
  const bool due = out.first_by_shear || go.normal_control >= held - tolerance;
  out.flat = due && !out.first_by_shear && go.normal_control <= held + tolerance;
  if (!due) {
    contact.set_normal_control(go.normal_control);
    out.equilibrium_before = contact.save();
  }
  if (observers.wants(EventKind::spring_detached)) {
    observers.emit({.kind = EventKind::spring_detached,
                    .state = contact.snapshot(),
                    .spring = contact.springs_in_contact(),
                    .in_cascade = due});
  }
  contact.detach_boundary_spring();
  out.detached = 1;
  ++counts.events;
  return out;
}

}  // namespace mdrsim
