// A held tension separates, a held tangential force slides away, a held compression (or a
// machine past the first spring) leaves the indenter pressed in on springs without glue.
#include "engine/result/lost_contact.hpp"

#include <fmt/format.h>

namespace mdrsim {

JumpEnd shorthand_flight(const Contact::State& lost, const AffineConstraint& normal,
                         const AffineConstraint& tangential, double first_image) {
  if (lost.springs_in_contact > 0) return JumpEnd::state;
  return lost_contact_flight(normal, lost.normal_control, tangential, lost.tangential_held,
                             first_image);
}

JumpEnd lost_contact_flight(const AffineConstraint& normal, double normal_held,
                            const AffineConstraint& tangential, double tangential_held,
                            double first_image) {
  // The held normal value falls during the pull-off: a fixed load at zero pulls next. A held
  // compression (Fig. 3a's positive branch, or the glue sheared off as the tangential load
  // was applied) pushed the row's last spring ever deeper instead, by F / (E* dx).
  if (holds_force(normal) && normal_held <= 0.0) return JumpEnd::separated;
  // Springs pressed without glue (and without friction) hold no tangential force.
  if (holds_force(tangential) && tangential_held != 0.0) return JumpEnd::sliding;
  if (holds_force(normal)) return JumpEnd::pressed;
  // With no spring the machine's force is zero: the indentation is the held value over a_u,
  // pressed in past the first spring where a glue sheared off under compression.
  if (normal_held / normal.displacement_coefficient > first_image) return JumpEnd::pressed;
  return JumpEnd::state;
}

std::string held_normal_text(const AffineConstraint& normal, double held) {
  return holds_force(normal) ? fmt::format("force {:.6g} N", held)
                             : fmt::format("value {:.6g} m", held);
}

}  // namespace mdrsim
