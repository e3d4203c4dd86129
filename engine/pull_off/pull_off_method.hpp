// The interface of a solver method: take the contact to its next detachment(s).
#pragma once

#include <cstdint>
#include <optional>

#include "detachment/criterion.hpp"
#include "engine/events/observer.hpp"
#include "engine/model/contact.hpp"
#include "engine/result/run_counts.hpp"

namespace mdrsim {

struct AdvanceOutcome {
  std::int64_t detached = 0;  ///< springs detached by this advance
  /// The equilibrium the control left before the first detachment; empty when the first
  /// detachment happened at the control value the contact already had (a cascade goes on).
  std::optional<Contact::State> equilibrium_before;
  bool first_by_shear = false;  ///< the first spring let go at zero elongation (margin < 0)
  /// The second spring of this advance (the first one due at the same control value) was
  /// broken at zero elongation: a cascade started by shear, not by a fold.
  bool second_by_shear = false;
  /// The spring went on a cascade (due at the held value, not by shear) whose control did not
  /// turn: its let-go value lies within the rounding of the held one, above it or below (a
  /// tie where d is flat to the bit, not a fold). False where the method cannot tell.
  bool flat = false;
};

class PullOffMethod {
 public:
  virtual ~PullOffMethod() = default;
  /// Lowers the normal control from its current value until at least one spring of the
  /// contact (which has one or more) detaches, and detaches it. Emits the detachments.
  virtual AdvanceOutcome advance(Contact& contact, const DetachmentCriterion& criterion,
                                 const ObserverList& observers, RunCounts& counts) = 0;
};

}  // namespace mdrsim
