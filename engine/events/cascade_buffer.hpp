// Holds a cascade's rows back until the cascade ends: one that ends in a flight is not shown.
#pragma once

#include <vector>

#include "engine/events/observer.hpp"

namespace mdrsim {

/// Passes every event on to `inner`, but holds the detachments inside a cascade (in_cascade)
/// until the next event outside one, or until flush(): a cascade that ends with the indenter
/// flying off under a fixed load (SPEC "A fixed load that loses the contact") has no rows
/// beyond its critical point, so its held rows are discarded instead. O(cascade) memory.
class CascadeBuffer final : public Observer {
 public:
  explicit CascadeBuffer(const ObserverList& inner) : inner_(&inner) {}

  void on_event(const Event& event) override {
    if (event.kind == EventKind::spring_detached && event.in_cascade) {
      held_.push_back(event);
      return;
    }
    flush();
    inner_->emit(event);
  }
  bool wants(EventKind kind) const override { return inner_->wants(kind); }

  /// The held rows go on: the cascade ended in an equilibrium.
  void flush() {
    for (const Event& e : held_) inner_->emit(e);
    held_.clear();
  }
  /// The held rows are dropped: the cascade ended in a flight.
  void discard() { held_.clear(); }

 private:
  const ObserverList* inner_;
  std::vector<Event> held_;
};

}  // namespace mdrsim
