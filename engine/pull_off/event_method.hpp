// The event method: jump the control straight to the exact let-go of the boundary spring.
#pragma once

#include "engine/pull_off/pull_off_method.hpp"

namespace mdrsim {

class EventMethod final : public PullOffMethod {
 public:
  AdvanceOutcome advance(Contact& contact, const DetachmentCriterion& criterion,
                         const ObserverList& observers, RunCounts& counts) override;
};

}  // namespace mdrsim
