// Finite-range adhesion in the MDR (Maugis-Dugdale): the contact and no-contact branches.
#include "engine/model/dugdale_zone.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "engine/base/bracketed_root.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

/// The zone at its half-chord s = sqrt(c^2 - a^2) [m] for a contact of radius a [m].
struct Zone {
  double angle;            ///< t = arccos(a/c) = atan2(s, a) [rad]
  double cohesive_radius;  ///< c [m]
};

Zone zone_at(double a, double s) { return {std::atan2(s, a), std::hypot(a, s)}; }

/// The zone's opening less h0 [m] at the half-chord s, and its slope in s at fixed a [1].
struct Opening {
  double excess;
  double slope;
};

/// The opening at the zone (t, c) of half-chord s from its gap integral.
Opening opening_of(const DugdaleLaw& law, double a, double s, double t, double c,
                   const DugdaleGap& gap) {
  // s t - (c - a) with c - a = s^2/(c + a); d/ds with dt/ds = a/c^2 and dc/ds = s/c.
  const double stretch = s * t - s * s / (c + a);
  const double stretch_slope = t - s * s * s / (c * c * (c + a));
  const double z = law.zone_strain();
  return {.excess = (2.0 / kPi) * (gap.integral + z * stretch) - law.range(),
          .slope = (2.0 / kPi) * (gap.angle_slope * a / (c * c) + z * stretch_slope)};
}

Opening opening(const Profile& profile, const DugdaleLaw& law, double a, double s) {
  const auto [t, c] = zone_at(a, s);
  return opening_of(law, a, s, t, c, profile.dugdale_gap(a, c, t));
}

/// A first half-chord from the opening's leading terms at small t, (2/pi)(g'(a) a t^3/3 +
/// (2 sigma_0/E*) a t^2/2) = h0: that cubic's root, which lies at or above the zone's own where
/// the omitted terms are positive (convex profiles), so that Newton's steps on a convex opening
/// fall onto the root from above. Where it is wide (t > 1), the cubic says nothing: the zone of
/// a contact closing onto the no-contact branch, whose c0 lies below h0 / ((2 sigma_0/E*)(1 -
/// 2/pi)) where the profile rises from its tip (dugdale_closing_radius).
double first_half_chord(const Profile& profile, const DugdaleLaw& law, double a) {
  const double z = law.zone_strain(), h0 = law.range();
  const double quadratic = z * a / kPi;
  const double cubic = 2.0 * profile.mdr_image_slope(a) * a / (3.0 * kPi);
  double t = std::sqrt(h0 / quadratic);
  if (cubic > 0.0 && std::isfinite(cubic)) {
    t = std::min(t, std::cbrt(h0 / cubic));
    for (int i = 0; i < 3; ++i) {  // convex and rising: from above, each step stays above
      t -= ((cubic * t + quadratic) * t * t - h0) / ((3.0 * cubic * t + 2.0 * quadratic) * t);
    }
  }
  if (t < 1.0) return a * std::tan(t);
  return std::max(a * std::tan(1.0), h0 / (z * (1.0 - 2.0 / kPi)));
}

}  // namespace

DugdaleSlopes dugdale_slopes_at_zone(const Profile& profile, const DugdaleLaw& law, double a,
                                     double s, double c, double t, const DugdaleGap& gap) {
  const double z = law.zone_strain(), image_slope = profile.mdr_image_slope(a);
  // At fixed s: dc/da = a/c, dt/da = -s/c^2; dJ/da = -g'(a) t (the lower limit, at fixed c)
  // + (dJ/dt)/(dc/dt) a/c with dc/dt = c tan t = c s/a; d(s t - (c - a))/da = -a (c - a)/c^2.
  const double opening_a = -image_slope * t + gap.angle_slope * a * a / (c * c * s) -
                           z * a * (s * s / (c + a)) / (c * c);
  const double opening_s = gap.angle_slope * a / (c * c) + z * (t - s * s * s / (c * c * (c + a)));
  const double chord_slope = -opening_a / opening_s;  // ds/da (the factor 2/pi cancels)
  // F = E* nf(a) - 2 sigma_0 (a s + c^2 t): dF/da at fixed s = 2 E* a g'(a) - 4 sigma_0 a t,
  // dF/ds = -4 sigma_0 (a + s t); d = g(a) - (2 sigma_0/E*) s.
  return {.indentation = image_slope - z * chord_slope,
          .normal_force = 2.0 * law.effective_modulus * a * image_slope -
                          4.0 * law.adhesive_stress * (a * t + (a + s * t) * chord_slope),
          .half_chord = chord_slope};
}

namespace {

/// The contact branch at a [m] by Newton's steps from the half-chord `first` [m]; `sloped`, where
/// given, gains the slopes at the last iterate's zone, whose gap integral the steps have read.
DugdaleState contact_state_from(const Profile& profile, const DugdaleLaw& law, double a,
                                double first, DugdaleSlopedState* sloped = nullptr,
                                const SlopedEnough& enough = {}) {
  // Newton in the half-chord s, which follows the zone on both sides: s = a tan t where it is
  // thin (t, and so s, to full precision) and s -> c where it is wide, where t -> pi/2 and the
  // opening's slope in t grows like sec^2 t. The steps are kept inside a bracket [lo, hi] of
  // the root: the opening is -h0 at s = 0; the widest zone the profile allows (c at its outer
  // radius) is read only when a step would leave the bracket before a point past the root is
  // known (a sphere's image diverges there).
  const double outer = profile.outer_radius();
  // A contact at or past the body's edge has no zone outside it (a sphere's image there is
  // not the body's): refused before the opening is read.
  if (!(a < outer)) {
    throw std::domain_error("the cohesive zone reaches beyond the profile's outer radius");
  }
  const double widest = std::isfinite(outer) ? std::sqrt((outer - a) * (outer + a))
                                             : std::numeric_limits<double>::infinity();
  double lo = 0.0, hi = widest;
  bool hi_known = false;
  double s = std::min(first, 0.5 * widest);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const auto [t, c] = zone_at(a, s);
    const DugdaleGap gap = profile.dugdale_gap(a, c, t);
    const Opening o = opening_of(law, a, s, t, c, gap);
    if (o.excess < 0.0) {
      lo = s;
    } else {
      hi = s;
      hi_known = true;
    }
    double next = s - o.excess / o.slope;
    if (enough && next > lo && next < hi) {  // a caller content with this iterate's slopes
      // The zone alone (a, c, t) for `enough`; d and F once it is content.
      const auto [t_next, c_next] = zone_at(a, next);
      DugdaleSlopedState here{
          .state = {.contact_radius = a, .cohesive_radius = c_next, .angle = t_next},
          .slopes = dugdale_slopes_at_zone(profile, law, a, s, c, t, gap),
          .offset = std::abs(next - s),
          .half_chord = next};
      if (enough(here)) {
        here.state = dugdale_contact_state_of_zone(profile, law, a, next, c_next, t_next);
        *sloped = here;
        return here.state;
      }
    }
    // Quadratic convergence: the step left is about (s O''/2O') 1e-18 s. A step onto the
    // bracket's end from a start at the root (a walk's exact guess, whose excess rounds to zero)
    // is converged too, not a step to bisect.
    if (std::abs(next - s) <= 1e-9 * s && next >= lo && next <= hi) {
      if (sloped != nullptr) {
        sloped->slopes = dugdale_slopes_at_zone(profile, law, a, s, c, t, gap);
        sloped->offset = std::abs(next - s);
      }
      s = next;
      break;
    }
    if (!(next > lo && next < hi)) {
      if (!hi_known && std::isfinite(hi)) {
        if (opening(profile, law, a, hi).excess < 0.0) {
          throw std::domain_error("the cohesive zone reaches beyond the profile's outer radius");
        }
        hi_known = true;
      }
      next = hi_known ? 0.5 * (lo + hi) : 2.0 * std::max(s, lo);
    }
    s = next;
    if (hi_known && hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) break;
  }
  const auto [t, c] = zone_at(a, s);
  const DugdaleState state = dugdale_contact_state_of_zone(profile, law, a, s, c, t);
  if (sloped != nullptr) {
    sloped->state = state;
    sloped->half_chord = s;
  }
  return state;
}

}  // namespace

DugdaleState dugdale_contact_state_of_zone(const Profile& profile, const DugdaleLaw& law, double a,
                                           double s, double c, double t) {
  return {.contact_radius = a,
          .cohesive_radius = c,
          .angle = t,
          .indentation = profile.mdr_image(a) - law.zone_strain() * s,
          .normal_force = law.effective_modulus * profile.nonadhesive_force_per_modulus(a) -
                          2.0 * law.adhesive_stress * (a * s + c * c * t)};
}

DugdaleState dugdale_contact_state(const Profile& profile, const DugdaleLaw& law, double a) {
  return contact_state_from(profile, law, a, first_half_chord(profile, law, a));
}

DugdaleState dugdale_contact_state(const Profile& profile, const DugdaleLaw& law, double a,
                                   double half_chord_guess) {
  if (!(half_chord_guess > 0.0) || !std::isfinite(half_chord_guess)) {
    return dugdale_contact_state(profile, law, a);
  }
  return contact_state_from(profile, law, a, half_chord_guess);
}

double ContinuedGuess::at(double x) const {
  if (known_ == 0) return 0.0;
  if (known_ >= 2 && std::isfinite(slope_[0]) && std::isfinite(slope_[1])) {
    // The cubic Hermite in u = (x - x1)/h from the older x1 (beyond [0, 1] it extrapolates).
    const double h = x_[0] - x_[1], u = (x - x_[1]) / h;
    const double u2 = u * u, u3 = u2 * u;
    const double y = (2.0 * u3 - 3.0 * u2 + 1.0) * y_[1] + (u3 - 2.0 * u2 + u) * h * slope_[1] +
                     (3.0 * u2 - 2.0 * u3) * y_[0] + (u3 - u2) * h * slope_[0];
    if (y > 0.0 && std::isfinite(y)) return y;
  }
  std::array<double, kFit> p = y_;
  for (int level = 1; level < known_; ++level) {
    for (int i = 0; i + level < known_; ++i) {
      p[i] = ((x - x_[i + level]) * p[i] - (x - x_[i]) * p[i + 1]) / (x_[i] - x_[i + level]);
    }
  }
  if (!(p[0] > 0.0) || !std::isfinite(p[0])) return y_[0];
  return p[0];
}

void ContinuedGuess::add(double x, double y, double slope) {
  if (known_ > 0 && x_[0] == x) return;
  std::copy_backward(x_.begin(), x_.end() - 1, x_.end());
  std::copy_backward(y_.begin(), y_.end() - 1, y_.end());
  std::copy_backward(slope_.begin(), slope_.end() - 1, slope_.end());
  x_[0] = x;
  y_[0] = y;
  slope_[0] = slope;
  known_ = std::min(known_ + 1, kFit);
}

std::vector<DugdaleState> dugdale_contact_states(const Profile& profile, const DugdaleLaw& law,
                                                 std::span<const double> contact_radii) {
  std::vector<DugdaleState> states;
  states.reserve(contact_radii.size());
  // The half-chords of the last zones with their slopes ds/da, read at each solve's last iterate
  // (its gap integral already taken): the cubic Hermite through the last two, a guess that, on
  // a curve of close radii, lies inside Newton's 1e-9, so that one step ends most solves.
  ContinuedGuess chords;
  for (const double a : contact_radii) {
    double first = chords.at(a);
    if (!(first > 0.0)) first = first_half_chord(profile, law, a);
    DugdaleSlopedState sloped;
    sloped.offset = std::numeric_limits<double>::infinity();
    contact_state_from(profile, law, a, first, &sloped);
    states.push_back(sloped.state);
    chords.add(a, sloped.half_chord,
               std::isfinite(sloped.offset) ? sloped.slopes.half_chord
                                            : std::numeric_limits<double>::quiet_NaN());
  }
  return states;
}

DugdaleSlopes dugdale_contact_slopes(const Profile& profile, const DugdaleLaw& law,
                                     const DugdaleState& state) {
  const double a = state.contact_radius, c = state.cohesive_radius, t = state.angle;
  const double s = c * std::sin(t);
  return dugdale_slopes_at_zone(profile, law, a, s, c, t, profile.dugdale_gap(a, c, t));
}

DugdaleSlopedState dugdale_sloped_contact_state(const Profile& profile, const DugdaleLaw& law,
                                                double a, double half_chord_guess,
                                                const SlopedEnough& enough) {
  const double first = half_chord_guess > 0.0 && std::isfinite(half_chord_guess)
                           ? half_chord_guess
                           : first_half_chord(profile, law, a);
  DugdaleSlopedState sloped;
  sloped.offset = std::numeric_limits<double>::infinity();
  contact_state_from(profile, law, a, first, &sloped, enough);
  return sloped;
}

DugdaleState dugdale_free_state(const Profile& profile, const DugdaleLaw& law, double c) {
  return {.contact_radius = 0.0,
          .cohesive_radius = c,
          .angle = 0.5 * kPi,
          .indentation = profile.shape(c) - 2.0 / kPi * law.zone_strain() * c - law.range(),
          .normal_force = -kPi * law.adhesive_stress * c * c};
}

double dugdale_closing_radius(const Profile& profile, const DugdaleLaw& law) {
  const double g0 = profile.mdr_image(0.0);
  const double pull = law.zone_strain() * (1.0 - 2.0 / kPi);
  const auto excess = [&](double c) { return profile.shape(c) - g0 + pull * c - law.range(); };
  double hi = law.range() / pull;  // f >= g(0): the root lies at or below the zone's own term
  const double outer = profile.outer_radius();
  if (std::isfinite(outer)) hi = std::min(hi, outer);
  if (excess(hi) < 0.0) {
    throw std::domain_error("the cohesive zone reaches beyond the profile's outer radius");
  }
  return bracket_root(excess, 0.0, hi, std::numeric_limits<double>::digits - 2).hi;
}

}  // namespace mdrsim
