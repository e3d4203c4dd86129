// When the boundary spring of the glued contact lets go: the detachment criterion interface.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>

#include "engine/base/hess_scale.hpp"
#include "engine/base/material.hpp"

namespace mdrsim {

/// The state of the boundary spring of the glued contact.
struct BoundarySpring {
  double elongation;               ///< normal stretch -u_z, zero when compressed [m]
  double tangential_displacement;  ///< u_x [m]
  double contact_radius;           ///< a, the position of the boundary spring [m]
};

/// The rule of Hess (paper eq. 12): the elongation dl(a) [m] at which a spring of a pure
/// normal contact lets go at contact radius a [m], with dgamma at a (a criterion always takes
/// the work of adhesion at the boundary spring's radius: p.work_of_adhesion_at(a)).
inline double hess_elongation_limit(const InterfaceProperties& p, double contact_radius) {
  return std::sqrt(hess_scale(p.work_of_adhesion_at(contact_radius), p.effective_modulus) *
                   contact_radius);
}

/// Ratios the closed-form criteria need at every let-go, computed once.
class ElongationScales {
 public:
  double shear_ratio;  ///< G* / E* [1]

  explicit ElongationScales(const InterfaceProperties& p)
      : shear_ratio(p.effective_shear_modulus / p.effective_modulus),
        hess_squared_per_radius_(hess_scale(p.work_of_adhesion, p.effective_modulus)),
        by_radius_(p.work_of_adhesion_by_radius.get()),
        effective_modulus_(p.effective_modulus) {}

  /// dl(a)^2 = 2 pi a dgamma(a) / E* [m^2], in the arithmetic of hess_elongation_limit.
  double hess_squared(double contact_radius) const {
    return (by_radius_ ? hess_scale(by_radius_->at(contact_radius), effective_modulus_)
                       : hess_squared_per_radius_) *
           contact_radius;
  }

 private:
  double hess_squared_per_radius_;   ///< 2 pi dgamma / E* of a uniform interface [m]
  const RadialAdhesion* by_radius_;  ///< dgamma(r), or null (owned by the material)
  double effective_modulus_;         ///< E* [Pa]
};

/// Required: margin(). Optional: critical_elongation().
///
/// The contract both engines rely on, at every contact radius a, for elongations >= 0:
/// 1. The margin is continuous and non-increasing in the elongation (u_x and a fixed): the
///    spring lets go at the first elongation where it reaches 0 and stays let go beyond it.
///    The let-go is located by doubling the elongation until the margin is <= 0 and
///    bracketing the root below (let_go.hpp): a margin that dips to 0 and rises again is
///    found at a later root or never, and a margin that rises back past 0 lets a spring hold
///    at a larger stretch than the one it let go at: the critical point is wrong.
/// 2. The set where the spring holds (margin > 0) is convex in (elongation, u_x): along any
///    line in that plane the margin is positive on one interval. A loading program moves the
///    indentation and u_x together along lines, and locates the next let-go on a line by one
///    sign change of the margin from the present state to the line's end: a holding set that
///    is not convex (a margin positive, then <= 0, then positive again on one line) loses the
///    let-go in between, and the spring is found to hold where it had let go.
/// The engine samples both on a grid at the run's radii before a run (criterion_contract.hpp)
/// and stops with an error naming the criterion where they fail, unless the criterion proves
/// them (proves_contract()). Every built-in criterion proves them, and the tests sample them
/// too (tests/engine/model/criterion_contract_test.cpp).
class DetachmentCriterion {
 public:
  virtual ~DetachmentCriterion() = default;

  /// Required: a signed margin, > 0 while the spring holds and <= 0 when it lets go;
  /// continuous and non-increasing in the elongation. Its unit is the criterion's own.
  virtual double margin(const BoundarySpring& spring) const = 0;

  /// Optional: the closed-form smallest elongation [m] with margin <= 0, for a spring whose
  /// margin at zero elongation is >= 0. Without it the engine root-finds margin().
  virtual std::optional<double> critical_elongation(double /*contact_radius*/,
                                                    double /*tangential_displacement*/) const {
    return std::nullopt;
  }

  /// Optional: whether the margin's form proves the contract above for every material, radius
  /// and u_x, so that a run need not sample it (a sampled grid costs more than the continuum
  /// route's whole answer). Default false: a criterion of one's own is sampled before each run.
  virtual bool proves_contract() const { return false; }
};

/// The margin of an unstretched boundary spring at radius a [m] under u_x [m]: where it is
/// negative the tangential load alone breaks the glue (eq. 20 with u_z = 0). The one place
/// that rule is written; its sign decides `now` let-gos, shear-off statuses and a_s.
inline double margin_at_rest(const DetachmentCriterion& criterion, double tangential_displacement,
                             double contact_radius) {
  return criterion.margin({0.0, tangential_displacement, contact_radius});
}

/// Whether the tangential load alone breaks the unstretched boundary spring.
inline bool broken_at_rest(const DetachmentCriterion& criterion, double tangential_displacement,
                           double contact_radius) {
  return margin_at_rest(criterion, tangential_displacement, contact_radius) < 0.0;
}

}  // namespace mdrsim
