// How a pull-off goes on once its last spring has let go: the rule the shorthand's row and the
// continuum route share (docs/programs.md "A fixed load that loses the contact").
#pragma once

#include <string>

#include "controllers/controller.hpp"
#include "engine/model/contact.hpp"
#include "engine/result/program_records.hpp"

namespace mdrsim {

/// How the pull-off of a contact that ended in `lost` (no spring left) goes on: under a
/// fixed load that holds a tension the indenter separates (one that holds a
/// compression presses it in on springs without glue, which the row does not follow); under a
/// tangential fixed load that holds a force it slides away (docs/programs.md "A fixed load that
/// loses the contact"); otherwise the machine holds it where the last spring left it, which
/// is pressed in too where that indentation is beyond `first_image`, g at the first spring
/// [m]: the glue sheared off under compression, and the springs pressed back carry a force
/// the row does not follow either.
JumpEnd shorthand_flight(const Contact::State& lost, const AffineConstraint& normal,
                         const AffineConstraint& tangential, double first_image);
/// The same rule from the held values alone, once no spring is left (the continuum route's,
/// with g(0) for `first_image`).
JumpEnd lost_contact_flight(const AffineConstraint& normal, double normal_held,
                            const AffineConstraint& tangential, double tangential_held,
                            double first_image);
/// "force 0.0207 N" or "value 6e-07 m": the held normal value in its unit, for the warning
/// that the shorthand does not follow a contact left pressed in.
std::string held_normal_text(const AffineConstraint& normal, double held);

}  // namespace mdrsim
