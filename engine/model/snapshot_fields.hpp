// The critical point's quantities in one table: names, symbols, units and scales for every output.
#pragma once

#include <array>
#include <stdexcept>

#include "engine/base/pull_off_scales.hpp"
#include "engine/model/contact_snapshot.hpp"
#include "engine/model/jkr_scales.hpp"

namespace mdrsim {

/// Which JKR scale makes a quantity dimensionless (paper eq. 16).
enum class ScaleKind { force, radius, depth };

/// F0, a0 or d0 of either scales type (both name them force, radius, depth).
template <class Scales>
inline double scale_of(const Scales& s, ScaleKind kind) {
  switch (kind) {
    case ScaleKind::force:
      return s.force;
    case ScaleKind::radius:
      return s.radius;
    case ScaleKind::depth:
      break;
  }
  return s.depth;
}

/// The scale's key in the result's `scales` (the JSON's and Python's), as PullOffScales names it.
inline const char* scale_key(ScaleKind kind) {
  switch (kind) {
    case ScaleKind::force:
      return "force";
    case ScaleKind::radius:
      return "radius";
    case ScaleKind::depth:
      break;
  }
  return "depth";
}

inline const char* scale_symbol(ScaleKind kind) {
  switch (kind) {
    case ScaleKind::force:
      return "F0";
    case ScaleKind::radius:
      return "a0";
    case ScaleKind::depth:
      break;
  }
  return "d0";
}

struct SnapshotField {
  const char* name;    ///< JSON key and CSV column (docs)
  const char* symbol;  ///< in the run summary
  const char* unit;    ///< SI
  ScaleKind scale;
  double ContactSnapshot::*member;
};

/// The physical quantities of a snapshot, in the order of docs/outputs.md: the JSON's `critical`
/// and `dimensionless`, the sweep's columns, the summary, the finiteness checks, Python's states.
inline constexpr std::array<SnapshotField, 5> kSnapshotFields{{
    {"normal_force", "F", "N", ScaleKind::force, &ContactSnapshot::normal_force},
    {"tangential_force", "Fx", "N", ScaleKind::force, &ContactSnapshot::tangential_force},
    {"contact_radius", "a", "m", ScaleKind::radius, &ContactSnapshot::contact_radius},
    {"indentation", "d", "m", ScaleKind::depth, &ContactSnapshot::indentation},
    {"tangential_displacement", "ux", "m", ScaleKind::depth,
     &ContactSnapshot::tangential_displacement},
}};

/// The field of kSnapshotFields that reads `member` (a compile error where none does).
constexpr const SnapshotField& snapshot_field(double ContactSnapshot::*member) {
  for (const SnapshotField& f : kSnapshotFields) {
    if (f.member == member) return f;
  }
  throw std::logic_error("snapshot_field: not a field of kSnapshotFields");
}

/// The fields in the order of a trajectory row (docs/outputs.md, "The trajectory CSV"): the
/// CSV's columns and Python's trajectory arrays.
inline constexpr std::array<SnapshotField, 5> kTrajectoryFields{
    snapshot_field(&ContactSnapshot::indentation), snapshot_field(&ContactSnapshot::normal_force),
    snapshot_field(&ContactSnapshot::contact_radius),
    snapshot_field(&ContactSnapshot::tangential_displacement),
    snapshot_field(&ContactSnapshot::tangential_force)};

/// Every quantity that varies smoothly along the branch: the fields above, the normal control
/// value, the cohesive zone's radius and the time (affine in the stage parameter, as the held
/// values are). Interpolation between springs and extrapolation across rows use these.
inline constexpr std::array<double ContactSnapshot::*, 8> kBranchQuantities{
    &ContactSnapshot::normal_control,   &ContactSnapshot::normal_force,
    &ContactSnapshot::tangential_force, &ContactSnapshot::contact_radius,
    &ContactSnapshot::indentation,      &ContactSnapshot::tangential_displacement,
    &ContactSnapshot::cohesive_radius,  &ContactSnapshot::time};

}  // namespace mdrsim
