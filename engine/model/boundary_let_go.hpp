// When the boundary spring lets go, expressed as a value of the normal controller.
#pragma once

#include "detachment/criterion.hpp"
#include "detachment/let_go.hpp"
#include "engine/model/contact.hpp"

namespace mdrsim {

struct BoundaryLetGo {
  LetGo let_go;               ///< where the criterion lets go, in elongation
  double normal_control = 0;  ///< the normal held value at which it does (at_elongation only)
};

/// Locates the let-go of the boundary spring of a contact with at least one spring.
/// With the attached springs fixed, the tangential displacement does not depend on the
/// normal control, so the criterion's critical elongation e gives the indentation
/// d = g(a) - e and the control value follows from the constraint.
BoundaryLetGo locate_boundary_let_go(const Contact& contact, const DetachmentCriterion& criterion);

/// Throws std::runtime_error naming the radius where `go` is LetGo::Kind::never: a criterion
/// that never lets go of the boundary spring at contact radius a [m] is faulty (both engines
/// ask this after every let-go they locate).
void require_let_go(const LetGo& go, double contact_radius);

/// The criterion evaluated at the contact's current state, as the paper's stepping does:
/// the spring lets go when its margin is <= 0 while stretched, or < 0 at zero elongation.
bool boundary_lets_go_now(const Contact& contact, const DetachmentCriterion& criterion);

/// The boundary spring's normal stretch -u_z at the contact's current state, 0 if compressed.
double boundary_elongation(const Contact& contact);

}  // namespace mdrsim
