// The branch's states from the profile's g, g' and nf and the criterion's let-go elongation.
#include "engine/continuum/continuum_branch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "detachment/let_go.hpp"
#include "engine/base/bracketed_root.hpp"
#include "engine/base/hess_scale.hpp"

namespace mdrsim {

ContactSnapshot BranchState::snapshot() const {
  ContactSnapshot s;
  s.normal_control = control;
  s.indentation = indentation;
  s.normal_force = normal_force;
  s.contact_radius = contact_radius;
  s.tangential_displacement = tangential_displacement;
  s.tangential_force = tangential_force;
  return s;
}

ContinuumBranch::ContinuumBranch(const Profile& profile, const DetachmentCriterion& criterion,
                                 const Material& material, const AffineConstraint& normal,
                                 const AffineConstraint& tangential, double tangential_held)
    : profile_(&profile),
      criterion_(&criterion),
      material_(material),
      normal_(normal),
      tangential_(tangential),
      tangential_held_(tangential_held),
      hess_per_radius_(hess_scale(material.work_of_adhesion, material.effective_modulus)) {}

double ContinuumBranch::tangential_displacement(double a) const {
  if (tangential_held_ == 0.0) return 0.0;
  return tangential_held_ /
         (tangential_.displacement_coefficient +
          tangential_.force_coefficient * 2.0 * material_.effective_shear_modulus * a);
}

BranchState ContinuumBranch::state(double a, double e) const {
  BranchState s;
  const double es = material_.effective_modulus;
  s.contact_radius = a;
  s.stretch = e;
  s.indentation = profile_->mdr_image(a) - e;
  s.normal_force = es * (profile_->nonadhesive_force_per_modulus(a) - 2.0 * a * e);
  s.tangential_displacement = tangential_displacement(a);
  s.tangential_force = 2.0 * material_.effective_shear_modulus * a * s.tangential_displacement;
  s.control = normal_.displacement_coefficient * s.indentation;
  if (normal_.force_coefficient != 0.0) s.control += normal_.force_coefficient * s.normal_force;
  return s;
}

double ContinuumBranch::stretch(double a) const {
  if (!(a > shear_off_radius_)) return 0.0;
  const LetGo go =
      locate_let_go(*criterion_, a, tangential_displacement(a), std::sqrt(hess_per_radius_ * a));
  iterations_ += go.root_iterations;
  return go.kind == LetGo::Kind::at_elongation ? go.elongation : 0.0;
}

BranchState ContinuumBranch::at(double a) const { return state(a, stretch(a)); }

double ContinuumBranch::slope_of(double a, bool force, double* error) const {
  const double reach = shear_off_radius_ > 0.0 ? a - shear_off_radius_ : a;
  double h = 1e-3 * std::min(reach, a);
  // Within the profile's domain (a sphere ends at its radius): the quotient reaches a + 4h.
  const double room = profile_->outer_radius() - a;
  if (room > 0.0) h = std::min(h, 0.2 * room);
  // Only what the slope needs: F without g, d without nf under fixed grips (each a pow for
  // power laws, the most of a sample's cost).
  const double es = material_.effective_modulus;
  const auto value = [&](double x) {
    const double e = stretch(x);
    const bool needs_force = force || normal_.force_coefficient != 0.0;
    const double f =
        needs_force ? es * (profile_->nonadhesive_force_per_modulus(x) - 2.0 * x * e) : 0.0;
    if (force) return f;
    double c = normal_.force_coefficient * f;
    if (normal_.displacement_coefficient != 0.0) {
      c += normal_.displacement_coefficient * (profile_->mdr_image(x) - e);
    }
    return c;
  };
  const double p1 = value(a + h), m1 = value(a - h);
  const double p2 = value(a + 2.0 * h), m2 = value(a - 2.0 * h);
  const double fine = (8.0 * (p1 - m1) - (p2 - m2)) / (12.0 * h);
  if (error) {
    // The same rule at 2h: its error is 16 times the fine one's, so the difference / 15.
    const double p4 = value(a + 4.0 * h), m4 = value(a - 4.0 * h);
    const double coarse = (8.0 * (p2 - m2) - (p4 - m4)) / (24.0 * h);
    *error = std::abs(fine - coarse) / 15.0;
  }
  return fine;
}

double ContinuumBranch::control_slope(double a, double* error) const {
  return slope_of(a, false, error);
}

double ContinuumBranch::force_slope(double a) const { return slope_of(a, true, nullptr); }

bool ContinuumBranch::locate_shear_off(double glued_radius) {
  shear_off_radius_ = 0.0;
  const auto rest = [&](double a) {
    return margin_at_rest(*criterion_, tangential_displacement(a), a);
  };
  if (rest(glued_radius) < 0.0) {
    shear_off_radius_ = glued_radius;
    return false;
  }
  // Below 1e-15 a_g no row or force feels a_s: the glue holds down to the smallest scale.
  const double low = 1e-15 * glued_radius;
  if (!(rest(low) < 0.0)) return true;
  const RootBracket r = bracket_root(rest, low, glued_radius);
  iterations_ += r.iterations;
  shear_off_radius_ = r.hi;  // the margin at rest is >= 0 above it
  return true;
}

double ContinuumBranch::zero_stretch_limit(double a) const {
  const auto rest = [&](double u) { return margin_at_rest(*criterion_, u, a); };
  double hi = std::abs(tangential_displacement(a));
  if (!(rest(hi) < 0.0)) return std::numeric_limits<double>::infinity();
  const RootBracket r = bracket_root(rest, 0.0, hi);
  iterations_ += r.iterations;
  return r.lo;
}

}  // namespace mdrsim
