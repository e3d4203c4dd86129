// A program's status from how it stopped: a limit, a load that nothing holds, or its losses.
#include "engine/program/program_outcome.hpp"

#include <fmt/format.h>

#include <string>

namespace mdrsim {

std::string ProgramOutcome::skipped_stages(const ProgramEnd& end) {
  const auto& stages = end.scene.program->stages;
  std::string skipped;
  for (auto it = stages.begin() + (&end.stage - stages.data()) + 1; it != stages.end(); ++it) {
    skipped += fmt::format("{}'{}'", skipped.empty() ? "" : ", ", it->name);
  }
  const bool separated = end.flight.end == JumpEnd::separated;
  return fmt::format(
      "stage '{}': the {} fixed load (F{} = {:.6g} N) lost what held it and the indenter {}: "
      "the program ends at its critical point; stages not run: {}",
      end.stage.name, separated ? "normal" : "tangential", separated ? "" : "x",
      separated ? end.row.normal().held : end.row.tangential().held,
      separated ? "separates" : "slides away", skipped);
}

void ProgramOutcome::decide(const ProgramEnd& end, RunResult& r) const {
  if (end.flight.flying() && &end.stage != &end.scene.program->stages.back()) {
    r.warnings.push_back(skipped_stages(end));
  }
  r.sliding = end.flight.end == JumpEnd::sliding;
  if (stop_ == Stop::limit) {
    stop_at_limit(r, limit_);
    // The stage under way did not end in an equilibrium: no critical point from it.
    if (limit_ == StopReason::overflow || limit_ == StopReason::unending_cascade) {
      r.critical.reset();
    }
    r.warnings.push_back(limit_warning(end, r));
  } else {
    decide_by_losses(end, r);
  }
  // The stage of the critical point, for the closing events.
  for (const auto* loss : {&losses_.last_contact_loss(), &losses_.last_glue_loss()}) {
    if (*loss && r.critical &&
        (*loss)->before.springs_in_contact == r.critical->springs_in_contact &&
        (*loss)->before.indentation == r.critical->indentation &&
        (*loss)->before.tangential_displacement == r.critical->tangential_displacement) {
      r.critical_stage = (*loss)->stage->name;
    }
  }
}

std::string ProgramOutcome::limit_warning(const ProgramEnd& end, const RunResult& r) const {
  const std::string& stage = end.stage.name;
  const ProgramRow& row = end.row;
  switch (limit_) {
    case StopReason::outgrew_row:
      return fmt::format(
          "stage '{}': the contact outgrew the row of {} springs (radius {:.6g} m): the program "
          "stops here",
          stage, end.max_springs, row.position(end.max_springs));
    case StopReason::no_end:
      return fmt::format(
          "stage '{}' runs until separation, but nothing on its path can part the contact ({} "
          "springs in contact): the program stops here",
          stage, row.in_contact());
    case StopReason::max_steps:
      return fmt::format(
          "the stepping method reached solver.max_steps = {} in stage '{}' before the program's "
          "end: there is no critical point",
          end.scene.solver.max_steps, stage);
    case StopReason::max_events:
      return fmt::format(
          "the row reached solver.max_events = {} in stage '{}' before the program's end: the "
          "program stops here",
          end.scene.solver.max_events, stage);
    case StopReason::max_events_per_spring:
      return fmt::format(
          "stage '{}' changed its spring row more than solver.max_events_per_spring = {} times "
          "per spring ({} events in the run; {} springs in contact, {} glued): the contact "
          "slides by stick-slip without end; the program stops here",
          stage, end.scene.solver.max_events_per_spring, r.counts.events, row.in_contact(),
          row.glued());
    case StopReason::overflow:
      return fmt::format(
          "stage '{}': the program's forces, displacements or work left the range of a double "
          "(the scene's values are too extreme together): it stops there, and only the stages "
          "before it are reported",
          stage);
    case StopReason::unending_cascade:
      return fmt::format(
          "stage '{}': at parameter {:.6g} the spring row kept changing without settling "
          "(rounding of values far beyond the scene's scales, {} springs in contact): it stops "
          "there, and only the stages before it are reported",
          stage, unending_at_, row.in_contact());
  }
  return {};
}

void ProgramOutcome::decide_by_losses(const ProgramEnd& end, RunResult& r) const {
  const ProgramRow& row = end.row;
  const auto decide_loss = [&](const Cascade& c) { ProgramLosses::decide(c, end.zero, r); };
  const auto& glue_loss = losses_.last_glue_loss();
  const auto& contact_loss = losses_.last_contact_loss();
  if (stop_ == Stop::cannot_hold_tangential) {
    if (end.scene.friction && row.in_contact() > 0) {
      // Every spring in contact slides at its limit and the held F_x asks for more: gross
      // sliding, at the last equilibrium (docs/friction.md "Statuses"): where the last
      // spring began to slide, or, where a glue's jump ended in the slide, before that jump.
      r.status = RunStatus::shear_off;
      if (end.flight.end == JumpEnd::sliding) {
        r.critical = end.flight.from;
        r.refined_critical = end.flight.refined_from;
      } else {
        r.critical = row.snapshot();
      }
      r.sliding = true;
      r.warnings.push_back(fmt::format(
          "stage '{}': friction can no longer hold F_x = {:.6g} N ({} springs in contact, all "
          "sliding): the contact slides away and the program ends here",
          end.stage.name, row.tangential().held, row.in_contact()));
    } else if (glue_loss) {
      decide_loss(*glue_loss);
      if (glue_loss->changes < 2) r.status = RunStatus::shear_off;
    } else {
      r.status = RunStatus::no_instability;
      r.warnings.push_back(fmt::format(
          "stage '{}': fixed-load holds F_x = {:.6g} N with no glued spring: the program ends "
          "here",
          end.stage.name, row.tangential().held));
    }
    return;
  }
  if (stop_ == Stop::cannot_hold_normal && !contact_loss) {
    r.status = RunStatus::no_instability;
    r.warnings.push_back(fmt::format(
        "stage '{}': a fixed load pulls (F = {:.6g} N, moving towards {:.6g} N) with no "
        "spring in contact, so nothing holds it: the program ends here",
        end.stage.name, row.normal().held, end.normal.start + end.normal.rate));
    return;
  }
  const bool lost = row.in_contact() == 0 && end.watch.ever_in_contact();
  if (stop_ == Stop::cannot_hold_normal || (lost && contact_loss)) {
    decide_loss(losses_.deciding());
    return;
  }
  r.status = RunStatus::completed;
  if (contact_loss) {
    r.critical = contact_loss->before;
    r.refined_critical = contact_loss->refined_before;
  }
}

}  // namespace mdrsim
