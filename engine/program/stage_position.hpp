// Where a program row stands in the stage under way: the row, the stage parameter t on the
// stage's line, the guards at t and the stage's work so far; moved along the line exactly.
#pragma once

#include <cmath>
#include <utility>

#include "engine/model/compensated_sum.hpp"
#include "engine/model/machine_work.hpp"
#include "engine/program/program_front.hpp"
#include "engine/program/program_row.hpp"
#include "engine/program/program_step.hpp"
#include "engine/result/program_records.hpp"
#include "engine/scene/program.hpp"

namespace mdrsim {

struct StagePosition {
  explicit StagePosition(ProgramRow r) : row(std::move(r)) {}

  ProgramRow row;
  const Stage* stage = nullptr;  ///< the stage under way
  double t = 0.0;
  StageLine line;              ///< held = start + rate * t on each axis
  SameParameterGuards guards;  ///< program_step.hpp
  AxisWork work;               ///< the machine's and friction's work in the stage [J]
  /// What the stage's energy balance needs beyond its work [J]. Its changes' release: at each
  /// glue and let-go, the machine's work there less its change of stored energy and friction's
  /// work. The surface changes only there, so the jump losses are the release less the stage's
  /// surface change, and no change looks the surface up.
  struct EnergyTally {
    double stored_at_start = 0.0;   ///< ProgramRow::stored_energy as the stage started
    double surface_at_start = 0.0;  ///< ProgramRow::glued_surface as the stage started
    /// ProgramRow::changes_stay_local for the stage (its axes' controls and friction are set
    /// as it starts): each change's release is then its own spring's, which the row sums.
    bool local = false;
    double row_released_at_start = 0.0;  ///< ProgramRow::released_by_changes then
    CompensatedSum released;             ///< otherwise: add_release's sum
  };
  EnergyTally energy;
  /// The stage's changes' release so far [J].
  double released() const {
    return energy.local ? row.released_by_changes() - energy.row_released_at_start
                        : energy.released.value();
  }
  /// The energies a change of the row moves.
  struct EnergyPoint {
    double machine_work, friction, stored;
  };
  EnergyPoint energy_point() const {
    return {work.normal + work.tangential, work.friction, row.stored_energy()};
  }
  /// Adds what the row's changes since `before` released, where they do not stay local (they
  /// move an axis or slip springs: the whole row's stored energy, before and after).
  void add_release(const EnergyPoint& before) {
    const EnergyPoint now = energy_point();
    energy.released.add((now.machine_work - before.machine_work) - (now.stored - before.stored) -
                        (now.friction - before.friction));
  }
  /// The stage's balance, its end's stored energy, glued surface and released() given [J].
  EnergyBalance balance(double stored, double surface, double released) const;

  /// Starts `next` at t = 0 on the line its axes' motions give from the present held values.
  void start(const Stage& next);
  /// Moves along the line to t with no change on the way; false where the work left the
  /// range of a double.
  bool advance_to(double to);
  /// A force or displacement beyond a double makes the work of its moving axis so.
  bool work_within_double() const {
    return std::isfinite(work.normal) && std::isfinite(work.tangential);
  }
  /// The driving points of the axes, for the work of a change (machine_work.hpp).
  AxisPoint normal_point() const {
    return {row.normal_force(),
            driving_point(row.normal().constraint, row.normal().held, row.indentation())};
  }
  AxisPoint tangential_point() const {
    return {row.tangential_force(),
            driving_point(row.tangential().constraint, row.tangential().held,
                          row.tangential_displacement())};
  }
  /// Adds the work from the given points (an axis not given did not move) to the present
  /// state: force and driving point are affine in between (the springs stay), so the
  /// trapezoid is exact.
  void add_work(const AxisPoint* normal_from, const AxisPoint* tangential_from) {
    if (normal_from) work.normal += trapezoid_work(*normal_from, normal_point());
    if (tangential_from) work.tangential += trapezoid_work(*tangential_from, tangential_point());
  }

 private:
  void set_parameter(double to);
};

}  // namespace mdrsim
