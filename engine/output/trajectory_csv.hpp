// The trajectory observer: one CSV row per event, written to a stream.
#pragma once

#include <ostream>

#include "engine/events/observer.hpp"

namespace mdrsim {

/// Columns: stage, event, in_cascade, the state's fields (kTrajectoryFields, SI units),
/// springs_in_contact; with friction also `sliding`, the springs of one half sliding
/// (docs/friction.md); with finite-range adhesion also `cohesive_radius` [m] (docs/maugis.md);
/// last, for a timed program, `time` [s] (docs/programs.md "Time").
class TrajectoryCsvWriter final : public Observer {
 public:
  explicit TrajectoryCsvWriter(std::ostream& out, bool friction = false, bool cohesive = false,
                               bool time = false);
  void on_event(const Event& event) override;

 private:
  std::ostream* out_;
  bool friction_;
  bool cohesive_;
  bool time_;
};

}  // namespace mdrsim
