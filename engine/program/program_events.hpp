// A program row's events on their way to the observers: passed on at once, or held while the
// cascade or trial step that makes them may still end in a flight or be taken back.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "engine/events/observer.hpp"
#include "engine/program/program_row.hpp"
#include "engine/program/stick_slip_spring.hpp"

namespace mdrsim {

class ProgramEvents {
 public:
  explicit ProgramEvents(const ObserverList& observers)
      : observers_(&observers),
        springs_(observers.wants(EventKind::spring_detached)),
        slips_(observers.wants(EventKind::spring_slipped)) {}

  /// Asked once: whether anyone observes single springs (a log observer asks spdlog), and
  /// slips and sticks.
  bool springs() const { return springs_; }
  bool slips() const { return slips_; }
  bool wants(EventKind kind) const { return observers_->wants(kind); }

  /// The stage the events from now on belong to (it outlives them).
  void start_stage(std::string_view name) { stage_ = name; }
  /// An event of the stage; held while holding.
  void emit(EventKind kind, const ContactSnapshot& state, std::int64_t spring = 0,
            bool in_cascade = false);
  /// A change of spring `spring` of `row`, where single springs are observed.
  void spring(EventKind kind, const ProgramRow& row, std::int64_t spring, bool in_cascade) {
    if (springs_) emit(kind, row.snapshot(), spring, in_cascade);
  }
  /// A slip or stick of spring `spring` of `row`, where they are observed (a limit kink is
  /// none).
  void slip(FrictionEventKind kind, const ProgramRow& row, std::int64_t spring, bool in_cascade) {
    if (!slips_ || kind == FrictionEventKind::limit_kink) return;
    emit(kind == FrictionEventKind::slip ? EventKind::spring_slipped : EventKind::spring_stuck,
         row.snapshot(), spring, in_cascade);
  }
  /// A stepping event (step_accepted, step_halved) at `row`'s state with its increment, never
  /// held, where it is observed.
  void step(EventKind kind, const ProgramRow& row, double step);

  /// Holds the events emitted from now on (`on`), or passes them on again.
  void hold(bool on) { holding_ = on; }
  /// Passes on the held events.
  void release();
  /// Drops the held events.
  void drop() { held_.clear(); }
  /// A cascade ended in a flight: its events past the critical point go. The event method's
  /// first change (not in_cascade) is at the critical point itself (`keep_first_changes`); a
  /// step's changes are all past it.
  void discard_flight(bool keep_first_changes);

 private:
  const ObserverList* observers_;
  bool springs_;
  bool slips_;
  bool holding_ = false;
  std::string_view stage_;
  std::vector<Event> held_;
};

}  // namespace mdrsim
