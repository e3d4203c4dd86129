// Where a boundary spring lets go: at an elongation, at once (shear), or never.
#pragma once

#include "detachment/criterion.hpp"

namespace mdrsim {

struct LetGo {
  enum class Kind {
    at_elongation,  ///< once the spring is stretched by `elongation`
    now,            ///< at once, even compressed: the tangential load alone breaks it
    never,          ///< the criterion never lets go (a faulty user criterion)
  };
  Kind kind;
  double elongation = 0.0;  ///< [m], for at_elongation
  int root_iterations = 0;  ///< iterations of the bracketing root search, 0 for closed forms
};

/// Locates the let-go of a boundary spring at contact radius a [m] with tangential
/// displacement u_x [m]. `elongation_scale` [m] > 0 seeds the bracket of the root search.
LetGo locate_let_go(const DetachmentCriterion& criterion, double contact_radius,
                    double tangential_displacement, double elongation_scale);

}  // namespace mdrsim
