// Let-go of the boundary spring, in elongation (criterion) and in control value (constraint).
#include "engine/model/boundary_let_go.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/model/graded_constants.hpp"

namespace mdrsim {

void require_let_go(const LetGo& go, double contact_radius) {
  if (go.kind != LetGo::Kind::never) return;
  throw std::runtime_error(fmt::format(
      "the detachment criterion never lets go of the boundary spring at a = {} m", contact_radius));
}

namespace {

/// Hess's rule on the graded springs (docs/graded.md): a graded row takes no criterion, as the
/// scene refuses [detachment] with grading and loads it normally only.
LetGo graded_let_go(const Contact& contact) {
  const SpringFoundation& row = contact.foundation();
  const double a = contact.contact_radius();
  return {
      .kind = LetGo::Kind::at_elongation,
      .elongation = graded_let_go_stretch(row.graded()->grading_exponent(), row.punch_constant(),
                                          contact.material().work_of_adhesion_at(a), a)};
}

}  // namespace

BoundaryLetGo locate_boundary_let_go(const Contact& contact, const DetachmentCriterion& criterion) {
  const double a = contact.contact_radius();
  const double ux = contact.tangential_displacement();
  // Only a root search needs the scale, and it widens its bracket from there.
  const double scale = std::abs(ux) + contact.foundation().spacing();
  BoundaryLetGo out{contact.foundation().graded() ? graded_let_go(contact)
                                                  : locate_let_go(criterion, a, ux, scale)};
  if (out.let_go.kind == LetGo::Kind::at_elongation) {
    out.normal_control =
        contact.normal_control_at(contact.boundary_image() - out.let_go.elongation);
  }
  return out;
}

double boundary_elongation(const Contact& contact) {
  return std::max(0.0, contact.boundary_image() - contact.indentation());
}

bool boundary_lets_go_now(const Contact& contact, const DetachmentCriterion& criterion) {
  const double a = contact.contact_radius();
  const double ux = contact.tangential_displacement();
  if (contact.foundation().graded()) {
    return contact.boundary_image() - contact.indentation() >= graded_let_go(contact).elongation;
  }
  if (broken_at_rest(criterion, ux, a)) return true;
  const double stretch = contact.boundary_image() - contact.indentation();
  return stretch >= 0.0 && criterion.margin({stretch, ux, a}) <= 0.0;
}

}  // namespace mdrsim
