// What a program row's equilibria tell of its path as they come: the most tensile one (the
// peak), whether any spring ever touched, and for the drivers that ask, the largest contact
// and whether the last stage keeps the zoom's conditions.
#pragma once

#include <optional>

#include "engine/model/contact_snapshot.hpp"
#include "engine/program/program_row.hpp"
#include "engine/program/program_runner.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Whether a state's numbers are all within a double (extreme scenes can leave it).
inline bool within_double(const ContactSnapshot& s) {
  return std::isfinite(s.indentation) && std::isfinite(s.normal_force) &&
         std::isfinite(s.tangential_displacement) && std::isfinite(s.tangential_force) &&
         std::isfinite(s.normal_control);
}

class PathWatch {
 public:
  /// `zero_force`: below it a force is rounding, no peak [N]; `largest`, `last_stage`: null
  /// where nobody asks.
  PathWatch(const Scene& scene, double zero_force, LargestContact* largest,
            LastStageStart* last_stage)
      : program_(&*scene.program),
        friction_(scene.friction.has_value()),
        zero_force_(zero_force),
        largest_(largest),
        last_stage_(last_stage) {}

  /// `stage` starts on `row`, after its controller switch: the last stage notes its start.
  void start_stage(const Stage& stage, const ProgramRow& row);
  /// An equilibrium of `row` in `stage`; `cascade_before`: the state the cascade that ended
  /// at `s` began at, where it did (LastStageStart::lost_after).
  void observe(const ContactSnapshot& s, const ProgramRow& row, const Stage& stage,
               const ContactSnapshot* cascade_before = nullptr) {
    if (!within_double(s)) return;
    if (s.springs_in_contact > 0 && s.normal_force < -zero_force_ &&
        (!peak_ || s.normal_force < peak_->normal_force)) {
      peak_ = s;
    }
    if (s.springs_in_contact > 0) ever_in_contact_ = true;
    if (largest_ || last_stage_) follow_contact(s, row, stage, cascade_before);
  }

  const std::optional<ContactSnapshot>& peak() const { return peak_; }
  bool ever_in_contact() const { return ever_in_contact_; }

 private:
  /// What the drivers ask of an equilibrium: the largest contact, the zoom's conditions.
  void follow_contact(const ContactSnapshot& s, const ProgramRow& row, const Stage& stage,
                      const ContactSnapshot* cascade_before);

  const Program* program_;
  bool friction_;
  double zero_force_;
  LargestContact* largest_;
  LastStageStart* last_stage_;
  std::optional<ContactSnapshot> peak_;
  bool ever_in_contact_ = false;
};

}  // namespace mdrsim
