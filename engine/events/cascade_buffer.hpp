// Holds a cascade's rows back until the cascade ends: one that ends in a flight is not shown.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/events/observer.hpp"

namespace mdrsim {

/// Holds every event for `inner` until flush() (the cascade, or the step, ended in an
/// equilibrium) or discard_flight() (it ended with the indenter flying off under a fixed load,
/// SPEC "A fixed load that loses the contact": no rows beyond the critical point).
/// O(cascade) memory.
class CascadeBuffer final : public Observer {
 public:
  explicit CascadeBuffer(const ObserverList& inner) : inner_(&inner) {}

  void on_event(const Event& event) override { held_.push_back(event); }
  bool wants(EventKind kind) const override { return inner_->wants(kind); }

  std::size_t held() const { return held_.size(); }
  /// Passes on the first `count` held events (those before a new equilibrium).
  void flush(std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) inner_->emit(held_[i]);
    held_.erase(held_.begin(), held_.begin() + static_cast<std::ptrdiff_t>(count));
  }
  void flush() { flush(held_.size()); }
  /// Drops the held rows but those at the critical state: a halved step's (taken back to
  /// it) and, with `keep_first_let_go`, the let-go that starts the cascade (the event
  /// method's is at the critical state; a stepping step's detachments are all past it).
  void discard_flight(bool keep_first_let_go) {
    for (const Event& e : held_) {
      const bool first = e.kind == EventKind::spring_detached && !e.in_cascade;
      if (e.kind == EventKind::step_halved || (keep_first_let_go && first)) inner_->emit(e);
    }
    held_.clear();
  }

 private:
  const ObserverList* inner_;
  std::vector<Event> held_;
};

}  // namespace mdrsim
