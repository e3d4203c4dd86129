// The samples of a segment inside an indentation range.
#include "engine/fit/fit_range.hpp"

#include <cstddef>

namespace mdrsim::fit {

PreparedSegment within_range(const PreparedSegment& segment, double contact_point,
                             const FitRange& range) {
  PreparedSegment out;
  out.height_channel = segment.height_channel;
  out.spring_constant = segment.spring_constant;
  for (std::size_t i = 0; i < segment.tip_position.size(); ++i) {
    const double depth = contact_point - segment.tip_position[i];
    if (depth >= range.from && depth <= range.to) {
      out.tip_position.push_back(segment.tip_position[i]);
      out.force.push_back(segment.force[i]);
    }
  }
  return out;
}

}  // namespace mdrsim::fit
