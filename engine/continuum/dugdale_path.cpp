// The shorthand's Dugdale path: its states, folds, most tensile point and work.
#include "engine/continuum/dugdale_path.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "engine/base/bracketed_root.hpp"
#include "engine/continuum/dugdale_branch_walk.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
/// Samples per phase: the branch above a_g, the branch below it (denser near the closing point)
/// and the no-contact branch (8 per halving of c, 40 halvings).
constexpr int kAboveGluedSamples = 64;
constexpr int kBranchSamples = 512;
constexpr int kNearClosingSamples = 256;
constexpr int kFreeSamples = 320;
constexpr double kFreeHalvings = 40.0;
/// The zone's angle beyond which the branch is followed in t rather than in a: c = a / cos(t)
/// from a given radius rounds to eps / cos(t) of itself, 2 eps at most below it.
constexpr double kAngleBeyond = std::numbers::pi / 3.0;
/// The phases: 0 and 1 the branch in a, 2 the branch in t, 3 the no-contact branch.
constexpr int kFreePhase = 3;
/// The difference quotients' step in s on the contact branch: rounding of the states (~1e-15 of
/// d) over it and the fourth-order rule's truncation, h^4 d^(5) / 30, both near 1e-11 of d per
/// unit s. The no-contact branch's c = c0 2^(-40 (s - 2)) varies 40 ln 2 times faster in s.
constexpr double kStep = 2.5e-4;

double step_of(int phase) {
  return phase == kFreePhase ? kStep / (kFreeHalvings * std::numbers::ln2) : kStep;
}
/// A fold that Brent places this close to a phase's end is that end (a corner of the path).
constexpr double kCornerWidth = 1e-6;

int phase_of(double s) { return std::clamp(static_cast<int>(std::floor(s)), 0, kFreePhase); }

std::vector<double> sample_parameters() {
  std::vector<double> s;
  for (int k = 0; k < kAboveGluedSamples; ++k)
    s.push_back(static_cast<double>(k) / kAboveGluedSamples);
  for (int k = 0; k < kBranchSamples; ++k) {
    s.push_back(1.0 + static_cast<double>(k) / kBranchSamples);
  }
  for (int k = 0; k < kNearClosingSamples; ++k) {
    s.push_back(2.0 + static_cast<double>(k) / kNearClosingSamples);
  }
  for (int k = 0; k <= kFreeSamples; ++k) s.push_back(3.0 + static_cast<double>(k) / kFreeSamples);
  return s;
}

/// Fourth-order central difference of fn at s with step h.
template <class Fn>
double slope(Fn fn, double s, double h) {
  return (8.0 * (fn(s + h) - fn(s - h)) - (fn(s + 2.0 * h) - fn(s - 2.0 * h))) / (12.0 * h);
}

double brent_minimum(const auto& value, double lo, double hi) {
  const double width = hi - lo;
  // Over the unit interval: Brent's absolute tolerance would stop it early on a narrow bracket.
  const double u =
      boost::math::tools::brent_find_minima([&](double x) { return value(lo + x * width); }, 0.0,
                                            1.0, std::numeric_limits<double>::digits)
          .first;
  return lo + u * width;
}

}  // namespace

namespace {

/// The zone's opening less h0 for a contact held at radius a, depth d and angle t.
double held_opening_excess(const Profile& profile, const DugdaleLaw& law, double a, double depth,
                           double t) {
  const double cos_t = std::cos(t);
  const double c = a / cos_t;
  // c - a = 2 a sin^2(t/2) / cos t, without the cancellation.
  const double half = std::sin(0.5 * t);
  const double zone = 2.0 * a * half * half / cos_t;
  return (2.0 / kPi) * (profile.dugdale_gap_integral(a, c, t) + (profile.mdr_image(a) - depth) * t -
                        law.zone_strain() * zone) -
         law.range();
}

/// The contact branch at the zone's angle t = arccos(a/c) < pi/2 [rad]: a from the opening at
/// fixed t, (2/pi)[int_a^c (g - g(a))/sqrt(c^2 - x^2) dx + (2 sigma_0/E*) a (t tan t - (sec t -
/// 1))] = h0, which rises with a from -h0 at a = 0. Next to the closing point c = a / cos(t) from
/// a radius found at a given angle keeps its digits, where one found from the angle at a
/// given radius (dugdale_contact_state) rounds to eps / cos(t) of itself, and the difference
/// quotients of d with it.
DugdaleState contact_state_at_angle(const Profile& profile, const DugdaleLaw& law, double t,
                                    double guess, DugdaleSlopedState* sloped = nullptr,
                                    const SlopedEnough& enough = {}) {
  const double cos_t = std::cos(t), tan_t = std::tan(t);
  const double half = std::sin(0.5 * t);
  const double stretch_per_radius = t * tan_t - 2.0 * half * half / cos_t;
  // Newton's steps in a from the guess, kept inside a bracket [lo, hi] of the root. With x = a y
  // in J, dJ/da at fixed t = (1/a) int_a^c x g'(x)/sqrt(c^2 - x^2) dx - g'(a) t, whose integral
  // is dJ/dt / tan(t) (Profile::dugdale_gap); t >= pi/3 here, where the two do not cancel.
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  double a = guess;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const DugdaleGap gap = profile.dugdale_gap(a, a / cos_t, t);
    const double excess =
        (2.0 / kPi) * (gap.integral + law.zone_strain() * a * stretch_per_radius) - law.range();
    if (excess < 0.0) {
      lo = a;
    } else {
      hi = a;  // also where the zone passes the body's edge (an excess that is not finite)
    }
    const double slope = gap.angle_slope / (a * tan_t) - profile.mdr_image_slope(a) * t +
                         law.zone_strain() * stretch_per_radius;
    double next = a - excess * (kPi / 2.0) / slope;
    if (enough && next > lo && next < hi) {  // a caller content with this iterate's slopes
      // The zone alone (a, c, t) for `enough`; d and F once it is content.
      DugdaleSlopedState here{
          .state = {.contact_radius = next, .cohesive_radius = next / cos_t, .angle = t},
          .slopes =
              dugdale_slopes_at_zone(profile, law, a, a * tan_t, a / cos_t, t,
                                     {.integral = gap.integral, .angle_slope = gap.angle_slope}),
          .offset = std::abs(next - a) * tan_t,
          .half_chord = next * tan_t};
      if (enough(here)) {
        here.state =
            dugdale_contact_state_of_zone(profile, law, next, next * tan_t, next / cos_t, t);
        *sloped = here;
        return here.state;
      }
    }
    // Quadratic convergence: the step left is about (a E''/2E') 1e-18 a; a step onto the
    // bracket's end from a start at the root is converged too.
    if (std::abs(next - a) <= 1e-9 * a && next >= lo && next <= hi) {
      if (sloped != nullptr) {  // the slopes at this iterate, its half-chord a tan(t)
        sloped->slopes =
            dugdale_slopes_at_zone(profile, law, a, a * tan_t, a / cos_t, t,
                                   {.integral = gap.integral, .angle_slope = gap.angle_slope});
        sloped->offset = std::abs(next - a) * tan_t;
      }
      a = next;
      break;
    }
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * a;
    a = next;
    if (std::isfinite(hi) && hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) break;
  }
  const DugdaleState state =
      dugdale_contact_state_of_zone(profile, law, a, a * tan_t, a / cos_t, t);
  if (sloped != nullptr) {
    sloped->state = state;
    sloped->half_chord = a * tan_t;
  }
  return state;
}

/// a_p >= a_g where the contact branch's depth is d_p (a_g where d_p is not above d(a_g)).
double radius_at_preload_depth(const Profile& profile, const DugdaleLaw& law, double glued_radius,
                               double preload_depth, double glued_depth) {
  if (!(preload_depth > glued_depth)) return glued_radius;
  const auto excess = [&](double a) {
    return dugdale_contact_state(profile, law, a).indentation - preload_depth;
  };
  // Widened by half its radius, or halfway to a body's edge, where the contact state throws
  // once its zone reaches past the edge.
  const double outer = profile.outer_radius();
  const auto wider = [&](double a) { return std::min(1.5 * a, 0.5 * (a + outer)); };
  double lo = glued_radius;
  double hi = wider(glued_radius);
  while (excess(hi) < 0.0) {
    if (!(hi < outer * (1.0 - 1e-12))) {
      throw std::domain_error("the cohesive zone reaches beyond the profile's outer radius");
    }
    lo = hi;
    hi = wider(hi);
  }
  return bracket_root(excess, lo, hi, std::numeric_limits<double>::digits - 2).hi;
}

}  // namespace

DugdalePath::DugdalePath(const Profile& profile, const DugdaleLaw& law, double glued_radius,
                         double preload_depth)
    : profile_(profile),
      law_(law),
      glued_radius_(glued_radius),
      glued_state_(dugdale_contact_state(profile, law, glued_radius)),
      closing_radius_(dugdale_closing_radius(profile, law)) {
  angle_state_ = glued_state_.angle >= kAngleBeyond
                     ? glued_state_
                     : contact_state_at_angle(profile, law, kAngleBeyond, glued_radius);
  preload_radius_ =
      radius_at_preload_depth(profile, law, glued_radius, preload_depth, glued_state_.indentation);
}

DugdaleState dugdale_held_state(const Profile& profile, const DugdaleLaw& law, double a,
                                double depth) {
  const auto excess = [&](double t) { return held_opening_excess(profile, law, a, depth, t); };
  // The branch's angle at a holds the root at the branch's depth; a deeper indentation opens
  // the zone less there, so that the root lies above it.
  const double outer = profile.outer_radius();
  const double top = std::isfinite(outer)
                         ? std::acos(std::min(1.0, a / outer))
                         : 0.5 * kPi * (1.0 - 4.0 * std::numeric_limits<double>::epsilon());
  double lo = dugdale_contact_state(profile, law, a).angle;
  double hi = lo;
  // At the branch's own depth the branch's angle is the root, so a rounding-sized excess of
  // either sign there is the root itself: the opening may turn down again just above it
  // (lambda = 10, three of Maugis' lengths: -6.6e-4 h0 at 0.99 t, +4.8e-4 h0 at 1.01 t, -3.6e-3
  // h0 at 1.1 t), and a widening search would pass to another root.
  const double rounding = 64.0 * std::numeric_limits<double>::epsilon() * law.range();
  if (std::abs(excess(lo)) <= rounding) {
    hi = lo;
  } else if (excess(lo) < 0.0) {
    while (excess(hi) < 0.0) {
      if (hi >= top) {
        throw std::domain_error("the cohesive zone reaches beyond the profile's outer radius");
      }
      lo = hi;
      hi = std::min(top, 1.5 * hi);
    }
  } else {
    while (excess(lo) > 0.0 && lo > 1e-300) {
      hi = lo;
      lo *= 0.5;
    }
  }
  const double t =
      lo == hi ? lo : bracket_root(excess, lo, hi, std::numeric_limits<double>::digits - 2).hi;
  const double c = a / std::cos(t);
  const double s = c * std::sin(t);
  const double e_star = law.effective_modulus;
  return {.contact_radius = a,
          .cohesive_radius = c,
          .angle = t,
          .indentation = depth,
          .normal_force = e_star * profile.nonadhesive_force_per_modulus(a) +
                          2.0 * e_star * a * (depth - profile.mdr_image(a)) -
                          2.0 * law.adhesive_stress * (c * c * t - a * s)};
}

DugdaleState DugdalePath::in_phase(int phase, double s, double guess) const {
  switch (phase) {
    case 0:
      // A preload at or above the glued depth leaves a_p = a_g: the whole phase is the glued
      // state, not one solve a sample (a walk would solve the same radius from its own root).
      if (s == 1.0 || preload_radius_ == glued_radius_) return glued_state_;
      return dugdale_contact_state(profile_, law_,
                                   preload_radius_ - s * (preload_radius_ - glued_radius_), guess);
    case 1: {
      if (s == 1.0) return glued_state_;
      if (s == 2.0) return angle_state_;
      // a from a_g down to a_t, where the zone's angle reaches kAngleBeyond.
      const double u = 2.0 - s;
      return dugdale_contact_state(
          profile_, law_,
          angle_state_.contact_radius + (glued_radius_ - angle_state_.contact_radius) * u * u,
          guess);
    }
    case 2: {
      if (s == 2.0) return angle_state_;
      // t = pi/2 - (pi/2 - t_t)(3 - s)^2: dense next to the closing point (t = pi/2, a = 0),
      // where the DMT side's folds sit, and even about s = 3.
      const double u = 3.0 - s;
      const double gap = (0.5 * kPi - angle_state_.angle) * u * u;
      if (!(gap > 1e-12)) return dugdale_free_state(profile_, law_, closing_radius_);
      // a ~ c0 cos(t) next to the closing point: a start for the bracket.
      return contact_state_at_angle(
          profile_, law_, 0.5 * kPi - gap,
          guess > 0.0 ? guess
                      : std::min(angle_state_.contact_radius, closing_radius_ * std::sin(gap)));
    }
    default:
      return dugdale_free_state(profile_, law_,
                                closing_radius_ * std::exp2(-kFreeHalvings * (s - kClosing)));
  }
}

DugdaleState DugdalePath::at(double s) const { return in_phase(phase_of(s), s); }

DugdaleState DugdalePath::walk_to(double s, ContinuedGuess& walk) const {
  const int phase = phase_of(s);
  if (phase == kFreePhase) return in_phase(phase, s);
  // The walk's variable at s before solving (in_phase's maps), and its value once solved: the
  // half-chord in the radius on [0, 2), the radius in the zone's angle on [2, 3).
  const bool in_angle = phase == 2;
  double x = 0.0;
  if (phase == 0) {
    x = preload_radius_ - s * (preload_radius_ - glued_radius_);
  } else if (phase == 1) {
    const double u = 2.0 - s;
    x = angle_state_.contact_radius + (glued_radius_ - angle_state_.contact_radius) * u * u;
  } else {
    const double u = 3.0 - s;
    x = 0.5 * kPi - (0.5 * kPi - angle_state_.angle) * u * u;
  }
  const DugdaleState st = in_phase(phase, s, walk.at(x));
  if (st.contact_radius > 0.0) {
    walk.add(in_angle ? st.angle : st.contact_radius,
             in_angle ? st.contact_radius : st.cohesive_radius * std::sin(st.angle));
  }
  return st;
}

DugdaleSlopedState DugdalePath::sloped_walk_to(double s, ContinuedGuess& walk,
                                               const SlopedEnough& enough) const {
  DugdaleSlopedState sloped;
  sloped.offset = std::numeric_limits<double>::infinity();
  const double u = 3.0 - s;
  const double gap = (0.5 * kPi - angle_state_.angle) * u * u;
  if (phase_of(s) != 2 || s == 2.0 || !(gap > 1e-12)) {
    sloped.state = walk_to(s, walk);
    return sloped;
  }
  const double guess = walk.at(0.5 * kPi - gap);
  contact_state_at_angle(
      profile_, law_, 0.5 * kPi - gap,
      guess > 0.0 ? guess : std::min(angle_state_.contact_radius, closing_radius_ * std::sin(gap)),
      &sloped, enough);
  // da/dt along the branch from ds/da, t = atan(s/a): dt/da = (a ds/da - s)/c^2.
  const DugdaleState& st = sloped.state;
  const double chord = sloped.half_chord;
  const double rate = std::isfinite(sloped.offset)
                          ? st.cohesive_radius * st.cohesive_radius /
                                (st.contact_radius * sloped.slopes.half_chord - chord)
                          : std::numeric_limits<double>::quiet_NaN();
  walk.add(st.angle, st.contact_radius, rate);
  return sloped;
}

std::vector<DugdaleState> DugdalePath::states(std::span<const double> places) const {
  std::vector<DugdaleState> out;
  out.reserve(places.size());
  ContinuedGuess walk;
  int walking = -1;
  for (const double s : places) {
    const int phase = phase_of(s);
    if (phase != walking) walk.clear();
    walking = phase;
    out.push_back(walk_to(s, walk));
  }
  return out;
}

double DugdalePath::depth_slope(double s) const {
  const int phase = phase_of(s);
  return slope([&](double x) { return in_phase(phase, x).indentation; }, s, step_of(phase));
}

namespace {

/// A fold on the no-contact branch, bracketed in [s_lo, s_hi]: the root of dv/dc = a_u (f'(c)
/// - 4 sigma_0/(pi E*)) - a_F 2 pi sigma_0 c, free of the -h0 in d that rounds a difference
/// quotient of d on the DMT side (where d barely moves about its fold); f' by central
/// differences of c 1e-6 and 2e-6 (second order: the fine root's error is a third of their gap).
std::optional<DugdaleFold> no_contact_fold(const DugdalePath& path, const AffineConstraint& control,
                                           double s_lo, double s_hi) {
  const Profile& profile = path.profile();
  const DugdaleLaw& law = path.law();
  const double pull = 4.0 * law.adhesive_stress / (kPi * law.effective_modulus);
  const auto root_with = [&](double relative) -> std::optional<double> {
    const auto dv = [&](double c) {
      const double h = relative * c;
      const double f_slope = (profile.shape(c + h) - profile.shape(c - h)) / (2.0 * h);
      return control.displacement_coefficient * (f_slope - pull) -
             control.force_coefficient * 2.0 * kPi * law.adhesive_stress * c;
    };
    const double c_hi = path.at(std::max(s_lo, DugdalePath::kClosing)).cohesive_radius;
    const double c_lo = path.at(s_hi).cohesive_radius;
    // Going down in c the value falls (dv/dc > 0) until the fold.
    if (!(dv(c_lo) < 0.0 && dv(c_hi) > 0.0)) return std::nullopt;
    return bracketed_root(dv, c_lo, c_hi);
  };
  const auto fine = root_with(1e-6);
  const auto coarse = root_with(2e-6);
  if (!fine || !coarse) return std::nullopt;
  DugdaleFold fold;
  fold.state = dugdale_free_state(profile, law, *fine);
  fold.s = DugdalePath::kClosing + std::log2(path.closing_radius() / *fine) / kFreeHalvings;
  const double coarse_force = dugdale_free_state(profile, law, *coarse).normal_force;
  fold.force_error =
      std::abs(fold.state.normal_force - coarse_force) / 3.0 +
      4.0 * std::numeric_limits<double>::epsilon() * std::abs(fold.state.normal_force);
  return fold;
}

}  // namespace

namespace {

/// The contact branch's samples for the fold scan: above a_g (a linear in s) and below it down
/// to a_t (a quadratic in s, as the path runs), then in the zone's angle up to 2^-8 of the
/// way from the closing point (its halvings, where the DMT side's folds sit).
constexpr int kFoldAboveGlued = 8;
constexpr int kFoldBranch = 16;
constexpr int kFoldAngle = 16;
constexpr int kFoldAngleHalvings = 4;

/// dv/da along the contact branch: positive while v falls with a, zero at a fold.
double control_slope(const AffineConstraint& control, const DugdaleSlopes& slopes) {
  return control.displacement_coefficient * slopes.indentation +
         control.force_coefficient * slopes.normal_force;
}

/// The radii from a_p down to a_t, each with its place s on the path.
struct BranchSample {
  double radius;
  double s;
};

std::vector<BranchSample> branch_samples(const DugdalePath& path) {
  const double a_p = path.preload_radius(), a_g = path.glued_radius();
  const double a_t = path.angle_state().contact_radius;
  std::vector<BranchSample> samples;
  if (a_p > a_g) {
    for (int k = 0; k < kFoldAboveGlued; ++k) {
      const double s = static_cast<double>(k) / kFoldAboveGlued;
      samples.push_back({a_p - s * (a_p - a_g), s});
    }
  }
  samples.push_back({a_g, 1.0});
  if (a_g > a_t) {
    for (int k = kFoldBranch - 1; k >= 0; --k) {
      const double u = static_cast<double>(k) / kFoldBranch;
      samples.push_back({a_t + (a_g - a_t) * u * u, 2.0 - u});
    }
  }
  return samples;
}

/// s on the path of a contact radius a in [a_t, a_p] (phases [0, 1] and [1, 2] inverted).
double s_of_radius(const DugdalePath& path, double a) {
  const double a_p = path.preload_radius(), a_g = path.glued_radius();
  const double a_t = path.angle_state().contact_radius;
  if (a >= a_g) return a_p > a_g ? std::clamp((a_p - a) / (a_p - a_g), 0.0, 1.0) : 1.0;
  if (!(a_g > a_t)) return 1.0;
  return 2.0 - std::sqrt(std::clamp((a - a_t) / (a_g - a_t), 0.0, 1.0));
}

/// The size of dv/da's terms at a state, times the cancellation's gain: dugdale_contact_slopes is
/// good to about eps times this, and slopes read at a Newton iterate (dugdale_sloped_contact_state)
/// to about the iterate's offset over the half-chord times this.
double slope_terms(const DugdaleLaw& law, const AffineConstraint& control,
                   const DugdaleState& state, const DugdaleSlopes& slopes, double half_chord) {
  const double a = state.contact_radius, t = state.angle, s = half_chord;
  const double z = law.zone_strain();
  // g'(a) and ds/da as the slopes hold them: dd/da = g'(a) - z ds/da.
  const double chord_slope = std::abs(slopes.half_chord);
  const double image_slope = std::abs(slopes.indentation + z * slopes.half_chord);
  const double terms =
      std::abs(control.displacement_coefficient) * (image_slope + z * chord_slope) +
      std::abs(control.force_coefficient) *
          (2.0 * law.effective_modulus * a * image_slope +
           4.0 * law.adhesive_stress * (a * t + (a + s * t) * chord_slope));
  return (1.0 + image_slope / (z * t)) * terms;
}

/// The error of F at a fold located as a root of dv/da between the radii lo and hi: the slope
/// is good to about eps (1 + g'(a)/((2 sigma_0/E*) t)) of its terms (dugdale_contact_slopes),
/// which moves its root by that over dv/da's rate (`slope_rate`, over the scan's bracket); F
/// moves by dF/da (`slopes`, the state's or the search's last) times that and the root's bracket.
double contact_fold_force_error(const DugdaleLaw& law, const AffineConstraint& control,
                                const DugdaleState& state, const DugdaleSlopes& slopes,
                                double bracket, double slope_rate) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double half_chord = state.cohesive_radius * std::sin(state.angle);
  const double noise = 16.0 * eps * slope_terms(law, control, state, slopes, half_chord);
  const double place = bracket + (slope_rate > 0.0 ? noise / slope_rate : 0.0);
  return std::abs(slopes.normal_force) * place + 4.0 * eps * std::abs(state.normal_force);
}

/// A slope read at a solve's last iterate: a scan and a root search trust its sign where it stands
/// this many times its error (the offset's share of its terms times the cancellation's gain) from
/// zero, else read the state's own slopes (the error's factor is at most 1.33 over the zone
/// tests' profiles, stresses and radii: DugdaleZone.SlopesAtTheLastIterateAreTheStatesToItsOffset).
constexpr double kSlopeDoubt = 8.0;
/// An iterate this close to the root (over the half-chord) gives its slopes whatever their size:
/// there they are the state's to about the rounding the fold's error already counts (16 eps of
/// the terms), as they are once its guesses lie at its roots (a Newton step from the root itself
/// is a few ulps of the excess over its slope).
constexpr double kRootOffset = 32.0 * std::numeric_limits<double>::epsilon();

/// dv/da from a solve's last iterate where its sign is sure or the iterate is the root, else
/// nullopt.
std::optional<double> read_slope(const DugdaleLaw& law, const AffineConstraint& control,
                                 const DugdaleSlopedState& sloped) {
  if (!std::isfinite(sloped.offset)) return std::nullopt;
  const DugdaleState& st = sloped.state;
  const double chord = sloped.half_chord;
  const double value = control_slope(control, sloped.slopes);
  if (sloped.offset <= kRootOffset * chord) return value;
  const double doubt = kSlopeDoubt *
                       (sloped.offset / chord + std::numeric_limits<double>::epsilon()) *
                       slope_terms(law, control, st, sloped.slopes, chord);
  if (std::abs(value) > doubt) return value;
  return std::nullopt;
}

/// The first fold on the contact branch from a_p down to the closing point (s in [0, 3)).
std::optional<DugdaleFold> contact_branch_fold(const DugdalePath& path,
                                               const AffineConstraint& control) {
  const Profile& profile = path.profile();
  const DugdaleLaw& law = path.law();
  const double eps = std::numeric_limits<double>::epsilon();
  DugdaleBranchWalk walk(profile, law);
  // dv/da at a radius: from the solve's last iterate where its sign is sure (TOMS 748 keeps its
  // bracket by signs: a value off by less than itself only slows it) or the iterate is the root
  // to rounding, else from the state's own slopes (one gap integral more).
  DugdaleSlopes last_slopes;
  const auto sign_read = [&](const DugdaleSlopedState& sloped) {
    return read_slope(law, control, sloped).has_value();
  };
  const auto slope_at_radius = [&](double a) {
    const DugdaleSlopedState sloped = walk.sloped_at(a, sign_read);
    if (const auto value = read_slope(law, control, sloped)) {
      last_slopes = sloped.slopes;
      return *value;
    }
    last_slopes = dugdale_contact_slopes(profile, law, sloped.state);
    return control_slope(control, last_slopes);
  };
  const std::vector<BranchSample> samples = branch_samples(path);
  double above = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double here = slope_at_radius(samples[k].radius);
    if (here > 0.0) {
      above = here;
      continue;
    }
    if (k == 0) {  // v rises from the start: the corner s = 0
      DugdaleFold fold{.s = 0.0, .state = path.at(0.0), .force_error = 0.0};
      fold.force_error = 4.0 * eps * std::abs(fold.state.normal_force);
      return fold;
    }
    const double lo = samples[k].radius, hi = samples[k - 1].radius;
    const RootBracket root = bracket_root(slope_at_radius, lo, hi, here, above);
    const double a = 0.5 * (root.lo + root.hi);
    const DugdaleSlopes search_slopes = last_slopes;
    DugdaleFold fold{.s = s_of_radius(path, a), .state = walk.at(a), .force_error = 0.0};
    fold.force_error = contact_fold_force_error(law, control, fold.state, search_slopes,
                                                root.hi - root.lo, (above - here) / (hi - lo));
    return fold;
  }
  // On in the zone's angle, s from 2 (a_t) towards the closing point.
  ContinuedGuess angle_walk;  // the scan's and the root search's zones, in the angle
  const auto slope_at_s = [&](double s, DugdaleState* state) {
    const DugdaleSlopedState sloped = path.sloped_walk_to(s, angle_walk, sign_read);
    if (state != nullptr) *state = sloped.state;
    if (const auto value = read_slope(law, control, sloped)) {
      last_slopes = sloped.slopes;
      return *value;
    }
    last_slopes = dugdale_contact_slopes(profile, law, sloped.state);
    return control_slope(control, last_slopes);
  };
  const auto root_slope_at_s = [&](double s) { return slope_at_s(s, nullptr); };
  double s_above = 2.0;
  double a_above = path.angle_state().contact_radius;
  std::vector<double> gaps;
  for (int k = kFoldAngle - 1; k >= 1; --k) gaps.push_back(static_cast<double>(k) / kFoldAngle);
  for (int k = 1; k <= kFoldAngleHalvings; ++k) gaps.push_back(std::ldexp(gaps.back(), -1));
  for (const double gap : gaps) {
    const double s = DugdalePath::kClosing - gap;
    DugdaleState state;
    const double here = slope_at_s(s, &state);
    if (here > 0.0) {
      above = here;
      s_above = s;
      a_above = state.contact_radius;
      continue;
    }
    const RootBracket root = bracket_root(root_slope_at_s, s_above, s, above, here);
    const double at = 0.5 * (root.lo + root.hi);
    const DugdaleSlopes search_slopes = last_slopes;
    DugdaleFold fold{.s = at, .state = path.walk_to(at, angle_walk), .force_error = 0.0};
    // The root's bracket in the radius: its width in s at the scan's da/ds there.
    const double radius_rate = std::abs(a_above - state.contact_radius) / (s - s_above);
    fold.force_error = contact_fold_force_error(
        law, control, fold.state, search_slopes, radius_rate * (root.hi - root.lo),
        (above - here) / std::abs(a_above - state.contact_radius));
    return fold;
  }
  return std::nullopt;
}

/// The first fold from the closing point on (s in [3, 4]): v sampled, Brent about the first
/// rise, the closing point where that is its corner, else the no-contact branch's root of dv/dc.
std::optional<DugdaleFold> closing_or_free_fold(const DugdalePath& path,
                                                const AffineConstraint& control) {
  const auto value_at = [&](double s) {
    const DugdaleState st = path.at(s);
    return control.displacement_coefficient * st.indentation +
           control.force_coefficient * st.normal_force;
  };
  std::vector<double> samples;
  for (int k = 0; k <= kFreeSamples; ++k) {
    samples.push_back(DugdalePath::kClosing + static_cast<double>(k) / kFreeSamples);
  }
  double before = value_at(samples[0]);
  for (std::size_t k = 1; k < samples.size(); ++k) {
    const double here = value_at(samples[k]);
    if (here <= before) {
      before = here;
      continue;
    }
    const double lo = samples[k >= 2 ? k - 2 : 0];
    const double hi = samples[k];
    double s = brent_minimum(value_at, lo, hi);
    if (lo == DugdalePath::kClosing && s - lo < kCornerWidth) s = DugdalePath::kClosing;
    if (s == DugdalePath::kClosing) {
      DugdaleFold fold{.s = s, .state = path.at(s), .force_error = 0.0};
      fold.force_error =
          4.0 * std::numeric_limits<double>::epsilon() * std::abs(fold.state.normal_force);
      return fold;
    }
    if (auto zone_fold = no_contact_fold(path, control, lo, hi)) return *zone_fold;
    // Brent's place to sqrt(eps) of the bracket: the force moves by F' times that.
    DugdaleFold fold{.s = s, .state = path.at(s), .force_error = 0.0};
    const double d = std::sqrt(std::numeric_limits<double>::epsilon()) * (hi - lo);
    fold.force_error =
        std::max(std::abs(path.at(s + d).normal_force - fold.state.normal_force),
                 std::abs(path.at(s - d).normal_force - fold.state.normal_force)) +
        4.0 * std::numeric_limits<double>::epsilon() * std::abs(fold.state.normal_force);
    return fold;
  }
  return std::nullopt;
}

}  // namespace

std::optional<DugdaleFold> first_fold(const DugdalePath& path, const AffineConstraint& control) {
  if (auto fold = contact_branch_fold(path, control)) return fold;
  return closing_or_free_fold(path, control);
}

DugdaleFold most_tensile(const DugdalePath& path, double s_end) {
  std::vector<double> samples;
  for (const double s : sample_parameters()) {
    if (s < s_end) samples.push_back(s);
  }
  samples.push_back(s_end);
  std::size_t best = 0;
  double best_force = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double f = path.at(samples[k]).normal_force;
    if (f < best_force) {
      best_force = f;
      best = k;
    }
  }
  const auto force = [&](double s) { return path.at(s).normal_force; };
  const double lo = samples[best > 0 ? best - 1 : 0];
  const double hi = samples[std::min(best + 1, samples.size() - 1)];
  double s = hi > lo ? brent_minimum(force, lo, hi) : lo;
  if (force(s_end) <= force(s)) s = s_end;
  DugdaleFold peak{.s = s, .state = path.at(s), .force_error = 0.0};
  // A minimum of F: Brent's sqrt(eps) in s costs F'' s^2 / 2, bounded by the neighbours' rise.
  const double d = std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(hi - lo, 1e-300);
  if (s != s_end && s > d) {
    peak.force_error = std::max(std::abs(force(s + d) - peak.state.normal_force),
                                std::abs(force(s - d) - peak.state.normal_force));
  }
  peak.force_error +=
      4.0 * std::numeric_limits<double>::epsilon() * std::abs(peak.state.normal_force);
  return peak;
}

double path_work(const DugdalePath& path, double s0, double s1, double& error) {
  double total = 0.0;
  for (int phase = 0; phase <= kFreePhase; ++phase) {
    const double lo = std::max(s0, static_cast<double>(phase));
    const double hi = std::min(s1, static_cast<double>(phase + 1));
    if (!(hi > lo)) continue;
    double err = 0.0;
    double l1 = 0.0;
    const double width = hi - lo;
    const auto integrand = [&](double u) {
      const double s = lo + width * u;
      return path.at(s).normal_force * path.depth_slope(s);
    };
    const double value = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
        integrand, 0.0, 1.0, 8, 1e-10, &err, &l1);
    total += width * value;
    // The quadrature's estimate, and the difference quotient's ~1e-11 of |F d'|.
    error += width * (err + 1e-11 * l1);
  }
  return total;
}

ContactSnapshot dugdale_snapshot(const DugdaleState& s, const AffineConstraint& normal) {
  ContactSnapshot c;
  c.indentation = s.indentation;
  c.normal_force = s.normal_force;
  c.contact_radius = s.contact_radius;
  c.cohesive_radius = s.cohesive_radius;
  c.normal_control =
      normal.displacement_coefficient * s.indentation + normal.force_coefficient * s.normal_force;
  return c;
}

}  // namespace mdrsim
