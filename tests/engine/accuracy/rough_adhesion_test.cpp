// docs/accuracy.md "Adhesion that jumps or bends": under rtol, a critical point where dgamma(r)
// steps or bends (the front pinned there) is reported within its own estimate, by the program's
// zoom and the shorthand's alike.
//
// References, derived apart from the engine. A parabola z = r^2 / (2 R) glued on touch to
// d = 2.7137818e-5 m (contact radius 5.2094e-4 m) and retracted under fixed grips. MDR: the
// front at radius a lets go at d(a) = a^2 / R - sqrt(2 pi a dgamma(a) / E*), with the force
// F(a) = 4 E* a^3 / (3 R) - sqrt(8 pi E* dgamma a^3). With dgamma_o = 0.05 outside a step at b
// and 0.02 inside, the front follows d(a) inward while it decreases; its smooth minimum under
// 0.05 is at a_o = (R/4 sqrt(2 pi dgamma_o / E*))^(2/3) = 1.2522e-4 m. For b > a_o the front
// reaches b at d_o(b), where the core's springs let go at once (d_i(b) > d_o(b)); every core
// state lies above min d_i = -2.55e-6 m, so for b = 1.5e-4 and 2.5e-4 m (d_o = -4.61e-6 and
// -2.61e-6 m) the contact separates from the front pinned at b: F_c = F(b) with dgamma_o.
// For b = 1.2e-4 < a_o the fold at a_o comes first: F_c = -5/9 F0(0.05) (paper eq. 18). For
// b = 4e-4 the jump at b lands on the core's branch (d_o(b) = 4.8e-6 m is above min d_i) and
// the last instability is the core's own fold: F_c = -5/9 F0(0.02). Plain rows of 2e4 and 2e5
// springs agree (1.5e-4: -1.60952e-3 and -1.60943e-3 N against F(b) = -1.6094053e-3 N).
// A tough ring (0.1 between 1.8e-4 and 2.2e-4 m, 0.05 elsewhere): the ring's own fold would
// be at 1.577e-4 m, inside it, so the front pins at its inner edge: F_c = F(1.8e-4) with 0.1.
// A ramp from 0.02 to 0.05 over 100 nm (1.5e-4 to 1.501e-4 m): d(a) is smallest at its outer
// kink, F_c = F(1.501e-4) with 0.05.
//
// Tolerance: the run's own estimate (estimate >= |error|), the promise rtol makes; and the
// error within rtol where rtol is reported met.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

constexpr double kModulus = 1e6;  // E* [Pa]
constexpr double kRadius = 0.01;  // R [m]

/// F(a) on the let-go branch with dgamma at the front.
double front_force(double a, double dgamma) {
  return 4.0 * kModulus * a * a * a / (3.0 * kRadius) -
         std::sqrt(8.0 * std::numbers::pi * kModulus * dgamma * a * a * a);
}

/// The fixed-grips JKR fold with a uniform dgamma: -5/9 F0, F0 = 3/2 pi R dgamma.
double fold_force(double dgamma) { return -5.0 / 9.0 * 1.5 * std::numbers::pi * kRadius * dgamma; }

std::string material(const std::string& table) {
  return "[material]\neffective_modulus = 1000000.0\nwork_of_adhesion = " + table +
         "\n[profile]\ntype = \"parabolic\"\nradius = 0.01\n";
}

std::string program(const std::string& table) {
  return material(table) +
         "[[loading.stage]]\nname = \"approach\"\n"
         "normal = { control = \"fixed-grips\", to = 2.713781792333937e-05 }\n"
         "[[loading.stage]]\nname = \"retract\"\n"
         "normal = { control = \"fixed-grips\", by = -2.713781792333937e-05 }\n"
         "until = \"separation\"\n[discretization]\nrtol = 1e-5\n";
}

/// The same path as the shorthand (method = "event": rtol alone takes the continuum route).
std::string shorthand(const std::string& table) {
  return material(table) +
         "[loading]\npreload = { contact_radius = 5.209397078678047e-4 }\n"
         "normal = { control = \"fixed-grips\" }\n[solver]\nmethod = \"event\"\n"
         "[discretization]\nrtol = 1e-5\n";
}

std::string step_at(const std::string& b) {
  return "{ r = [0.0, " + b + ", " + b + "], value = [0.02, 0.02, 0.05] }";
}

void expect_within_estimate(const std::string& table, double expected) {
  for (const bool as_program : {true, false}) {
    const std::string text = as_program ? program(table) : shorthand(table);
    const RunResult r = run_scene(test::build_scene_text(text), {});
    const char* which = as_program ? "program" : "shorthand";
    ASSERT_TRUE(r.critical.has_value()) << which;
    ASSERT_TRUE(r.accuracy.critical_error_estimate.has_value()) << which;
    const double error = std::abs(r.critical->normal_force - expected);
    EXPECT_LE(error, *r.accuracy.critical_error_estimate)
        << which << ": F = " << r.critical->normal_force << " against " << expected;
    if (r.accuracy.rtol_met) {
      EXPECT_LE(error, 1e-5 * std::abs(expected)) << which;
    }
  }
}

TEST(RoughAdhesion, StepOutsideTheFoldLeavesTheFold) {
  expect_within_estimate(step_at("1.2e-4"), fold_force(0.05));
}

TEST(RoughAdhesion, FrontPinnedAtAStepNearTheFold) {
  expect_within_estimate(step_at("1.5e-4"), front_force(1.5e-4, 0.05));
}

TEST(RoughAdhesion, FrontPinnedAtAStepFarOutside) {
  expect_within_estimate(step_at("2.5e-4"), front_force(2.5e-4, 0.05));
}

TEST(RoughAdhesion, JumpAtAStepLandsOnTheCoresFold) {
  expect_within_estimate(step_at("4.0e-4"), fold_force(0.02));
}

TEST(RoughAdhesion, FrontPinnedAtAToughRingsInnerEdge) {
  expect_within_estimate(
      "{ r = [0.0, 1.8e-4, 1.8e-4, 2.2e-4, 2.2e-4], value = [0.05, 0.05, 0.1, 0.1, 0.05] }",
      front_force(1.8e-4, 0.1));
}

TEST(RoughAdhesion, FrontPinnedAtARampsOuterKink) {
  expect_within_estimate("{ r = [0.0, 1.5e-4, 1.501e-4], value = [0.02, 0.02, 0.05] }",
                         front_force(1.501e-4, 0.05));
}

}  // namespace
}  // namespace mdrsim
