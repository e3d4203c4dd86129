// Measured force curves as read from an instrument's file: segments, calibration, map position.
#include "engine/measured/force_curve.hpp"

#include <algorithm>

namespace mdrsim::measured {

const char* segment_kind_name(SegmentKind kind) {
  switch (kind) {
    case SegmentKind::approach:
      return "approach";
    case SegmentKind::retract:
      return "retract";
    case SegmentKind::pause:
      return "pause";
  }
  return "pause";
}

std::size_t Segment::size() const {
  return std::max({time.size(), piezo_height.size(), measured_height.size(), tip_position.size(),
                   deflection.size(), force.size()});
}

}  // namespace mdrsim::measured
