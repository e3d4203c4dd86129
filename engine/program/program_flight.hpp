// A fixed load that nothing holds any more: when an axis of a program row cannot hold its load,
// and the flight that a cascade losing that hold ends in (docs/programs.md "A fixed load that
// loses the contact").
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "engine/model/contact_snapshot.hpp"
#include "engine/program/program_cascade.hpp"
#include "engine/program/program_front.hpp"
#include "engine/program/program_row.hpp"
#include "engine/result/program_records.hpp"

namespace mdrsim {

/// A flight that ended the program; its stage ends at the cascade's critical point.
struct Flight {
  JumpEnd end = JumpEnd::state;                 ///< state: no flight
  ContactSnapshot from;                         ///< the critical point, where the last stage ends
  std::optional<ContactSnapshot> refined_from;  ///< `from` located between springs
  double stored_from = 0.0;                     ///< the stored energy at `from` [J]
  double surface_from = 0.0;                    ///< the glued surface at `from` [J]
  double released_from = 0.0;                   ///< StagePosition::released at `from` [J]

  bool flying() const { return end != JumpEnd::state; }
};

/// Whether a fixed-load axis holds a force that nothing holds: a tension (or a pull about to
/// start) with no spring in contact, a tangential force with nothing glued.
inline bool normal_cannot_hold(const ProgramRow& row, const AxisMotion& normal) {
  if (row.normal_has_stiffness() || row.in_contact() != 0) return false;
  const double held = row.normal().held;
  // Zero to the rounding of the held line's value (start + rate t, to a few eps of its terms):
  // a falling force whose last spring lifts within that of zero has lost the contact there.
  const double zero = 8.0 * std::numeric_limits<double>::epsilon() *
                      (std::abs(normal.start) + std::abs(normal.rate));
  return held < 0.0 || (held <= zero && normal.rate < 0.0);
}
inline bool tangential_cannot_hold(const ProgramRow& row, const AxisMotion& tangential) {
  return !row.tangential_has_stiffness() &&
         (row.tangential().held != 0.0 || tangential.rate != 0.0);
}
inline bool cannot_hold(const ProgramRow& row, const StageLine& line) {
  return normal_cannot_hold(row, line.normal) || tangential_cannot_hold(row, line.tangential);
}

/// How a cascade that just ran ends: with the contact lost under a fixed load that nothing
/// holds any more, in a flight.
inline JumpEnd flight_of(const Cascade& cascade, const ProgramRow& row, const StageLine& line) {
  if (cascade.in_contact > 0 && row.in_contact() == 0 && normal_cannot_hold(row, line.normal)) {
    return JumpEnd::separated;
  }
  if (cascade.glued > 0 && row.glued() == 0 && tangential_cannot_hold(row, line.tangential)) {
    return JumpEnd::sliding;
  }
  return JumpEnd::state;
}

}  // namespace mdrsim
