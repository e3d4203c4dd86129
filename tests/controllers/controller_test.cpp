// The affine constraint of each controller and the one-division equilibrium it gives.
#include "controllers/controller.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

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

// The questions the engine asks instead of comparing names: each built-in answers them as its
// constraint does (one rule: fixed load a_u = 0, compliant a_u, a_F > 0, fixed grips a_F = 0),
// and an outside controller that answers none gets its constraint's answers.
TEST(Controllers, QuestionsAgreeWithTheConstraint) {
  struct Answers {
    bool force;
    bool spring;
    bool grips;
  };
  const auto answers = [](const mdrsim::AxisController& c) {
    return Answers{c.holds_force(), c.drives_through_spring(), c.is_fixed_grips()};
  };
  const auto of_constraint = [](const mdrsim::AxisController& c) {
    const AffineConstraint k = c.constraint();
    return Answers{mdrsim::holds_force(k), mdrsim::drives_through_spring(k),
                   mdrsim::is_fixed_grips(k)};
  };
  struct Outside final : mdrsim::AxisController {
    AffineConstraint constraint() const override { return {0.0, 2.0}; }  // a load cell
    std::string_view held_value_key() const override { return "force"; }
  };
  const mdrsim::FixedGripsController grips;
  const mdrsim::FixedLoadController load;
  const mdrsim::CompliantController spring(40.0);
  const mdrsim::CompliantController infinitely_stiff(INFINITY);  // 1 / k = 0: fixed grips
  const Outside outside;
  const std::vector<std::pair<const mdrsim::AxisController*, Answers>> expected{
      {&grips, {false, false, true}},
      {&load, {true, false, false}},
      {&spring, {false, true, false}},
      {&infinitely_stiff, {false, false, true}},
      {&outside, {true, false, false}}};
  for (const auto& [controller, want] : expected) {
    for (const Answers got : {answers(*controller), of_constraint(*controller)}) {
      EXPECT_EQ(got.force, want.force);
      EXPECT_EQ(got.spring, want.spring);
      EXPECT_EQ(got.grips, want.grips);
    }
  }
}

// The unit of the held value follows its key: m for a displacement, N for a force.
TEST(Controllers, HeldValueUnitFollowsTheKey) {
  EXPECT_STREQ(mdrsim::FixedGripsController().held_value_unit(), "m");
  EXPECT_STREQ(mdrsim::FixedLoadController().held_value_unit(), "N");
  EXPECT_STREQ(mdrsim::CompliantController(40.0).held_value_unit(), "m");
  struct Outside final : mdrsim::AxisController {
    AffineConstraint constraint() const override { return {1.0, 0.0}; }
    std::string_view held_value_key() const override { return "angle"; }
  };
  EXPECT_STREQ(Outside().held_value_unit(), "SI");
}
