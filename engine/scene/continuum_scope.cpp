// The continuum route's reach: shorthand scenes on the convex classic profiles; else the row.
#include "engine/scene/continuum_scope.hpp"

namespace mdrsim {

bool continuum_answers(const Scene& scene) {
  // One fold on the branch: the shapes that are always one disk (convex classics). A table
  // or a ripple may fold several times; the row follows every jump.
  return !scene.program && scene.profile->always_one_disk();
}

}  // namespace mdrsim
