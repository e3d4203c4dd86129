// Finite-range adhesion in the MDR (Maugis-Dugdale): the contact and no-contact branches.
#include "engine/model/dugdale_zone.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "engine/base/angle_series.hpp"
#include "engine/base/bracketed_root.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

/// The zone's opening less h0 at the angle t of a contact of radius a [m].
double opening_excess(const Profile& profile, const DugdaleLaw& law, double a, double t) {
  const double cos_t = std::cos(t);
  const double c = a / cos_t;
  // s t - (c - a) = a (t tan t - (sec t - 1)), with sec t - 1 = 2 sin^2(t/2) / cos t.
  const double half = std::sin(0.5 * t);
  const double stretch_term = a * (t * std::tan(t) - 2.0 * half * half / cos_t);
  return (2.0 / kPi) * (profile.dugdale_gap_integral(a, c, t) + law.zone_strain() * stretch_term) -
         law.range();
}

}  // namespace

DugdaleState dugdale_contact_state(const Profile& profile, const DugdaleLaw& law, double a) {
  // The widest angle the profile allows: c = a / cos t within its outer radius.
  const double outer = profile.outer_radius();
  const double top = std::isfinite(outer)
                         ? std::acos(std::min(1.0, a / outer))
                         : 0.5 * kPi * (1.0 - 4.0 * std::numeric_limits<double>::epsilon());
  // Bracket from below: t doubles from a small start until the opening exceeds h0.
  double lo = 0.0;
  double hi = std::min(top, 1e-3);
  while (opening_excess(profile, law, a, hi) < 0.0) {
    if (hi >= top) {
      throw std::domain_error("the cohesive zone reaches beyond the profile's outer radius");
    }
    lo = hi;
    hi = std::min(top, 2.0 * hi);
  }
  const double t = bracket_root([&](double x) { return opening_excess(profile, law, a, x); }, lo,
                                hi, std::numeric_limits<double>::digits - 2)
                       .hi;
  const double c = a / std::cos(t);
  const double s = c * std::sin(t);
  return {.contact_radius = a,
          .cohesive_radius = c,
          .angle = t,
          .indentation = profile.mdr_image(a) - law.zone_strain() * s,
          .normal_force = law.effective_modulus * profile.nonadhesive_force_per_modulus(a) -
                          2.0 * law.adhesive_stress * (a * s + c * c * t)};
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
