// The built-in controllers: fixed-grips, fixed-load and compliant (a machine spring).
#pragma once

#include <stdexcept>

#include "controllers/controller.hpp"

namespace mdrsim {

/// Holds the displacement: a stiff machine.
class FixedGripsController final : public AxisController {
 public:
  AffineConstraint constraint() const override { return {1.0, 0.0}; }
  std::string_view held_value_key() const override { return "displacement"; }
};

/// Holds the force: a soft machine.
class FixedLoadController final : public AxisController {
 public:
  AffineConstraint constraint() const override { return {0.0, 1.0}; }
  std::string_view held_value_key() const override { return "force"; }
};

/// Drives the indenter through a spring of stiffness k: F = k (w - u), so u + F/k = w, the
/// held machine displacement. k -> infinity is fixed-grips, k -> 0 fixed-load.
class CompliantController final : public AxisController {
 public:
  explicit CompliantController(double stiffness) : stiffness_(stiffness) {
    if (!(stiffness > 0.0)) throw std::invalid_argument("stiffness must be positive");
  }
  AffineConstraint constraint() const override { return {1.0, 1.0 / stiffness_}; }
  std::string_view held_value_key() const override { return "displacement"; }

 private:
  double stiffness_;  ///< k [N/m]
};

}  // namespace mdrsim
