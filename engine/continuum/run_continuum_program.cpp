// Stages, jumps and work of a normal loading program from the continuum front, stage by stage.
#include "engine/continuum/run_continuum_program.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "controllers/builtin_controllers.hpp"
#include "engine/base/bracketed_root.hpp"
#include "engine/base/hess_scale.hpp"
#include "engine/base/text.hpp"
#include "engine/continuum/continuum_pull_off.hpp"
#include "engine/continuum/continuum_work.hpp"
#include "engine/continuum/front_speed_walk.hpp"
#include "engine/continuum/program_clock.hpp"
#include "engine/model/gluing_depth.hpp"
#include "engine/model/graded_constants.hpp"
#include "engine/result/rtol_rule.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

/// Why the route cannot follow the program past a stage: thrown from deep in the walk, caught
/// by run_continuum_program, which returns it.
class CannotFollow : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The glued disk: radius a (0: nothing in contact) at indentation d.
struct Disk {
  double radius = 0.0;       ///< a [m]
  double indentation = 0.0;  ///< d [m]
};

/// One stretch of a stage's path, for the samples: the front pinned at `radius` while the
/// stretch goes from e0 to e1, or moving from radius a0 to a1 on the limit `advancing`
/// (else the let-go stretch).
struct Piece {
  enum class Kind { pinned, advancing, receding, empty, rate_law } kind;
  double a0 = 0.0, a1 = 0.0;          ///< [m]
  double e0 = 0.0, e1 = 0.0;          ///< pinned: the stretches; empty: the indentations [m]
  std::vector<FrontSpeedPoint> path;  ///< rate_law: the front's walk, step by step
};

/// The advancing limit on a graded half-space at radius a [m]: Hess's rule on the graded
/// springs with dgamma_a, sqrt(4 pi a^(1-k) dgamma_a / ((1 + k) C_k)) (docs/graded.md
/// "Programs").
double graded_advancing_stretch(const ContinuumBranch& branch, double a) {
  const Material& m = branch.material();
  return graded_let_go_stretch(branch.graded()->grading_exponent(), m.grading.punch_constant,
                               m.approach_work_of_adhesion, a);
}

/// C_k a^(1+k) [N/m]: what a graded disk of radius a [m] pulls per unit of boundary stretch.
double graded_punch_stiffness(const ContinuumBranch& branch, double a) {
  return branch.material().grading.punch_constant *
         std::pow(a, 1.0 + branch.graded()->grading_exponent());
}

/// One stage on the continuum: the branch of its normal control with the tangential axis
/// held (every glued spring carries the same u_x: the glue took no spring after u_x moved),
/// the advancing and receding limits, and the work and pieces it went through.
class ContinuumStage {
 public:
  ContinuumStage(const Scene& scene, const AffineConstraint& normal,
                 const AffineConstraint& tangential, double tangential_held)
      : branch_(*scene.profile, *scene.criterion, scene.material, normal, tangential,
                tangential_held, scene.graded_image),
        advancing_per_radius_(
            hess_scale(scene.material.approach_work_of_adhesion, scene.material.effective_modulus)),
        modulus_(scene.material.effective_modulus) {}

  ContinuumBranch& branch() { return branch_; }
  /// The advancing limit at radius a [m] and the depth at which the front reaches a
  /// (engine/model/gluing_depth.hpp; graded: Hess's rule with dgamma_a on the graded springs,
  /// docs/graded.md "Programs") [m].
  double advancing_stretch(double a) const {
    if (branch_.graded()) return graded_advancing_stretch(branch_, a);
    return advancing_limit(branch_.material(), true, a);
  }
  double advancing_depth(double a) const {
    if (branch_.graded()) return branch_.image(a) - advancing_stretch(a);
    return gluing_depth(branch_.profile(), branch_.material(), true, a);
  }
  double receding_stretch(double a) const { return branch_.stretch(a); }

  /// The equilibrium of the disk (the empty contact: F = 0 at d).
  BranchState state(const Disk& disk) const {
    if (disk.radius == 0.0) {
      BranchState s;
      s.indentation = disk.indentation;
      s.control = branch_.normal().displacement_coefficient * disk.indentation;
      // Out of contact fixed grips hold u_x; a tangential fixed load has flown off already.
      if (is_fixed_grips(branch_.tangential()))
        s.tangential_displacement = branch_.tangential_held();
      return s;
    }
    return branch_.state(disk.radius, branch_.image(disk.radius) - disk.indentation);
  }
  /// The disk at radius a whose control is c (pinned: the control is affine in the stretch,
  /// C(a, e) = C(a, 0) - e (a_u + 2 E* a a_F); graded: C_k a^(1+k) for 2 E* a).
  Disk pinned_at(double a, double c) const {
    const AffineConstraint& n = branch_.normal();
    const double rest = branch_.state(a, 0.0).control;
    const double pinned_stiffness =
        branch_.graded() ? graded_punch_stiffness(branch_, a) : 2.0 * modulus_ * a;
    const double e =
        (rest - c) / (n.displacement_coefficient + pinned_stiffness * n.force_coefficient);
    return {a, branch_.image(a) - e};
  }
  double advancing_control(double a) const {
    return branch_.state(a, advancing_stretch(a)).control;
  }
  double receding_control(double a) const { return branch_.at(a).control; }

  /// The largest radius above `from` whose advancing control is c, the control rising with a
  /// there (the stable side of the advancing branch); `from` has a control <= c.
  double advance_to(double from, double c) {
    // Outward by factors of 4 from the front (from 1e-30 m at the tip) to the first radius
    // whose control exceeds c: the bracket of the first crossing.
    // A body of finite radius (the sphere) ends the search just inside it, where its image
    // and so its control grow without bound.
    const double outer = std::nextafter(branch_.profile().outer_radius(), 0.0);
    double lo = from;
    double hi = std::min(std::max(1.25 * from, 1e-30), outer);
    for (int k = 0; advancing_control(hi) <= c; ++k) {
      if (k > 600 || hi >= outer) {
        throw std::runtime_error("continuum: the advancing front does not stop");
      }
      lo = hi;
      hi = std::min(4.0 * hi, outer);
    }
    const RootBracket r = bracket_root([&](double a) { return advancing_control(a) - c; }, lo, hi);
    iterations_ += r.iterations;
    return 0.5 * (r.lo + r.hi);
  }
  /// The radius in (bottom, top) whose receding control is c, along a stable stretch.
  double recede_to(double top, double bottom, double c) {
    const RootBracket r =
        bracket_root([&](double a) { return receding_control(a) - c; }, bottom, top);
    iterations_ += r.iterations;
    return 0.5 * (r.lo + r.hi);
  }

  /// The machine's work from `from` to `to` with the front pinned or moving: the stored
  /// energy's change, plus the energy the receding springs take away, minus what gluing at
  /// the advancing limit gives (E* e_a(x)^2 per unit of x, both halves: 2 pi x dgamma_a).
  /// A tangential fixed load moves u_x with the radius: its share is the held force times
  /// that move, the normal axis the rest.
  AxisWork work(const Disk& from, const Disk& to, double& error) const {
    // Pinned or receding: the shorthand's stretch work (stored energy plus what the springs
    // take away); advancing, less what gluing at the advancing limit gives, in closed form:
    // int_a0^a1 E* (2 pi x dgamma_a / E*) dx.
    AxisWork w = stretch_work(branch_, state(from), state(to), error);
    if (to.radius > from.radius && branch_.graded()) {
      // c_k(x) e_a(x)^2 = 2 pi x dgamma_a on the graded springs as well.
      w.normal -= std::numbers::pi * branch_.material().approach_work_of_adhesion *
                  (to.radius * to.radius - from.radius * from.radius);
    } else if (to.radius > from.radius) {
      w.normal -= modulus_ * advancing_per_radius_ * 0.5 *
                  (to.radius * to.radius - from.radius * from.radius);
    }
    return w;
  }
  long long iterations() const { return iterations_ + branch_.iterations(); }

  std::vector<Piece> pieces;
  ContinuumStageClock clock;  ///< the stage's time by its normal control

 private:
  ContinuumBranch branch_;
  double advancing_per_radius_;  ///< 2 pi dgamma_a / E* [m]
  double modulus_;               ///< E* [Pa]
  long long iterations_ = 0;
};

/// What the program run keeps across stages.
struct ProgramWalk {
  Disk disk;
  bool retracted = false;  ///< a stage has let springs go
  bool flying = false;     ///< a fixed load lost the contact: the indenter separated
  RunResult result;
  double work_error = 0.0;
  double front_error = 0.0;  ///< of the rate law's dissipated_at_front [J]
  double critical_error = 0.0;
  double peak_error = 0.0;
  BranchState critical;      ///< result.critical's state
  BranchState peak;          ///< result.peak's state
  double force_scale = 0.0;  ///< the largest |F| met [N]
  long long iterations = 0;
  /// The rate law of the receding front, where the scene gives one, and the rtol its walks
  /// meet.
  std::optional<FrontSpeedLaw> front_speed_law;
  double rtol = 0.0;
  /// Where a rate-law walk lost the contact: its time [s], which the stage's clock cannot
  /// give from the indentation in a hold.
  std::optional<double> lost_time;
  /// The largest relative error estimate of the indentation where a rate-law walk lost the
  /// contact [1].
  double lost_indentation_error = 0.0;
};

void note_state(ProgramWalk& w, const BranchState& s) {
  w.force_scale = std::max(w.force_scale, std::abs(s.normal_force));
  if (s.normal_force < 0.0 && (!w.result.peak || s.normal_force < w.result.peak->normal_force)) {
    w.result.peak = s.snapshot();
    w.peak = s;
  }
}

/// Presses the disk from control c0 up to c1 (fixed grips from an empty contact: touch at
/// d = 0, then the jump-in where the advancing limit lets the front glue at once).
void press(ContinuumStage& st, ProgramWalk& w, const Stage& stage, double c1,
           AxisWork& stage_work) {
  Disk& disk = w.disk;
  if (disk.radius == 0.0 && !is_fixed_grips(st.branch().normal())) {
    // A compressive fixed load on an empty contact: the indenter falls in at F = 0 (no work)
    // to touch, and onto the advancing branch where it holds F = 0.
    constexpr double kTip = 1e-30;  // [m]
    const BranchState before = st.state(disk);
    disk.indentation = 0.0;
    if (st.advancing_control(kTip) < 0.0) {
      const double a = st.advance_to(kTip, 0.0);
      disk = {a, st.advancing_depth(a)};
    }
    const BranchState after = st.state(disk);
    w.result.jumps.push_back({.stage = stage.name,
                              .inward = true,
                              .critical = before.snapshot(),
                              .after = after.snapshot()});
  } else if (disk.radius == 0.0) {
    if (c1 < 0.0) {
      st.pieces.push_back({Piece::Kind::empty, 0.0, 0.0, disk.indentation, c1});
      disk.indentation = c1;
      return;
    }
    st.pieces.push_back({Piece::Kind::empty, 0.0, 0.0, disk.indentation, 0.0});
    disk.indentation = 0.0;
    // At touch every radius whose advancing control is below 0 glues at once.
    constexpr double kTip = 1e-30;  // [m]: the advancing limit dips below g there already
    if (st.advancing_control(kTip) < 0.0) {
      const BranchState before = st.state(disk);
      disk.radius = st.advance_to(kTip, 0.0);
      disk.indentation = 0.0;
      const BranchState after = st.state(disk);
      note_state(w, after);
      w.result.jumps.push_back({.stage = stage.name,
                                .inward = true,
                                .critical = before.snapshot(),
                                .after = after.snapshot()});
    } else {
      // No jump: the front grows from the tip on g(a) - e_a(a) = d.
      disk.radius = 0.0;
    }
  }
  const double a = disk.radius;
  const double onset = a > 0.0 ? st.advancing_control(a) : 0.0;
  if (a > 0.0 && c1 <= onset) {
    const Disk end = st.pinned_at(a, c1);
    stage_work += st.work(disk, end, w.work_error);
    st.pieces.push_back({Piece::Kind::pinned, a, a, st.state(disk).stretch, st.state(end).stretch});
    disk = end;
    return;
  }
  if (a > 0.0) {
    const Disk start = st.pinned_at(a, onset);
    stage_work += st.work(disk, start, w.work_error);
    st.pieces.push_back(
        {Piece::Kind::pinned, a, a, st.state(disk).stretch, st.state(start).stretch});
    disk = start;
  }
  const double to = st.advance_to(std::max(a, 1e-300), c1);
  const Disk end{to, st.advancing_depth(to)};
  stage_work += st.work(disk, end, w.work_error);
  st.pieces.push_back({Piece::Kind::advancing, disk.radius, to, 0.0, 0.0});
  disk = end;
}

/// G / dgamma of the disk: E* e^2 / (2 pi a dgamma) in tension, 0 in compression.
double release_ratio(ContinuumStage& st, const Disk& disk) {
  const double e = std::max(st.branch().image(disk.radius) - disk.indentation, 0.0);
  const Material& m = st.branch().material();
  return e * e / (hess_scale(m.work_of_adhesion, m.effective_modulus) * disk.radius);
}

/// The normal fixed grips lowered towards c1 (or held, c1 = c0) with the receding front on the
/// rate law: pinned while G <= dgamma, then a(t) by walk_front_speed to the stage's end or to the
/// axis, where the contact is lost (docs/rate_law.md).
void recede_by_rate_law(ContinuumStage& st, ProgramWalk& w, const Stage& stage, double c1,
                        AxisWork& stage_work) {
  Disk& disk = w.disk;
  const double a = disk.radius;
  const Material& m = st.branch().material();
  if (release_ratio(st, disk) < 1.0) {
    // Pinned until e reaches Hess's stretch sqrt(2 pi a dgamma / E*): G = dgamma.
    const double onset =
        st.branch().image(a) - std::sqrt(hess_scale(m.work_of_adhesion, m.effective_modulus) * a);
    if (c1 >= onset) {
      const Disk end = st.pinned_at(a, c1);
      stage_work += st.work(disk, end, w.work_error);
      st.pieces.push_back(
          {Piece::Kind::pinned, a, a, st.state(disk).stretch, st.state(end).stretch});
      disk = end;
      return;
    }
    const Disk start = st.pinned_at(a, onset);
    stage_work += st.work(disk, start, w.work_error);
    st.pieces.push_back(
        {Piece::Kind::pinned, a, a, st.state(disk).stretch, st.state(start).stretch});
    disk = start;
  }
  note_state(w, st.state(disk));
  w.retracted = true;

  const ContinuumStageClock& clock = st.clock;
  FrontSpeedStart start{.radius = disk.radius, .indentation = disk.indentation};
  start.rate = clock.per_control != 0.0 ? 1.0 / clock.per_control : 0.0;
  start.time = clock.per_control != 0.0 ? clock.at(disk.indentation) : clock.start;
  start.end_time = stage.until_separation ? std::numeric_limits<double>::infinity() : clock.end;
  const FrontSpeedWalk walk = walk_front_speed(st.branch(), *w.front_speed_law, start, w.rtol);
  w.result.counts.steps += walk.steps;  // the walks' ODE steps
  stage_work.normal += walk.machine_work;
  stage_work.front += walk.dissipated;
  w.work_error += walk.energy_error;
  w.front_error += walk.energy_error;
  if (walk.peak) {
    note_state(w, *walk.peak);
    w.peak_error = std::max(w.peak_error, walk.peak_error);
  }
  Piece piece{Piece::Kind::rate_law, disk.radius, walk.end.contact_radius, 0.0, 0.0};
  piece.path = walk.path;
  st.pieces.push_back(std::move(piece));
  disk = {walk.end.contact_radius, walk.end.indentation};
  if (!walk.lost) return;
  // The front reached the axis: the contact is lost there, at a finite speed, with no jump.
  w.result.critical_stage = stage.name;
  w.result.status = RunStatus::instability;
  w.result.critical = walk.end.snapshot();
  w.critical = walk.end;
  w.critical_error = 0.0;  // F = 0 at the axis exactly; the walk's error is in d and t
  w.lost_indentation_error =
      std::max(w.lost_indentation_error, walk.end_error / std::abs(walk.end.indentation));
  w.lost_time = walk.end_time;
  disk = {0.0, walk.end.indentation};
  if (std::isfinite(c1) && !stage.until_separation) {
    st.pieces.push_back({Piece::Kind::empty, 0.0, 0.0, disk.indentation, c1});
    disk.indentation = c1;
  }
}

/// Lowers the control from c0 towards c1 (or until the contact is lost, for `until =
/// "separation"`): pinned until the boundary reaches its let-go stretch, then the receding
/// branch with its partial jumps, and the jump-out at the fold.
void retract(ContinuumStage& st, ProgramWalk& w, const Stage& stage, double c1,
             AxisWork& stage_work) {
  Disk& disk = w.disk;
  const bool grips = is_fixed_grips(st.branch().normal());
  if (disk.radius == 0.0) {
    if (!grips) {
      // A tension held on an empty contact: nothing holds the indenter, which flies off.
      w.flying = true;
      w.result.critical_stage = stage.name;
    } else if (std::isfinite(c1)) {
      st.pieces.push_back({Piece::Kind::empty, 0.0, 0.0, disk.indentation, c1});
      disk.indentation = c1;
    }
    return;
  }
  if (w.front_speed_law) {
    recede_by_rate_law(st, w, stage, c1, stage_work);
    return;
  }
  const double a = disk.radius;
  const double onset = st.receding_control(a);
  if (c1 >= onset) {
    const Disk end = st.pinned_at(a, c1);
    stage_work += st.work(disk, end, w.work_error);
    st.pieces.push_back({Piece::Kind::pinned, a, a, st.state(disk).stretch, st.state(end).stretch});
    disk = end;
    return;
  }
  const Disk start = st.pinned_at(a, onset);
  stage_work += st.work(disk, start, w.work_error);
  st.pieces.push_back({Piece::Kind::pinned, a, a, st.state(disk).stretch, st.state(start).stretch});
  disk = start;
  note_state(w, st.state(disk));
  w.retracted = true;

  const ContinuumPullOff p = continuum_pull_off(st.branch(), a);
  const auto note_peak = [&](double top, double bottom) {
    // The branch's most tensile state, where the stage passes it.
    if (p.peak && p.peak->contact_radius <= top && p.peak->contact_radius >= bottom) {
      note_state(w, *p.peak);
      w.peak_error = std::max(w.peak_error, p.peak_error);
    }
  };
  for (std::size_t k = 0; k < p.segments.size(); ++k) {
    const double top = p.segments[k].first;
    const BranchState bottom = k < p.partial_jumps.size() ? p.partial_jumps[k].from : p.critical;
    if (c1 > bottom.control) {
      const double to = st.recede_to(top, bottom.contact_radius, c1);
      const Disk end{to, st.branch().at(to).indentation};
      stage_work += st.work(disk, end, w.work_error);
      st.pieces.push_back({Piece::Kind::receding, top, to, 0.0, 0.0});
      note_peak(top, to);
      disk = end;
      note_state(w, st.state(disk));
      return;
    }
    const Disk end{bottom.contact_radius, bottom.indentation};
    stage_work += st.work(disk, end, w.work_error);
    st.pieces.push_back({Piece::Kind::receding, top, bottom.contact_radius, 0.0, 0.0});
    note_peak(top, bottom.contact_radius);
    note_state(w, bottom);
    disk = end;
    if (k < p.partial_jumps.size()) {
      const ContinuumJump& jump = p.partial_jumps[k];
      stage_work += jump_work(st.branch(), jump.from, jump.to);
      w.result.jumps.push_back({.stage = stage.name,
                                .inward = false,
                                .critical = jump.from.snapshot(),
                                .after = jump.to.snapshot()});
      disk = {jump.to.contact_radius, jump.to.indentation};
      note_state(w, jump.to);
    }
  }
  // The contact is lost: at a fold (a jump) or by a smooth peel to a -> 0.
  const BranchState last = p.critical;
  w.result.critical_stage = stage.name;
  if (p.end == ContinuumPullOff::End::shear_off ||
      p.end == ContinuumPullOff::End::shear_off_at_application) {
    // The glue breaks unstretched where its springs are pressed in: they stay in contact
    // without glue, a disk the route does not follow.
    throw CannotFollow(fmt::format(
        "stage '{}': the tangential load breaks the glue unstretched at a = {:.6g} m with "
        "springs still pressed in, and the continuum route does not follow pressed springs "
        "without glue",
        stage.name, last.contact_radius));
  }
  if (p.end == ContinuumPullOff::End::smooth_peel) {
    w.result.status = RunStatus::no_instability;
    w.result.critical.reset();
  } else {
    w.result.status = RunStatus::instability;
    w.result.critical = last.snapshot();
    w.critical = last;
    w.critical_error = p.critical_error;
    w.peak_error = std::max(w.peak_error, p.critical_error);
  }
  JumpRecord out{.stage = stage.name, .inward = false, .critical = last.snapshot()};
  const AffineConstraint& tangential = st.branch().tangential();
  if (grips && holds_force(tangential) && st.branch().tangential_held() != 0.0) {
    out.end = JumpEnd::sliding;  // nothing holds the tangential fixed load: it slides away
    w.result.sliding = true;
    w.flying = true;
    disk = {0.0, last.indentation};
  } else if (grips) {
    BranchState empty;
    empty.indentation = last.indentation;
    empty.control = last.control;
    out.after = empty.snapshot();
    disk = {0.0, last.indentation};
  } else {
    out.end = JumpEnd::separated;  // nothing holds the fixed load: the indenter flies off
    w.flying = true;
    disk = {0.0, last.indentation};
  }
  if (p.end != ContinuumPullOff::End::smooth_peel) w.result.jumps.push_back(out);
  if (grips && !w.flying && std::isfinite(c1) && !stage.until_separation) {
    st.pieces.push_back({Piece::Kind::empty, 0.0, 0.0, disk.indentation, c1});
    disk.indentation = c1;
  }
}

/// Gives the states the stage added (its jumps, the critical point and the peak where it found
/// them) their times.
void stamp_stage_states(ProgramWalk& w, const ContinuumStageClock& clock, const Stage& stage,
                        std::size_t jumps_before,
                        const std::optional<ContactSnapshot>& peak_before) {
  for (std::size_t k = jumps_before; k < w.result.jumps.size(); ++k) {
    JumpRecord& jump = w.result.jumps[k];
    clock.stamp(jump.critical);
    jump.after.time = jump.critical.time;  // a jump takes no time
  }
  if (w.result.critical && w.result.critical_stage == stage.name) clock.stamp(*w.result.critical);
  if (w.result.peak && (!peak_before || peak_before->normal_force != w.result.peak->normal_force)) {
    clock.stamp(*w.result.peak);
  }
}

/// `samples` points along the pieces, shared evenly, as `sample` events of their stage.
void emit_samples(const std::vector<std::pair<const Stage*, ContinuumStage*>>& stages,
                  std::int64_t samples, const ObserverList& observers) {
  std::size_t pieces = 0;
  for (const auto& s : stages) pieces += s.second->pieces.size();
  if (samples < 2 || pieces == 0) return;
  const std::int64_t per_piece =
      std::max<std::int64_t>(2, samples / static_cast<std::int64_t>(pieces));
  for (const auto& [stage, st] : stages) {
    for (const Piece& piece : st->pieces) {
      for (std::int64_t k = 0; k < per_piece; ++k) {
        const double t = static_cast<double>(k) / static_cast<double>(per_piece - 1);
        BranchState s;
        switch (piece.kind) {
          case Piece::Kind::pinned:
            s = st->branch().state(piece.a0, piece.e0 + (piece.e1 - piece.e0) * t);
            break;
          case Piece::Kind::advancing: {
            const double a = piece.a0 + (piece.a1 - piece.a0) * t;
            s = st->branch().state(a, st->advancing_stretch(a));
            break;
          }
          case Piece::Kind::receding:
            s = st->branch().at(piece.a0 + (piece.a1 - piece.a0) * t);
            break;
          case Piece::Kind::empty:
            s = st->state({0.0, piece.e0 + (piece.e1 - piece.e0) * t});
            break;
          case Piece::Kind::rate_law:
            break;
        }
        std::optional<double> time;
        if (piece.kind == Piece::Kind::rate_law) {
          // The walk's steps, evenly by index: its own times, not the clock's of d.
          if (piece.path.empty()) continue;
          const std::size_t last = piece.path.size() - 1;
          const FrontSpeedPoint& p =
              piece.path[static_cast<std::size_t>(std::llround(t * static_cast<double>(last)))];
          s = st->state({p.radius, p.indentation});
          time = p.time;
        }
        Event e{.kind = EventKind::sample, .state = s.snapshot()};
        st->clock.stamp(e.state);
        if (time) e.state.time = *time;
        e.stage = stage->name;
        observers.emit(e);
      }
    }
  }
}

RunResult walk_program(const Scene& scene, double rtol, std::int64_t samples,
                       const ObserverList& observers) {
  ProgramWalk w;
  w.front_speed_law = scene.front_speed_law;
  w.rtol = rtol;
  w.result.accuracy.route = Accuracy::Route::continuum;
  w.result.status = RunStatus::completed;
  AffineConstraint control = FixedGripsController().constraint();
  AffineConstraint tangential = FixedGripsController().constraint();
  double tangential_held = 0.0;
  std::vector<ContinuumStage> stages;
  std::vector<const Stage*> stage_of;  ///< the program's stage of each of `stages`
  stages.reserve(scene.program->stages.size());
  std::vector<std::string> not_run;
  std::vector<Event> stage_ends;
  double largest_radius = 0.0;
  double now = 0.0;  // the program's clock as the stage starts [s]
  for (const Stage& stage : scene.program->stages) {
    if (w.flying) {
      not_run.push_back(stage.name);
      continue;
    }
    if (stage.normal) control = stage.normal->controller->constraint();
    AxisWork stage_work;
    double tangential_rate = 0.0;
    const std::size_t jumps_before = w.result.jumps.size();
    const std::optional<ContactSnapshot> peak_before = w.result.peak;
    if (stage.tangential) {
      // The normal axis holds (continuum_program_refusal): the disk keeps its radius and
      // stretch while u_x moves on the uniformly stretched glue, F_x = 2 G* a u_x.
      const ContinuumStage before(scene, control, tangential, tangential_held);
      const BranchState s0 = before.state(w.disk);
      const AffineConstraint next = stage.tangential->controller->constraint();
      const double a = w.disk.radius;
      const double t0 = next.displacement_coefficient * s0.tangential_displacement +
                        next.force_coefficient * s0.tangential_force;
      double t1 = t0;
      if (stage.tangential->motion == StageAxis::Motion::to) t1 = stage.tangential->value;
      if (stage.tangential->motion == StageAxis::Motion::by) t1 = t0 + stage.tangential->value;
      tangential = next;
      tangential_held = t1;
      tangential_rate = t1 - t0;
      const ContinuumStage after(scene, control, tangential, tangential_held);
      const BranchState s1 = after.state(w.disk);
      const double shear = scene.material.effective_shear_modulus;
      stage_work.tangential = a * shear *
                              (s1.tangential_displacement * s1.tangential_displacement -
                               s0.tangential_displacement * s0.tangential_displacement);
      // The boundary holds along the whole ramp if it holds at its end (the criterion's
      // holding set is convex in (elongation, u_x), and the start holds).
      if (a > 0.0 && scene.criterion->margin(
                         {std::max(s1.stretch, 0.0), s1.tangential_displacement, a}) <= 0.0) {
        throw CannotFollow(fmt::format(
            "stage '{}': the tangential load lets the glue go as it is applied (at a = {:.6g} "
            "m), and the continuum route does not follow a front receding under a moving "
            "tangential load",
            stage.name, a));
      }
      if (a == 0.0 && holds_force(tangential) && tangential_held != 0.0) {
        // A tangential fixed load with nothing in contact: the indenter slides away.
        w.result.sliding = true;
        w.flying = true;
        w.result.critical_stage = stage.name;
      }
    }
    ContinuumStage& st = stages.emplace_back(scene, control, tangential, tangential_held);
    stage_of.push_back(&stage);
    const double c0 = st.state(w.disk).control;
    double c1 = c0;
    if (stage.normal && stage.normal->motion == StageAxis::Motion::to) c1 = stage.normal->value;
    if (stage.normal && stage.normal->motion == StageAxis::Motion::by) {
      c1 = c0 + stage.normal->value;
    }
    st.clock = continuum_stage_clock(stage, now, c0, c1, tangential_rate);
    if (stage.until_separation) {
      c1 = -std::numeric_limits<double>::infinity();
      if (w.disk.radius == 0.0) {
        w.result.warnings.push_back(fmt::format(
            "stage '{}' runs until separation but starts with no spring in contact: it ends at "
            "once",
            stage.name));
        c1 = c0;
      }
    }
    if (c1 > c0) {
      if (w.retracted && !scene.program->rebinding) {
        throw SceneError(fmt::format(
            "loading: stage '{}' presses the contact again after springs let go: without "
            "loading.rebinding = true they push back unglued, which the continuum route does "
            "not follow; use solver.method = \"event\"",
            printable(stage.name)));
      }
      press(st, w, stage, c1, stage_work);
    } else if (c1 < c0) {
      retract(st, w, stage, c1, stage_work);
    } else if (w.front_speed_law && w.disk.radius > 0.0 && release_ratio(st, w.disk) > 1.0) {
      // A hold on the rate law: the front goes on receding while G > dgamma.
      recede_by_rate_law(st, w, stage, c1, stage_work);
    }
    largest_radius = std::max(largest_radius, w.disk.radius);
    const BranchState end = st.state(w.disk);
    note_state(w, end);
    stamp_stage_states(w, st.clock, stage, jumps_before, peak_before);
    if (w.lost_time) {
      w.result.critical->time = *w.lost_time;
      w.lost_time.reset();
    }
    StageRecord record{stage.name, end.snapshot(), {}};
    // A stage that runs to its end ends at its clock's end, whatever the rounding of its control.
    record.end.time =
        stage.until_separation ? st.clock.at(record.end.normal_control) : st.clock.end;
    if (w.flying) record.end = w.result.critical.value_or(record.end);
    now = record.end.time;
    record.work = stage_work;
    w.result.stages.push_back(record);
    Event e{.kind = EventKind::stage_end, .state = record.end};
    e.stage = stage.name;
    stage_ends.push_back(e);
  }
  // The events once every stage stands (a stage the route cannot follow throws above, before
  // any): the stage ends, then the samples.
  for (const Event& e : stage_ends) observers.emit(e);
  if (!not_run.empty()) {
    const std::string stages_not_run = quoted_names(not_run);
    if (w.result.sliding) {
      w.result.warnings.push_back(fmt::format(
          "stage '{}': the tangential fixed load lost what held it and the indenter slides "
          "away: the program ends at its critical point; stages not run: {}",
          w.result.critical_stage, stages_not_run));
    } else {
      w.result.warnings.push_back(fmt::format(
          "stage '{}': the normal fixed load (F = {:.6g} N) lost what held it and the indenter "
          "separates: the program ends at its critical point; stages not run: {}",
          w.result.critical_stage, w.result.critical ? w.result.critical->normal_force : 0.0,
          stages_not_run));
    }
  }
  std::vector<std::pair<const Stage*, ContinuumStage*>> walked;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    walked.emplace_back(stage_of[k], &stages[k]);
  }
  emit_samples(walked, samples, observers);

  AxisWork total;
  AxisWork magnitude;  // of the stages' works, which the total rounds a few ulps of
  for (const StageRecord& stage : w.result.stages) {
    total += stage.work;
    magnitude += AxisWork{.normal = std::abs(stage.work.normal),
                          .tangential = std::abs(stage.work.tangential),
                          .front = std::abs(stage.work.front)};
  }
  w.result.work = total;
  long long iterations = 0;
  for (const ContinuumStage& st : stages) iterations += st.iterations();
  w.result.counts.root_iterations = iterations;
  w.result.accuracy.outer_radius = largest_radius;
  w.result.accuracy.work_error_estimate =
      AxisWork{.normal = with_rounding(w.work_error, magnitude.normal),
               .tangential = with_rounding(w.work_error, magnitude.tangential),
               .front = with_rounding(w.front_error, magnitude.front)};
  const double modulus = scene.material.effective_modulus;
  // |F| and its terms' magnitudes, on the graded springs where the half-space is graded.
  const auto magnitude_of = [&](const BranchState& s) {
    if (!scene.graded_image || stages.empty()) return force_magnitude(s, modulus);
    return stages.front().branch().force_magnitude(s);
  };
  if (w.result.critical) {
    w.result.accuracy.critical_error_estimate =
        with_rounding(w.critical_error, magnitude_of(w.critical));
  }
  if (w.result.peak) {
    w.result.accuracy.peak_error_estimate = with_rounding(w.peak_error, magnitude_of(w.peak));
  }
  w.result.accuracy.covers = {"critical.normal_force",
                              "peak_adhesion.normal_force",
                              "stages.end.normal_force",
                              "jumps.critical.normal_force",
                              "jumps.after.normal_force",
                              "stages.work",
                              "work"};
  const double floor = 1e-300 + 1e-6 * w.force_scale;
  // The work relative to the path's scale, the sum of the stages' magnitudes: a cycle's net
  // work may cancel to nothing (no adhesion) while its parts are of that size.
  double work_scale = 1e-300;
  for (const StageRecord& stage : w.result.stages) {
    work_scale += std::abs(stage.work.normal) + std::abs(stage.work.tangential);
  }
  bool met = meets_rtol(w.work_error, work_scale, rtol);
  if (w.result.critical) {
    met = met && meets_rtol(*w.result.accuracy.critical_error_estimate,
                            w.result.critical->normal_force, rtol, floor);
  }
  met = met && w.lost_indentation_error <= rtol;
  w.result.accuracy.rtol_met = met;
  if (!met) {
    w.result.warnings.push_back(fmt::format(
        "continuum: the root searches' and quadratures' error estimates exceed rtol = {:.3g}",
        rtol));
  }
  return w.result;
}

}  // namespace

ContinuumProgramRun run_continuum_program(const Scene& scene, double rtol, std::int64_t samples,
                                          const ObserverList& observers) {
  try {
    return {walk_program(scene, rtol, samples, observers), std::nullopt};
  } catch (const CannotFollow& stop) {
    return {RunResult{}, std::string(stop.what())};
  }
}

}  // namespace mdrsim
