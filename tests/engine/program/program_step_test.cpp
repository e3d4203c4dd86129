// The change locator of a program row: the parameter of its next touch, lift, glue, let-go and
// fall-in against hand computations on a row of four springs, and nothing where nothing changes.
//
// The row: a parabola g(x) = x^2/R with R = 1 cm, springs at x_i = i dx, dx = 0.1 mm, so
// g_i = i^2 um; E* = 1 MPa, G* = 0.8 MPa, dgamma = 0.05 J/m^2. Under fixed grips the held value
// is d itself, so along a stage d = d_0 + v t and a change at indentation d* is at
// t* = (d* - d_0)/v: the locator computes it as (d* - d_0) times 1/v, a few roundings, hence
// the 1e-15 relative below. Each located change is also due just after its parameter and not
// just before (1e-9 of it on either side: the changes here lie 0.1 or more apart).
#include "engine/program/program_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <ostream>

#include "detachment/mode_mixed_criterion.hpp"
#include "detachment/normal_only_criterion.hpp"
#include "profiles/parabolic_profile.hpp"
#include "tests/support/program_row_state.hpp"

namespace mdrsim {

/// The change's name in a failure's message.
[[maybe_unused]] static void PrintTo(Change change, std::ostream* os) {
  constexpr const char* kNames[] = {"fall_in", "let_go", "glue", "touch", "lift", "friction"};
  *os << kNames[static_cast<int>(change)];
}

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.01;      // R [m]
constexpr double kSpacing = 1e-4;     // dx [m]
constexpr std::int64_t kSprings = 4;  // N
constexpr double kModulus = 1e6;      // E* [Pa]
constexpr double kShear = 0.8e6;      // G* [Pa]
constexpr double kAdhesion = 0.05;    // dgamma [J/m^2]

Material material(double work_of_adhesion, double approach) {
  return {.effective_modulus = kModulus,
          .effective_shear_modulus = kShear,
          .work_of_adhesion = work_of_adhesion,
          .approach_work_of_adhesion = approach};
}

double image(int i) { return (i * kSpacing) * (i * kSpacing) / kRadius; }  ///< g_i [m]
/// sqrt(2 pi x_i w / E*): the Hess elongation (w = dgamma) or the approach gap (dgamma_a) [m].
double hess(int i, double w) { return std::sqrt(2.0 * kPi * i * kSpacing * w / kModulus); }

/// A stage along which each held value moves as start + rate t.
struct Stage {
  AxisMotion normal;
  AxisMotion tangential;
  SameParameterGuards guards;
  std::int64_t max_springs = kSprings;

  StepLine at(double t) const { return {t, normal, tangential, guards, max_springs, kSprings}; }
  /// `row` with its held values at t.
  ProgramRow placed(ProgramRow row, double t) const {
    if (normal.rate != 0.0) row.set_normal_held(normal.start + normal.rate * t);
    if (tangential.rate != 0.0) row.set_tangential_held(tangential.start + tangential.rate * t);
    return row;
  }
};

/// A fixed-grips press (v > 0) or retract (v < 0) from d_0 at the row's present indentation.
Stage normal_ramp(const ProgramRow& row, double v) {
  return {.normal = {row.normal().held, v, std::nullopt}, .tangential = {}};
}

class Locating {
 public:
  explicit Locating(const DetachmentCriterion& criterion) : locator_(criterion, iterations_) {}

  /// The next change from t_0 before t_end; where one is found, checks that it is due just
  /// after its parameter and not just before.
  std::optional<std::pair<double, Change>> next(const ProgramRow& row, const Stage& stage,
                                                double t0, double t_end) {
    const auto next = locator_.next_change(row, stage.at(t0), t_end);
    if (next) {
      const auto [t, change] = *next;
      EXPECT_EQ(due(stage.placed(row, t * (1.0 + 1e-9)), stage, t * (1.0 + 1e-9)), change)
          << "just after t = " << t;
      EXPECT_EQ(due(stage.placed(row, t * (1.0 - 1e-9)), stage, t * (1.0 - 1e-9)), std::nullopt)
          << "just before t = " << t;
    }
    return next;
  }
  std::optional<Change> due(const ProgramRow& row, const Stage& stage, double t) {
    bool outgrew = false;
    const auto change = locator_.due(row, stage.at(t), outgrew);
    EXPECT_FALSE(outgrew);
    return change;
  }
  std::int64_t root_iterations() const { return iterations_; }

 private:
  std::int64_t iterations_ = 0;
  ChangeLocator locator_;
};

/// Expects the change `want` at t_want (to 1e-15 relative, or `tolerance`) and returns the row
/// placed there with it applied by `apply`.
template <class Apply>
ProgramRow expect_next(Locating& locating, const ProgramRow& row, const Stage& stage, double t0,
                       Change want, double t_want, Apply apply, double tolerance = 1e-15) {
  const auto next = locating.next(row, stage, t0, 10.0);
  EXPECT_TRUE(next.has_value()) << "nothing found, " << static_cast<int>(want) << " expected";
  if (!next) return row;
  EXPECT_EQ(next->second, want);
  EXPECT_NEAR(next->first, t_want, tolerance * t_want);
  ProgramRow after = stage.placed(row, next->first);
  apply(after);
  return after;
}

// Without adhesion a press touches spring i where d reaches g_i: from d_0 = 0 at v = 10 um per
// unit of t, at t = g_i/v = 0.1 i^2; once the last spring is pressed nothing more happens.
TEST(ChangeLocator, APressTouchesEachSpringAtItsImage) {
  const ParabolicProfile profile(kRadius);
  const NormalOnlyCriterion criterion(material(0.0, 0.0));
  Locating locating(criterion);
  ProgramRow row = test::row_on(profile, material(0.0, 0.0), kSprings * kSpacing, kSprings);
  const Stage press = normal_ramp(row, 1e-5);
  double t = 0.0;
  for (int i = 1; i <= kSprings; ++i) {
    const double want = image(i) / 1e-5;
    row = expect_next(locating, row, press, t, Change::touch, want,
                      [](ProgramRow& r) { r.touch_next(); });
    ASSERT_EQ(row.in_contact(), i);
    t = want;
  }
  EXPECT_EQ(locating.next(row, press, t, 1e3), std::nullopt);
}

// Three springs pressed at d = 10 um, retracting at 10 um per unit of t: spring 3 lifts where d
// falls to g_3 = 9 um (t = 0.1), spring 2 at g_2 = 4 um (t = 0.6), spring 1 at 1 um (t = 0.9).
TEST(ChangeLocator, ARetractLiftsTheOuterSpringAtItsImage) {
  const ParabolicProfile profile(kRadius);
  const NormalOnlyCriterion criterion(material(0.0, 0.0));
  Locating locating(criterion);
  ProgramRow row = test::row_on(profile, material(0.0, 0.0), kSprings * kSpacing, kSprings);
  row.set_normal_held(1e-5);
  for (int i = 0; i < 3; ++i) row.touch_next();
  const Stage retract = normal_ramp(row, -1e-5);
  double t = 0.0;
  for (int i = 3; i >= 1; --i) {
    const double want = (image(i) - 1e-5) / -1e-5;
    row = expect_next(locating, row, retract, t, Change::lift, want,
                      [](ProgramRow& r) { r.lift_outer(); });
    ASSERT_EQ(row.in_contact(), i - 1);
    t = want;
  }
  EXPECT_EQ(locating.next(row, retract, t, 1e3), std::nullopt);
}

// dgamma_a = 0: the advancing front glues each spring as it touches it, at d = g_i (glue, not
// touch: a glued edge touches by gluing).
TEST(ChangeLocator, AFrontThatGluesOnTouchGluesAtTheImage) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(kAdhesion, 0.0);
  const NormalOnlyCriterion criterion(m);
  Locating locating(criterion);
  ProgramRow row = test::row_on(profile, m, kSprings * kSpacing, kSprings);
  const Stage press = normal_ramp(row, 1e-5);
  double t = 0.0;
  for (int i = 1; i <= kSprings; ++i) {
    const double want = image(i) / 1e-5;
    row = expect_next(locating, row, press, t, Change::glue, want,
                      [](ProgramRow& r) { r.glue_next(); });
    ASSERT_EQ(row.glued(), i);
    t = want;
  }
}

// dgamma_a = 1 mJ/m^2: spring i > 1 glues ahead of its touch, where the gap g_i - d closes to
// sqrt(2 pi x_i dgamma_a / E*) (1.12 um at spring 2, 1.37 um at spring 3); the first spring
// has no front to glue it ahead and glues on touch.
TEST(ChangeLocator, AnAdvancingFrontGluesAtTheApproachGap) {
  const ParabolicProfile profile(kRadius);
  const double approach = 1e-3;
  const Material m = material(kAdhesion, approach);
  const NormalOnlyCriterion criterion(m);
  Locating locating(criterion);
  ProgramRow row = test::row_on(profile, m, kSprings * kSpacing, kSprings);
  const Stage press = normal_ramp(row, 1e-5);
  double t = 0.0;
  for (int i = 1; i <= 3; ++i) {
    const double want = (image(i) - (i == 1 ? 0.0 : hess(i, approach))) / 1e-5;
    row = expect_next(locating, row, press, t, Change::glue, want,
                      [](ProgramRow& r) { r.glue_next(); });
    t = want;
  }
}

// Springs 1-3 glued at d = g_3, retracting at 10 um per unit of t with u_x = 0: the boundary
// spring lets go where its elongation g_3 - d reaches the Hess limit sqrt(2 pi x_3 dgamma / E*)
// (paper eq. 12), at t = dl_3 / v = 0.97; then spring 2 at t = (g_3 - g_2 + dl_2)/v.
TEST(ChangeLocator, ARetractLetsGoWhereTheElongationReachesTheHessLimit) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(kAdhesion, 0.0);
  const NormalOnlyCriterion criterion(m);
  Locating locating(criterion);
  ProgramRow row = test::row_on(profile, m, kSprings * kSpacing, kSprings);
  row.set_normal_held(image(3));
  row.glue_through(3);
  const Stage retract = normal_ramp(row, -1e-5);
  const double first = hess(3, kAdhesion) / 1e-5;
  row = expect_next(locating, row, retract, 0.0, Change::let_go, first,
                    [](ProgramRow& r) { r.let_go_boundary(false); });
  ASSERT_EQ(row.glued(), 2);
  ASSERT_EQ(row.in_contact(), 2);
  expect_next(locating, row, retract, first, Change::let_go,
              (image(3) - image(2) + hess(2, kAdhesion)) / 1e-5,
              [](ProgramRow& r) { r.let_go_boundary(false); });
}

// Springs 1-3 glued, d held at g_3 - 2 um, u_x ramped at 10 um per unit of t: the mode-mixed
// margin 2 pi a dgamma - E* e^2 - G* u_x^2 of spring 3 (paper eq. 20) reaches zero at
// u* = sqrt((2 pi x_3 dgamma - E* e^2) / G*), t* = u*/v = 1.06. Root-found along the line: its
// bracket ends within a few ulp of the computed margin's root, which the margin's rounding
// (terms of 1e-4 against a slope of 17 per metre) moves by 1e-16 relative: 1e-13 holds it.
TEST(ChangeLocator, AShearRampLetsGoWhereTheMixedModeMarginCrossesZero) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(kAdhesion, 0.0);
  const ModeMixedCriterion criterion(m);
  Locating locating(criterion);
  ProgramRow row = test::row_on(profile, m, kSprings * kSpacing, kSprings);
  const double elongation = 2e-6;
  row.set_normal_held(image(3));
  row.glue_through(3);
  row.set_normal_held(image(3) - elongation);
  const Stage shear{.normal = {row.normal().held, 0.0, std::nullopt},
                    .tangential = {0.0, 1e-5, std::nullopt}};
  const double a = 3 * kSpacing;
  const double u =
      std::sqrt((2.0 * kPi * a * kAdhesion - kModulus * elongation * elongation) / kShear);
  expect_next(
      locating, row, shear, 0.0, Change::let_go, u / 1e-5,
      [](ProgramRow& r) { r.let_go_boundary(false); }, 1e-13);
  EXPECT_GT(locating.root_iterations(), 0);
}

// A held force with nothing in contact: the indenter rests at d = 0 until the force turns
// compressive, at t = -F_0/v = 0.1 (from -1 mN at 10 mN per unit of t); then it falls in.
TEST(ChangeLocator, ACompressiveHeldForceWithNothingInContactFallsIn) {
  const ParabolicProfile profile(kRadius);
  const NormalOnlyCriterion criterion(material(0.0, 0.0));
  Locating locating(criterion);
  ProgramRow row = test::row_on(profile, material(0.0, 0.0), kSprings * kSpacing, kSprings);
  row.edit_normal() = {{0.0, 1.0}, -1e-3, 0.0};
  const Stage push{.normal = {-1e-3, 1e-2, std::nullopt}, .tangential = {}};
  expect_next(locating, row, push, 0.0, Change::fall_in, 0.1, [](ProgramRow&) {});
}

// Nothing changes before t_end: a row held still (both rates 0), a press whose next touch
// (t = 0.1) lies beyond t_end = 0.09, and a retract of glued springs whose let-go (t = 0.97)
// lies beyond t_end = 0.9.
TEST(ChangeLocator, FindsNothingWhereNothingChangesBeforeTheEnd) {
  const ParabolicProfile profile(kRadius);
  const Material m = material(kAdhesion, 0.0);
  const NormalOnlyCriterion criterion(m);
  Locating locating(criterion);
  ProgramRow row = test::row_on(profile, material(0.0, 0.0), kSprings * kSpacing, kSprings);
  EXPECT_EQ(locating.next(row, normal_ramp(row, 1e-5), 0.0, 0.09), std::nullopt);
  EXPECT_TRUE(locating.next(row, normal_ramp(row, 1e-5), 0.0, 0.11).has_value());

  ProgramRow glued = test::row_on(profile, m, kSprings * kSpacing, kSprings);
  glued.set_normal_held(image(3));
  glued.glue_through(3);
  EXPECT_EQ(locating.next(glued, normal_ramp(glued, 0.0), 0.0, 1e6), std::nullopt);
  EXPECT_EQ(locating.next(glued, normal_ramp(glued, -1e-5), 0.0, 0.9), std::nullopt);
  EXPECT_TRUE(locating.next(glued, normal_ramp(glued, -1e-5), 0.0, 1.0).has_value());
}

// A row that may hold 2 springs (a pilot row's max_springs) pressed beyond g_3: the touch of
// spring 3 is not returned as due; the locator says the row outgrew instead.
TEST(ChangeLocator, ATouchBeyondTheRowOutgrowsIt) {
  const ParabolicProfile profile(kRadius);
  const NormalOnlyCriterion criterion(material(0.0, 0.0));
  std::int64_t iterations = 0;
  ChangeLocator locator(criterion, iterations);
  ProgramRow row = test::row_on(profile, material(0.0, 0.0), kSprings * kSpacing, kSprings);
  row.set_normal_held(1e-5);
  row.touch_next();
  row.touch_next();
  Stage stage = normal_ramp(row, 1e-5);
  stage.max_springs = 2;
  bool outgrew = false;
  EXPECT_EQ(locator.due(row, stage.at(0.0), outgrew), std::nullopt);
  EXPECT_TRUE(outgrew);
  stage.max_springs = 3;
  outgrew = false;
  EXPECT_EQ(locator.due(row, stage.at(0.0), outgrew), Change::touch);
  EXPECT_FALSE(outgrew);
}

}  // namespace
}  // namespace mdrsim
