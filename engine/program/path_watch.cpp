// The largest contact and the last stage's zoom conditions, from a program row's equilibria.
#include "engine/program/path_watch.hpp"

#include <limits>

namespace mdrsim {

void PathWatch::start_stage(const Stage& stage, const ProgramRow& row) {
  if (!last_stage_ || &stage != &program_->stages.back()) return;
  *last_stage_ = {
      .zoomable = stage.until_separation && !program_->rebinding && !friction_ && row.glued() > 0 &&
                  row.glued() == row.in_contact() && row.one_offset(),
      .stage = program_->stages.size() - 1,
      .normal = row.normal(),
      .tangential = row.tangential(),
      .offset = row.glued() > 0 ? row.boundary_offset() : 0.0,
      .springs = row.glued(),
      .peak_before = peak_ ? peak_->normal_force : std::numeric_limits<double>::infinity()};
}

void PathWatch::follow_contact(const ContactSnapshot& s, const ProgramRow& row, const Stage& stage,
                               const ContactSnapshot* cascade_before) {
  // The zoom's conditions through the last stage: nothing pressed, nothing glued anew.
  if (last_stage_ && last_stage_->zoomable && &stage == &program_->stages.back() &&
      ((row.in_contact() > 0 && row.in_contact() != row.glued()) ||
       row.glued() > last_stage_->springs)) {
    last_stage_->zoomable = false;
    if (cascade_before) last_stage_->lost_after = *cascade_before;
  }
  if (largest_ && s.springs_in_contact > 0) {
    largest_->most_springs = std::max(largest_->most_springs, s.springs_in_contact);
    if (largest_->springs == 0 || s.indentation > largest_->indentation) {
      largest_->springs = s.springs_in_contact;
      largest_->indentation = s.indentation;
      largest_->glued_edge = row.glued() == row.in_contact();
      largest_->normal_constraint = row.normal().constraint;
      largest_->normal_held = s.normal_control;
    }
  }
}

}  // namespace mdrsim
