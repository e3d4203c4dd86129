// The rate-law front's ODE on the continuum branch, in t while the front is slow and in a once
// it runs to the axis, with its peak and the stage's end located inside a step.
#include "engine/continuum/front_speed_walk.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>

// Odeint's steppers copy their scratch arrays, unset until the first step, when the controlled
// stepper is built; GCC at -O3 sees the copy of the unset std::array.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "engine/base/hess_scale.hpp"

namespace mdrsim {
namespace {

namespace odeint = boost::numeric::odeint;
// In the time walk (x, D, W), in the radius walk (s, D, W): x = a / l, s = (t - t0) / (l / v*),
// D and W the dissipation and the machine's work over dgamma l^2, l the starting radius.
using FrontVector = std::array<double, 3>;
using FrontStepper = odeint::runge_kutta_fehlberg78<FrontVector>;
constexpr long long kMaxFrontSteps = 10'000'000;

/// The walk's equations in the scaled variables.
class FrontEquations {
 public:
  FrontEquations(const ContinuumBranch& branch, const FrontSpeedLaw& law,
                 const FrontSpeedStart& start)
      : branch_(branch),
        law_(law),
        length_(start.radius),
        indentation0_(start.indentation),
        // dd/ds [m]: the grips' move per unit of scaled time.
        indentation_per_s_(start.rate * start.radius / law.speed),
        hess_per_radius_(
            hess_scale(branch.material().work_of_adhesion, branch.material().effective_modulus)),
        work_scale_(branch.material().work_of_adhesion * start.radius * start.radius) {}

  double indentation(double s) const { return indentation0_ + indentation_per_s_ * s; }
  /// e [m] (positive in tension) at x and d.
  double stretch(double x, double d) const { return branch_.image(length_ * x) - d; }
  /// G / dgamma - 1: e^2 / (2 pi a dgamma / E* a) - 1 in tension, -1 in compression.
  double excess(double x, double d) const {
    const double e = std::max(stretch(x, d), 0.0);
    // At the axis a stretched edge releases without bound; an unstretched one not at all.
    if (!(x > 0.0)) return e > 0.0 ? std::numeric_limits<double>::infinity() : -1.0;
    return e * e / (hess_per_radius_ * length_ * x) - 1.0;
  }
  /// v / v*.
  double speed(double x, double d) const {
    return law_.front_speed(excess(x, d) + 1.0) / law_.speed;
  }
  double force(double x, double d) const {
    return branch_.state(length_ * x, stretch(x, d)).normal_force;
  }
  /// dF/dt over 2 E* v* l, negative while the tension grows: x dd/ds / l - e / l dx/ds.
  double force_slope(double x, double d) const {
    return x * indentation_per_s_ / length_ + stretch(x, d) / length_ * speed(x, d);
  }
  /// The radius walk keeps G growing to the axis: the front runs, the grips do not press, and
  /// at fixed d G = E* e^2 / (2 pi a) grows as a falls (2 a g'(a) < e).
  bool runs_to_axis(double x, double d) const {
    const double a = length_ * x;
    return speed(x, d) >= 1.0 && indentation_per_s_ <= 0.0 &&
           2.0 * a * branch_.profile().mdr_image_slope(a) < stretch(x, d);
  }
  /// dW/ds over dgamma l^2 with the front speed q.
  double work_rate(double x, double d) const {
    return force(x, d) * indentation_per_s_ / work_scale_;
  }

  void in_time(const FrontVector& y, FrontVector& dy, double s) const {
    const double x = std::max(y[0], 0.0);
    const double d = indentation(s);
    const double q = speed(x, d);
    dy[0] = -q;
    dy[1] = q > 0.0 ? excess(x, d) * 2.0 * std::numbers::pi * x * q : 0.0;
    dy[2] = work_rate(x, d);
  }
  // (G / dgamma - 1) 2 pi x written as 2 pi e^2 / (hess l) - 2 pi x: finite at the axis.
  void in_radius(const FrontVector& y, FrontVector& dy, double x) const {
    const double d = indentation(y[0]);
    const double e = std::max(stretch(x, d), 0.0);
    const double excess_times = 2.0 * std::numbers::pi * (e * e / (hess_per_radius_ * length_) - x);
    if (!(excess_times > 0.0)) {
      // Only a trial stage of a step too long for a fast retraction gets here (along the walk G
      // grows as the front runs in): no number, so that the step is taken again shorter.
      dy.fill(std::numeric_limits<double>::quiet_NaN());
      return;
    }
    const double inverse_speed = x > 0.0 ? 1.0 / speed(x, d) : 0.0;
    dy[0] = -inverse_speed;
    dy[1] = -excess_times;
    dy[2] = -work_rate(x, d) * inverse_speed;
  }

  double length() const { return length_; }
  double time_scale() const { return length_ / law_.speed; }
  double work_scale() const { return work_scale_; }

 private:
  const ContinuumBranch& branch_;
  FrontSpeedLaw law_;
  double length_;             ///< l [m]
  double indentation0_;       ///< d at s = 0 [m]
  double indentation_per_s_;  ///< [m]
  double hess_per_radius_;    ///< 2 pi dgamma / E* [m]
  double work_scale_;         ///< dgamma l^2 [J]
};

/// A walk's scaled state as (s, x, D, W).
struct FrontScaled {
  double s = 0.0, x = 0.0, dissipated = 0.0, work = 0.0;
};

/// One walk at local tolerance `tol`.
struct ScaledWalk {
  FrontScaled end;
  bool lost = false;
  bool peak_found = false;
  FrontScaled peak;
  long long steps = 0;
  std::vector<FrontScaled> path;
};

/// Steps `y` (independent variable `v`) by controlled steps while `go_on` holds. Where `stop`
/// turns from negative to non-negative within a step the walk ends there; where `peak` does
/// (before any stop), the state there is the walk's peak. Both are located by redoing the step
/// with the plain stepper, its length root-found (TOMS 748).
/// A step that leaves the walk's domain (a radius below the axis, or a number that is not
/// finite: the front's speed grows without bound there) is taken again at half its length, as a
/// step whose error is too large: a loose tolerance must not carry the walk past the axis.
template <class System, class ToScaled, class Peak, class Stop, class GoOn, class Bound>
void front_walk_steps(const System& system, FrontVector& y, double& v, double step, double tol,
                      const ToScaled& to_scaled, const Peak& peak, const Stop& stop,
                      const GoOn& go_on, const Bound& bound, ScaledWalk& walk, bool record,
                      bool first_is_radius) {
  auto controlled = odeint::make_controlled(tol, tol, FrontStepper());
  FrontStepper plain;
  for (;;) {
    if (++walk.steps > kMaxFrontSteps) {
      throw std::runtime_error("continuum: the rate-law front took ten million steps");
    }
    const FrontVector before = y;
    const double v_before = v;
    double tried = bound(to_scaled(y, v), step);
    for (;;) {
      while (controlled.try_step(system, y, v, tried) == odeint::fail) {
      }
      const bool finite =
          std::isfinite(v) && std::isfinite(y[0]) && std::isfinite(y[1]) && std::isfinite(y[2]);
      if (finite && !(first_is_radius && y[0] < 0.0)) break;
      tried = 0.5 * (v - v_before);
      y = before;
      v = v_before;
      if (!(std::abs(tried) > 0.0)) {
        throw std::runtime_error("continuum: the rate-law front's step fell to zero at the axis");
      }
    }
    step = tried;
    const FrontScaled at_start = to_scaled(before, v_before);
    const auto redo = [&](double h) {
      FrontVector z = before;
      if (h != 0.0) plain.do_step(system, z, v_before, h);
      return to_scaled(z, v_before + h);
    };
    // The length of step from the start at which f turns non-negative, within (0, taken].
    const auto crossing = [&](const auto& f, double taken) {
      const double lo = std::min(0.0, taken);
      const double hi = std::max(0.0, taken);
      const double width = std::abs(taken);
      std::uintmax_t iterations = 200;
      const auto root = boost::math::tools::toms748_solve(
          [&](double h) { return f(redo(h)); }, lo, hi, f(redo(lo)), f(redo(hi)),
          [width](double a, double b) { return std::abs(b - a) <= 1e-14 * width; }, iterations);
      return 0.5 * (root.first + root.second);
    };
    double taken = v - v_before;
    FrontScaled now = to_scaled(y, v);
    const bool stopped = stop(at_start) < 0.0 && stop(now) >= 0.0;
    if (stopped) {
      taken = crossing(stop, taken);
      now = redo(taken);
    }
    if (!walk.peak_found && peak(at_start) < 0.0 && peak(now) >= 0.0) {
      walk.peak = redo(crossing(peak, taken));
      walk.peak_found = true;
    }
    if (record) walk.path.push_back(now);
    if (stopped || !go_on(now)) {
      walk.end = now;
      return;
    }
  }
}

ScaledWalk scaled_front_walk(const FrontEquations& eq, double s_end, double tol, bool record) {
  ScaledWalk walk;
  const auto peak_slope = [&](const FrontScaled& p) {
    return eq.force_slope(p.x, eq.indentation(p.s));
  };
  // In time while the front is slow.
  FrontVector y{1.0, 0.0, 0.0};
  double s = 0.0;
  const auto from_time = [](const FrontVector& z, double t) {
    return FrontScaled{t, std::max(z[0], 0.0), z[1], z[2]};
  };
  bool switch_to_radius = false;
  front_walk_steps([&](const FrontVector& z, FrontVector& dz, double t) { eq.in_time(z, dz, t); },
                   y, s, std::min(1e-3, 1e-3 * s_end), tol, from_time, peak_slope,
                   [](const FrontScaled&) { return -1.0; },
                   [&](const FrontScaled& p) {
                     if (p.s >= s_end) return false;
                     switch_to_radius = eq.runs_to_axis(p.x, eq.indentation(p.s));
                     return !switch_to_radius;
                   },
                   [&](const FrontScaled& p, double next) {
                     // Land on the stage's end; never step past the axis.
                     const double q = eq.speed(p.x, eq.indentation(p.s));
                     if (q > 0.0) next = std::min(next, 0.5 * p.x / q);
                     return std::min(next, s_end - p.s);
                   },
                   walk, record, true);
  if (!switch_to_radius) return walk;
  if (!(walk.end.x > 0.0)) {  // the time walk reached the axis itself
    walk.lost = true;
    walk.end.x = 0.0;
    return walk;
  }

  // In the radius down to the axis, or to the stage's end on the way.
  FrontVector z{walk.end.s, walk.end.dissipated, walk.end.work};
  double x = walk.end.x;
  const auto from_radius = [](const FrontVector& w, double r) {
    return FrontScaled{w[0], r, w[1], w[2]};
  };
  bool ended = false;
  front_walk_steps([&](const FrontVector& w, FrontVector& dw, double r) { eq.in_radius(w, dw, r); },
                   z, x, -1e-3 * x, tol, from_radius, peak_slope,
                   [&](const FrontScaled& p) {
                     const double left = p.s - s_end;
                     if (left >= 0.0) ended = true;
                     return left;
                   },
                   [&](const FrontScaled& p) { return p.x > 0.0; },
                   [&](const FrontScaled& p, double next) { return std::max(next, -p.x); }, walk,
                   record, false);
  walk.lost = !ended;
  if (walk.lost) walk.end.x = 0.0;
  return walk;
}

}  // namespace

FrontSpeedWalk walk_front_speed(const ContinuumBranch& branch, const FrontSpeedLaw& law,
                                const FrontSpeedStart& start, double rtol) {
  const FrontEquations eq(branch, law, start);
  const double s_end = std::isfinite(start.end_time)
                           ? (start.end_time - start.time) / eq.time_scale()
                           : std::numeric_limits<double>::infinity();
  const ScaledWalk tight = scaled_front_walk(eq, s_end, 1e-2 * rtol, true);
  const ScaledWalk loose = scaled_front_walk(eq, s_end, 1e-1 * rtol, false);

  const auto state_of = [&](const FrontScaled& p) {
    const double d = eq.indentation(p.s);
    return branch.state(eq.length() * p.x, eq.stretch(p.x, d));
  };
  const auto time_of = [&](const FrontScaled& p) { return start.time + eq.time_scale() * p.s; };
  FrontSpeedWalk out;
  out.end = state_of(tight.end);
  out.end_time = tight.lost ? time_of(tight.end) : start.end_time;
  out.lost = tight.lost;
  if (tight.peak_found) {
    out.peak = state_of(tight.peak);
    out.peak_time = time_of(tight.peak);
    if (loose.peak_found) {
      out.peak_error = std::abs(state_of(loose.peak).normal_force - out.peak->normal_force);
    }
  }
  out.machine_work = eq.work_scale() * tight.end.work;
  out.dissipated = eq.work_scale() * tight.end.dissipated;
  out.energy_error =
      eq.work_scale() * std::max(std::abs(tight.end.work - loose.end.work),
                                 std::abs(tight.end.dissipated - loose.end.dissipated));
  out.end_error = std::abs(eq.indentation(tight.end.s) - eq.indentation(loose.end.s));
  out.steps = tight.steps + loose.steps;
  out.path.reserve(tight.path.size());
  for (const FrontScaled& p : tight.path) {
    out.path.push_back({time_of(p), eq.length() * p.x, eq.indentation(p.s)});
  }
  return out;
}

}  // namespace mdrsim
