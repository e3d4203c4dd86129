// The general branch and its folds: closed-form slopes from g'(a), scan and TOMS 748 roots.
#include "engine/reference/branch_reference.hpp"

#include "engine/base/bracketed_root.hpp"
#include "engine/base/hess_scale.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace mdrsim::branch_reference {
namespace {}  // namespace

EquilibriumBranch::EquilibriumBranch(const Profile& profile, const Material& material,
                                     TangentialHold tangential)
    : profile_(&profile),
      material_(material),
      tangential_(tangential),
      adhesion_length_(hess_scale(material.work_of_adhesion, material.effective_modulus)) {}

// Held u: (G*/E*) u^2. Held F_x: u = F_x/(2 G* a), so (G*/E*) u^2 = F_x^2/(4 E* G* a^2).
double EquilibriumBranch::shear_term(double a) const {
  const double e = material_.effective_modulus, g = material_.effective_shear_modulus;
  const double v = tangential_.value;
  if (tangential_.kind == TangentialHold::Kind::displacement) return g / e * v * v;
  return v * v / (4.0 * e * g * a * a);
}

double EquilibriumBranch::shear_term_slope(double a) const {
  if (tangential_.kind == TangentialHold::Kind::displacement) return 0.0;
  return -2.0 * shear_term(a) / a;
}

double EquilibriumBranch::shear_off_radius() const {
  if (tangential_.value == 0.0) return 0.0;
  if (!(adhesion_length_ > 0.0)) return std::numeric_limits<double>::infinity();
  const double e = material_.effective_modulus, g = material_.effective_shear_modulus;
  const double v = tangential_.value;
  // e(a)^2 = adhesion_length a - shear_term(a) = 0.
  if (tangential_.kind == TangentialHold::Kind::displacement) {
    return g / e * v * v / adhesion_length_;
  }
  return std::cbrt(v * v / (4.0 * e * g * adhesion_length_));
}

double EquilibriumBranch::stretch(double a) const {
  return std::sqrt(std::max(0.0, adhesion_length_ * a - shear_term(a)));
}

BranchPoint EquilibriumBranch::at(double a) const {
  const double e_star = material_.effective_modulus;
  const double e = stretch(a);
  const double u = tangential_.kind == TangentialHold::Kind::displacement
                       ? tangential_.value
                       : tangential_.value / (2.0 * material_.effective_shear_modulus * a);
  // F_z = 2 E* (a d - integral g) = E* * 2 (a g(a) - integral g) - 2 E* a e.
  return {a, profile_->mdr_image(a) - e,
          e_star * profile_->nonadhesive_force_per_modulus(a) - 2.0 * e_star * a * e, u,
          2.0 * material_.effective_shear_modulus * a * u};
}

// d' = g' - e', e' = (e^2)'/(2e) = (adhesion_length - shear_term')/(2e).
double EquilibriumBranch::indentation_slope(double a) const {
  // Without adhesion and tangential load e stays 0: its slope is 0, not 0/0.
  const double rate = adhesion_length_ - shear_term_slope(a);
  const double stretch_slope = rate == 0.0 ? 0.0 : rate / (2.0 * stretch(a));
  return profile_->mdr_image_slope(a) - stretch_slope;
}

// F_z' = 2 E* (d + a d' - g) = 2 E* (a d' - e).
double EquilibriumBranch::normal_force_slope(double a) const {
  return 2.0 * material_.effective_modulus * (a * indentation_slope(a) - stretch(a));
}

double EquilibriumBranch::control_slope(const AffineConstraint& c, double a) const {
  double slope = 0.0;
  if (c.displacement_coefficient != 0.0) slope += c.displacement_coefficient * indentation_slope(a);
  if (c.force_coefficient != 0.0) slope += c.force_coefficient * normal_force_slope(a);
  return slope;
}

std::vector<BranchPoint> EquilibriumBranch::folds(const AffineConstraint& c, double lo, double hi,
                                                  int scan) const {
  std::vector<BranchPoint> out;
  const auto slope = [&](double a) { return control_slope(c, a); };
  double upper = hi;
  double upper_slope = slope(hi);
  for (int j = scan - 1; j >= 0; --j) {
    double a = lo + (hi - lo) * (static_cast<double>(j) / scan);
    double s = a > lo ? slope(a) : std::numeric_limits<double>::quiet_NaN();
    if (j == 0) {
      // The lower end may be singular (e = 0, e' infinite): approach it geometrically.
      double gap = upper - lo;
      for (int k = 0; k < 60; ++k) {
        gap *= 0.5;
        a = lo + gap;
        s = slope(a);
        if (!std::isfinite(s) || (s > 0.0) != (upper_slope > 0.0)) break;
      }
    }
    if (std::isfinite(s) && std::isfinite(upper_slope) && (s > 0.0) != (upper_slope > 0.0)) {
      out.push_back(at(bracketed_root(slope, a, upper)));
    }
    upper = a;
    upper_slope = s;
  }
  return out;
}

Critical EquilibriumBranch::critical(const AffineConstraint& c, double glued_radius) const {
  const double lowest = shear_off_radius();
  if (!(glued_radius > lowest)) {
    return {Critical::Kind::shear_off, at(glued_radius)};
  }
  if (!(control_slope(c, glued_radius) > 0.0)) {
    return {Critical::Kind::first_detachment, at(glued_radius)};
  }
  // Stable at a_g, so the first sign change below it is the turn from stable to unstable.
  const std::vector<BranchPoint> found = folds(c, lowest, glued_radius);
  if (!found.empty()) return {Critical::Kind::fold, found.front()};
  return {Critical::Kind::none, at(glued_radius)};
}

}  // namespace mdrsim::branch_reference
