// The paper's stepping procedure (Section 3): fixed increments, halved when a step detaches
// more than one spring.
#pragma once

#include <vector>

#include "engine/pull_off/pull_off_method.hpp"

namespace mdrsim {

/// A step lowers the normal control by `step`. If more than one spring lets go, the step is
/// undone and halved, at most `max_halvings` times in a row; at the fold no step is small
/// enough, so the last halving is accepted with its cascade. The base step is used again
/// after every accepted step.
class SteppingMethod final : public PullOffMethod {
 public:
  SteppingMethod(double step, int max_halvings);
  AdvanceOutcome advance(Contact& contact, const DetachmentCriterion& criterion,
                         const ObserverList& observers, RunCounts& counts) override;

 private:
  double step_;  ///< base increment [control units]
  int max_halvings_;
  std::vector<Event> pending_;  ///< detachments of the step on trial (at most two are kept)
};

}  // namespace mdrsim
