// What a loading program reports besides the critical point: stage ends, jumps and work.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "engine/model/contact_snapshot.hpp"

namespace mdrsim {

/// The work done by the machine on each axis [J]: the integral of the force over the
/// displacement of the machine's driving point (docs/programs.md).
struct AxisWork {
  double normal = 0.0;
  double tangential = 0.0;
  /// The part of the work friction dissipated: the slip limit times each slip distance,
  /// summed (docs/friction.md `dissipated_by_friction`) [J].
  double friction = 0.0;
  /// The part of it the rate law's front dissipated: int (G - dgamma) 2 pi a |da|
  /// (docs/rate_law.md `dissipated_at_front`) [J].
  double front = 0.0;
  /// The part of the work a relaxing bulk's dashpots dissipated (docs/viscoelastic.md
  /// `dissipated_by_bulk`) [J].
  double bulk = 0.0;
  AxisWork& operator+=(const AxisWork& more) {
    normal += more.normal;
    tangential += more.tangential;
    friction += more.friction;
    front += more.front;
    bulk += more.bulk;
    return *this;
  }
};

/// The energy balance of a stage, or of the program (docs/outputs.md, "energy"), each term
/// computed on its own, so that machine_work = stored_change + surface_change +
/// dissipated_by_friction + dissipated_by_bulk + jump_losses + residual, the residual rounding [J].
/// A term a later physics adds (a viscous loss) is one more field here and one more key.
struct EnergyBalance {
  double machine_work = 0.0;   ///< the machine's work on both axes (AxisWork's normal + tangential)
  double stored_change = 0.0;  ///< the springs' elastic energy (a compliant machine's included)
  /// Surface energy created: 2 pi x dgamma dx over the springs whose glue went, less over
  /// those that glued.
  double surface_change = 0.0;
  double dissipated_by_friction = 0.0;  ///< AxisWork::friction
  double dissipated_by_bulk = 0.0;      ///< AxisWork::bulk
  /// What the row's changes at one parameter value (glues and let-gos) lost: the machine's
  /// work there less their change of stored, surface and friction energy; >= 0 (to rounding).
  double jump_losses = 0.0;
  double residual = 0.0;  ///< machine_work less the other terms
  EnergyBalance& operator+=(const EnergyBalance& more) {
    machine_work += more.machine_work;
    stored_change += more.stored_change;
    surface_change += more.surface_change;
    dissipated_by_friction += more.dissipated_by_friction;
    dissipated_by_bulk += more.dissipated_by_bulk;
    jump_losses += more.jump_losses;
    residual += more.residual;
    return *this;
  }
};

struct StageRecord {
  std::string name;
  ContactSnapshot end;  ///< the state at the stage's end (or where the contact was lost)
  AxisWork work;
  /// The stage's energy balance (program rows).
  std::optional<EnergyBalance> energy;
  /// `end` with the row's front located between springs (rows run to be extrapolated).
  std::optional<ContactSnapshot> refined_end;
  /// With rtol: a posteriori bounds on |reported - continuum| of the end's forces [N].
  std::optional<double> normal_force_error_estimate;
  std::optional<double> tangential_force_error_estimate;
  /// Timed programs whose stage ends with the contact (viscoelastic rows under Richardson or
  /// rtol): the same for `end.time` [s].
  std::optional<double> time_error_estimate;
  /// With rtol or Richardson: a posteriori bounds on |reported - continuum| of `work` [J].
  std::optional<AxisWork> work_error_estimate;
};

/// Where a jump lands: an equilibrium, or none because a held fixed load lost what held it
/// (docs/programs.md "A fixed load that loses the contact"), and `after` holds nothing: the
/// indenter separates under a held tension or slides away under a held tangential force; or,
/// for the shorthand only, it stays pressed in under a held compression once the glue is gone,
/// on springs pressed back that the shorthand's row does not follow.
enum class JumpEnd { state, separated, sliding, pressed };

/// The name of a jump's end, as the JSON's `after` key and Python's `end` spell it.
inline const char* to_string(JumpEnd end) {
  switch (end) {
    case JumpEnd::separated:
      return "separated";
    case JumpEnd::sliding:
      return "sliding";
    case JumpEnd::pressed:
      return "pressed";
    case JumpEnd::state:
      break;
  }
  return "state";
}

/// A cascade of springs gluing or letting go at one value of the stage parameter.
struct JumpRecord {
  std::string stage;
  bool inward = false;       ///< "in": the contact grew; "out": it shrank
  ContactSnapshot critical;  ///< the last equilibrium before the jump
  ContactSnapshot after;     ///< the equilibrium after it (end == state only)
  JumpEnd end = JumpEnd::state;
  std::int64_t springs = 0;        ///< change of the springs in contact
  std::int64_t glued_springs = 0;  ///< change of the glued springs
  bool by_shear = false;  ///< the first spring due after the critical point broke at zero stretch
  /// `critical` and `after` with the row's front located between springs (rows run to be
  /// extrapolated), where the branch allows it.
  std::optional<ContactSnapshot> refined_critical;
  std::optional<ContactSnapshot> refined_after;
  /// With rtol: a posteriori bounds on |reported - continuum| of the normal force at the
  /// critical point and after the jump [N].
  std::optional<double> critical_error_estimate;
  std::optional<double> after_error_estimate;
};

}  // namespace mdrsim
