// The continuum equilibrium branch of any profile (paper eqs. 20-24, g(a) for a^2/R) and its folds.
#pragma once

#include <optional>
#include <vector>

#include "controllers/controller.hpp"
#include "engine/base/material.hpp"
#include "profiles/profile.hpp"

namespace mdrsim::branch_reference {

/// What the tangential machine holds during the pull-off: a displacement (fixed grips, the
/// paper's case) or a force (fixed load, where eq. 24 gives u_x = F_x/(2 G* a)).
struct TangentialHold {
  enum class Kind { displacement, force };
  Kind kind = Kind::displacement;
  double value = 0.0;  ///< u_x [m] or F_x [N]
};

struct BranchPoint {
  double contact_radius;           ///< a [m]
  double indentation;              ///< d [m]
  double normal_force;             ///< F_z [N]
  double tangential_displacement;  ///< u_x [m]
  double tangential_force;         ///< F_x [N]
};

/// Where a pull-off glued at radius a_g ends.
struct Critical {
  enum class Kind {
    fold,              ///< the held normal value turns at a radius below a_g
    first_detachment,  ///< the branch is unstable at a_g already: the first let-go jumps
    shear_off,         ///< the tangential load alone breaks the glue at a_g
    none,              ///< the control never turns: the contact peels off smoothly
  };
  Kind kind;
  BranchPoint point;  ///< the last equilibrium (for none and shear_off: the state at a_g)
};

/// The mode-mixed criterion (eq. 20) on the continuum contact of radius a: the boundary
/// stretch e(a) = sqrt(2 pi a dgamma/E* - (G*/E*) u_x(a)^2) (eq. 21), the indentation
/// d = g(a) - e (eq. 22), F_z = 2 E* (a d - integral_0^a g dx) (eq. 23) and F_x = 2 G* a u_x
/// (eq. 24). With g = x^2/R these are the paper's eqs. 25-27; with a held F_x they extend it.
/// The same branch holds for the deformation and stress criteria when G* = E*.
class EquilibriumBranch {
 public:
  EquilibriumBranch(const Profile& profile, const Material& material,
                    TangentialHold tangential = {});

  BranchPoint at(double contact_radius) const;
  double stretch(double contact_radius) const;             ///< e(a) [m]
  double indentation_slope(double contact_radius) const;   ///< dd/da [1]
  double normal_force_slope(double contact_radius) const;  ///< dF_z/da [N/m]
  /// d/da of the held normal value a_u d + a_F F_z: a fold is where it vanishes
  /// (fixed grips: dd/da = 0, fixed load: dF_z/da = 0, compliant: dF_z/da + k dd/da = 0).
  double control_slope(const AffineConstraint& normal, double contact_radius) const;
  /// The smallest radius with a real stretch: below it the tangential load alone breaks the
  /// boundary spring (0 without tangential load; infinite with one but no adhesion) [m].
  double shear_off_radius() const;

  /// The folds of the normal control in (lo, hi] [m], largest first: sign changes of
  /// control_slope found on `scan` equal intervals, each refined by TOMS 748 to full
  /// precision. Two folds closer than one interval are missed.
  std::vector<BranchPoint> folds(const AffineConstraint& normal, double lo, double hi,
                                 int scan = 4000) const;
  /// The last equilibrium of a pull-off from glued radius a_g [m]: the largest fold below
  /// a_g, where the control slope turns from positive (stable) to negative.
  Critical critical(const AffineConstraint& normal, double glued_radius) const;

 private:
  /// (G*/E*) u_x(a)^2 and its a-derivative [m^2, m].
  double shear_term(double a) const;
  double shear_term_slope(double a) const;

  const Profile* profile_;
  Material material_;
  TangentialHold tangential_;
  double adhesion_length_;  ///< 2 pi dgamma / E* [m], so that dl(a)^2 = adhesion_length_ a
};

}  // namespace mdrsim::branch_reference
