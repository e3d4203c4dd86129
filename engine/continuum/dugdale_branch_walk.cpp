// The contact branch walked through nearby radii: each state from its neighbours' zones.
#include "engine/continuum/dugdale_branch_walk.hpp"

#include <cmath>

namespace mdrsim {

double DugdaleBranchWalk::guess(double a) const {
  if (sloped_known_ == 0) return chords_.at(a);  // 0 (none) before the first
  const Sloped& p1 = sloped_[0];
  double s = p1.half_chord + p1.slope * (a - p1.radius);
  if (sloped_known_ == 2 && sloped_[1].radius != p1.radius) {
    // The cubic Hermite through both, in u = (a - a0)/h (beyond [0, 1] where it extrapolates).
    const Sloped& p0 = sloped_[1];
    const double h = p1.radius - p0.radius, u = (a - p0.radius) / h;
    const double u2 = u * u, u3 = u2 * u;
    s = (2.0 * u3 - 3.0 * u2 + 1.0) * p0.half_chord + (u3 - 2.0 * u2 + u) * h * p0.slope +
        (3.0 * u2 - 2.0 * u3) * p1.half_chord + (u3 - u2) * h * p1.slope;
  }
  return s > 0.0 && std::isfinite(s) ? s : chords_.at(a);
}

DugdaleState DugdaleBranchWalk::at(double contact_radius) {
  if (solved_ > 0 && last_converged_ && contact_radius == last_.contact_radius) return last_;
  last_ = dugdale_contact_state(profile_, law_, contact_radius, guess(contact_radius));
  last_converged_ = true;
  chords_.add(contact_radius, last_.cohesive_radius * std::sin(last_.angle));
  ++solved_;
  return last_;
}

void DugdaleBranchWalk::add_sloped(double contact_radius, double half_chord, double chord_slope) {
  if (!(sloped_known_ > 0 && sloped_[0].radius == contact_radius)) {
    sloped_[1] = sloped_[0];
    sloped_known_ = sloped_known_ > 0 ? 2 : 1;
  }
  sloped_[0] = {contact_radius, half_chord, chord_slope};
}

DugdaleSlopes DugdaleBranchWalk::slopes_at(double contact_radius) {
  const DugdaleState state = at(contact_radius);
  const DugdaleSlopes slopes = dugdale_contact_slopes(profile_, law_, state);
  add_sloped(contact_radius, state.cohesive_radius * std::sin(state.angle), slopes.half_chord);
  return slopes;
}

DugdaleSlopedState DugdaleBranchWalk::sloped_at(double contact_radius, const SlopedEnough& enough) {
  const DugdaleSlopedState sloped =
      dugdale_sloped_contact_state(profile_, law_, contact_radius, guess(contact_radius), enough);
  last_ = sloped.state;
  last_converged_ = !enough;
  chords_.add(contact_radius, sloped.half_chord);
  ++solved_;
  if (std::isfinite(sloped.offset)) {
    add_sloped(contact_radius, sloped.half_chord, sloped.slopes.half_chord);
  }
  return sloped;
}

}  // namespace mdrsim
