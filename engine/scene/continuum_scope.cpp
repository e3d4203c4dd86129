// The continuum route's reach: the shorthand; programs stay on the spring row for now.
#include "engine/scene/continuum_scope.hpp"

namespace mdrsim {

bool continuum_answers(const Scene& scene) { return !scene.program; }

}  // namespace mdrsim
