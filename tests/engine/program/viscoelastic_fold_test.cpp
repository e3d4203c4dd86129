// The viscoelastic row's fold located between springs from the let-gos before a cascade, on
// let-go branches written here: a held value h_k = (k - 5.3)^2 at the let-go of spring k turns
// at k = 5.3, between springs 5 and 6, and every field linear in k is interpolated exactly.
#include "engine/program/viscoelastic_fold.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>

namespace mdrsim {
namespace {

constexpr double kFoldTestSpacing = 1.0e-5;  // [m]

/// The equilibrium before spring k lets go, k springs glued, at time 10 - k [s].
ViscoelasticRowSample before_let_go(std::int64_t k) {
  ViscoelasticRowSample s{};
  s.time = 10.0 - static_cast<double>(k);
  s.depth = 1.0e-6 * static_cast<double>(k);
  s.force = -0.01 * static_cast<double>(k);
  s.contact_radius = kFoldTestSpacing * static_cast<double>(k);
  s.pressed = k;
  s.glued = k;
  s.glued_radius = s.contact_radius;
  return s;
}

double folding_held(std::int64_t k) {
  const double x = static_cast<double>(k) - 5.3;
  return x * x;
}

/// Springs 10 down to 5 let go one by one in stage "pull" (held values `held(k)`), and spring 5's
/// let-go starts a cascade (spring 4 at the same time): the cascade that lost the glue.
template <class Held>
ViscoelasticCascade peel_to_cascade(ViscoelasticFold& fold, Held held, std::int64_t first = 10) {
  for (std::int64_t k = first; k >= 5; --k) {
    fold.change(ViscoelasticRowChange::let_go, "pull", before_let_go(k), held(k), false);
  }
  ViscoelasticRowSample within = before_let_go(4);
  within.time = before_let_go(5).time;
  fold.change(ViscoelasticRowChange::let_go, "pull", within, held(4), false);
  ViscoelasticCascade loss;
  loss.stage = "pull";
  loss.time = within.time;
  loss.changes = 5;
  loss.before = before_let_go(5);
  return loss;
}

TEST(ViscoelasticFold, LocatesTheTurnOfTheHeldValue) {
  ViscoelasticFold fold;
  const ViscoelasticCascade loss = peel_to_cascade(fold, folding_held);
  const auto located = fold.located(loss);
  ASSERT_TRUE(located.has_value());
  const ContactSnapshot* q = &located->state;
  // Rounding moves it by a few last bits of the held values only.
  EXPECT_LT(located->rounding.normal_force, 1e-12);
  EXPECT_LT(located->rounding.contact_radius, 1e-18);
  // Exact to rounding: the held values are a parabola, the fields lines in k.
  EXPECT_NEAR(q->contact_radius, 5.3 * kFoldTestSpacing, 1e-15);
  EXPECT_NEAR(q->glued_radius, 5.3 * kFoldTestSpacing, 1e-15);
  EXPECT_NEAR(q->normal_force, -0.053, 1e-14);
  EXPECT_NEAR(q->indentation, 5.3e-6, 1e-18);
  EXPECT_NEAR(q->time, 10.0 - 5.3, 1e-13);
  EXPECT_EQ(q->springs_in_contact, 5);
}

TEST(ViscoelasticFold, LocatesNothingWhereTheBranchDoesNotFold) {
  {
    // A held force that does not move (creep under a fixed load): no turn of it.
    ViscoelasticFold fold;
    const ViscoelasticCascade loss = peel_to_cascade(fold, [](std::int64_t) { return -0.02; });
    EXPECT_FALSE(fold.located(loss).has_value());
  }
  {
    // The cascade starts at the first let-go.
    ViscoelasticFold fold;
    const ViscoelasticCascade loss = peel_to_cascade(fold, folding_held, 5);
    EXPECT_FALSE(fold.located(loss).has_value());
  }
  {
    // A shear-off: the cascade's first let-go broke a spring at rest.
    ViscoelasticFold fold;
    ViscoelasticCascade loss = peel_to_cascade(fold, folding_held);
    loss.first_by_shear = true;
    EXPECT_FALSE(fold.located(loss).has_value());
  }
  {
    // Another change of the row (a glue) between the last let-gos.
    ViscoelasticFold fold;
    for (std::int64_t k = 10; k >= 7; --k) {
      fold.change(ViscoelasticRowChange::let_go, "pull", before_let_go(k), folding_held(k), false);
    }
    fold.change(ViscoelasticRowChange::glue, "pull", before_let_go(6), 0.0, false);
    const ViscoelasticCascade loss = peel_to_cascade(fold, folding_held, 6);
    EXPECT_FALSE(fold.located(loss).has_value());
  }
  {
    // The held value still falling fast at spring 5: no turn within half a spacing of it.
    ViscoelasticFold fold;
    const ViscoelasticCascade loss =
        peel_to_cascade(fold, [](std::int64_t k) { return static_cast<double>(k * k); });
    EXPECT_FALSE(fold.located(loss).has_value());
  }
}

}  // namespace
}  // namespace mdrsim
