// A program row moved along its stage's line: the held values at t, and the work on the way.
#include "engine/program/stage_position.hpp"

#include <cmath>
#include <optional>

#include "engine/program/stage_motion.hpp"

namespace mdrsim {

void StagePosition::start(const Stage& next) {
  stage = &next;
  t = 0.0;
  line = {axis_motion(next.normal, row.normal().held),
          axis_motion(next.tangential, row.tangential().held)};
  // The reader leaves a stage with a speed one moving axis.
  const double rate = line.normal.rate != 0.0 ? line.normal.rate : line.tangential.rate;
  line.clock = {
      .start = row.time(), .rate = seconds_per_parameter(next, rate), .end = std::nullopt};
  guards = {};
  work = {};
  energy = {.stored_at_start = row.stored_energy(),
            .surface_at_start = row.glued_surface(),
            .local = row.changes_stay_local(),
            .row_released_at_start = row.released_by_changes(),
            .released = {}};
}

EnergyBalance StagePosition::balance(double stored, double surface, double released) const {
  EnergyBalance b;
  b.machine_work = work.normal + work.tangential;
  b.stored_change = stored - energy.stored_at_start;
  b.surface_change = energy.surface_at_start - surface;
  b.dissipated_by_friction = work.friction;
  b.jump_losses = released - b.surface_change;
  b.residual = b.machine_work - b.stored_change - b.surface_change - b.dissipated_by_friction -
               b.jump_losses;
  return b;
}

void StagePosition::set_parameter(double to) {
  // An axis that does not move keeps its cached equilibrium; `to` lands exactly on its value.
  const bool until_separation = stage && stage->until_separation;
  const bool lands = to == 1.0 && !until_separation;
  if (line.normal.rate != 0.0 || (lands && line.normal.end)) {
    row.set_normal_held(line.normal.at(to, until_separation));
  }
  if (line.tangential.rate != 0.0 || (lands && line.tangential.end)) {
    row.set_tangential_held(line.tangential.at(to, until_separation));
  }
  row.set_time(line.clock.at(to, until_separation));
}

bool StagePosition::advance_to(double to) {
  // While the row stays as it is, an axis whose held value does not move stays where it is.
  const bool normal_moves = line.normal.rate != 0.0;
  // With friction under a held F_x, u_x follows d too (the sliding springs' mu f_z).
  const bool tangential_moves =
      line.tangential.rate != 0.0 ||
      (normal_moves && row.friction() && !is_fixed_grips(row.tangential().constraint));
  const AxisPoint n0 = normal_moves ? normal_point() : AxisPoint{};
  const AxisPoint x0 = tangential_moves ? tangential_point() : AxisPoint{};
  // The friction row follows d and u_x along the line; no friction event lies before `to`.
  std::optional<LinearMotion> along;
  if (row.friction() && to > t) along = ChangeLocator::motion(row, t, line.normal, line.tangential);
  set_parameter(to);
  if (along) work.friction += row.advance_friction(*along, to);
  add_work(normal_moves ? &n0 : nullptr, tangential_moves ? &x0 : nullptr);
  t = to;
  guards = {};
  // An axis that does not move keeps its state until a change, which the cascade's end checks.
  return work_within_double();
}

}  // namespace mdrsim
