// The scene's [friction] table: the Coulomb coefficient and what a glued spring does under shear.
#pragma once

namespace mdrsim {

/// What a glued spring does under tangential load (docs/friction.md).
enum class GluedLaw {
  unlimited,  ///< holds any stretch until the detachment criterion lets it go (the paper's model)
  coulomb,    ///< slides, staying glued, where |f_x| > mu max(f_z, 0) + tau_0 dx
};

/// The scene's [friction] table.
struct FrictionSettings {
  double coefficient = 0.0;  ///< mu >= 0 [1]
  GluedLaw glued = GluedLaw::unlimited;
  double shear_strength = 0.0;  ///< tau_0 [Pa], with GluedLaw::coulomb
};

}  // namespace mdrsim
