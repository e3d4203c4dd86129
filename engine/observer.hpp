// Observers are sinks of events; a run fans each event out to all of them.
#pragma once

#include <vector>

#include "engine/event.hpp"

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

}  // namespace mdrsim
