// The continuum MDR branch of the shorthand's pull-off: the state at each contact radius a.
#pragma once

#include "controllers/controller.hpp"
#include "detachment/criterion.hpp"
#include "engine/base/material.hpp"
#include "engine/model/contact_snapshot.hpp"
#include "engine/model/graded_image.hpp"
#include "profiles/profile.hpp"

#include <optional>

namespace mdrsim {

/// One equilibrium of the continuum contact (one spring per dx -> 0), with the value the
/// normal machine holds there.
struct BranchState {
  double contact_radius = 0.0;           ///< a [m]
  double stretch = 0.0;                  ///< boundary elongation e = g(a) - d [m]
  double indentation = 0.0;              ///< d [m]
  double normal_force = 0.0;             ///< F = E* (nf(a) - 2 a e) [N]
  double tangential_displacement = 0.0;  ///< u_x [m]
  double tangential_force = 0.0;         ///< F_x = 2 G* a u_x [N]
  double control = 0.0;                  ///< a_u d + a_F F [m]

  ContactSnapshot snapshot() const;
};

/// What a continuum estimate reports for a value summed from terms whose magnitudes add up to
/// `magnitude` (the value's own included) [its unit]: the search's or quadrature's `error` plus
/// the sum's rounding, 4 eps of `magnitude`. A search that lands on the exact place still
/// rounds there: no estimate claims exactness.
double with_rounding(double error, double magnitude);

/// |F| plus the magnitudes of its two terms, E* nf(a) and 2 E* a e, at state s on E* [Pa] [N]:
/// what F's rounding is a few ulps of.
double force_magnitude(const BranchState& s, double effective_modulus);

/// The glued contact of the shorthand after the tangential load is applied: every glued
/// spring carries the same u_x, which the tangential machine sets from the contact's
/// tangential stiffness 2 G* a (a_u u_x + a_F 2 G* a u_x = held value). On the receding
/// branch the boundary spring sits at its let-go elongation e(a) (the criterion's
/// critical_elongation, else a root of its margin), so that d(a) = g(a) - e(a).
///
/// On a graded half-space (`graded`, material.grading; normal loads only) g is the graded
/// image g_k, the springs' stiffness per unit length c_k(x) = (1 + k) C_k |x|^k / 2, so that
/// F(a) = C_k (nf_k(a) - a^(1+k) e), and e(a) is Hess's rule on those springs
/// (docs/graded.md); the criterion is not asked.
class ContinuumBranch {
 public:
  ContinuumBranch(const Profile& profile, const DetachmentCriterion& criterion,
                  const Material& material, const AffineConstraint& normal,
                  const AffineConstraint& tangential, double tangential_held,
                  const std::optional<GradedImage>& graded = std::nullopt);

  double tangential_displacement(double a) const;  ///< u_x(a) [m]
  /// The state at radius a [m] with boundary stretch e [m] (any e: pinned states too).
  BranchState state(double a, double stretch) const;
  /// The state on the receding branch at a > shear_off_radius() [m].
  BranchState at(double a) const;
  /// The let-go elongation e(a) [m]; 0 where the glue breaks unstretched (a <= a_s).
  double stretch(double a) const;
  /// d(control)/da [1] on the branch, by a fourth-order central difference of e(a) with a
  /// step of 1e-3 of the distance to a_s (e goes like sqrt(a - a_s) there); `error` [1] gets
  /// the difference from the step twice as large, over 15 (its Richardson estimate).
  double control_slope(double a, double* error = nullptr) const;
  /// The part of F the boundary's stretch pulls off at state s, 2 E* a e (graded: C_k
  /// a^(1+k) e) [N]: what F's rounding is a few ulps of, with F.
  double pulled_force(const BranchState& s) const;
  /// The image the branch follows at x [m]: g, or g_k on a graded half-space.
  double image(double x) const;
  /// The same for F: dF/da [N/m].
  double force_slope(double a) const;
  /// de/da [1] at a > shear_off_radius() to about the rounding of e: Ridders' extrapolation of
  /// central differences of e^2 from a step of 0.4 (a - a_s) down (or a quarter, a sixteenth,
  /// ... of it where e bends on a shorter scale), stopped where rounding takes over; `error`
  /// [1] gets the extrapolation's own estimate and the spread of those from first steps a
  /// half and a quarter as long, which the let-go's roughness moves.
  double stretch_slope(double a, double* error = nullptr) const;
  /// The let-go elongation's own error at radius a [m]: its residual in the criterion's margin
  /// over the margin's slope in the elongation (a tabulated let-go is off by up to 1e-13 of e
  /// where the margin barely moves with it). 0 where e = 0.
  double stretch_error(double a) const;
  /// dF/da [N/m] = E* (2 a g'(a) - 2 e - 2 a e') (nf' = 2 a g'), from the profile's g' and
  /// stretch_slope: where F turns, its terms cancel no worse than e's rounding, so a root of it
  /// places the turn to a few ulps (the difference quotients above, to about 1e-12).
  double precise_force_slope(double a, double* error = nullptr) const;
  /// d(control)/da [1] the same way: a_u (g' - e') + a_F dF/da.
  double precise_control_slope(double a, double* error = nullptr) const;
  /// a_s [m]: below it the tangential load alone breaks the unstretched boundary (0: never).
  double shear_off_radius() const { return shear_off_radius_; }
  /// The width of the bracket a_s was found in [m] (0 where a_s is 0 or a_g).
  double shear_off_bracket() const { return shear_off_bracket_; }
  /// Finds a_s below `glued_radius` [m]; returns false if the glue breaks at the glued radius.
  bool locate_shear_off(double glued_radius);
  /// The largest |u_x| [m] the unstretched boundary holds at radius a (infinite: any).
  double zero_stretch_limit(double a) const;
  /// Root iterations spent so far (let-go searches and the branch's own root searches).
  long long& iterations() const { return iterations_; }

  /// |F| plus the magnitudes of its two terms at state s [N] (force_magnitude, on the branch's
  /// springs).
  double force_magnitude(const BranchState& s) const;
  /// The graded image on a graded half-space, else none.
  const std::optional<GradedImage>& graded() const { return graded_; }
  const Material& material() const { return material_; }
  const Profile& profile() const { return *profile_; }
  const AffineConstraint& normal() const { return normal_; }
  const AffineConstraint& tangential() const { return tangential_; }
  double tangential_held() const { return tangential_held_; }

 private:
  double slope_of(double a, bool force, double* error) const;
  double image_slope(double x) const;
  /// F [N] at radius a [m] with boundary stretch e [m].
  double force(double a, double e) const;

  const Profile* profile_;
  const DetachmentCriterion* criterion_;
  Material material_;
  AffineConstraint normal_;
  AffineConstraint tangential_;
  double tangential_held_;
  double hess_per_radius_;  ///< 2 pi dgamma / E* [m]: dl(a)^2 = that times a
  std::optional<GradedImage> graded_;
  double shear_off_radius_ = 0.0;
  double shear_off_bracket_ = 0.0;  ///< [m]
  mutable long long iterations_ = 0;
};

}  // namespace mdrsim
