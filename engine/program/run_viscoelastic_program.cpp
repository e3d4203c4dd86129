// The viscoelastic row driven by a program's stages: segments of constant rate, records, events.
#include "engine/program/run_viscoelastic_program.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "engine/model/viscoelastic_edge.hpp"
#include "engine/program/run_program.hpp"
#include "engine/program/stage_motion.hpp"
#include "engine/program/viscoelastic_fold.hpp"
#include "engine/program/viscoelastic_jumps.hpp"
#include "engine/program/viscoelastic_row.hpp"

namespace mdrsim {
namespace {

/// How far the held depth of a stage moves and in what time: its change [m] (per unit of the
/// stage parameter until separation) and seconds (the same).
struct ViscoelasticStageDrive {
  double change = 0.0;
  double seconds = 0.0;
  double end = 0.0;  ///< the held depth at the stage's end [m] (not until separation)
  double rate() const { return seconds > 0.0 ? change / seconds : 0.0; }
};

ViscoelasticStageDrive stage_drive(const Stage& stage, double held, double tangential_change) {
  ViscoelasticStageDrive drive{.end = held};
  if (stage.normal && stage.normal->motion == StageAxis::Motion::to) {
    drive.change = stage.normal->value - held;
    drive.end = stage.normal->value;
  } else if (stage.normal && stage.normal->motion == StageAxis::Motion::by) {
    drive.change = stage.normal->value;
    drive.end = held + drive.change;
  }
  // The reader leaves a stage with a speed one moving axis.
  drive.seconds =
      seconds_per_parameter(stage, drive.change != 0.0 ? drive.change : tangential_change);
  return drive;
}

/// The row's force [N]: a sum of pressed springs' loads, so none pressed, none at all.
double row_force(const ViscoelasticRowSample& s) { return s.pressed > 0 ? s.force : 0.0; }

/// The held value of `control` at the row's state: a_u d + a_F F.
double held_value(const AffineConstraint& control, const ViscoelasticRowSample& s) {
  return control.displacement_coefficient * s.depth + control.force_coefficient * row_force(s);
}

/// What a machine spring stores at force F [J]: F^2 / (2 k), k = a_u / a_F; none without one.
double machine_spring_energy(const AffineConstraint& control, double force) {
  if (!drives_through_spring(control)) return 0.0;
  return 0.5 * force * force * control.force_coefficient / control.displacement_coefficient;
}

/// The row's state as a snapshot whose held value is `control`'s.
ContactSnapshot held_snapshot(const ViscoelasticRowSample& s, const AffineConstraint& control) {
  ContactSnapshot c = viscoelastic_snapshot(s);
  c.normal_control = held_value(control, s);
  return c;
}

EventKind viscoelastic_event_kind(ViscoelasticRowChange change) {
  switch (change) {
    case ViscoelasticRowChange::touch:
      return EventKind::spring_touched;
    case ViscoelasticRowChange::release:
      return EventKind::spring_lifted;
    case ViscoelasticRowChange::glue:
      return EventKind::spring_glued;
    case ViscoelasticRowChange::slip:
      return EventKind::spring_slipped;
    case ViscoelasticRowChange::stick:
      return EventKind::spring_stuck;
    case ViscoelasticRowChange::let_go:
      break;
  }
  return EventKind::spring_detached;
}

/// The row's N springs: x_i = i a_max / N, spring N at the frame's image.
ViscoelasticRowSprings viscoelastic_springs(const Scene& scene, const ProgramRowSpec& spec,
                                            std::int64_t n) {
  ViscoelasticRowSprings springs{scene.material.effective_modulus,
                                 scene.material.relaxation,
                                 spec.reference_radius / static_cast<double>(n),
                                 {}};
  springs.shear_ratio = scene.material.effective_shear_modulus / scene.material.effective_modulus;
  if (scene.friction) springs.friction = scene.friction->coefficient;
  springs.images.reserve(static_cast<std::size_t>(n));
  for (std::int64_t i = 1; i < n; ++i) {
    springs.images.push_back(program_image(scene, springs.spacing * static_cast<double>(i)));
  }
  springs.images.push_back(spec.reference_image);
  return springs;
}

/// A stage's record: its end, its work and energy balance from the row's energies at its start
/// and end, each term summed apart; a machine spring's change of F^2 / (2k) is stored energy.
StageRecord viscoelastic_stage_record(const std::string& name, const ViscoelasticRowSample& end,
                                      const AffineConstraint& control,
                                      const ViscoelasticRowEnergy& before,
                                      const ViscoelasticRowEnergy& now,
                                      double machine_spring_change) {
  StageRecord record;
  record.name = name;
  record.end = held_snapshot(end, control);
  record.work.normal = now.machine_work - before.machine_work;
  record.work.tangential = now.tangential_work - before.tangential_work;
  record.work.bulk = now.dissipated_by_bulk - before.dissipated_by_bulk;
  record.work.friction = now.dissipated_by_friction - before.dissipated_by_friction;
  EnergyBalance e;
  e.machine_work = record.work.normal + record.work.tangential;
  e.stored_change = now.stored - before.stored + machine_spring_change;
  e.dissipated_by_bulk = record.work.bulk;
  e.surface_change = now.surface - before.surface;
  e.jump_losses = now.jump_losses - before.jump_losses;
  e.dissipated_by_friction = record.work.friction;
  e.residual = e.machine_work - e.stored_change - e.surface_change - e.dissipated_by_bulk -
               e.jump_losses - e.dissipated_by_friction;
  record.energy = e;
  return record;
}

/// A stage until separation runs in pieces of its parameter's unit until the contact is lost;
/// this many without a loss is taken for one that never comes.
constexpr int kMostSeparationPieces = 1 << 16;

/// Springs beyond spring N where a stage holds a force or a machine end: the frame's radius is
/// the relaxed elastic contact's, which a creeping contact reaches only in the limit, but a
/// force switched on from a glassy state can carry it further.
constexpr std::int64_t kHeldReachSprings = 16;

bool holds_other_than_depth(const Program& program) {
  return std::any_of(program.stages.begin(), program.stages.end(), [](const Stage& stage) {
    return stage.normal && !stage.normal->controller->is_fixed_grips();
  });
}

/// A stage under a fixed load or a machine spring: its held value h moves linearly in time, the
/// depth following the row (viscoelastic_row.hpp), and u_x moves by `tangential` (its motion
/// over the stage parameter) as under fixed grips. Until separation it runs in pieces of the
/// stage parameter's unit until the contact is lost; whether it was is returned with h there.
struct HeldStageEnd {
  double held;
  bool separated;
};

HeldStageEnd run_held_stage(ViscoelasticRowDrive& drive, const Stage& stage,
                            const AffineConstraint& control, double held,
                            const AxisMotion& tangential,
                            const std::function<std::optional<HeldShearForce>()>& shear_force,
                            bool stop_at_loss, const ViscoelasticRowDrive::OnChange& on_change) {
  const AxisMotion m = axis_motion(stage.normal, held);
  // The reader leaves a stage with a speed one moving axis.
  const double seconds = seconds_per_parameter(stage, m.rate != 0.0 ? m.rate : tangential.rate);
  const double rate = seconds > 0.0 ? m.rate / seconds : 0.0;
  const double tangential_rate = seconds > 0.0 && !shear_force() ? tangential.rate / seconds : 0.0;
  std::vector<ViscoelasticRowSample> no_samples;
  if (!stage.until_separation) {
    const double start = drive.sample().time;
    const bool lost = drive.run({seconds, 0.0, std::nullopt, HeldAxisMotion{control, held, rate},
                                 tangential_rate, tangential.at(1.0, false), shear_force()},
                                stop_at_loss, {}, no_samples, on_change);
    if (lost) return {held + rate * (drive.sample().time - start), true};
    return {m.end.value_or(held + m.rate), false};
  }
  if (drive.sample().pressed == 0) return {held, false};
  bool separated = false;
  for (int piece = 0; piece < kMostSeparationPieces && !separated && rate < 0.0 && !drive.limited();
       ++piece) {
    const double start = drive.sample().time;
    separated = drive.run({seconds, 0.0, std::nullopt, HeldAxisMotion{control, held, rate},
                           tangential_rate, std::nullopt, shear_force()},
                          true, {}, no_samples, on_change);
    held += rate * (drive.sample().time - start);
  }
  return {held, separated};
}

/// The names of the stages after `stage`, quoted, for a warning that they are not run.
std::string stages_after(const Program& program, const Stage& stage) {
  std::string skipped;
  for (auto it = program.stages.begin() + (&stage - program.stages.data()) + 1;
       it != program.stages.end(); ++it) {
    skipped += fmt::format("{}'{}'", skipped.empty() ? "" : ", ", it->name);
  }
  return skipped;
}

}  // namespace

RunResult run_viscoelastic_program(const Scene& scene, const ObserverList& observers) {
  RunResult result;
  const Program& program = *scene.program;
  const std::int64_t n = scene.springs;
  result.springs = n;
  result.accuracy.rows = {n};

  // The row: spring N where the front reaches at the deepest held depth, as an elastic
  // program's frame puts it (program_row_frame) for a fixed-grips program.
  const ProgramRowFrame frame = program_row_frame(scene);
  ProgramRowSpec spec = program_row(scene, frame, n);
  if (!scene.material.glues_on_touch()) {
    // The front glues at the glassy gap: spring N where it glues at the deepest depth (the zero
    // scale stays the relaxed material's).
    Scene glassy = scene;
    glassy.material = glassy_material(scene.material);
    // Where the deepest contact is held by a force or a machine end, the row's radius is the
    // one reaching it, as program_row finds it for an elastic program.
    const ProgramRowSpec at_glassy_gap = program_row(glassy, program_row_frame(glassy), n);
    spec.reference_radius = at_glassy_gap.reference_radius;
    spec.reference_image = at_glassy_gap.reference_image;
  }
  result.accuracy.outer_radius = spec.reference_radius;
  ViscoelasticRowSprings springs = viscoelastic_springs(scene, spec, n);
  if (holds_other_than_depth(program)) {
    const double outer = scene.profile->outer_radius();
    for (std::int64_t i = n + 1; i <= 2 * n + kHeldReachSprings; ++i) {
      const double x = springs.spacing * static_cast<double>(i);
      if (!(x < outer)) break;
      const double g = program_image(scene, x);
      if (!std::isfinite(g)) break;
      springs.images.push_back(g);
    }
  }
  const bool extended = springs.images.size() > static_cast<std::size_t>(n);
  const double row_end = springs.spacing * static_cast<double>(springs.images.size());
  bool reached_row_end = false;
  // The adhesive edge: the scene's criterion is built on the glassy material (a let-go is
  // instantaneous), docs/viscoelastic.md.
  const bool adhesive = scene.material.adhesive();
  std::optional<ViscoelasticEdge> edge;
  if (adhesive) {
    edge = viscoelastic_edge(*scene.criterion, scene.material, springs.spacing,
                             springs.images.size(), program.rebinding);
    springs.edge = &*edge;
  }

  ViscoelasticRowDrive drive(springs);
  ViscoelasticJumps jumps;
  ViscoelasticFold fold;  // the critical point between springs, for the accuracy routes
  std::string_view stage_name;
  // The normal axis's controller and held value; a program starts under fixed grips at 0.
  AffineConstraint control{1.0, 0.0};
  const auto report_jump = [&](std::optional<JumpRecord> jump) {
    if (!jump) return;
    observers.emit({.kind = EventKind::jump, .state = jump->after, .stage = jump->stage});
    result.jumps.push_back(std::move(*jump));
  };
  // Under a fixed load with adhesion the let-gos at one time are held back until they are known
  // to keep the contact: those that lose it are the flight, of which only the first is told
  // (SPEC "A fixed load that loses the contact").
  bool hold_let_gos = false;
  std::vector<Event> held_let_gos;
  const auto release_let_gos = [&] {
    for (const Event& e : held_let_gos) observers.emit(e);
    held_let_gos.clear();
  };
  const auto on_change = [&](ViscoelasticRowChange change, const ViscoelasticRowSample& s) {
    if (extended && s.contact_radius >= row_end * (1.0 - 1e-12)) reached_row_end = true;
    if (!held_let_gos.empty() &&
        (change != ViscoelasticRowChange::let_go || held_let_gos.back().state.time != s.time)) {
      release_let_gos();
    }
    const bool friction_change =
        change == ViscoelasticRowChange::slip || change == ViscoelasticRowChange::stick;
    if (adhesive && !friction_change) {
      const bool by_shear = change == ViscoelasticRowChange::let_go && drive.last_let_go_by_shear();
      report_jump(
          jumps.change(change, stage_name, drive.before_last_change(), drive.sample(), by_shear));
      fold.change(change, stage_name, drive.before_last_change(),
                  held_value(control, drive.before_last_change()), by_shear);
    }
    // An event no observer listens to is not built (a run without observers reports none).
    const EventKind kind = viscoelastic_event_kind(change);
    if (!observers.wants(kind)) return;
    Event event{.kind = kind, .state = held_snapshot(s, control), .stage = stage_name};
    if (change == ViscoelasticRowChange::let_go) {
      event.spring = s.glued;
      event.in_cascade = jumps.cascading();
      if (hold_let_gos) {
        held_let_gos.push_back(event);
        return;
      }
    }
    observers.emit(event);
  };
  // Without adhesion, a row reaching past the contact, a held control (a loss of the contact
  // ends at the state before the last release) or an observer of the springs' changes,
  // on_change does nothing: the drive then builds no states around each change.
  const bool listens =
      extended || adhesive || holds_other_than_depth(program) ||
      observers.wants(EventKind::spring_touched) || observers.wants(EventKind::spring_lifted) ||
      observers.wants(EventKind::spring_glued) || observers.wants(EventKind::spring_detached) ||
      observers.wants(EventKind::spring_slipped) || observers.wants(EventKind::spring_stuck);
  const ViscoelasticRowDrive::OnChange report =
      listens ? ViscoelasticRowDrive::OnChange(on_change) : ViscoelasticRowDrive::OnChange();
  std::vector<ViscoelasticRowSample> no_samples;
  ViscoelasticRowEnergy before = drive.energy();
  AxisWork total;
  EnergyBalance total_energy;
  bool ever_in_contact = false;
  bool lost = false;
  double held = 0.0;
  double held_tangential = 0.0;  ///< u_x [m]
  // The tangential axis's control: u_x held (fixed grips), or F_x (a fixed load) or a machine
  // spring's end (compliant); a stage that does not name the axis keeps it.
  AffineConstraint tangential_control{1.0, 0.0};
  bool shear_force_held = false;
  double held_shear_force = 0.0;  ///< its held value a_u u_x + a_F F_x [N or m]
  bool shear_lost = false;        ///< a held F_x lost its last glued spring
  for (const Stage& stage : program.stages) {
    stage_name = stage.name;
    // A row's changes settle in a few events per spring and stage; a stage that takes more than
    // solver.max_events_per_spring stops, as an elastic program's does.
    drive.limit_events(drive.counts().events() + scene.solver.max_events_per_spring * n);
    if (stage.normal) {
      const AffineConstraint c = stage.normal->controller->constraint();
      if (c.displacement_coefficient != control.displacement_coefficient ||
          c.force_coefficient != control.force_coefficient) {
        // A switch sets the new held value from the present state: nothing jumps.
        held = held_value(c, drive.sample());
        control = c;
      }
    }
    if (stage.tangential) {
      const AffineConstraint c = stage.tangential->controller->constraint();
      if (c.displacement_coefficient != tangential_control.displacement_coefficient ||
          c.force_coefficient != tangential_control.force_coefficient) {
        // A switch sets the new held value from the present state: nothing jumps.
        tangential_control = c;
        shear_force_held = !is_fixed_grips(c);
        const ViscoelasticRowSample now = drive.sample();
        held_shear_force = c.displacement_coefficient * now.tangential_displacement +
                           c.force_coefficient * now.tangential_force;
      }
    }
    // Under a held F_x (not a machine spring) a loss of the glue is a flight.
    const bool shear_holds_force = shear_force_held && holds_force(tangential_control);
    const double spring_energy_before = machine_spring_energy(control, row_force(drive.sample()));
    const double tangential_spring_before =
        machine_spring_energy(tangential_control, drive.sample().tangential_force);
    // What the machine springs store more at the stage's end `end` [J].
    const auto spring_change = [&](const ViscoelasticRowSample& end) {
      double change = machine_spring_energy(control, row_force(end)) - spring_energy_before;
      if (drives_through_spring(tangential_control)) {
        change += machine_spring_energy(tangential_control, end.tangential_force) -
                  tangential_spring_before;
      }
      return change;
    };
    const AxisMotion tangential =
        axis_motion(stage.tangential, shear_force_held ? held_shear_force : held_tangential);
    const ViscoelasticStageDrive sd = stage_drive(stage, held, tangential.rate);
    const double rate = sd.rate();
    // u_x (or a held F_x) moves linearly over the stage, under any normal control.
    const double axis_rate = sd.seconds > 0.0 ? tangential.rate / sd.seconds : 0.0;
    const double tangential_rate = shear_force_held ? 0.0 : axis_rate;
    const double stage_start = drive.sample().time;
    // A held F_x from the present time on.
    const auto shear_force = [&]() -> std::optional<HeldShearForce> {
      if (!shear_force_held) return std::nullopt;
      return HeldShearForce{tangential.start + axis_rate * (drive.sample().time - stage_start),
                            axis_rate, tangential_control};
    };
    // A held F_x that lost its glue slides away, unless a normal fixed load lost the contact
    // with it (the indenter separates: the normal axis's flight), as in the elastic program.
    const auto slides = [&] {
      return shear_force_held && drive.shear_unheld() &&
             !(holds_force(control) && drive.sample().pressed == 0);
    };
    std::optional<ViscoelasticCascade> flight;
    // The held let-gos of a stage's end: where they lost what held the indenter (`flies`), a
    // flight (the stage ends at the critical point, the first let-go told, the rest not); the
    // others told.
    const auto end_held_let_gos = [&](bool flies) {
      if (flies) {
        if (!held_let_gos.empty()) observers.emit(held_let_gos.front());
        held_let_gos.clear();
        flight = jumps.open_cascade();
      }
      release_let_gos();
      hold_let_gos = false;
    };
    bool unglued_loss = false;  ///< a held force without adhesion fell to zero in contact
    ViscoelasticRowSample unglued_end{};
    if (!is_fixed_grips(control)) {
      const bool in_contact = drive.sample().pressed > 0;
      // A held F_x that loses its glue is a flight under a machine spring too.
      hold_let_gos = adhesive && (!drives_through_spring(control) || shear_holds_force);
      // Without adhesion a held force that falls to zero loses the contact at zero force, where
      // the last pressed spring's load (the force) reaches zero: the stage stops there.
      const bool falls = !adhesive && holds_force(control) && in_contact &&
                         (stage.until_separation ||
                          !((stage.normal ? held_after(*stage.normal, held, false) : held) > 0.0));
      const HeldStageEnd held_end =
          run_held_stage(drive, stage, control, held, tangential, shear_force,
                         (adhesive || falls) && !drives_through_spring(control), report);
      held = held_end.held;
      if (falls && (held_end.separated || !(held > 0.0))) {
        // As the elastic program's: the stage ends at the loss, the last spring at zero load.
        unglued_loss = true;
        unglued_end = drive.sample().pressed > 0 ? drive.sample() : drive.before_last_change();
      }
      const bool flies = !drives_through_spring(control) || drive.shear_unheld();
      end_held_let_gos(hold_let_gos && held_end.separated && flies);
      if (stage.until_separation && in_contact && !held_end.separated && !drive.limited()) {
        stop_at_limit(result, StopReason::no_end);
        result.warnings.push_back(fmt::format(
            "stage '{}' runs until separation, but nothing on its path can part the contact ({} "
            "springs in contact): the program stops here",
            stage.name, drive.sample().pressed));
      }
    } else if (!stage.until_separation) {
      // Under a held F_x the let-gos that lose the glue are a flight: only the first is told.
      hold_let_gos = adhesive && shear_holds_force;
      drive.run({sd.seconds, rate, sd.end, std::nullopt, tangential_rate, tangential.at(1.0, false),
                 shear_force()},
                false, {}, no_samples, report);
      held = sd.end;
      // A held F_x that lost its last glued spring: the indenter slides away from the let-gos'
      // critical point (as the normal held force's flight).
      end_held_let_gos(drive.shear_unheld());
    } else if (drive.sample().pressed > 0) {
      bool separated = false;
      hold_let_gos = adhesive && shear_holds_force;
      if (rate < 0.0) {
        for (int piece = 0; piece < kMostSeparationPieces && !separated && !drive.limited();
             ++piece) {
          separated = drive.run({sd.seconds, rate, std::nullopt, std::nullopt, tangential_rate,
                                 std::nullopt, shear_force()},
                                true, {}, no_samples, report);
          if (drive.shear_unheld()) break;
        }
      }
      end_held_let_gos(drive.shear_unheld());
      held = drive.sample().depth;
      if (!separated && !drive.limited()) {
        stop_at_limit(result, StopReason::no_end);
        result.warnings.push_back(fmt::format(
            "stage '{}' runs until separation, but nothing on its path can part the contact ({} "
            "springs in contact): the program stops here",
            stage.name, drive.sample().pressed));
      }
    }
    if (drive.limited()) {
      stop_at_limit(result, StopReason::max_events_per_spring);
      result.warnings.push_back(fmt::format(
          "stage '{}' took more than {} events per spring (solver.max_events_per_spring): the "
          "program stops here",
          stage.name, scene.solver.max_events_per_spring));
    }
    ViscoelasticRowSample end = drive.sample();
    ViscoelasticRowEnergy now = drive.energy();
    if (flight) {
      // Up to the critical point: the let-gos' run (their glassy steps included) taken back.
      end = flight->before;
      const ViscoelasticRowEnergy run = drive.let_go_run();
      now.machine_work -= run.machine_work;
      now.tangential_work -= run.tangential_work;
      now.stored -= run.stored;
      now.surface -= run.surface;
      now.jump_losses -= run.jump_losses;
      if (auto jump = jumps.close()) {
        jump->end = slides() ? JumpEnd::sliding : JumpEnd::separated;
        jump->after = {};
        observers.emit({.kind = EventKind::jump, .state = jump->critical, .stage = jump->stage});
        result.jumps.push_back(std::move(*jump));
      }
      if (&stage != &program.stages.back()) {
        const std::string skipped = stages_after(program, stage);
        if (slides()) {
          result.warnings.push_back(fmt::format(
              "stage '{}': the tangential fixed load (Fx = {:.6g} N) lost what held it and the "
              "indenter slides away: the program ends at its critical point; stages not run: {}",
              stage.name, flight->before.tangential_force, skipped));
        } else {
          result.warnings.push_back(fmt::format(
              "stage '{}': the normal fixed load (F = {:.6g} N) lost what held it and the "
              "indenter separates: the program ends at its critical point; stages not run: {}",
              stage.name, held, skipped));
        }
      }
    } else if (adhesive) {
      report_jump(jumps.close());
    }
    if (unglued_loss) {
      end = unglued_end;
      if (&stage != &program.stages.back()) {
        result.warnings.push_back(fmt::format(
            "stage '{}': the normal fixed load (F = 0 N) lost what held it and the indenter "
            "separates: the program ends at its critical point; stages not run: {}",
            stage.name, stages_after(program, stage)));
      }
    }
    if (adhesive) jumps.observe(end);
    held_tangential = end.tangential_displacement;
    shear_lost = slides();
    if (shear_force_held) {
      held_shear_force = !shear_lost && !stage.until_separation
                             ? tangential.at(1.0, false)
                             : tangential.start + axis_rate * (end.time - stage_start);
    }
    ever_in_contact = ever_in_contact || drive.counts().touches + drive.counts().glues > 0;
    const StageRecord record =
        viscoelastic_stage_record(stage.name, end, control, before, now, spring_change(end));
    total += record.work;
    total_energy += *record.energy;
    before = now;
    result.stages.push_back(record);
    observers.emit({.kind = EventKind::stage_end, .state = record.end, .stage = stage_name});
    lost = ever_in_contact && (end.pressed == 0 || flight || unglued_loss);
    if (result.stop_reason || flight || unglued_loss || shear_lost ||
        (shear_force_held && drive.shear_unheld())) {
      break;
    }
  }
  if (reached_row_end) {
    result.warnings.push_back(fmt::format(
        "the contact reached the row's last spring (x = {:.6g} m): the row ends there, so the "
        "force beyond it is too small",
        row_end));
  }
  result.work = total;
  result.energy = total_energy;
  result.counts.events = drive.counts().events();
  if (!result.stop_reason) {
    // Without glue the contact is lost at zero force: no critical point (docs/programs.md
    // "How a program ends"); a contact lost after its glue ends as the cascade that lost the
    // glue decides.
    result.status = lost ? RunStatus::no_instability : RunStatus::completed;
    if (shear_lost) {
      // The held F_x lost its last glued spring: as an elastic program's (the glue's loss
      // decides; by shear alone a shear-off).
      result.sliding = true;
      if (jumps.glue_loss()) {
        ViscoelasticJumps::decide(*jumps.glue_loss(), spec.zero.contact_force, result);
        if (jumps.glue_loss()->changes < 2) result.status = RunStatus::shear_off;
      } else {
        result.status = RunStatus::no_instability;
        result.warnings.push_back(fmt::format(
            "stage '{}': fixed-load holds F_x = {:.6g} N with no glued spring: the program ends "
            "here",
            stage_name, held_shear_force));
      }
    } else if (lost && jumps.glue_loss()) {
      ViscoelasticJumps::decide(*jumps.glue_loss(), spec.zero.contact_force, result);
      if (result.critical) fold.locate(*jumps.glue_loss(), result);
    }
  }
  if (const auto& peak = jumps.most_tensile(); peak && peak->force < -spec.zero.force) {
    result.peak = viscoelastic_snapshot(*peak);
  }
  return result;
}

}  // namespace mdrsim
