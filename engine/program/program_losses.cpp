// Which loss decides a program's end, and the status it decides.
#include "engine/program/program_losses.hpp"

#include "engine/result/loss_status.hpp"

namespace mdrsim {

void ProgramLosses::record(const Cascade& cascade, std::int64_t glued_after,
                           std::int64_t in_contact_after) {
  if (cascade.glued > 0 && glued_after == 0) {
    last_glue_loss_ = cascade;
    glue_loss_contact_ = contact_losses_;
  }
  if (cascade.in_contact > 0 && in_contact_after == 0) {
    last_contact_loss_ = cascade;
    ++contact_losses_;
  }
}

const Cascade& ProgramLosses::deciding() const {
  // The glue's jump counts for the contact it broke: not for one pressed again later.
  const bool same_contact = glue_loss_contact_ == contact_losses_ - 1;
  const bool glue_jumped = last_glue_loss_ && last_glue_loss_->changes >= 2;
  if (glue_jumped && same_contact && last_contact_loss_->glued == 0) return *last_glue_loss_;
  return *last_contact_loss_;
}

void ProgramLosses::decide(const Cascade& c, const ZeroScale& zero, RunResult& r) {
  if (zero.zero_force(c.before.normal_force) && c.glued == 0) {
    // Nothing carried a force or glue when the contact went: no critical point.
    r.status = c.first_by_shear ? RunStatus::shear_off : RunStatus::no_instability;
    return;
  }
  const LossCascade loss{.changes = c.changes,
                         .springs_before = c.in_contact,
                         .force_before = c.before.normal_force,
                         .force_scale = zero.contact_force,
                         .first_by_shear = c.first_by_shear,
                         .second_by_shear = c.second_by_shear};
  r.status = loss_status(loss);
  if (r.status == RunStatus::shear_off) r.fold_above_shear_off = c.fold_above_shear_off;
  if (c.changes >= 2) {
    r.critical = c.before;
    r.refined_critical = c.refined_before;
  } else if (!peels_smoothly(loss)) {
    r.critical = c.before;
  }
}

}  // namespace mdrsim
