// The contact branch walked through nearby radii: each state from its neighbours' zones.
#include "engine/continuum/dugdale_branch_walk.hpp"

#include <cmath>

namespace mdrsim {
namespace {

double half_chord(const DugdaleState& state) {
  return state.cohesive_radius * std::sin(state.angle);
}

}  // namespace

DugdaleState DugdaleBranchWalk::at(double contact_radius) {
  double guess = 0.0;  // none: dugdale_contact_state's own start
  if (solved_ >= 2 && last_.contact_radius != before_.contact_radius) {
    const double s_last = half_chord(last_), s_before = half_chord(before_);
    guess = s_last + (s_last - s_before) * (contact_radius - last_.contact_radius) /
                         (last_.contact_radius - before_.contact_radius);
  } else if (solved_ == 1) {
    guess = half_chord(last_);
  }
  before_ = last_;
  last_ = dugdale_contact_state(profile_, law_, contact_radius, guess);
  ++solved_;
  return last_;
}

}  // namespace mdrsim
