// Work between let-gos is the trapezoid of force against driving point (both affine while the
// springs stay); a let-go moves the driving point only under fixed load, at constant force.
#include "engine/run/shorthand_path.hpp"

namespace mdrsim {

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
  const double driving = normal_through_spring_ ? to.normal_control : d;
  pull_off_work_.normal += 0.5 * (force_ + force) * (driving - driving_);
  force_ = force;
  driving_ = driving;
  last_indentation_ = d;
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
  stages_.push_back(stage);
}

void ShorthandPath::tangential(const Contact& contact, std::optional<double> machine_stiffness) {
  StageRecord stage{"tangential", contact.snapshot(), {}};
  const ContactSnapshot& s = stage.end;
  stage.work.tangential = 0.5 * s.tangential_force * s.tangential_displacement;
  if (machine_stiffness) {
    stage.work.tangential += 0.5 * s.tangential_force * s.tangential_force / *machine_stiffness;
  }
  stages_.push_back(stage);
  last_ = contact.save();
  force_ = s.normal_force;
  driving_ = normal_through_spring_ ? s.normal_control : s.indentation;
  last_indentation_ = s.indentation;
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
    close_cascade(contact);
    add_work(contact, *out.equilibrium_before);
    cascade_ = Cascade{*out.equilibrium_before, 0, out.detached > 1 && out.second_by_shear};
  } else if (cascade_ && cascade_->springs == 1) {
    cascade_->by_shear = out.first_by_shear;
  }
  if (cascade_) cascade_->springs += out.detached;
  last_ = contact.save();
  add_work(contact, last_);
}

void ShorthandPath::finish(const Contact& contact, std::vector<StageRecord>& stages,
                           std::vector<JumpRecord>& jumps, std::optional<AxisWork>& work) {
  close_cascade(contact);
  stages_.push_back({"pull-off", snapshot(contact, last_), pull_off_work_});
  AxisWork total;
  for (const StageRecord& stage : stages_) total += stage.work;
  stages = std::move(stages_);
  jumps = std::move(jumps_);
  work = total;
}

}  // namespace mdrsim
