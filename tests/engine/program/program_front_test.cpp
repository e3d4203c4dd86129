// The front of a program row between springs: where it places the receding, advancing and
// pressed front and the fold of a run of let-gos, against the parabola's closed forms (JKR and
// Hertz), and the row put back as it was.
//
// The row: a parabola g(x) = x^2/R, R = 1 cm, E* = 1 MPa, dgamma = 0.05 J/m^2, 200 springs
// across 0.5 mm (dx = 2.5 um; a0 = 0.26 mm). Under fixed grips at indentation d the continuum
// front sits where a margin f(a) crosses zero: the let-go margin sqrt(2 pi a dgamma / E*) -
// (a^2/R - d) for the receding front (JKR: d = a^2/R - sqrt(2 pi a dgamma / E*)), the gap
// a^2/R - d - sqrt(2 pi a dgamma_a / E*) for the advancing one, a^2/R - d for a pressed one
// (Hertz: a = sqrt(R d)). The front reads its phase off the margins at the two springs around
// the root, linearly, so its radius misses the root by |f''| (a - x_k)(x_k+1 - a) / (2 |f'|)
// at most (the chord's error; 0.2 % of dx here); the forces carry the row's own first-order
// error, E* dx (f(a) - f(0)) for the right-endpoint sum of 2 E* (d - g) over the springs.
#include "engine/program/program_front.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include "detachment/criterion.hpp"
#include "detachment/normal_only_criterion.hpp"
#include "engine/model/jkr_scales.hpp"
#include "engine/reference/parabolic_reference.hpp"
#include "profiles/parabolic_profile.hpp"
#include "tests/support/program_row_state.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.01;    // R [m]
constexpr double kModulus = 1e6;    // E* [Pa]
constexpr double kAdhesion = 0.05;  // dgamma [J/m^2]
constexpr std::int64_t kSprings = 200;
constexpr double kReference = 5e-4;  // a_ref [m]
constexpr double kSpacing = kReference / kSprings;

Material material(double approach) {
  return {.effective_modulus = kModulus,
          .effective_shear_modulus = kModulus,
          .work_of_adhesion = kAdhesion,
          .approach_work_of_adhesion = approach};
}

double g(double a) { return a * a / kRadius; }
/// sqrt(2 pi a w / E*) [m]: the Hess elongation (w = dgamma) or the approach gap (dgamma_a).
double hess(double a, double w) { return std::sqrt(2.0 * kPi * a * w / kModulus); }
/// The JKR indentation at which the front sits at a, for the work of adhesion w.
double jkr_depth(double a, double w) { return g(a) - hess(a, w); }
/// F = 2 E* int_0^a (d - g) dx = 2 E* (a d - a^3 / (3R)) [N].
double continuum_force(double a, double d) {
  return 2.0 * kModulus * (a * d - a * a * a / (3.0 * kRadius));
}

/// The chord's error bound above for a root a between springs k and k + 1 of a margin with
/// the given slope and curvature there, with 5 % for their change across one spacing.
double chord_error(double a, double slope, double curvature) {
  const double k = std::floor(a / kSpacing);
  return 1.05 * std::abs(curvature) * (a - k * kSpacing) * ((k + 1) * kSpacing - a) /
         (2.0 * std::abs(slope));
}

/// The front's root lies 0.37 spacings beyond spring 120 (a = 0.3 mm).
constexpr double kFront = (120 + 0.37) * kSpacing;

/// Springs 1..k glued at fixed grips, indentation d.
ProgramRow glued_row(const Profile& profile, const Material& m, double d, std::int64_t k) {
  ProgramRow row = test::row_on(profile, m, kReference, kSprings);
  row.set_normal_held(d);
  row.glue_through(k);
  return row;
}

// Receding: the let-go margin's root is the JKR radius at d. Springs 1..120 glued, spring 120
// holds and spring 121 would not.
TEST(ProgramFront, ARecedingFrontSitsAtTheJkrRadius) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(0.0);
  const NormalOnlyCriterion criterion(m);
  const double d = jkr_depth(kFront, kAdhesion);
  ProgramRow row = glued_row(profile, m, d, 120);
  ASSERT_GT(hess(120 * kSpacing, kAdhesion) - (g(120 * kSpacing) - d), 0.0);
  ASSERT_LT(hess(121 * kSpacing, kAdhesion) - (g(121 * kSpacing) - d), 0.0);
  (void)row.snapshot();
  const ProgramRow before = row;

  ProgramFront front(criterion);
  const auto at = front.at_rest(row);
  ASSERT_TRUE(at.has_value());
  test::expect_same_row(row, before, "after at_rest");
  const double c = std::sqrt(2.0 * kPi * kAdhesion / kModulus);
  const double slope = c / (2.0 * std::sqrt(kFront)) - 2.0 * kFront / kRadius;
  const double curvature = -c / (4.0 * std::pow(kFront, 1.5)) - 2.0 / kRadius;
  EXPECT_NEAR(at->contact_radius, kFront, chord_error(kFront, slope, curvature));
  EXPECT_EQ(at->indentation, d);  // fixed grips: the three branches share d
  EXPECT_NEAR(at->normal_force, continuum_force(kFront, d), 1.5 * kModulus * kSpacing * g(kFront));
  EXPECT_EQ(at->springs_in_contact, 120);
}

// Advancing (dgamma_a = 0.01 J/m^2): spring 121 glues once its gap g - d closes to
// sqrt(2 pi x dgamma_a / E*); springs 1..120 have glued, 121 has not.
TEST(ProgramFront, AnAdvancingFrontSitsWhereTheGapMeetsTheApproachLimit) {
  const ParabolicProfile profile(kRadius);
  const double approach = 0.01;
  const Material m = material(approach);
  const NormalOnlyCriterion criterion(m);
  const double d = jkr_depth(kFront, approach);
  ProgramRow row = glued_row(profile, m, d, 120);
  ASSERT_LE(g(120 * kSpacing) - d - hess(120 * kSpacing, approach), 0.0);
  ASSERT_GT(g(121 * kSpacing) - d - hess(121 * kSpacing, approach), 0.0);
  (void)row.snapshot();
  const ProgramRow before = row;

  ProgramFront front(criterion);
  const auto at = front.at_rest(row);
  ASSERT_TRUE(at.has_value());
  test::expect_same_row(row, before, "after at_rest");
  const double c = std::sqrt(2.0 * kPi * approach / kModulus);
  const double slope = 2.0 * kFront / kRadius - c / (2.0 * std::sqrt(kFront));
  const double curvature = 2.0 / kRadius + c / (4.0 * std::pow(kFront, 1.5));
  EXPECT_NEAR(at->contact_radius, kFront, chord_error(kFront, slope, curvature));
  EXPECT_NEAR(at->normal_force, continuum_force(kFront, d), 1.5 * kModulus * kSpacing * g(kFront));
}

// Pressed without glue to d: the front sits at the Hertz radius sqrt(R d); the row's force
// errs by E* dx d (f(0) = d, f(a) = 0).
TEST(ProgramFront, APressedFrontSitsAtTheHertzRadius) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(0.0);
  const NormalOnlyCriterion criterion(m);
  const double d = g(kFront);
  ProgramRow row = test::row_on(profile, m, kReference, kSprings);
  row.set_normal_held(d);
  for (int i = 0; i < 120; ++i) row.touch_next();
  (void)row.snapshot();
  const ProgramRow before = row;

  ProgramFront front(criterion);
  const auto at = front.at_rest(row);
  ASSERT_TRUE(at.has_value());
  test::expect_same_row(row, before, "after at_rest");
  EXPECT_NEAR(at->contact_radius, std::sqrt(kRadius * d),
              chord_error(kFront, 2.0 * kFront / kRadius, 2.0 / kRadius));
  EXPECT_NEAR(at->normal_force, 4.0 * kModulus * kFront * kFront * kFront / (3.0 * kRadius),
              1.5 * kModulus * kSpacing * d);
}

// Where the branch is not simple the front declines: springs pressed outside the glued ones
// (a second front), a single glued spring. With nothing in contact there is no front: the
// row's own state.
TEST(ProgramFront, DeclinesWhereTheBranchIsNotSimple) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(0.0);
  const NormalOnlyCriterion criterion(m);
  ProgramFront front(criterion);
  const double d = jkr_depth(kFront, kAdhesion);
  ProgramRow pressed_outside = glued_row(profile, m, g(122 * kSpacing), 120);
  pressed_outside.touch_next();
  EXPECT_EQ(front.at_rest(pressed_outside), std::nullopt);
  ProgramRow one = glued_row(profile, m, d, 1);
  EXPECT_EQ(front.at_rest(one), std::nullopt);
  ProgramRow empty = test::row_on(profile, m, kReference, kSprings);
  const auto none = front.at_rest(empty);
  ASSERT_TRUE(none.has_value());
  EXPECT_EQ(none->springs_in_contact, 0);
}

// Pinned (glued out to spring 110 at the d whose JKR radius is 0.3 mm: spring 111 would hold
// too, and spring 110, stretched, would not have glued on this retract): the front keeps the
// phase it had where it last moved; knowing none, it declines. After a spring glued alone the
// phase is 0, after one let go alone it is 1. The radius is then x_110 + phase dx to rounding
// (the three branch radii lie on a line: 1e-12).
TEST(ProgramFront, APinnedFrontKeepsTheLastPhase) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(0.0);
  const NormalOnlyCriterion criterion(m);
  const double d = jkr_depth(kFront, kAdhesion);
  ProgramRow pinned = glued_row(profile, m, d, 110);
  ProgramFront front(criterion);
  EXPECT_EQ(front.at_rest(pinned), std::nullopt);

  ProgramRow moving = glued_row(profile, m, d, 120);
  const auto at = front.at_rest(moving);
  ASSERT_TRUE(at.has_value());
  const double phase = at->contact_radius / kSpacing - 120.0;
  ASSERT_GT(phase, 0.3);
  ASSERT_LT(phase, 0.4);
  const double x = 110 * kSpacing;
  const auto kept = front.at_rest(pinned);
  ASSERT_TRUE(kept.has_value());
  EXPECT_NEAR(kept->contact_radius, x + phase * kSpacing, 1e-12 * x);

  front.glued_one(0.0, 110, pinned.snapshot());
  EXPECT_NEAR(front.at_rest(pinned)->contact_radius, x, 1e-12 * x);
  front.let_go_one(0.0, 111, pinned.snapshot());
  EXPECT_NEAR(front.at_rest(pinned)->contact_radius, x + kSpacing, 1e-12 * x);
}

// The fold of a retract at fixed grips: every spring glued at d = g_N, the held d falling at
// one metre per unit of t. Spring k lets go at d_k = g(x_k) - sqrt(2 pi x_k dgamma / E*), the
// JKR curve sampled at the springs, single let-gos while d_k falls, until the spring inside is
// due at once: the fold, between springs, at the minimum of d(a) (paper eqs. 31-33 at u = 0:
// a = (1/9)^(1/3) a0, F = -5/9 F0). The parabola's vertex through three
// samples misses the minimum by |d'''| dx^2 / (3 |d''|) at most (its slope errs by
// |d'''| max|w'| / 6, w = (x - x_k-1)(x - x_k)(x - x_k+1), |w'| <= 2 dx^2); its value by
// |d'''| dx^3 / 9 more than the samples' rounding (1e-15 of g_N); the force carries the row's
// E* dx g(a) of first order.
TEST(ProgramFront, TheFoldOfARunOfLetGosIsTheJkrFixedGripsFold) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(0.0);
  const NormalOnlyCriterion criterion(m);
  ProgramRow row = glued_row(profile, m, g(kReference), kSprings);
  const StageLine line{.normal = {g(kReference), -1.0, std::nullopt}, .tangential = {}};
  ProgramFront front(criterion);
  front.stage_started();
  const auto let_go_at = [&](std::int64_t k) {  // the parameter where spring k lets go
    return g(kReference) - (row.image(k) - hess_elongation_limit(m, row.position(k)));
  };
  std::optional<ContactSnapshot> fold;
  double t = 0.0;
  while (row.glued() > 2 && !fold) {
    const std::int64_t k = row.glued();
    t = let_go_at(k);
    line.place(row, t);
    const ContactSnapshot before = row.snapshot();
    row.let_go_boundary(false);
    if (let_go_at(k - 1) > t) {
      front.let_go_one(t, k, before);
    } else {
      fold = front.fold(row, line, t, before);
      ASSERT_TRUE(fold.has_value()) << "at spring " << k;
    }
  }
  ASSERT_TRUE(fold.has_value());
  const JkrScales scales = *JkrScales::of(kRadius, kModulus, kAdhesion);
  const auto want = parabolic_reference::fixed_grips_critical(0.0);
  const double a = want.contact_radius * scales.radius;
  const double c = std::sqrt(2.0 * kPi * kAdhesion / kModulus);
  const double d2 = 2.0 / kRadius + c / (4.0 * std::pow(a, 1.5));  // d''(a)
  const double d3 = -3.0 * c / (8.0 * std::pow(a, 2.5));           // d'''(a)
  EXPECT_NEAR(fold->contact_radius, a, std::abs(d3) * kSpacing * kSpacing / (3.0 * d2));
  EXPECT_NEAR(fold->indentation, want.indentation * scales.depth,
              std::abs(d3) * std::pow(kSpacing, 3) / 9.0 + 1e-15 * g(kReference));
  EXPECT_NEAR(fold->normal_force, want.normal_force * scales.force,
              1.5 * kModulus * kSpacing * g(a));
}

}  // namespace
}  // namespace mdrsim
