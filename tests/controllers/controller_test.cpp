// The affine constraint of each controller and the one-division equilibrium it gives.
#include "controllers/controller.hpp"

#include <gtest/gtest.h>

#include "controllers/builtin_controllers.hpp"
#include "controllers/controller_registry.hpp"

using mdrsim::AffineConstraint;
using mdrsim::LinearResponse;

TEST(Controllers, RegistryHoldsTheThreeBuiltins) {
  mdrsim::ControllerRegistry registry;
  mdrsim::register_builtin_controllers(registry);
  EXPECT_EQ(registry.names(), (std::vector<std::string>{"compliant", "fixed-grips", "fixed-load"}));
}

// Equilibrium by one division solves the constraint, and held_value_at inverts it.
TEST(Controllers, EquilibriumSolvesTheConstraint) {
  const LinearResponse contact{250.0, 0.7};  // F = 250 u - 0.7
  for (const AffineConstraint c :
       {mdrsim::FixedGripsController().constraint(), mdrsim::FixedLoadController().constraint(),
        mdrsim::CompliantController(40.0).constraint()}) {
    for (const double held : {-1e-3, 0.0, 2e-3}) {
      const double u = mdrsim::displacement_under(c, contact, held);
      const double f = contact.stiffness * u - contact.offset;
      EXPECT_NEAR(c.displacement_coefficient * u + c.force_coefficient * f, held, 1e-15);
      EXPECT_NEAR(mdrsim::held_value_at(c, contact, u), held, 1e-15);
    }
  }
}

// The machine spring: F = k (w - u), and its two limits.
TEST(Controllers, CompliantSpringAndItsLimits) {
  const LinearResponse contact{250.0, 0.7};
  const double w = 3e-3;
  const double k = 40.0;
  const double u =
      mdrsim::displacement_under(mdrsim::CompliantController(k).constraint(), contact, w);
  EXPECT_NEAR(contact.stiffness * u - contact.offset, k * (w - u), 1e-14);
  EXPECT_NEAR(
      mdrsim::displacement_under(mdrsim::CompliantController(1e12).constraint(), contact, w), w,
      1e-12);
  // k -> 0 with w = F/k holds the force F: the spring barely changes length as u moves.
  const double held_force = 2e-3;
  const double k_soft = 1e-9;
  const double u_soft = mdrsim::displacement_under(mdrsim::CompliantController(k_soft).constraint(),
                                                   contact, held_force / k_soft);
  EXPECT_NEAR(contact.stiffness * u_soft - contact.offset, held_force,
              1e-9 * std::abs(u_soft) + 1e-15);
  EXPECT_THROW(mdrsim::CompliantController(0.0), std::invalid_argument);
}
