// Work between let-gos is the trapezoid of force against driving point (both affine while the
// springs stay); a let-go moves the driving point only under fixed load, at constant force.
#include "engine/pull_off/shorthand_path.hpp"

#include "engine/model/machine_work.hpp"
#include "engine/result/lost_contact.hpp"

namespace mdrsim {

namespace {

/// A stage that ends with every spring of the row in contact ends at a right-endpoint sum
/// over the springs, smooth in the spacing: its end is located as it is, for Richardson.
void locate_whole_row(const Contact& contact, StageRecord& stage) {
  if (stage.end.springs_in_contact == contact.foundation().springs()) stage.refined_end = stage.end;
}

}  // namespace

ShorthandPath::ShorthandPath(const AffineConstraint& normal, const AffineConstraint& tangential)
    : normal_(normal),
      tangential_(tangential),
      tangential_fixed_load_(holds_force(tangential)),
      holds_normal_force_(holds_force(normal)) {}

ContactSnapshot ShorthandPath::snapshot(const Contact& contact, const Contact::State& state) const {
  if (state.springs_in_contact > 0) return contact.snapshot_of(state);
  // Lost: the program engine's convention, the indenter where the last spring left it.
  ContactSnapshot s;
  s.normal_control = state.normal_control;
  s.indentation = last_indentation_;
  return s;
}

void ShorthandPath::add_work(const Contact& contact, const Contact::State& to) {
  // A lost contact carries no force, and nothing moves the machine after it (as in programs).
  if (to.springs_in_contact == 0) {
    force_ = 0.0;
    return;
  }
  const auto [d, force] = contact.normal_state_of(to);
  const double driving = driving_point(normal_, to.normal_control, d);
  pull_off_work_.normal += trapezoid_work({force_, driving_}, {force, driving});
  force_ = force;
  driving_ = driving;
  last_indentation_ = d;
  if (tangential_fixed_load_) {
    // F_x is held: the indenter moves at constant force as the row softens. (Under fixed
    // grips u_x stays; through a compliant machine its end, the driving point, stays.)
    const double u = contact.snapshot_of(to).tangential_displacement;
    pull_off_work_.tangential += to.tangential_held * (u - tangential_displacement_);
    tangential_displacement_ = u;
  }
}

void ShorthandPath::add_held_work(const Contact& contact) {
  if (held_count_ == 0) return;
  add_work(contact, held_first_);
  if (held_count_ > 1) {
    // The row's own let-gos from the first state give the others, to the bit.
    Contact again = contact;
    again.restore(held_first_);
    for (std::int64_t k = 1; k < held_count_; ++k) {
      again.detach_boundary_spring();
      add_work(again, again.save());
    }
  }
  held_count_ = 0;
}

void ShorthandPath::preload(const Contact& contact) {
  const SpringFoundation& row = contact.foundation();
  const double d = contact.indentation();
  const double n = static_cast<double>(row.springs());
  // sum (d - g_i)^2 = N d^2 - 2 d sum g_i + sum g_i^2: no cancellation, each term is of the
  // size of the result.
  const double squares = n * d * d - 2.0 * d * row.total_image() + row.total_image_squares();
  StageRecord stage{"preload", contact.snapshot(), {}};
  stage.work.normal = contact.material().effective_modulus * row.spacing() * squares;
  if (row.graded()) {
    // sum w_i (d - g_i)^2 / 2, the sums weighted by the springs' stiffness.
    stage.work.normal = 0.5 * (row.graded_stiffness_to(row.springs()) * d * d -
                               2.0 * d * row.total_image() + row.total_image_squares());
  }
  locate_whole_row(contact, stage);
  stages_.push_back(stage);
}

void ShorthandPath::tangential(const Contact& contact, std::optional<double> machine_stiffness) {
  StageRecord stage{"tangential", contact.snapshot(), {}};
  const ContactSnapshot& s = stage.end;
  stage.work.tangential = 0.5 * s.tangential_force * s.tangential_displacement;
  if (machine_stiffness) {
    stage.work.tangential += 0.5 * s.tangential_force * s.tangential_force / *machine_stiffness;
  }
  locate_whole_row(contact, stage);
  stages_.push_back(stage);
  last_ = contact.save();
  force_ = s.normal_force;
  driving_ = driving_point(normal_, s.normal_control, s.indentation);
  last_indentation_ = s.indentation;
  tangential_displacement_ = s.tangential_displacement;
}

void ShorthandPath::close_cascade(const Contact& contact) {
  if (cascade_ && cascade_->springs > 1) {
    JumpRecord jump{.stage = "pull-off",
                    .inward = false,
                    .critical = contact.snapshot_of(cascade_->critical),
                    .after = snapshot(contact, last_),
                    .springs = -cascade_->springs,
                    .glued_springs = -cascade_->springs,
                    .by_shear = cascade_->by_shear};
    jumps_.push_back(jump);
  }
  cascade_.reset();
}

void ShorthandPath::advanced(const Contact& contact, const AdvanceOutcome& out, bool equilibrium) {
  if (out.detached == 0) return;
  if (equilibrium) {
    add_held_work(contact);  // the cascade before ended in a state: its work counts
    close_cascade(contact);
    add_work(contact, *out.equilibrium_before);
    // Field by field: a copy of the struct just written stalls the store buffer, at every let-go.
    work_at_equilibrium_.normal = pull_off_work_.normal;
    work_at_equilibrium_.tangential = pull_off_work_.tangential;
    // Braces: clang 14 does not build an aggregate from parentheses (C++20's P0960).
    cascade_.emplace(
        Cascade{*out.equilibrium_before, out.detached, out.detached > 1 && out.second_by_shear});
  } else if (cascade_) {
    if (cascade_->springs == 1) cascade_->by_shear = out.first_by_shear;
    cascade_->springs += out.detached;
  }
  // One let-go at the held values of the state before: a cascade going on (the stepping method
  // moves the control at every advance, so its states never go on here).
  const bool goes_on = !equilibrium && out.detached == 1 &&
                       contact.normal_control() == last_.normal_control &&
                       contact.tangential_held() == last_.tangential_held &&
                       contact.springs_in_contact() == last_.springs_in_contact - 1;
  last_ = contact.save();
  if (!holds_normal_force_) {
    add_work(contact, last_);
    return;
  }
  if (goes_on && held_count_ > 0) {
    ++held_count_;
    return;
  }
  add_held_work(contact);
  held_first_ = last_;
  held_count_ = 1;
}

JumpEnd ShorthandPath::finish(const Contact& contact, std::vector<StageRecord>& stages,
                              std::vector<JumpRecord>& jumps, std::optional<AxisWork>& work) {
  if (contact.springs_in_contact() > 0) {
    // Stopped at a limit with the contact in place: the stage ends where the control is.
    add_held_work(contact);
    last_ = contact.save();
    add_work(contact, last_);
  }
  const JumpEnd flight =
      shorthand_flight(last_, normal_, tangential_, contact.foundation().image(1));
  if (flight == JumpEnd::state) {
    add_held_work(contact);
    close_cascade(contact);
    stages_.push_back({"pull-off", snapshot(contact, last_), pull_off_work_});
  } else if (cascade_) {
    held_count_ = 0;
    // The flight starts at the last equilibrium: what the springs did after it (the held
    // force on ever fewer springs, moving at constant force) grows with the spring count.
    const ContactSnapshot critical = contact.snapshot_of(cascade_->critical);
    if (cascade_->springs > 1) {
      jumps_.push_back({.stage = "pull-off",
                        .inward = false,
                        .critical = critical,
                        .end = flight,
                        .springs = -cascade_->springs,
                        .glued_springs = -cascade_->springs,
                        .by_shear = cascade_->by_shear});
    }
    cascade_.reset();
    stages_.push_back({"pull-off", critical, work_at_equilibrium_});
  } else {
    // Not one equilibrium: the tangential load broke the glue as it was applied, and the
    // flight starts there.
    stages_.push_back({"pull-off", stages_.back().end, {}});
  }
  AxisWork total;
  for (const StageRecord& stage : stages_) total += stage.work;
  stages = std::move(stages_);
  jumps = std::move(jumps_);
  work = total;
  return flight;
}

}  // namespace mdrsim
