// A friction law: the slip limit of each spring in contact that is not glued (docs/friction.md
// "Friction laws"). Coulomb's law is the built-in one; a user may register their own.
#pragma once

#include <optional>

namespace mdrsim {

/// A spring's slip limit, mu max(f_z, 0) + constant: linear in its normal force f_z on each side
/// of 0, so that along a loading program's line (d and u_x linear in its parameter) every slip
/// and every stick is the root of a linear function, located exactly.
struct SlipLimit {
  double coefficient = 0.0;  ///< mu >= 0 [1]
  double constant = 0.0;     ///< >= 0, what the spring holds with no normal force [N]
};

/// Velocity-independent: a spring's limit depends on where it sits, never on how fast it slides.
class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;
  /// The limit of the spring at radius `radius` [m] of a row of spacing `spacing` [m] (the
  /// spring's width: a constant per unit length times `spacing`). Called once per spring as it
  /// touches; >= 0 each.
  virtual SlipLimit limit_at(double radius, double spacing) const = 0;
  /// The coefficient where every spring has it and no constant (Coulomb's law): the engine then
  /// keeps its springs on ordered slip keys, O(log m) per event. None otherwise: spring by
  /// spring, O(m) per event.
  virtual std::optional<double> uniform_coefficient() const { return std::nullopt; }
};

}  // namespace mdrsim
