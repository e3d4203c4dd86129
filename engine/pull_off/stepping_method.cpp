// Trial steps on a saved state: restore and halve on a multi-spring detachment, else accept.
#include "engine/pull_off/stepping_method.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/model/boundary_let_go.hpp"

namespace mdrsim {

SteppingMethod::SteppingMethod(double step, int max_halvings)
    : step_(step), max_halvings_(max_halvings) {
  if (!(step > 0.0)) throw std::invalid_argument("the stepping increment must be positive");
  if (max_halvings < 0) throw std::invalid_argument("max_halvings must be >= 0");
}

AdvanceOutcome SteppingMethod::advance(Contact& contact, const DetachmentCriterion& criterion,
                                       const ObserverList& observers, RunCounts& counts) {
  const Contact::State start = contact.save();
  const bool emit = observers.wants(EventKind::spring_detached);
  double step = step_;
  for (int halvings = 0;; ++halvings) {
    // A step must move the control value, and halving ends where it no longer could: below
    // the resolution of a double a trial would detach nothing and be accepted forever.
    double target = start.normal_control - step;
    if (target == start.normal_control) {
      target = std::nextafter(start.normal_control, -std::numeric_limits<double>::infinity());
    }
    const bool last_try =
        halvings >= max_halvings_ || start.normal_control - 0.5 * step == start.normal_control;
    contact.set_normal_control(target);
    pending_.clear();
    AdvanceOutcome out;
    while (contact.springs_in_contact() > 0 && boundary_lets_go_now(contact, criterion)) {
      if (out.detached < 2) {
        const bool by_shear =
            broken_at_rest(criterion, contact.tangential_displacement(), contact.contact_radius());
        (out.detached == 0 ? out.first_by_shear : out.second_by_shear) = by_shear;
      }
      if (emit) {
        Event e{.kind = EventKind::spring_detached,
                .state = contact.snapshot(),
                .spring = contact.springs_in_contact(),
                .in_cascade = out.detached > 0};
        if (last_try) {
          observers.emit(e);
        } else {
          pending_.push_back(e);
        }
      }
      contact.detach_boundary_spring();
      ++out.detached;
      if (out.detached > 1 && !last_try) break;  // the step will be halved
    }
    if (out.detached > 1 && !last_try) {
      contact.restore(start);
      step *= 0.5;
      ++counts.halvings;
      if (observers.wants(EventKind::step_halved)) {
        observers.emit({.kind = EventKind::step_halved, .state = contact.snapshot(), .step = step});
      }
      continue;
    }
    for (const Event& e : pending_) observers.emit(e);
    counts.events += out.detached;
    ++counts.steps;
    if (observers.wants(EventKind::step_accepted)) {
      observers.emit({.kind = EventKind::step_accepted, .state = contact.snapshot(), .step = step});
    }
    if (out.detached > 0) {
      out.equilibrium_before = start;
    }
    return out;
  }
}

}  // namespace mdrsim
