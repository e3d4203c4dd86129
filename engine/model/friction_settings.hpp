// The scene's [friction] table: the Coulomb coefficient and what a glued spring does under shear.
#pragma once

#include <memory>

#include "friction/friction_law.hpp"

namespace mdrsim {

/// What a glued spring does under tangential load (docs/friction.md): the scene's
/// glued = "unlimited" or "coulomb".
enum class GluedShear {
  unlimited,  ///< holds any stretch until the detachment criterion lets it go (the paper's model)
  limited,  ///< slides, staying glued, where |f_x| > mu max(f_z, 0) + 2 tau_0 sqrt(a_g^2 - x^2) dx
};

/// The scene's [friction] table.
struct FrictionSettings {
  double coefficient = 0.0;  ///< mu >= 0 [1]
  GluedShear glued = GluedShear::unlimited;
  double shear_strength = 0.0;  ///< tau_0 [Pa], with GluedShear::limited
  /// The springs' law where it is not Coulomb's at `coefficient` (which glued springs under
  /// GluedShear::limited keep): each spring's limit from it as it touches, its slips spring by
  /// spring.
  std::shared_ptr<const FrictionLaw> law;
};

}  // namespace mdrsim
