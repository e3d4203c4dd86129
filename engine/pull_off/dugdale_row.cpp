// The spring row's Maugis-Dugdale pull-off: O(1) let-go events, the fold between springs, and
// the no-contact branch once the contact has closed.
#include "engine/pull_off/dugdale_row.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "engine/base/bracketed_root.hpp"
#include "engine/model/compensated_sum.hpp"
#include "engine/model/fold_refinement.hpp"
#include "engine/model/machine_work.hpp"
#include "engine/model/spring_foundation.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

/// The zone's opening less h0 at the angle t = arccos(a/c) of a contact of radius a [m] whose
/// edge holds (d = g(a) - (2 sigma_0/E*) s): the sum of K(a, c) = int_a^c (g - g(a))/sqrt(c^2 -
/// x^2) dx and the line load's own term (2 sigma_0/E*)(s t - (c - a)), times 2/pi.
double opening_excess(const Profile& profile, const DugdaleLaw& law, double a, double t) {
  const double cos_t = std::cos(t);
  const double c = a / cos_t;
  // s t - (c - a) = a (t tan t - (sec t - 1)), with sec t - 1 = 2 sin^2(t/2) / cos t.
  const double half = std::sin(0.5 * t);
  const double stretch_term = a * (t * std::tan(t) - 2.0 * half * half / cos_t);
  return (2.0 / kPi) * (profile.dugdale_gap_integral(a, c, t) + law.zone_strain() * stretch_term) -
         law.range();
}

/// The angle t at each let-go, for contact radii falling by dx from one call to the next: the
/// last three angles extrapolated (error O(dx^3)), then secant steps with the last slope
/// de/dt, which changes by O(dx) per spring. At 1e5 springs one evaluation of the opening
/// usually settles t to 1e-13; anything odd (a step out of (0, t_max), a slope that is not
/// positive, no convergence in a few steps) falls back to the bracketed solve of the zone.
class LetGoAngle {
 public:
  LetGoAngle(const Profile& profile, const DugdaleLaw& law, DugdaleRowCounts& counts)
      : profile_(profile), law_(law), counts_(counts) {}

  double at(double a) {
    const std::optional<double> warm = known_ == 3 ? secant(a) : std::nullopt;
    const double t = warm ? *warm : bracketed(a);
    history_ = {t, history_[0], history_[1]};
    known_ = std::min(3, known_ + 1);
    return t;
  }

 private:
  double excess(double a, double t) {
    ++counts_.opening_evaluations;
    return opening_excess(profile_, law_, a, t);
  }

  double bracketed(double a) {
    ++counts_.bracketed_solves;
    const double t = dugdale_contact_state(profile_, law_, a).angle;
    // The slope at the root by a central difference, for the secant steps that follow.
    const double h = 1e-6 * t;
    slope_ = (excess(a, t + h) - excess(a, t - h)) / (2.0 * h);
    return t;
  }

  std::optional<double> secant(double a) {
    const double outer = profile_.outer_radius();
    const double top = std::isfinite(outer) ? std::acos(std::min(1.0, a / outer))
                                            : 0.5 * kPi * (1.0 - 4.0 * kEpsilon);
    const auto inside = [&](double t) { return t > 0.0 && t < top; };
    double t0 = 3.0 * history_[0] - 3.0 * history_[1] + history_[2];
    if (!inside(t0) || !(slope_ > 0.0)) return std::nullopt;
    double e0 = excess(a, t0);
    double slope = slope_;
    for (int step = 0; step < 6; ++step) {
      if (e0 == 0.0) return t0;
      const double t1 = t0 - e0 / slope;
      if (!inside(t1)) return std::nullopt;
      // The step left is the last one times the slope's relative error: below 1e-13 of t here.
      if (std::abs(t1 - t0) <= 1e-13 * t1) return t1;
      const double e1 = excess(a, t1);
      const double secant_slope = (e1 - e0) / (t1 - t0);
      if (!(secant_slope > 0.0)) return std::nullopt;
      slope = secant_slope;
      slope_ = secant_slope;
      t0 = t1;
      e0 = e1;
    }
    return std::nullopt;
  }

  const Profile& profile_;
  const DugdaleLaw& law_;
  DugdaleRowCounts& counts_;
  std::array<double, 3> history_{};  ///< the last three angles, the latest first [rad]
  int known_ = 0;
  double slope_ = 0.0;  ///< de/dt at the last let-go [m/rad]
};

/// An equilibrium of the row with the machine's held value there.
struct Held {
  DugdaleRowState state;
  double control = 0.0;  ///< a_u d + a_F F [m or N]
};

double control_of(const AffineConstraint& normal, const DugdaleRowState& s) {
  return normal.displacement_coefficient * s.indentation +
         normal.force_coefficient * s.normal_force;
}

/// The state at s on the parabolas through the let-gos at n - 1 (inner), n and n + 1 (outer):
/// the row's branch between springs, in n, where every quantity is smooth.
DugdaleRowState between_springs(const DugdaleRowState& inner, const DugdaleRowState& at,
                                const DugdaleRowState& outer, double s) {
  return {.springs_in_contact = at.springs_in_contact,
          .contact_radius =
              quadratic_through(inner.contact_radius, at.contact_radius, outer.contact_radius, s),
          .cohesive_radius = quadratic_through(inner.cohesive_radius, at.cohesive_radius,
                                               outer.cohesive_radius, s),
          .indentation = quadratic_through(inner.indentation, at.indentation, outer.indentation, s),
          .normal_force =
              quadratic_through(inner.normal_force, at.normal_force, outer.normal_force, s)};
}

/// The smallest of `value` over the let-gos n - 1, n, n + 1, between springs: the vertex of
/// their parabola (the row's fold or peak); the let-go at n itself without an outer one.
template <class Value>
DugdaleRowState vertex(const std::optional<Held>& outer, const Held& at, const Held& inner,
                       Value value) {
  if (!outer) return at.state;
  const std::optional<double> s = parabola_vertex(value(inner), value(at), value(*outer));
  return s ? between_springs(inner.state, at.state, outer->state, *s) : at.state;
}

/// The no-contact branch: the zone's disk alone, in closed form (its cells' loads sum to
/// -pi sigma_0 c^2, its opening is f(c) - d - 4 sigma_0 c/(pi E*) with no spring in it).
DugdaleRowState free_state(const Profile& profile, const DugdaleLaw& law, double c) {
  const DugdaleState s = dugdale_free_state(profile, law, c);
  return {.springs_in_contact = 0,
          .contact_radius = 0.0,
          .cohesive_radius = c,
          .indentation = s.indentation,
          .normal_force = s.normal_force};
}

/// d(control)/dc along the no-contact branch [m/m or N/m]: a_u (f'(c) - 4 sigma_0/(pi E*)) -
/// a_F 2 pi sigma_0 c; the path goes on down c while it is positive.
double free_slope(const Profile& profile, const DugdaleLaw& law, const AffineConstraint& normal,
                  double c) {
  const double h = 1e-6 * c;  // f' by a central difference: f is smooth away from r = 0
  const double depth_slope = (profile.shape(c + h) - profile.shape(c - h)) / (2.0 * h) -
                             4.0 * law.adhesive_stress / (kPi * law.effective_modulus);
  return normal.displacement_coefficient * depth_slope -
         normal.force_coefficient * 2.0 * kPi * law.adhesive_stress * c;
}

}  // namespace

DugdaleRowResult run_dugdale_row(const Profile& profile, const DugdaleLaw& law,
                                 const DugdaleRowSpec& spec) {
  if (!(law.adhesive_stress > 0.0) || !(law.work_of_adhesion > 0.0) ||
      !(law.effective_modulus > 0.0)) {
    throw std::invalid_argument("the Dugdale law needs a positive stress, work and modulus");
  }
  const SpringFoundation foundation(profile, spec.glued_radius, spec.springs);
  const AffineConstraint& normal = spec.normal;
  DugdaleRowResult result;
  LetGoAngle angle(profile, law, result.counts);
  const double zone_strain = law.zone_strain();
  const double two_k = 2.0 * law.effective_modulus * foundation.spacing();  // both halves' k_z
  CompensatedSum images;  // sum of g_i over the springs in contact
  images.add(foundation.total_image());

  // The let-go of spring n, with images holding its contact's sum.
  const auto let_go = [&](std::int64_t n) {
    const double a = foundation.position(n);
    const double t = angle.at(a);
    const double c = a / std::cos(t);
    const double s = a * std::tan(t);
    const double d = foundation.image(n) - zone_strain * s;
    const double force = two_k * (static_cast<double>(n) * d - images.value()) -
                         2.0 * law.adhesive_stress * (c * c * t - a * s);
    const DugdaleRowState state{.springs_in_contact = n,
                                .contact_radius = a,
                                .cohesive_radius = c,
                                .indentation = d,
                                .normal_force = force};
    return Held{state, control_of(normal, state)};
  };
  const auto force_of = [](const Held& h) { return h.state.normal_force; };
  const auto held_of = [](const Held& h) { return h.control; };
  const auto point_of = [&](const DugdaleRowState& s) {
    return AxisPoint{s.normal_force, driving_point(normal, control_of(normal, s), s.indentation)};
  };
  const auto add_work = [&](const DugdaleRowState& from, const DugdaleRowState& to) {
    result.work += trapezoid_work(point_of(from), point_of(to));
  };
  if (spec.record_path) result.path.reserve(static_cast<std::size_t>(spec.springs) + 3);

  std::optional<Held> outer;
  Held at = let_go(spec.springs);
  result.first = at.state;
  double lowest = std::numeric_limits<double>::infinity();  // the smallest F at a let-go [N]
  for (;;) {
    if (spec.record_path) result.path.push_back(at.state);
    ++result.counts.events;
    if (at.state.springs_in_contact == 1) {
      if (at.state.normal_force < lowest) result.peak = at.state;
      break;
    }
    if (result.counts.events >= spec.max_events) {
      if (at.state.normal_force < lowest) result.peak = at.state;
      result.critical = at.state;
      result.instability = false;
      result.event_limit = true;
      return result;
    }
    images.add(-foundation.image(at.state.springs_in_contact));
    const Held inner = let_go(at.state.springs_in_contact - 1);
    if (at.state.normal_force < lowest) {
      lowest = at.state.normal_force;
      result.peak = vertex(outer, at, inner, force_of);
    }
    // Due at the held value (a cascade), up to rounding of the two control values.
    const double tolerance =
        4.0 * kEpsilon * std::max(std::abs(at.control), std::abs(inner.control));
    if (inner.control >= at.control - tolerance) {
      result.critical = vertex(outer, at, inner, held_of);
      result.instability = true;
      add_work(at.state, result.critical);
      return result;
    }
    add_work(at.state, inner.state);
    outer = at;
    at = inner;
  }

  // The last spring has let go: the path joins the no-contact branch at the closing radius c0
  // where the control still falls along it going down c, and jumps from the last let-go where
  // it does not (fixed load: F = -pi sigma_0 c^2 only rises as c shrinks).
  const double closing = dugdale_closing_radius(profile, law);
  const auto slope = [&](double c) { return free_slope(profile, law, normal, c); };
  if (!(slope(closing) > 0.0)) {
    result.critical = at.state;
    result.instability = true;
    return result;
  }
  const DugdaleRowState closed = free_state(profile, law, closing);
  if (spec.record_path) result.path.push_back(closed);
  add_work(at.state, closed);
  result.no_contact_start = closing;
  if (closed.normal_force < result.peak.normal_force) result.peak = closed;
  // Down from c0 while the control falls: the first c where it turns, on a geometric scan to
  // 1e-12 of c0, below which the zone carries nothing a force could show.
  double above = closing;
  for (int k = 1; k <= 8 * 40; ++k) {
    const double c = closing * std::exp2(-k / 8.0);
    if (!(slope(c) > 0.0)) {
      result.critical = free_state(profile, law, bracketed_root(slope, c, above));
      result.instability = true;
      if (spec.record_path) result.path.push_back(result.critical);
      return result;
    }
    above = c;
  }
  result.critical = free_state(profile, law, 0.0);
  result.instability = false;
  if (spec.record_path) result.path.push_back(result.critical);
  return result;
}

}  // namespace mdrsim
