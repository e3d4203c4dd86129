// The largest tangential force a glued contact can carry at its present normal state.
#pragma once

#include <optional>

#include "detachment/criterion.hpp"
#include "engine/model/contact.hpp"

namespace mdrsim {

/// The boundary spring keeps its normal stretch e while the tangential displacement grows;
/// it breaks at the smallest u with margin(e, u, a) <= 0, and then every spring inside it
/// follows (the criteria's thresholds fall with the radius). The strength is the contact's
/// tangential force at that u, 2 G* a u [N]. Nothing for a criterion that ignores u_x.
std::optional<double> tangential_strength(const Contact& contact,
                                          const DetachmentCriterion& criterion);

}  // namespace mdrsim
