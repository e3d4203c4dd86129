// The spring row on a graded half-space E(z) = E0 (z / z0)^k (method = "event") against the
// closed forms of docs/graded.md: the parabola's pull-off at both controls within the row's
// estimate, its order in 1/N, the flat punch's exact stiffness, and the continuum route (the
// parabola, the cone, a power law).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/model/graded_constants.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 1e-2, kDgamma = 0.05;

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "graded_row.toml").build(registries);
}

RunResult run(const std::string& text) { return run_scene(build(text), ObserverList{}); }

/// A graded scene (E0 = 1 MPa, nu = 0.3, z0 = 1 mm) with `profile`, the preload, the control,
/// and `tail` (its [solver] and [discretization]).
std::string graded_scene(double k, const std::string& profile, const std::string& preload,
                         const std::string& control, const std::string& tail) {
  return "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\n"
         "grading = { exponent = " +
         std::to_string(k) + ", depth = 1.0e-3 }\n[profile]\n" + profile +
         "\n[loading]\npreload = { " + preload + " }\nnormal = { control = \"" + control +
         "\" }\n" + tail;
}

const char* kParabola = "type = \"parabolic\"\nradius = 1.0e-2";

std::string parabola_row(double k, const std::string& control, const std::string& discretization) {
  return graded_scene(k, kParabola, "contact_radius = 2.0e-3", control,
                      "[solver]\nmethod = \"event\"\n[discretization]\n" + discretization + "\n");
}

double closed_form(double k, const std::string& control) {
  return control == "fixed-load"
             ? -(3.0 + k) * kPi * kDgamma * kRadius / 2.0
             : -(1.0 - k) * (5.0 + 3.0 * k) * kPi * kDgamma * kRadius / (2.0 * (3.0 + k));
}

TEST(GradedRow, ParabolaPullOffWithinTheRowsEstimate) {
  // Richardson over rows of N/2, N, 2N springs at N = 2000 and 4000, and rtol 1e-6: the
  // distance from -(3 + k) pi dgamma R / 2 (fixed load) and -(1 - k)(5 + 3k) pi dgamma R /
  // (2 (3 + k)) (fixed grips) within the row's own estimate, and rtol's to 1e-6.
  for (double k : {0.25, 0.5, 0.75}) {
    for (const std::string control : {"fixed-load", "fixed-grips"}) {
      SCOPED_TRACE(std::to_string(k) + " " + control);
      const double exact = closed_form(k, control);
      for (int springs : {2000, 4000}) {
        const RunResult r = run(parabola_row(
            k, control,
            "springs = " + std::to_string(springs) + "\nextrapolation = \"richardson\""));
        ASSERT_TRUE(r.critical && r.accuracy.critical_error_estimate);
        EXPECT_EQ(r.status, RunStatus::instability);
        EXPECT_LE(std::abs(r.critical->normal_force - exact), *r.accuracy.critical_error_estimate)
            << springs;
      }
      const RunResult r = run(parabola_row(k, control, "rtol = 1e-6"));
      ASSERT_TRUE(r.critical && r.accuracy.critical_error_estimate);
      EXPECT_TRUE(r.accuracy.rtol_met);
      EXPECT_LE(std::abs(r.critical->normal_force - exact), *r.accuracy.critical_error_estimate);
      EXPECT_NEAR(r.critical->normal_force / exact, 1.0, 1e-6);
    }
  }
}

TEST(GradedRow, PlainRowIsFirstOrderAndRichardsonSecond) {
  // Fixed load, k = 0.5: the plain row's error halves as N doubles (C/N; the ratio within
  // 2 +- 0.02 at N = 2000 -> 4000 -> 8000) and Richardson's quarters (within 4 +- 0.3): the
  // order the estimates assume holds for the graded row too.
  const double k = 0.5, exact = closed_form(k, "fixed-load");
  double plain[3], extrapolated[3];
  for (int j = 0; j < 3; ++j) {
    const std::string n = std::to_string(2000 << j);
    plain[j] = run(parabola_row(k, "fixed-load", "springs = " + n)).critical->normal_force - exact;
    extrapolated[j] =
        run(parabola_row(k, "fixed-load", "springs = " + n + "\nextrapolation = \"richardson\""))
            .critical->normal_force -
        exact;
  }
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(plain[j] / plain[j + 1], 2.0, 0.02) << j;
    EXPECT_NEAR(extrapolated[j] / extrapolated[j + 1], 4.0, 0.3) << j;
  }
}

TEST(GradedRow, FlatPunchCarriesThePunchStiffness) {
  // Each spring's stiffness is c_k integrated over its cell, so that the row of N springs
  // carries C_k A^(1+k) exactly at any N: the preload F = C_k d A^(1+k) and the fixed-load
  // pull-off -sqrt(4 pi C_k A^(3+k) dgamma / (1 + k)) to rounding (1e-12) on 7 springs, where
  // c_k(x_i) dx would miss by percents.
  const double k = 0.5, a = 5e-4, d = 2e-6;
  const double ck = graded_punch_constant({k, 1e-3}, 1.0e6, 0.3);
  const RunResult r =
      run(graded_scene(k, "type = \"flat_punch\"\nradius = 5.0e-4", "depth = 2.0e-6", "fixed-load",
                       "[solver]\nmethod = \"event\"\n[discretization]\n"
                       "springs = 7\n"));
  ASSERT_TRUE(r.critical);
  ASSERT_FALSE(r.stages.empty());
  EXPECT_NEAR(r.stages[0].end.normal_force / (ck * d * std::pow(a, 1.0 + k)), 1.0, 1e-12);
  const double pull_off = -std::sqrt(4.0 * kPi * ck * std::pow(a, 3.0 + k) * kDgamma / (1.0 + k));
  EXPECT_NEAR(r.critical->normal_force / pull_off, 1.0, 1e-12);
}

TEST(GradedRow, ConvergesToTheContinuumRoute) {
  // rtol 1e-8 on the row against the continuum route (rtol 1e-10): the pull-off and the
  // preload's work agree within the row's estimates (plus the route's 1e-10).
  for (const std::string control : {"fixed-load", "fixed-grips"}) {
    SCOPED_TRACE(control);
    const RunResult row = run(parabola_row(0.5, control, "rtol = 1e-8"));
    const RunResult continuum =
        run(graded_scene(0.5, kParabola, "contact_radius = 2.0e-3", control, ""));
    ASSERT_TRUE(row.critical && continuum.critical && row.accuracy.critical_error_estimate);
    EXPECT_EQ(continuum.accuracy.route, Accuracy::Route::continuum);
    const double f = continuum.critical->normal_force;
    EXPECT_LE(std::abs(row.critical->normal_force - f),
              *row.accuracy.critical_error_estimate + 1e-10 * std::abs(f));
    EXPECT_NEAR(row.critical->normal_force / f, 1.0, 1e-8);
    ASSERT_TRUE(row.work && continuum.work && !row.stages.empty() && !continuum.stages.empty());
    EXPECT_NEAR(row.stages[0].work.normal / continuum.stages[0].work.normal, 1.0, 1e-8);
  }
}

TEST(GradedRow, ConeAndPowerLawMeetTheContinuumRoute) {
  // The other graded images on the row (g_k = K |x|^n, n = 1 and 3), rtol 1e-7, against the
  // continuum route (rtol 1e-10): within the row's estimate plus the route's 1e-10.
  for (const std::string profile : {"type = \"cone\"\nslope_angle_deg = 10.0",
                                    "type = \"power_law\"\ncoefficient = 1.0e4\nexponent = 3.0"}) {
    for (const std::string control : {"fixed-load", "fixed-grips"}) {
      SCOPED_TRACE(profile + " " + control);
      const RunResult row =
          run(graded_scene(0.5, profile, "contact_radius = 2.0e-3", control,
                           "[solver]\nmethod = \"event\"\n[discretization]\nrtol = 1e-7\n"));
      const RunResult continuum =
          run(graded_scene(0.5, profile, "contact_radius = 2.0e-3", control, ""));
      ASSERT_TRUE(row.critical && continuum.critical && row.accuracy.critical_error_estimate);
      const double f = continuum.critical->normal_force;
      EXPECT_LE(std::abs(row.critical->normal_force - f),
                *row.accuracy.critical_error_estimate + 1e-10 * std::abs(f));
    }
  }
}

}  // namespace
}  // namespace mdrsim
