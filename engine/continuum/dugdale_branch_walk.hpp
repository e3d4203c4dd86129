// The contact branch walked through nearby radii, each state solved from its neighbours' zones:
// the scans and root searches of the continuum route's Dugdale folds.
#pragma once

#include "engine/model/dugdale_zone.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// dugdale_contact_state at the radii asked for, in any order: each solve starts from the cubic
/// through the zones of the last four (a scan's neighbours, a root search's latest points,
/// ContinuedGuess), one or two Newton steps where they lie close, instead of five from the
/// small-t cubic; the radius just solved again is that state.
class DugdaleBranchWalk {
 public:
  DugdaleBranchWalk(const Profile& profile, const DugdaleLaw& law) : profile_(profile), law_(law) {}

  DugdaleState at(double contact_radius);
  /// The state at `contact_radius` and its slopes dd/da, dF/da.
  DugdaleSlopes slopes_at(double contact_radius) {
    return dugdale_contact_slopes(profile_, law_, at(contact_radius));
  }
  const DugdaleState& last() const { return last_; }

 private:
  const Profile& profile_;
  DugdaleLaw law_;
  ContinuedGuess chords_;  ///< the half-chords of the last four zones
  DugdaleState last_;
  int solved_ = 0;
};

}  // namespace mdrsim
