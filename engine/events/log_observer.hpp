// The logging observer: milestones at info, detachments at debug, steps at trace (spdlog).
#pragma once

#include "engine/events/observer.hpp"

namespace mdrsim {

class LogObserver final : public Observer {
 public:
  void on_event(const Event& event) override;
  bool wants(EventKind kind) const override;
};

}  // namespace mdrsim
