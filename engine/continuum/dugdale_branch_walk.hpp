// The contact branch walked through nearby radii, each state solved from its neighbours' zones:
// the scans and root searches of the continuum route's Dugdale folds.
#pragma once

#include "engine/model/dugdale_zone.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// dugdale_contact_state at the radii asked for, in any order: each solve starts from the cubic
/// Hermite through the last two zones whose slopes ds/da were asked for (a scan's samples, a
/// root search's latest points), else from the cubic through the last four zones
/// (ContinuedGuess): one or two Newton steps where they lie close, instead of five from the
/// small-t cubic; the radius just solved again is that state.
class DugdaleBranchWalk {
 public:
  DugdaleBranchWalk(const Profile& profile, const DugdaleLaw& law) : profile_(profile), law_(law) {}

  DugdaleState at(double contact_radius);
  /// The state at `contact_radius` and its slopes dd/da, dF/da (and ds/da, which the walk keeps).
  DugdaleSlopes slopes_at(double contact_radius);
  /// The state at `contact_radius` with the slopes at its solve's last iterate
  /// (dugdale_sloped_contact_state): one gap integral fewer than slopes_at, for a scan that reads
  /// their signs or a root search whose guesses have come to lie at its roots.
  /// `enough`: as dugdale_sloped_contact_state's (a scan's sign read, a step short of the root).
  DugdaleSlopedState sloped_at(double contact_radius, const SlopedEnough& enough = {});
  const DugdaleState& last() const { return last_; }

 private:
  /// A solved zone with its slope: the half-chord s [m] and ds/da [1] at the radius a [m].
  struct Sloped {
    double radius, half_chord, slope;
  };
  double guess(double contact_radius) const;
  /// Keeps a solved zone and its slope ds/da as the newest node of the Hermite guess.
  void add_sloped(double contact_radius, double half_chord, double chord_slope);

  const Profile& profile_;
  DugdaleLaw law_;
  ContinuedGuess chords_;  ///< the half-chords of the last four zones
  Sloped sloped_[2]{};     ///< the last two zones with slopes, the newest first
  int sloped_known_ = 0;
  DugdaleState last_;
  bool last_converged_ = false;  ///< last_ solved to the root (not a scan's step short of it)
  int solved_ = 0;
};

}  // namespace mdrsim
