// dgamma(r): a table's linear pieces, steps and ends, the sinusoid, the uniform limits to the
// bit, and the comparison of dgamma_a with dgamma.
#include "engine/base/radial_adhesion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mdrsim {
namespace {

TEST(RadialAdhesionTable, LinearBetweenPointsConstantBeyondAndOuterAtAStep) {
  const RadialAdhesion w(
      RadialAdhesion::Table{{1e-4, 2e-4, 3e-4, 3e-4, 4e-4}, {0.1, 0.3, 0.3, 0.05, 0.15}});
  EXPECT_EQ(w.at(0.0), 0.1);                        // constant before the first point
  EXPECT_DOUBLE_EQ(w.at(1.5e-4), 0.2);              // linear between points
  EXPECT_EQ(w.at(2e-4), 0.3);                       // at a point
  EXPECT_EQ(w.at(std::nextafter(3e-4, 0.0)), 0.3);  // the step's inner value just inside it
  EXPECT_EQ(w.at(3e-4), 0.05);                      // and its outer value at its radius
  EXPECT_DOUBLE_EQ(w.at(3.5e-4), 0.1);
  EXPECT_EQ(w.at(1.0), 0.15);       // constant beyond the last point
  EXPECT_EQ(w.scale_value(), 0.1);  // the value at r = 0
  EXPECT_EQ(w.largest(), 0.3);
  EXPECT_EQ(w.breakpoints().size(), 4u);  // the step's radius once
  EXPECT_DOUBLE_EQ(w.finest_length(), 1e-4);
}

TEST(RadialAdhesionTable, AConstantTableAndAFlatSinusoidGiveTheNumberToTheBit) {
  const double value = 0.0123456789;
  const RadialAdhesion table(RadialAdhesion::Table{{0.0, 1e-4, 7e-4}, {value, value, value}});
  const RadialAdhesion flat(RadialAdhesion::Sinusoid{value, 0.0, 3e-5});
  for (const double r : {0.0, 3.3e-5, 1e-4, 2.71828e-4, 1.0}) {
    EXPECT_EQ(table.at(r), value) << r;
    EXPECT_EQ(flat.at(r), value) << r;
  }
}

TEST(RadialAdhesionSinusoid, MeanTimesOnePlusAmplitudeSine) {
  const RadialAdhesion w(RadialAdhesion::Sinusoid{0.05, 0.2, 1e-4});
  EXPECT_EQ(w.at(0.0), 0.05);
  EXPECT_DOUBLE_EQ(w.at(0.25e-4), 0.06);
  EXPECT_DOUBLE_EQ(w.at(0.75e-4), 0.04);
  EXPECT_EQ(w.scale_value(), 0.05);
  EXPECT_DOUBLE_EQ(w.largest(), 0.06);
  EXPECT_TRUE(w.breakpoints().empty());
  EXPECT_EQ(w.finest_length(), 1e-4);
}

TEST(RadialAdhesion, RefusesBadForms) {
  using Table = RadialAdhesion::Table;
  using Sinusoid = RadialAdhesion::Sinusoid;
  EXPECT_THROW(RadialAdhesion(Table{{}, {}}), std::invalid_argument);
  EXPECT_THROW(RadialAdhesion(Table{{0.0, 1e-4}, {0.1}}), std::invalid_argument);
  EXPECT_THROW(RadialAdhesion(Table{{0.0, 1e-4}, {0.1, -0.1}}), std::invalid_argument);
  EXPECT_THROW(RadialAdhesion(Table{{1e-4, 0.0}, {0.1, 0.1}}), std::invalid_argument);
  EXPECT_THROW(RadialAdhesion(Table{{0.0, 1e-4, 1e-4, 1e-4}, {0.1, 0.1, 0.2, 0.3}}),
               std::invalid_argument);
  EXPECT_THROW(RadialAdhesion(Table{{0.0, NAN}, {0.1, 0.1}}), std::invalid_argument);
  EXPECT_THROW(RadialAdhesion(Sinusoid{0.05, 1.5, 1e-4}), std::invalid_argument);
  EXPECT_THROW(RadialAdhesion(Sinusoid{0.05, 0.5, 0.0}), std::invalid_argument);
  EXPECT_THROW(RadialAdhesion(Sinusoid{-0.05, 0.5, 1e-4}), std::invalid_argument);
  const auto problem = find_adhesion_table_problem(Table{{0.0, 2e-4, 1e-4}, {0.1, 0.1, 0.1}});
  ASSERT_TRUE(problem.has_value());
  EXPECT_EQ(problem->column, "r");
  EXPECT_EQ(problem->point, 2u);
}

TEST(RadialAdhesion, FindsWhereTheApproachExceedsTheRecedingValue) {
  const RadialAdhesion receding(RadialAdhesion::Table{{0.0, 1e-4, 1e-4}, {0.2, 0.2, 0.05}});
  // Equal to dgamma inside the step, above it from the step on.
  const RadialAdhesion above(RadialAdhesion::Table{{0.0}, {0.1}});
  const auto r = first_radius_where_approach_exceeds(above, receding, 1.0);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(*r, 1e-4);
  const RadialAdhesion below(RadialAdhesion::Table{{0.0}, {0.05}});
  EXPECT_FALSE(first_radius_where_approach_exceeds(below, receding, 1.0).has_value());
  // dgamma_a stepping down later than dgamma: above it from dgamma's step on.
  const RadialAdhesion core(RadialAdhesion::Table{{0.0, 1e-4, 1e-4}, {0.05, 0.05, 0.0}});
  const RadialAdhesion late(RadialAdhesion::Table{{0.0, 2e-4, 2e-4}, {0.05, 0.05, 0.0}});
  const auto at_step = first_radius_where_approach_exceeds(late, core, 1.0);
  ASSERT_TRUE(at_step.has_value());
  EXPECT_EQ(*at_step, 1e-4);
  EXPECT_FALSE(first_radius_where_approach_exceeds(core, late, 1.0).has_value());
  // A sinusoid dips below a uniform dgamma_a equal to its mean: found on the grid.
  const RadialAdhesion ripple(RadialAdhesion::Sinusoid{0.05, 0.2, 1e-4});
  const auto dip = first_radius_where_approach_exceeds(
      RadialAdhesion(RadialAdhesion::Table{{0.0}, {0.05}}), ripple, 64e-4);
  ASSERT_TRUE(dip.has_value());
  EXPECT_GT(*dip, 0.5e-4);
  EXPECT_LT(*dip, 1e-4);
}

}  // namespace
}  // namespace mdrsim
