// --range FROM:TO: the samples of a segment whose indentation lies in [FROM, TO].
#pragma once

#include "engine/fit/prepared_curve.hpp"

namespace mdrsim::fit {

/// Indentation bounds [m]: contact_point - tip position, positive into the sample; a negative
/// FROM keeps that much of the baseline before contact.
struct FitRange {
  double from = 0.0;  ///< [m]
  double to = 0.0;    ///< [m]
};

/// The samples of `segment`, in their order, with from <= contact_point - z <= to.
PreparedSegment within_range(const PreparedSegment& segment, double contact_point,
                             const FitRange& range);

}  // namespace mdrsim::fit
