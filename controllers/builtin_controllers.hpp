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
  bool holds_force() const override { return false; }
  bool drives_through_spring() const override { return false; }
  bool is_fixed_grips() const override { return true; }
};

/// Holds the force: a soft machine.
class FixedLoadController final : public AxisController {
 public:
  AffineConstraint constraint() const override { return {0.0, 1.0}; }
  std::string_view held_value_key() const override { return "force"; }
  bool holds_force() const override { return true; }
  bool drives_through_spring() const override { return false; }
  bool is_fixed_grips() const override { return false; }
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
  bool holds_force() const override { return false; }
  /// Through a spring for every finite k; k = inf is fixed grips (1 / k = 0).
  bool drives_through_spring() const override { return 1.0 / stiffness_ > 0.0; }
  bool is_fixed_grips() const override { return 1.0 / stiffness_ == 0.0; }

 private:
  double stiffness_;  ///< k [N/m]
};

}  // namespace mdrsim
