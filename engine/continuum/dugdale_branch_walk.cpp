// The contact branch walked through nearby radii: each state from its neighbours' zones.
#include "engine/continuum/dugdale_branch_walk.hpp"

#include <cmath>

namespace mdrsim {

DugdaleState DugdaleBranchWalk::at(double contact_radius) {
  if (solved_ > 0 && contact_radius == last_.contact_radius) return last_;
  // 0 (none) before the first: dugdale_contact_state's own start.
  last_ = dugdale_contact_state(profile_, law_, contact_radius, chords_.at(contact_radius));
  chords_.add(contact_radius, last_.cohesive_radius * std::sin(last_.angle));
  ++solved_;
  return last_;
}

}  // namespace mdrsim
