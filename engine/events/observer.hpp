// Observers are sinks of events; a run fans each event out to all of them.
#pragma once

#include <vector>

#include "engine/events/event.hpp"

namespace mdrsim {

class Observer {
 public:
  virtual ~Observer() = default;
  virtual void on_event(const Event& event) = 0;
  /// Optional: whether events of this kind are wanted at all; saves building them.
  virtual bool wants(EventKind /*kind*/) const { return true; }
};

/// Non-owning list of observers.
class ObserverList {
 public:
  void add(Observer& observer) { observers_.push_back(&observer); }
  void emit(const Event& event) const {
    for (Observer* o : observers_) o->on_event(event);
  }
  bool empty() const { return observers_.empty(); }
  bool wants(EventKind kind) const {
    for (const Observer* o : observers_) {
      if (o->wants(kind)) return true;
    }
    return false;
  }

 private:
  std::vector<Observer*> observers_;
};

/// Passes on only the preload events (preload_reached, tangential_applied) or only the
/// events of the pull-off itself (detachments and steps): a run of several rows shows its
/// observers one preload and one row's detachments.
class PhaseFilter : public Observer {
 public:
  enum class Phase { preload, pull_off };
  PhaseFilter(const ObserverList& inner, Phase phase) : inner_(&inner), phase_(phase) {}
  void on_event(const Event& event) override {
    if (passes(event.kind)) inner_->emit(event);
  }
  bool wants(EventKind kind) const override { return passes(kind) && inner_->wants(kind); }

 private:
  bool passes(EventKind kind) const {
    const bool preload =
        kind == EventKind::preload_reached || kind == EventKind::tangential_applied;
    const bool pull_off = kind == EventKind::spring_detached || kind == EventKind::step_accepted ||
                          kind == EventKind::step_halved;
    return phase_ == Phase::preload ? preload : pull_off;
  }
  const ObserverList* inner_;
  Phase phase_;
};

}  // namespace mdrsim
