// The in-memory observer: keeps every event, for tests and plots.
#pragma once

#include <vector>

#include "engine/events/observer.hpp"

namespace mdrsim {

class EventRecorder final : public Observer {
 public:
  void on_event(const Event& event) override { events_.push_back(event); }
  const std::vector<Event>& events() const { return events_; }

 private:
  std::vector<Event> events_;
};

}  // namespace mdrsim
