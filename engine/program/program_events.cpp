// A program row's events: passed on at once, or held until their cascade or step ends.
#include "engine/program/program_events.hpp"

namespace mdrsim {

void ProgramEvents::emit(EventKind kind, const ContactSnapshot& state, std::int64_t spring,
                         bool in_cascade) {
  const Event e{
      .kind = kind, .state = state, .spring = spring, .in_cascade = in_cascade, .stage = stage_};
  if (holding_) {
    held_.push_back(e);
  } else {
    observers_->emit(e);
  }
}

void ProgramEvents::step(EventKind kind, const ProgramRow& row, double step) {
  if (!observers_->wants(kind)) return;
  observers_->emit({.kind = kind, .state = row.snapshot(), .step = step, .stage = stage_});
}

void ProgramEvents::release() {
  for (const Event& e : held_) observers_->emit(e);
  held_.clear();
}

void ProgramEvents::discard_flight(bool keep_first_changes) {
  if (keep_first_changes) {
    for (const Event& e : held_) {
      if (!e.in_cascade) observers_->emit(e);
    }
  }
  held_.clear();
}

}  // namespace mdrsim
