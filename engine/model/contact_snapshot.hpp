// The observable state of the contact at one moment, in SI units.
#pragma once

#include <cstdint>

namespace mdrsim {

struct ContactSnapshot {
  double normal_control = 0.0;           ///< value held by the normal controller [m or N]
  double indentation = 0.0;              ///< d, positive into the half-space [m]
  double normal_force = 0.0;             ///< F_z, positive pressing [N]
  double contact_radius = 0.0;           ///< a [m]
  double tangential_displacement = 0.0;  ///< u_x [m]
  double tangential_force = 0.0;         ///< F_x [N]
  std::int64_t springs_in_contact = 0;   ///< attached springs of one half
  /// With friction (docs/friction.md): springs of one half sliding, and the radius inside
  /// which every spring in contact sticks (the contact radius when none slides) [m].
  std::int64_t springs_sliding = 0;
  double stick_radius = 0.0;
  /// The normal and tangential force of the outermost spring in contact (both halves) [N]:
  /// how far the row's force can sit from the continuum's for the front's place between two
  /// springs. Set by loading programs' rows; rtol adds it to its estimates.
  double edge_normal_force = 0.0;
  double edge_tangential_force = 0.0;
  /// Loading programs: the radius out to which the springs in contact are glued [m] (the
  /// contact radius when all are, 0 when none); negative where every spring in contact is
  /// glued by construction (the shorthand). The disk check asks for p >= 0 beyond it.
  double glued_radius = -1.0;
  /// Whether the MDR's one contact disk holds at this state (engine/model/disk_validity):
  /// set on reported states after a run; true where the profile's shape guarantees it.
  bool disk_valid = true;
  /// With finite-range adhesion (docs/maugis.md): c, the outer radius of the cohesive zone, out
  /// to which the Dugdale stress pulls [m] (0 where nothing pulls).
  double cohesive_radius = 0.0;
  /// Timed loading programs (docs/programs.md "Time"): the time since the program started [s];
  /// 0 elsewhere, and not reported.
  double time = 0.0;
};

}  // namespace mdrsim
