// A timed program on the continuum route with detachment.front_speed_law: an elastic parabola
// pressed reversibly to JKR's zero-force state, then retracted at constant speed until the
// contact is lost, against the independent solution of tests/support/rate_law_front; and the
// key's refusals, one line each.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/events/observer.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/expect_throw_msg.hpp"
#include "tests/support/rate_law_front.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kModulus = 1e6;      // E* [Pa] (nu = 0)
constexpr double kRadius = 0.01;      // R [m]
constexpr double kWork = 0.05;        // dgamma [J/m^2]
constexpr double kFrontSpeed = 1e-6;  // v* [m/s]
constexpr double kPress = 2.0;        // the approach's duration [s]

/// JKR's zero-force state: a0^3 = 9 pi dgamma R^2 / (2 E*), d0 = a0^2 / R - sqrt(2 pi a0 dgamma
/// / E*).
double zero_force_radius() { return std::cbrt(4.5 * kPi * kWork * kRadius * kRadius / kModulus); }
double zero_force_depth() {
  const double a0 = zero_force_radius();
  return a0 * a0 / kRadius - std::sqrt(2.0 * kPi * a0 * kWork / kModulus);
}
/// The grips' speed [m/s] of beta = (V / v*) (E* R / dgamma)^(1/3).
double grips_speed(double beta) {
  return beta * kFrontSpeed / std::cbrt(kModulus * kRadius / kWork);
}

std::string rate_law_scene(double beta, double exponent, const std::string& extra = "",
                           const std::string& retract_time = "") {
  return fmt::format(
      "[material]\nyoungs_modulus = {}\npoisson_ratio = 0.0\nwork_of_adhesion = {}\n"
      "approach_work_of_adhesion = {}\n"
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[detachment]\nfront_speed_law = {{ speed = {}, exponent = {} }}\n"
      "[[loading.stage]]\nname = \"approach\"\n"
      "normal = {{ control = \"fixed-grips\", to = {:.17g} }}\nduration = {}\n"
      "[[loading.stage]]\nname = \"retract\"\nnormal = {{ by = -1e-5 }}\nuntil = \"separation\"\n"
      "{}\n{}",
      kModulus, kWork, kWork, kRadius, kFrontSpeed, exponent, zero_force_depth(), kPress,
      retract_time.empty() ? fmt::format("speed = {:.17g}", grips_speed(beta)) : retract_time,
      extra.empty() ? "[solver]\nmethod = \"continuum\"\n" : extra);
}

// The peak tension, the indentation and time of the lost contact, the stage's machine work
// and dissipated_at_front against the reference at rtol 1e-10, compared at 1e-8 (each within
// about 1e-9 of the exact numbers); its energy balance to 1e-9 of the starting stored energy.
TEST(FrontSpeedProgram, RetractionAgreesWithTheReference) {
  const test::RateLawScales sc = test::rate_law_scales(kModulus, kRadius, kWork, kFrontSpeed);
  for (const double n : {1.0, 0.5}) {
    for (const double beta : {0.01, 1.0, 100.0}) {
      const RunResult r = run_scene(test::build_scene_text(rate_law_scene(beta, n)), {});
      const test::RateLawRetraction ref = test::rate_law_retraction(beta, n, 1e-10);
      EXPECT_EQ(r.status, RunStatus::instability);
      ASSERT_TRUE(r.peak);
      ASSERT_TRUE(r.critical);
      ASSERT_EQ(r.stages.size(), 2u);
      EXPECT_TRUE(r.accuracy.rtol_met);
      EXPECT_NEAR(r.peak->normal_force / (ref.peak.force * sc.force), 1.0, 1e-8) << beta << n;
      EXPECT_NEAR(r.critical->indentation / (ref.lost.delta * sc.indentation), 1.0, 1e-8)
          << beta << " " << n;
      EXPECT_EQ(r.critical->contact_radius, 0.0);
      EXPECT_NEAR((r.critical->time - kPress) / (ref.lost.tau * sc.time), 1.0, 1e-8)
          << beta << " " << n;
      EXPECT_NEAR((r.peak->time - kPress) / (ref.peak.tau * sc.time), 1.0, 1e-6)
          << beta << " " << n;
      const AxisWork& w = r.stages[1].work;
      EXPECT_NEAR(w.normal / (ref.lost.machine_work * sc.energy), 1.0, 1e-8) << beta << " " << n;
      EXPECT_NEAR(w.front / (ref.lost.dissipated * sc.energy), 1.0, 1e-8) << beta << " " << n;
      // The front's dissipation carries the walk's estimate (it said 0 J, no error at all), within
      // rtol 1e-10 of it.
      ASSERT_TRUE(r.accuracy.work_error_estimate);
      EXPECT_GT(r.accuracy.work_error_estimate->front, 0.0) << beta << " " << n;
      EXPECT_LT(r.accuracy.work_error_estimate->front, 1e-10 * w.front) << beta << " " << n;
      // Machine work = stored change + adhesion energy change + dissipated_at_front: from
      // E* int_0^a0 (d0 - x^2 / R)^2 dx and -pi a0^2 dgamma to nothing.
      const double a0 = zero_force_radius();
      const double d0 = zero_force_depth();
      const double stored = kModulus * (d0 * d0 * a0 - 2.0 * d0 * a0 * a0 * a0 / (3.0 * kRadius) +
                                        std::pow(a0, 5) / (5.0 * kRadius * kRadius));
      EXPECT_NEAR((w.normal - (-stored + kPi * a0 * a0 * kWork) - w.front) / stored, 0.0, 1e-9)
          << beta << " " << n;
    }
  }
}

// A loose rtol walks the front in long steps: one of them must not carry the radius past the
// axis, where the front's speed has no bound (at rtol 1e-3 the walk ran on to s = inf with a
// NaN radius and the run ended on a non-finite force). The lost contact's state is finite and
// the peak within rtol of the reference's.
TEST(FrontSpeedProgram, LooseRtolStaysFiniteAtTheAxis) {
  const test::RateLawScales sc = test::rate_law_scales(kModulus, kRadius, kWork, kFrontSpeed);
  const test::RateLawRetraction ref = test::rate_law_retraction(1.0, 0.5, 1e-10);
  for (const double rtol : {1e-2, 1e-3, 1e-4}) {
    const RunResult r = run_scene(
        test::build_scene_text(rate_law_scene(
            1.0, 0.5,
            fmt::format("[solver]\nmethod = \"continuum\"\n[discretization]\nrtol = {}\n", rtol))),
        {});
    EXPECT_EQ(r.status, RunStatus::instability) << rtol;
    ASSERT_TRUE(r.peak);
    ASSERT_TRUE(r.critical);
    EXPECT_EQ(r.critical->contact_radius, 0.0) << rtol;
    EXPECT_TRUE(std::isfinite(r.critical->normal_force)) << rtol;
    EXPECT_TRUE(std::isfinite(r.critical->indentation)) << rtol;
    EXPECT_NEAR(r.peak->normal_force / (ref.peak.force * sc.force), 1.0, rtol) << rtol;
  }
}

// A fast retraction (beta 1e7 and 1e8) walks to the axis in radius, where a trial stage of a
// long step can see the stretch of a grip position the front never meets with G < dgamma: that
// stage is taken again shorter, not an error (it ended "the front stopped on its way to the
// axis" with exit 1). The peak against the independent solution, as at slower speeds.
TEST(FrontSpeedProgram, FastRetractionReachesTheAxis) {
  const test::RateLawScales sc = test::rate_law_scales(kModulus, kRadius, kWork, kFrontSpeed);
  for (const double n : {1.0, 0.5}) {
    for (const double beta : {1e7, 1e8}) {
      const test::RateLawRetraction ref = test::rate_law_retraction(beta, n, 1e-10);
      const RunResult r = run_scene(test::build_scene_text(rate_law_scene(beta, n)), {});
      EXPECT_EQ(r.status, RunStatus::instability) << beta << " " << n;
      ASSERT_TRUE(r.peak) << beta << " " << n;
      EXPECT_NEAR(r.peak->normal_force / (ref.peak.force * sc.force), 1.0, 1e-8)
          << beta << " " << n;
    }
  }
}

// The rate law dissipates where the quasi-static front does not: the same scene without the
// key reaches JKR's fixed-grips peak -F0, and with it the peak is beyond it.
TEST(FrontSpeedProgram, SlowRetractionNearsJkr) {
  const RunResult r = run_scene(test::build_scene_text(rate_law_scene(1e-4, 1.0)), {});
  const double f0 = 1.5 * kPi * kWork * kRadius;
  ASSERT_TRUE(r.peak);
  EXPECT_LT(r.peak->normal_force, -f0);
  EXPECT_NEAR(r.peak->normal_force / -f0, 1.0, 1e-3);  // the lag ~ beta^n (the reference's test)
}

// A stage that ends while the front recedes, then a hold: the front goes on receding in the
// hold (machine work 0, dissipation > 0) until G = dgamma, with the contact kept.
TEST(FrontSpeedProgram, TheFrontRecedesInAHold) {
  const std::string text = fmt::format(
      "[material]\nyoungs_modulus = {}\npoisson_ratio = 0.0\nwork_of_adhesion = {}\n"
      "approach_work_of_adhesion = {}\n"
      "[profile]\ntype = \"parabolic\"\nradius = {}\n"
      "[detachment]\nfront_speed_law = {{ speed = {}, exponent = 1.0 }}\n"
      "[[loading.stage]]\nname = \"approach\"\n"
      "normal = {{ control = \"fixed-grips\", to = {:.17g} }}\nduration = {}\n"
      "[[loading.stage]]\nname = \"retract\"\nnormal = {{ by = {:.17g} }}\nduration = 1.0\n"
      "[[loading.stage]]\nname = \"hold\"\nduration = 1000.0\n"
      "[solver]\nmethod = \"continuum\"\n",
      kModulus, kWork, kWork, kRadius, kFrontSpeed, zero_force_depth(), kPress,
      -0.5 * zero_force_depth());
  const RunResult r = run_scene(test::build_scene_text(text), {});
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_EQ(r.status, RunStatus::completed);
  EXPECT_GT(r.stages[2].end.contact_radius, 0.0);
  EXPECT_LT(r.stages[2].end.contact_radius, r.stages[1].end.contact_radius);
  EXPECT_EQ(r.stages[2].work.normal, 0.0);
  EXPECT_GT(r.stages[2].work.front, 0.0);
  EXPECT_EQ(r.stages[2].end.time, kPress + 1.0 + 1000.0);
}

constexpr const char* kRateLawAt = "test.toml:10:19: detachment.front_speed_law: ";

TEST(FrontSpeedReader, RefusesBadValuesAndKeys) {
  const auto refuse = [](const std::string& law, const std::string& message) {
    std::string text = rate_law_scene(1.0, 1.0);
    const std::size_t at = text.find("front_speed_law = ");
    text.replace(at, text.find('\n', at) - at, "front_speed_law = " + law);
    EXPECT_THROW_MSG(test::build_scene_text(text), SceneError, message);
  };
  refuse("{ speed = 0.0, exponent = 0.5 }",
         "test.toml:10:29: detachment.front_speed_law.speed = 0 is outside (0, inf)");
  refuse("{ speed = 1e-6, exponent = 1.5 }",
         "test.toml:10:46: detachment.front_speed_law.exponent = 1.5 is outside (0, 1]");
  refuse("{ speed = 1e-6, exponent = 0.0 }",
         "test.toml:10:46: detachment.front_speed_law.exponent = 0 is outside (0, 1]");
  refuse("{ speed = 1e-6, exponant = 0.5 }",
         "test.toml:10:35: detachment.front_speed_law.exponant: unknown key; did you mean "
         "'exponent'? (known: exponent, speed)");
}

TEST(FrontSpeedReader, RefusesWhatItDoesNotTakeYet) {
  const std::string scope = " (docs/rate_law.md)";
  // An untimed program.
  std::string untimed = rate_law_scene(1.0, 1.0);
  untimed.replace(untimed.find("duration = 2\n"), std::string("duration = 2\n").size(), "");
  const std::size_t speed = untimed.find("speed = ", untimed.find("until"));
  untimed.erase(speed, untimed.find('\n', speed) - speed);
  EXPECT_THROW_MSG(test::build_scene_text(untimed), SceneError,
                   std::string(kRateLawAt) +
                       "a program whose every stage has duration or speed is needed with "
                       "detachment.front_speed_law");
  // The spring rows take the event method only (tests/engine/program/rate_law_row_test.cpp).
  EXPECT_THROW_MSG(
      test::build_scene_text(rate_law_scene(1.0, 1.0, "[solver]\nmethod = \"stepping\"\n")),
      SceneError,
      std::string(kRateLawAt) +
          "runs on the row with solver.method = \"event\" (or on the continuum route: "
          "solver.method = \"continuum\")" +
          scope);
  // Friction (on its own the scene would take the row; the law's scope is checked first).
  EXPECT_THROW_MSG(
      test::build_scene_text(rate_law_scene(1.0, 1.0, "[friction]\ncoefficient = 0.3\n")),
      SceneError, std::string(kRateLawAt) + "is not yet taken with [friction]" + scope);
}

}  // namespace
}  // namespace mdrsim
