// Coulomb's law: a spring slides at mu max(f_z, 0), the same coefficient everywhere.
#pragma once

#include <optional>

#include "friction/friction_law.hpp"

namespace mdrsim {

/// The built-in law (`law = "coulomb"`, key `coefficient`): the MDR image of the 3D law |tau| <=
/// mu p for any body of revolution (docs/friction.md).
class CoulombFriction final : public FrictionLaw {
 public:
  explicit CoulombFriction(double coefficient) : coefficient_(coefficient) {}
  SlipLimit limit_at(double /*radius*/, double /*spacing*/) const override {
    return {coefficient_, 0.0};
  }
  std::optional<double> uniform_coefficient() const override { return coefficient_; }

 private:
  double coefficient_;  ///< mu >= 0 [1]
};

}  // namespace mdrsim
