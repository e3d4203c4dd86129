// The Maugis-Dugdale model fitted to one prepared segment: youngs_modulus, work_of_adhesion and
// the Maugis parameter lambda (or lambda held), contact point and baseline; and the regime
// (DMT, Maugis, JKR) that a fitted lambda picks for `--model auto`.
#pragma once

#include <string>
#include <vector>

#include "engine/fit/adhesive_fit.hpp"
#include "engine/fit/prepared_curve.hpp"
#include "engine/fit/tip_shape.hpp"
#include "engine/model/dugdale_zone.hpp"
#include "profiles/profile.hpp"

namespace mdrsim::fit {

/// sigma_0 [Pa] of the Maugis parameter lambda for a tip of radius R [m] on E* [Pa] with work
/// of adhesion w [J/m^2]: sigma_0 = (lambda/2) (pi w K^2 / R)^(1/3), K = 4 E*/3 (SPEC).
double maugis_adhesive_stress(double lambda, double reduced_modulus, double work, double radius);

/// The retract's path of the MDR's Maugis-Dugdale model (engine/model/dugdale_zone.hpp) for
/// any profile, sampled (no root of the zone's opening per data point) down to the first fold
/// of the depth, the fixed-grips end: the contact branch in the contact radius a, 193 states
/// from the radius that reaches the deepest indentation down to 1e-3 of it, cut at its fold;
/// where it closes first (small lambda), the no-contact branch after it in the zone's radius c
/// (48 states from c0 down to its fold). A depth is placed on it by the cubic Hermite
/// interpolants of d and F in a or c (their slopes exact, dugdale_contact_slopes), so that F(d)
/// and dF/dd are smooth in d and in the parameters.
class MaugisBranch {
 public:
  /// Throws std::domain_error where the zone reaches past the profile (a sphere pressed deep).
  MaugisBranch(const Profile& profile, const DugdaleLaw& law, double deepest);

  struct State {
    double force = 0.0;            ///< [N]
    double d_force_d_depth = 0.0;  ///< [N/m]; 0 beyond the branch's shallow end
  };
  /// The state at indentation `depth` [m]; below the branch's shallowest depth, its end.
  State at(double depth) const;
  /// [N] the lowest force along the branch (the pull-off under fixed load).
  double lowest_force() const { return lowest_force_; }
  double shallowest_depth() const { return depth_.front(); }  ///< [m]
  /// [m] Where a lever of stiffness k [N/m] lets the retract go: the depth, coming out, at which
  /// the branch's slope dF/dd first falls to -k (there the lever's base q = d + F/k turns),
  /// else the branch's shallow end (its fixed-grips fold). `turns` tells which.
  double release_depth(double stiffness, bool* turns = nullptr) const;

 private:
  // Nodes by rising depth: the no-contact branch's (in c) then the contact branch's (in a).
  std::vector<double> radius_, depth_, force_, depth_slope_, force_slope_;
  std::vector<char> contact_;
  double lowest_force_ = 0.0;
};

struct MaugisFitOptions {
  TipShape tip;  ///< parabolic or sphere (lambda is defined by the tip radius)
  double poisson_ratio = 0.5;
  AdhesiveFixed fixed;
  bool retract = true;  ///< the samples run from the deepest point out (false: an approach)
};

/// Fits the model. Retract: the samples from the deepest point to the jump off (the largest
/// rise of the force after its minimum, as adhesive_fit finds it) lie on the path, past the
/// fixed-load pull-off as far as the lever held them, the rest on the baseline. Approach: the
/// samples from the jump in (a change point of the force, then the split of least squares of
/// the fitted model) lie on it, and the jump's position is one more residual: the tip there at d =
/// -h0 = -w / sigma_0, the zone's range, which is what tells lambda (weighted by the sampling step
/// and the change point's spread). A retract whose spring constant is known adds its jump off where
/// it stands out of the noise: the lever's base there, where q = d + F/k turns on the path
/// (release_depth); where it does not, the retract's samples on the path are those the fitted
/// model's lever holds. Starts from the DMT and JKR fits (adhesive_fit) and the best of five
/// lambdas.
AdhesiveFit fit_maugis(const PreparedSegment& segment, const MaugisFitOptions& options);

/// Approach and retract on one path (`--segment both`): one E, dgamma, lambda, contact point and
/// baseline; the retract's samples as fit_maugis takes them, the approach's from its jump in,
/// and the jump in's position. Starts from the retract's DMT and JKR fits, and again from the
/// retract's own Maugis fit with the jump in where its tip passes -h0 (the lower squares kept).
AdhesiveFit fit_maugis_both(const PreparedSegment& approach, const PreparedSegment& retract,
                            const MaugisFitOptions& options);

/// `--model auto`'s choice from a fitted lambda: below 0.1 DMT, above 5 JKR, Maugis between
/// (Johnson & Greenwood's adhesion map, 1997; docs/afm.md gives the pull-off forces there).
struct RegimeChoice {
  const char* model;   ///< "dmt", "maugis" or "jkr"
  std::string reason;  ///< "auto: lambda = 0.42 -> maugis"
};
RegimeChoice choose_regime(double lambda);

}  // namespace mdrsim::fit
