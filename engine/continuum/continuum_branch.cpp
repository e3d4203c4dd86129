// The branch's states from the profile's g, g' and nf and the criterion's let-go elongation.
#include "engine/continuum/continuum_branch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "detachment/let_go.hpp"
#include "engine/base/bracketed_root.hpp"
#include "engine/base/hess_scale.hpp"
#include "engine/model/graded_constants.hpp"

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

double with_rounding(double error, double magnitude) {
  return error + 4.0 * std::numeric_limits<double>::epsilon() * std::abs(magnitude);
}

ContinuumBranch::ContinuumBranch(const Profile& profile, const DetachmentCriterion& criterion,
                                 const Material& material, const AffineConstraint& normal,
                                 const AffineConstraint& tangential, double tangential_held,
                                 const std::optional<GradedImage>& graded)
    : profile_(&profile),
      criterion_(&criterion),
      material_(material),
      normal_(normal),
      tangential_(tangential),
      tangential_held_(tangential_held),
      hess_per_radius_(hess_scale(material.work_of_adhesion, material.effective_modulus)),
      graded_(graded) {}

double ContinuumBranch::image(double x) const {
  return graded_ ? graded_->image(x) : profile_->mdr_image(x);
}

double ContinuumBranch::image_slope(double x) const {
  return graded_ ? graded_->image_slope(x) : profile_->mdr_image_slope(x);
}

double ContinuumBranch::force(double a, double e) const {
  if (graded_) {
    const double ck = material_.grading.punch_constant;
    return ck * (graded_->nonadhesive_force_per_constant(a) -
                 std::pow(a, 1.0 + graded_->grading_exponent()) * e);
  }
  return material_.effective_modulus * (profile_->nonadhesive_force_per_modulus(a) - 2.0 * a * e);
}

double ContinuumBranch::pulled_force(const BranchState& s) const {
  if (graded_) {
    return material_.grading.punch_constant *
           std::pow(s.contact_radius, 1.0 + graded_->grading_exponent()) * s.stretch;
  }
  return 2.0 * material_.effective_modulus * s.contact_radius * s.stretch;
}

double ContinuumBranch::tangential_displacement(double a) const {
  if (tangential_held_ == 0.0) return 0.0;
  return tangential_held_ /
         (tangential_.displacement_coefficient +
          tangential_.force_coefficient * 2.0 * material_.effective_shear_modulus * a);
}

BranchState ContinuumBranch::state(double a, double e) const {
  BranchState s;
  s.contact_radius = a;
  s.stretch = e;
  s.indentation = image(a) - e;
  s.normal_force = force(a, e);
  s.tangential_displacement = tangential_displacement(a);
  s.tangential_force = 2.0 * material_.effective_shear_modulus * a * s.tangential_displacement;
  s.control = normal_.displacement_coefficient * s.indentation;
  if (normal_.force_coefficient != 0.0) s.control += normal_.force_coefficient * s.normal_force;
  return s;
}

double force_magnitude(const BranchState& s, double effective_modulus) {
  const double pulled = 2.0 * effective_modulus * s.contact_radius * s.stretch;
  return std::abs(s.normal_force) + std::abs(s.normal_force + pulled) + std::abs(pulled);
}

double ContinuumBranch::force_magnitude(const BranchState& s) const {
  const double pulled = pulled_force(s);
  return std::abs(s.normal_force) + std::abs(s.normal_force + pulled) + std::abs(pulled);
}

double ContinuumBranch::stretch(double a) const {
  if (!(a > shear_off_radius_)) return 0.0;
  if (graded_) {
    return graded_let_go_stretch(graded_->grading_exponent(), material_.grading.punch_constant,
                                 material_.work_of_adhesion, a);
  }
  const LetGo go =
      locate_let_go(*criterion_, a, tangential_displacement(a), std::sqrt(hess_per_radius_ * a));
  iterations_ += go.root_iterations;
  return go.kind == LetGo::Kind::at_elongation ? go.elongation : 0.0;
}

BranchState ContinuumBranch::at(double a) const { return state(a, stretch(a)); }

double ContinuumBranch::slope_of(double a, bool of_force, double* error) const {
  const double reach = shear_off_radius_ > 0.0 ? a - shear_off_radius_ : a;
  double h = 1e-3 * std::min(reach, a);
  // Within the profile's domain (a sphere ends at its radius): the quotient reaches a + 4h.
  const double room = profile_->outer_radius() - a;
  if (room > 0.0) h = std::min(h, 0.2 * room);
  // Only what the slope needs: F without g, d without nf under fixed grips (each a pow for
  // power laws, the most of a sample's cost).
  const auto value = [&](double x) {
    const double e = stretch(x);
    const bool needs_force = of_force || normal_.force_coefficient != 0.0;
    const double f = needs_force ? this->force(x, e) : 0.0;
    if (of_force) return f;
    double c = normal_.force_coefficient * f;
    if (normal_.displacement_coefficient != 0.0) {
      c += normal_.displacement_coefficient * (image(x) - e);
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

namespace {

/// d(e^2)/da [m] at a by Ridders' extrapolation (Numerical Recipes' dfridr): the central
/// difference at steps h, h/1.4, h/1.4^2, ... extrapolated to h -> 0 in a Neville table (its
/// error is even in h) until the table's diagonal grows, rounding's turn. `error` [m] gets the
/// table's own estimate, and at least the differences' rounding.
template <class Stretch>
double squared_stretch_slope(const Stretch& stretch, double a, double h, double& error) {
  constexpr int kLevels = 10;
  constexpr double kShrink = 1.4;
  constexpr double kShrinkSquared = kShrink * kShrink;
  constexpr double kGrowthStop = 2.0;
  double rounding = 0.0;
  const auto quotient = [&](double step) {
    const double up = a + step, down = a - step;
    const double e_up = stretch(up), e_down = stretch(down);
    rounding = 2.0 * std::numeric_limits<double>::epsilon() * (e_up * e_up + e_down * e_down) /
               (up - down);
    return (e_up * e_up - e_down * e_down) / (up - down);
  };
  double table[kLevels][kLevels];
  table[0][0] = quotient(h);
  double best = table[0][0];
  error = std::numeric_limits<double>::infinity();
  for (int i = 1; i < kLevels; ++i) {
    h /= kShrink;
    table[i][0] = quotient(h);
    double factor = kShrinkSquared;
    for (int j = 1; j <= i; ++j) {
      table[i][j] = (table[i][j - 1] * factor - table[i - 1][j - 1]) / (factor - 1.0);
      factor *= kShrinkSquared;
      const double change = std::max(std::abs(table[i][j] - table[i][j - 1]),
                                     std::abs(table[i][j] - table[i - 1][j - 1]));
      if (change <= error) {
        error = change;
        best = table[i][j];
      }
    }
    if (std::abs(table[i][i] - table[i - 1][i - 1]) >= kGrowthStop * error) break;
  }
  error = std::max(error, rounding);
  return best;
}

}  // namespace

double ContinuumBranch::stretch_slope(double a, double* error) const {
  // Of e^2, not e: a let-go energy E* e^2 is W(a) = 2 pi a dgamma less a share of the shear's,
  // linear in a under a held u_x, where every difference is exact but for rounding. The first
  // step keeps a - h above a_s, where e goes like sqrt(a - a_s); a let-go that bends on a
  // shorter scale (the mode-dependent one at small lambda, where t ~ lambda) takes a shorter
  // one: each a quarter of the last until the table's own estimate is down to rounding, the
  // best of them kept.
  constexpr double kFirstStep = 0.4;  ///< of a - a_s
  constexpr double kShorter = 0.25;
  constexpr int kTries = 4;
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  constexpr double kDone = 64.0 * kEps;  ///< of |d(e^2)/da|
  const double e = stretch(a);
  if (!(e > 0.0)) {
    if (error) *error = std::numeric_limits<double>::infinity();
    return std::numeric_limits<double>::infinity();
  }
  const auto at = [this](double x) { return stretch(x); };
  const double reach = a - shear_off_radius_;
  double first = kFirstStep * reach;
  double best_first = first;
  double best_error = std::numeric_limits<double>::infinity();
  double best = 0.0;
  for (int k = 0; k < kTries; ++k, first *= kShorter) {
    double table_error = 0.0;
    const double slope = squared_stretch_slope(at, a, first, table_error);
    if (table_error < best_error) {
      best = slope;
      best_error = table_error;
      best_first = first;
    }
    if (best_error <= kDone * std::abs(best)) break;
  }
  if (!error) return best / (2.0 * e);
  // A let-go tabulated or root-found to a few ulps is rough at that scale, which the table's
  // own estimate misses (4x on a tabulated mode-dependent let-go): the spread of the tables
  // from first steps a half and a quarter of the best's shows it, doubled (on 4000 random
  // scenes that bounds the slope's error where the spread alone fell short by up to 1.2x).
  double low = best, high = best;
  for (const double shorter : {0.5, 0.25}) {
    double other_error = 0.0;
    const double other = squared_stretch_slope(at, a, shorter * best_first, other_error);
    low = std::min(low, other);
    high = std::max(high, other);
  }
  *error = (best_error + 2.0 * (high - low)) / (2.0 * e) + kEps * std::abs(best) / (2.0 * e);
  return best / (2.0 * e);
}

double ContinuumBranch::stretch_error(double a) const {
  if (graded_) return 0.0;  // Hess's rule in closed form: rounding only
  const double e = stretch(a);
  if (!(e > 0.0)) return 0.0;
  const double ux = tangential_displacement(a);
  const auto margin = [&](double x) { return criterion_->margin({x, ux, a}); };
  const double step = 1e-4 * e;
  const double falls = (margin(e - step) - margin(e + step)) / (2.0 * step);
  if (!(falls > 0.0)) return 0.0;
  return std::abs(margin(e)) / falls;
}

double ContinuumBranch::precise_force_slope(double a, double* error) const {
  const double de = stretch_slope(a, error);
  if (graded_) {
    // dF/da = C_k (a^(1+k) g_k' - (1 + k) a^k e - a^(1+k) e') (nf_k' = a^(1+k) g_k').
    const double k = graded_->grading_exponent();
    const double ck = material_.grading.punch_constant;
    const double ak = std::pow(a, k);
    if (error) *error *= ck * ak * a;
    return ck * ak * (a * graded_->image_slope(a) - (1.0 + k) * stretch(a) - a * de);
  }
  const double es = material_.effective_modulus;
  if (error) *error *= 2.0 * es * a;
  return 2.0 * es * (a * profile_->mdr_image_slope(a) - stretch(a) - a * de);
}

double ContinuumBranch::precise_control_slope(double a, double* error) const {
  const double de = stretch_slope(a, error);
  const double slope_error = error ? *error : 0.0;
  double c = 0.0, c_error = 0.0;
  if (normal_.displacement_coefficient != 0.0) {
    c += normal_.displacement_coefficient * (image_slope(a) - de);
    c_error += std::abs(normal_.displacement_coefficient) * slope_error;
  }
  if (normal_.force_coefficient != 0.0 && graded_) {
    double force_error = 0.0;
    c += normal_.force_coefficient * precise_force_slope(a, error ? &force_error : nullptr);
    c_error += std::abs(normal_.force_coefficient) * force_error;
  } else if (normal_.force_coefficient != 0.0) {
    const double es = material_.effective_modulus;
    c += normal_.force_coefficient * 2.0 * es *
         (a * profile_->mdr_image_slope(a) - stretch(a) - a * de);
    c_error += std::abs(normal_.force_coefficient) * 2.0 * es * a * slope_error;
  }
  if (error) *error = c_error;
  return c;
}

bool ContinuumBranch::locate_shear_off(double glued_radius) {
  shear_off_radius_ = 0.0;
  shear_off_bracket_ = 0.0;
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
  shear_off_bracket_ = r.hi - r.lo;
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
