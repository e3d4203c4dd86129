// Cascades of the viscoelastic row's edge grouped by time, as jumps and the loss of the glue.
#include "engine/program/viscoelastic_jumps.hpp"

#include "engine/result/loss_status.hpp"

namespace mdrsim {

ContactSnapshot viscoelastic_snapshot(const ViscoelasticRowSample& s) {
  ContactSnapshot c;
  c.normal_control = s.depth;
  c.indentation = s.depth;
  // The contact's force is a sum of the loads of the springs in contact: none, none at all.
  c.normal_force = s.pressed > 0 ? s.force : 0.0;
  c.contact_radius = s.contact_radius;
  c.springs_in_contact = s.pressed;
  c.glued_radius = s.glued_radius;
  c.tangential_displacement = s.tangential_displacement;
  c.tangential_force = s.tangential_force;
  c.springs_sliding = s.sliding;
  c.stick_radius = s.stick_radius;
  c.time = s.time;
  return c;
}

std::optional<JumpRecord> ViscoelasticJumps::change(ViscoelasticRowChange change,
                                                    std::string_view stage,
                                                    const ViscoelasticRowSample& before,
                                                    const ViscoelasticRowSample& after,
                                                    bool by_shear) {
  const bool edge =
      change == ViscoelasticRowChange::glue || change == ViscoelasticRowChange::let_go;
  const bool inward = change == ViscoelasticRowChange::glue;
  const bool continues = edge && open_ && open_->time == after.time && open_->inward == inward &&
                         open_->stage == stage;
  // A let-go that continues a cascade starts from no equilibrium of the path but from a state
  // within the jump (under a held force every one of them stands at the held force, to
  // rounding): the peak is sought among the states a let-go starts from outside a jump.
  if (change == ViscoelasticRowChange::let_go && !continues) observe(before);
  if (continues) {
    if (++open_->changes == 2) open_->second_by_shear = by_shear;
    open_->after = after;
    return std::nullopt;
  }
  std::optional<JumpRecord> jump = close();
  if (edge) {
    open_ = ViscoelasticCascade{std::string(stage), after.time, inward, 1, before, after, by_shear};
  }
  return jump;
}

std::optional<JumpRecord> ViscoelasticJumps::close() {
  if (!open_) return std::nullopt;
  const ViscoelasticCascade c = std::move(*open_);
  open_.reset();
  if (!c.inward && c.after.glued == 0 && c.before.glued > 0) glue_loss_ = c;
  if (c.changes < 2) return std::nullopt;
  JumpRecord jump;
  jump.stage = c.stage;
  jump.inward = c.inward;
  jump.critical = viscoelastic_snapshot(c.before);
  jump.after = viscoelastic_snapshot(c.after);
  jump.springs = c.after.pressed - c.before.pressed;
  jump.glued_springs = c.after.glued - c.before.glued;
  // As the elastic program's: the first spring due after the critical point broke at zero
  // stretch (the tangential load alone).
  jump.by_shear = c.second_by_shear;
  return jump;
}

void ViscoelasticJumps::observe(const ViscoelasticRowSample& s) {
  if (s.pressed > 0 && (!most_tensile_ || s.force < most_tensile_->force)) most_tensile_ = s;
}

void ViscoelasticJumps::decide(const ViscoelasticCascade& loss, double force_scale, RunResult& r) {
  const LossCascade cascade{.changes = loss.changes,
                            .springs_before = loss.before.pressed,
                            .force_before = loss.before.force,
                            .force_scale = force_scale,
                            .first_by_shear = loss.first_by_shear,
                            .second_by_shear = loss.second_by_shear};
  r.status = loss_status(cascade);
  if (r.status == RunStatus::instability ||
      (r.status == RunStatus::shear_off && loss.changes >= 2)) {
    r.critical = viscoelastic_snapshot(loss.before);
    r.critical_stage = loss.stage;
  }
}

}  // namespace mdrsim
