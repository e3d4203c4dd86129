// Stages, jumps and work of a normal loading program on the Dugdale law's equilibria.
#include "engine/continuum/dugdale_program.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "controllers/builtin_controllers.hpp"
#include "engine/base/bracketed_root.hpp"
#include "engine/base/text.hpp"
#include "engine/continuum/continuum_branch.hpp"
#include "engine/continuum/dugdale_path.hpp"
#include "engine/continuum/program_clock.hpp"
#include "engine/model/dugdale_material.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNearStep = 1.0 / 128.0;  ///< the grid on u in [0, 3]
constexpr double kFarStep = 1.0 / 32.0;    ///< beyond: a grows by e^(1/32) a step
constexpr double kFar = 3.0;
constexpr double kLast = kFar + 100.0;        ///< a = 4 c0 e^100: a front that never stops
constexpr double kProgramCornerWidth = 1e-6;  ///< a fold this close to a corner is the corner
constexpr double kSlopeStep = 1e-5;           ///< the fold's difference quotients' step in u

/// The equilibria as one curve of u (docs/maugis.md "Programs"): u <= 0 separated, d = f(0) -
/// h0 + u h0 and F = 0; [0, 1] the no-contact branch, c = c0 u; [1, 3] the contact branch up to
/// a = 4 c0 as the shorthand's path runs it backwards (s = 4 - u: in the zone's angle next to
/// the closing point, where a radius would round c, then in a); u > 3 the contact branch at
/// a = 4 c0 e^(u - 3) (a sphere: halfway from c0 to its radius in place of 4 c0). Its corners,
/// where the branches meet, are u = 0 and u = 1; the parameter's own are u = 2 and 3.
class Equilibria {
 public:
  static constexpr double kStretchEnds[] = {0.0, 1.0, 2.0, kFar};

  Equilibria(const Profile& profile, const DugdaleLaw& law)
      : profile_(profile),
        law_(law),
        closing_(dugdale_closing_radius(profile, law)),
        open_depth_(dugdale_free_state(profile, law, 0.0).indentation),
        near_radius_(std::isfinite(profile.outer_radius())
                         ? std::min(4.0 * closing_, 0.5 * (closing_ + profile.outer_radius()))
                         : 4.0 * closing_),
        near_(profile, law, near_radius_, -std::numeric_limits<double>::infinity()) {}

  DugdaleState at(double u) const {
    if (u <= 0.0) {
      DugdaleState s;
      s.indentation = open_depth_ + u * law_.range();
      return s;
    }
    if (u <= 1.0) return dugdale_free_state(profile_, law_, closing_ * u);
    if (u <= kFar) return near_.at(path_of(u));
    return dugdale_contact_state(profile_, law_, near_radius_ * std::exp(u - kFar));
  }
  /// u of the separated state at depth d [m].
  double separated_at(double depth) const { return (depth - open_depth_) / law_.range(); }

  /// The grid point next beyond u going the way of dir.
  static double next(double u, int dir) {
    const bool far = dir > 0 ? u >= kFar : u > kFar;
    const double base = far ? kFar : 0.0;
    const double step = far ? kFarStep : kNearStep;
    const double k = (u - base) / step;
    return base + (dir > 0 ? std::floor(k) + 1.0 : std::ceil(k) - 1.0) * step;
  }
  /// The end of u's smooth stretch the way of dir.
  static double stretch_end(double u, int dir) {
    if (dir > 0) {
      for (const double end : kStretchEnds) {
        if (u < end) return end;
      }
      return kLast;
    }
    for (int k = 3; k >= 0; --k) {
      if (u > kStretchEnds[k]) return kStretchEnds[k];
    }
    return -std::numeric_limits<double>::infinity();
  }

  /// int F dd over [u0, u1] [J] by Gauss-Kronrod on F d'(u), split at the stretches' ends;
  /// `scale` gains int |F dd|, `error` its bound: the quadrature's estimate and the difference
  /// quotient's ~1e-11 of |F d'| (on [1, 3] the shorthand's path's d'(s), elsewhere a fourth-order
  /// quotient, one-sided at a stretch's ends, of closed forms or of a root far from the closing
  /// point).
  double work(double u0, double u1, double& error, double& scale) const {
    const double lo = std::min(u0, u1);
    const double hi = std::max(u0, u1);
    double total = 0.0;
    double from = std::max(lo, 0.0);  // F = 0 on the separated side
    while (from < hi) {
      const double to = std::min(hi, stretch_end(from, +1));
      const bool near = from >= 1.0 && to <= kFar;
      const double s_lo = stretch_end(0.5 * (from + to), -1);
      const double s_hi = stretch_end(0.5 * (from + to), +1);
      double err = 0.0;
      double l1 = 0.0;
      const auto integrand = [&](double u) {
        const double slope = near ? -near_.depth_slope(path_of(u)) : depth_slope(u, s_lo, s_hi);
        return at(u).normal_force * slope;
      };
      // Two rules, 31 and 15 points: their gap bounds the 15's error and so the 31's; the
      // rules' own |Kronrod - Gauss| sees the noise of the difference quotient, ~1e-11 of
      // |F d'| near the closing point, and would stall there.
      const double fine = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
          integrand, from, to, 3, 1e-14, &err, &l1);
      const double coarse = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
          integrand, from, to, 3, 1e-14);
      total += fine;
      error += std::abs(fine - coarse) + 1e-11 * l1;
      scale += l1;
      from = to;
    }
    return u1 >= u0 ? total : -total;
  }

 private:
  static double path_of(double u) { return 4.0 - u; }

  double depth_slope(double u, double lo, double hi) const {
    constexpr double h = 1e-3;  // each stretch is smooth on a scale of 1 in u
    const auto d = [&](double x) { return at(x).indentation; };
    if (u - 2.0 * h >= lo && u + 2.0 * h <= hi) {
      return (8.0 * (d(u + h) - d(u - h)) - (d(u + 2.0 * h) - d(u - 2.0 * h))) / (12.0 * h);
    }
    const double s = u - 2.0 * h < lo ? h : -h;
    return (-25.0 * d(u) + 48.0 * d(u + s) - 36.0 * d(u + 2.0 * s) + 16.0 * d(u + 3.0 * s) -
            3.0 * d(u + 4.0 * s)) /
           (12.0 * s);
  }

  const Profile& profile_;
  DugdaleLaw law_;
  double closing_;      ///< c0 [m]
  double open_depth_;   ///< f(0) - h0 [m]: where the zone appears
  double near_radius_;  ///< 4 c0, or halfway from c0 to a body's outer radius [m]
  DugdalePath near_;    ///< the contact branch from near_radius_ to the closing point
};

/// Where a march along the curve stopped: at the stage's control, at a fold of it, nowhere
/// (a tensile fixed load past the separated end: nothing holds the indenter), or at the last
/// state before the contact branch leaves the body (its zone past a sphere's radius) or grows
/// without bound.
struct Reach {
  enum class Kind { reached, fold, flies, edge } kind;
  double u = 0.0;
  double force_error = 0.0;  ///< a fold's: a bound on the error of its normal force [N]
};

double brent_maximum(const auto& value, double lo, double hi) {
  const double width = hi - lo;
  // Over the unit interval: Brent's absolute tolerance would stop it early on a narrow bracket.
  return lo + width * boost::math::tools::brent_find_minima(
                          [&](double x) { return -value(lo + x * width); }, 0.0, 1.0,
                          std::numeric_limits<double>::digits)
                          .first;
}

/// The walk of one control along the curve.
class ControlWalk {
 public:
  ControlWalk(const Equilibria& eq, const AffineConstraint& control) : eq_(eq), n_(control) {}

  double value(const DugdaleState& s) const {
    return n_.displacement_coefficient * s.indentation + n_.force_coefficient * s.normal_force;
  }
  double value_at(double u) const { return value(eq_.at(u)); }
  bool holds_depth() const { return n_.displacement_coefficient > 0.0; }

  /// From u0 the way of dir until the control reaches `target` (-inf: until the zone is gone)
  /// or folds.
  Reach march(double u0, int dir, double target) const {
    double before = u0;  // the grid point before `prev`: a fold's bracket starts there
    double prev = u0;
    double v_prev = value_at(u0);
    for (;;) {
      if (dir < 0 && prev <= 0.0) return separated_reach(target);
      if (dir > 0 && prev < 0.0) {
        // Separated: the control is a_u d until the zone appears at u = 0.
        if (!holds_depth()) {
          if (target <= 0.0) return {Reach::Kind::reached, prev};
        } else if (target <= value_at(0.0)) {
          return {Reach::Kind::reached, eq_.separated_at(target / n_.displacement_coefficient)};
        }
        before = prev = 0.0;
        v_prev = value_at(0.0);
        continue;
      }
      if (dir > 0 && prev >= kLast) return {Reach::Kind::edge, prev};
      const double p = Equilibria::next(prev, dir);
      double vp = 0.0;
      try {
        vp = value_at(p);
      } catch (const std::domain_error&) {
        if (dir < 0) throw;
        return {Reach::Kind::edge, prev};
      }
      if (dir < 0 && p <= 0.0 && !std::isfinite(target) && vp <= v_prev) {
        return {Reach::Kind::reached, 0.0};  // the zone shrank to nothing without a fold
      }
      if (dir * (vp - target) >= 0.0 && dir * (vp - v_prev) >= 0.0) {
        return {Reach::Kind::reached, crossing(prev, p, target)};
      }
      if (dir * (vp - v_prev) < 0.0) {
        Reach fold = locate_fold(std::min(before, p), std::max(before, p), dir);
        if (dir * (value_at(fold.u) - target) >= 0.0) {
          return {Reach::Kind::reached, crossing(before, fold.u, target)};
        }
        return fold;
      }
      before = prev;
      prev = p;
      v_prev = vp;
    }
  }

  /// The equilibrium a jump from the fold at u_f lands on: the first beyond it, the way of
  /// dir, where the control returns to its value at the fold; none under a fixed load past the
  /// separated end; `edge` where the contact branch leaves the body before it.
  std::optional<double> land(double u_f, int dir, bool& edge) const {
    const double v_f = value_at(u_f);
    double prev = u_f;
    bool beyond = false;  // the control has left v_f the wrong way (the fold's other side)
    for (;;) {
      if (dir < 0 && prev <= 0.0) {
        if (!holds_depth()) return std::nullopt;
        return std::min(prev, eq_.separated_at(v_f / n_.displacement_coefficient));
      }
      const double p = Equilibria::next(prev, dir);
      double vp = 0.0;
      try {
        if (dir > 0 && prev >= kLast) throw std::domain_error("the contact grows without bound");
        vp = value_at(p);
      } catch (const std::domain_error&) {
        if (dir < 0) throw;
        edge = true;
        return std::nullopt;
      }
      if (beyond && dir * (vp - v_f) >= 0.0) return crossing(prev, p, v_f);
      if (dir * (vp - v_f) < 0.0) beyond = true;
      prev = p;
    }
  }

 private:
  Reach separated_reach(double target) const {
    if (!std::isfinite(target)) return {Reach::Kind::reached, 0.0};
    if (!holds_depth()) return {Reach::Kind::flies, 0.0};
    return {Reach::Kind::reached,
            std::min(0.0, eq_.separated_at(target / n_.displacement_coefficient))};
  }

  double crossing(double u0, double u1, double target) const {
    const auto excess = [&](double u) { return value_at(u) - target; };
    if (excess(u0) == 0.0) return u0;
    if (excess(u1) == 0.0) return u1;
    return bracketed_root(excess, std::min(u0, u1), std::max(u0, u1));
  }

  /// The fold in [lo, hi]: Brent's maximum of dir * v, at a corner exactly, else refined to
  /// the root of v' with steps h and 2h, whose gap bounds the force's error.
  Reach locate_fold(double lo, double hi, int dir) const {
    const auto along = [&](double u) { return dir * value_at(u); };
    double u = brent_maximum(along, lo, hi);
    for (const double corner : {0.0, 1.0}) {
      if (corner >= lo && corner <= hi && std::abs(u - corner) < kProgramCornerWidth) {
        return {Reach::Kind::fold, corner, 4.0 * kEps * std::abs(eq_.at(corner).normal_force)};
      }
    }
    const double s_lo = Equilibria::stretch_end(u, -1);
    const double s_hi = Equilibria::stretch_end(u, +1);
    const auto root_with = [&](double h) -> std::optional<double> {
      const auto dv = [&](double x) {
        return dir *
               (8.0 * (value_at(x + h) - value_at(x - h)) -
                (value_at(x + 2.0 * h) - value_at(x - 2.0 * h))) /
               (12.0 * h);
      };
      const double w = 1e-4 * (hi - lo);
      const double a = u - w;
      const double b = u + w;
      if (a - 2.0 * h <= s_lo || b + 2.0 * h >= s_hi) return std::nullopt;
      if (!(dv(a) > 0.0 && dv(b) < 0.0)) return std::nullopt;
      return bracketed_root(dv, a, b);
    };
    const auto fine = root_with(kSlopeStep);
    const auto coarse = root_with(2.0 * kSlopeStep);
    double error = 0.0;
    if (fine && coarse) {
      u = *fine;
      error = std::abs(eq_.at(*fine).normal_force - eq_.at(*coarse).normal_force) / 15.0;
    } else {
      const double d = std::sqrt(kEps) * (hi - lo);
      const double f = eq_.at(u).normal_force;
      error = std::max(std::abs(eq_.at(u + d).normal_force - f),
                       std::abs(eq_.at(u - d).normal_force - f));
    }
    return {Reach::Kind::fold, u, error + 4.0 * kEps * std::abs(eq_.at(u).normal_force)};
  }

  const Equilibria& eq_;
  AffineConstraint n_;
};

/// One stretch of a stage's path on the curve, from u0 to u1 under `control`.
struct Piece {
  const Stage* stage;
  AffineConstraint control;
  double u0 = 0.0;
  double u1 = 0.0;
  ContinuumStageClock clock;  ///< its stage's time by the normal control
};

/// The machine's work over a piece [J]: int F dX with X = d + (a_F/a_u) F the machine's end
/// (the spring's energy change on top of int F dd).
double machine_work(const Equilibria& eq, const Piece& p, double& error, double& scale) {
  double w = eq.work(p.u0, p.u1, error, scale);
  if (p.control.displacement_coefficient > 0.0 && p.control.force_coefficient > 0.0) {
    const double f0 = eq.at(p.u0).normal_force;
    const double f1 = eq.at(p.u1).normal_force;
    w += 0.5 * p.control.force_coefficient / p.control.displacement_coefficient *
         (f1 * f1 - f0 * f0);
  }
  return w;
}

/// The most tensile state of a piece: the grid's, refined by Brent between its neighbours.
std::pair<double, double> most_tensile(const Equilibria& eq, const Piece& p) {
  const double lo = std::max(std::min(p.u0, p.u1), 0.0);
  const double hi = std::max(p.u0, p.u1);
  if (!(hi > lo)) return {lo, 0.0};
  std::vector<double> grid{lo};
  for (double u = Equilibria::next(lo, 1); u < hi; u = Equilibria::next(u, 1)) grid.push_back(u);
  grid.push_back(hi);
  std::size_t best = 0;
  for (std::size_t k = 1; k < grid.size(); ++k) {
    if (eq.at(grid[k]).normal_force < eq.at(grid[best]).normal_force) best = k;
  }
  const double a = grid[best > 0 ? best - 1 : 0];
  const double b = grid[std::min(best + 1, grid.size() - 1)];
  const auto force = [&](double u) { return eq.at(u).normal_force; };
  double u = b > a ? brent_maximum([&](double x) { return -force(x); }, a, b) : a;
  if (force(grid[best]) < force(u)) u = grid[best];
  const double d = std::sqrt(kEps) * std::max(b - a, 1e-300);
  const double f = force(u);
  double error = 4.0 * kEps * std::abs(f);
  if (u - d > lo && u + d < hi) {
    error += std::max(std::abs(force(u + d) - f), std::abs(force(u - d) - f));
  }
  return {u, error};
}

}  // namespace

RunResult run_dugdale_program(const Scene& scene, double rtol, std::int64_t samples,
                              const ObserverList& observers) {
  const DugdaleLaw law = dugdale_law(scene.material);
  const Equilibria eq(*scene.profile, law);
  RunResult result;
  result.accuracy.route = Accuracy::Route::continuum;
  result.status = RunStatus::completed;

  AffineConstraint control = FixedGripsController().constraint();
  double u = 0.0;  // the indenter comes from far: separated, at the edge of the zone's range
  bool flying = false;
  double work_error = 0.0;
  double work_scale = 0.0;  // int |F dd| over the path [J]
  double critical_error = 0.0;
  double largest_radius = 0.0;
  bool at_edge = false;
  std::vector<Piece> pieces;
  std::vector<std::string> not_run;
  std::vector<Event> stage_ends;
  double now = 0.0;  // the program's clock as the stage starts [s]
  const auto lost_contact = [&](const Stage& stage) {
    if (result.status != RunStatus::completed) return;
    result.status = RunStatus::no_instability;
    result.critical_stage = stage.name;
  };
  for (const Stage& stage : scene.program->stages) {
    if (flying || at_edge) {
      not_run.push_back(stage.name);
      continue;
    }
    if (stage.normal) control = stage.normal->controller->constraint();
    const ControlWalk walk(eq, control);
    AxisWork stage_work;
    const double v0 = walk.value_at(u);
    double target = v0;
    if (stage.normal && stage.normal->motion == StageAxis::Motion::to) target = stage.normal->value;
    if (stage.normal && stage.normal->motion == StageAxis::Motion::by) {
      target = v0 + stage.normal->value;
    }
    if (stage.until_separation) target = -std::numeric_limits<double>::infinity();
    const ContinuumStageClock clock = continuum_stage_clock(stage, now, v0, target);
    const std::size_t jumps_before = result.jumps.size();
    const bool critical_before = result.critical.has_value();
    const int dir = target > v0 ? 1 : (target < v0 ? -1 : 0);
    while (dir != 0 && !flying && !at_edge && !(stage.until_separation && u <= 0.0)) {
      const Reach r = walk.march(u, dir, target);
      if (r.kind == Reach::Kind::flies) {
        // A tension held with no zone: nothing holds the indenter.
        flying = true;
        result.critical_stage = stage.name;
        break;
      }
      const Piece piece{&stage, control, u, r.u, clock};
      stage_work.normal += machine_work(eq, piece, work_error, work_scale);
      pieces.push_back(piece);
      if (dir < 0 && u > 0.0 && r.u <= 0.0) lost_contact(stage);
      u = r.u;
      largest_radius = std::max(largest_radius, eq.at(u).contact_radius);
      if (r.kind == Reach::Kind::reached) break;
      if (r.kind == Reach::Kind::edge) {
        at_edge = true;
        result.status = RunStatus::step_limit;
        result.stop_reason = StopReason::outgrew_row;
        result.critical_stage = stage.name;
        break;
      }

      const DugdaleState from = eq.at(u);
      bool no_landing_inside = false;
      const std::optional<double> landing = walk.land(u, dir, no_landing_inside);
      if (no_landing_inside) {
        at_edge = true;
        result.status = RunStatus::step_limit;
        result.stop_reason = StopReason::outgrew_row;
        result.critical_stage = stage.name;
        break;
      }
      JumpRecord jump{
          .stage = stage.name, .inward = dir > 0, .critical = dugdale_snapshot(from, control)};
      if (dir < 0 && result.status == RunStatus::completed) {
        result.status = RunStatus::instability;
        result.critical = jump.critical;
        result.critical_stage = stage.name;
        critical_error = r.force_error;
      }
      if (!landing) {
        jump.end = JumpEnd::separated;  // nothing holds the fixed load: the indenter flies off
        flying = true;
        result.jumps.push_back(jump);
        break;
      }
      const DugdaleState to = eq.at(*landing);
      jump.after = dugdale_snapshot(to, control);
      result.jumps.push_back(jump);
      // At fixed grips or through a spring the machine's end stands still; a fixed load
      // moves with the indenter.
      if (!walk.holds_depth())
        stage_work.normal += from.normal_force * (to.indentation - from.indentation);
      u = *landing;
      largest_radius = std::max(largest_radius, to.contact_radius);
    }
    for (std::size_t k = jumps_before; k < result.jumps.size(); ++k) {
      clock.stamp(result.jumps[k].critical);
      result.jumps[k].after.time = result.jumps[k].critical.time;  // a jump takes no time
    }
    if (result.critical && !critical_before) clock.stamp(*result.critical);
    ContactSnapshot end = dugdale_snapshot(eq.at(u), control);
    // A stage that runs to its end ends at its clock's end, whatever the rounding of its control.
    end.time = stage.until_separation ? clock.at(end.normal_control) : clock.end;
    StageRecord record{stage.name, end, {}};
    if (flying) record.end = result.critical.value_or(end);
    now = record.end.time;
    record.work = stage_work;
    result.stages.push_back(record);
    Event e{.kind = EventKind::stage_end, .state = record.end};
    e.stage = stage.name;
    stage_ends.push_back(e);
  }
  for (const Event& e : stage_ends) observers.emit(e);
  if (at_edge) {
    const double outer = scene.profile->outer_radius();
    result.warnings.push_back(fmt::format(
        "stage '{}': the contact grows to a = {:.6g} m and no equilibrium lies beyond it "
        "before the stage's control is reached ({}): the program stops here{}",
        result.critical_stage, largest_radius,
        std::isfinite(outer) ? fmt::format("its cohesive zone reaches the profile's outer radius "
                                           "{:.6g} m",
                                           outer)
                             : std::string("the contact grows without bound"),
        not_run.empty() ? std::string()
                        : fmt::format("; stages not run: {}", quoted_names(not_run))));
  } else if (!not_run.empty()) {
    result.warnings.push_back(fmt::format(
        "stage '{}': the normal fixed load lost what held it and the indenter separates: the "
        "program ends there; stages not run: {}",
        result.critical_stage, quoted_names(not_run)));
  }

  // The samples, shared evenly among the pieces; the peak over every piece.
  if (samples >= 2 && !pieces.empty()) {
    const std::int64_t per_piece =
        std::max<std::int64_t>(2, samples / static_cast<std::int64_t>(pieces.size()));
    for (const Piece& p : pieces) {
      for (std::int64_t k = 0; k < per_piece; ++k) {
        const double t = static_cast<double>(k) / static_cast<double>(per_piece - 1);
        Event e{.kind = EventKind::sample,
                .state = dugdale_snapshot(eq.at(p.u0 + (p.u1 - p.u0) * t), p.control)};
        p.clock.stamp(e.state);
        e.stage = p.stage->name;
        observers.emit(e);
      }
    }
  }
  double peak_error = 0.0;
  for (const Piece& p : pieces) {
    const auto [at, error] = most_tensile(eq, p);
    const DugdaleState s = eq.at(at);
    if (s.normal_force < 0.0 && (!result.peak || s.normal_force < result.peak->normal_force)) {
      result.peak = dugdale_snapshot(s, p.control);
      p.clock.stamp(*result.peak);
      peak_error = error;
    }
  }

  AxisWork total;
  double magnitude = 0.0;
  for (const StageRecord& stage : result.stages) {
    total += stage.work;
    magnitude += std::abs(stage.work.normal);
  }
  result.work = total;
  result.counts.root_iterations = 0;
  result.accuracy.outer_radius = largest_radius;
  result.accuracy.work_error_estimate = AxisWork{with_rounding(work_error, magnitude), 0.0};
  if (result.critical) {
    result.accuracy.critical_error_estimate =
        with_rounding(critical_error, std::abs(result.critical->normal_force));
  }
  if (result.peak) {
    result.accuracy.peak_error_estimate =
        with_rounding(peak_error, std::abs(result.peak->normal_force));
  }
  result.accuracy.covers = {"critical.normal_force", "peak_adhesion.normal_force", "stages.work",
                            "work"};
  const double floor = 1e-300 + 1e-6 * (result.peak ? std::abs(result.peak->normal_force) : 0.0);
  // The work relative to the path's scale, int |F dd|: a cycle's net work (its loop) is a
  // small difference of its stages' where lambda is small.
  bool met = meets_rtol(work_error, std::max(magnitude, work_scale), rtol);
  if (result.critical) {
    met = met && meets_rtol(*result.accuracy.critical_error_estimate, result.critical->normal_force,
                            rtol, floor);
  }
  result.accuracy.rtol_met = met;
  if (!met) {
    result.warnings.push_back(fmt::format(
        "continuum: the Dugdale program's error estimates exceed rtol = {:.3g} (critical {:.3g} "
        "N, work {:.3g} J)",
        rtol, result.accuracy.critical_error_estimate.value_or(0.0), work_error));
  }
  return result;
}

}  // namespace mdrsim
