// The sphere on a graded half-space (its image by quadrature): its fixed-load pull-off
// tending to the parabola's closed form as the contact shrinks against R, and the continuum
// route against the graded spring row.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

RunResult run_graded_sphere(double k, double e0, const std::string& control,
                            const std::string& preload, const std::string& tail = "") {
  static const Registries registries = Registries::builtin();
  const std::string text = "[material]\nyoungs_modulus = " + std::to_string(e0) +
                           "\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\n"
                           "grading = { exponent = " +
                           std::to_string(k) +
                           ", depth = 1.0e-3 }\n[profile]\ntype = \"sphere\"\nradius = 1.0e-2\n"
                           "[loading]\npreload = { " +
                           preload + " }\nnormal = { control = \"" + control + "\" }\n" + tail;
  return run_scene(SceneDocument::from_text(text, "graded_sphere.toml").build(registries),
                   ObserverList{});
}

TEST(GradedSphere, FixedLoadPullOffTendsToTheParabolas) {
  // The sphere's tip is the parabola r^2 / (2R): its pull-off tends to -(3 + k) pi dgamma R / 2
  // as the fold's radius a shrinks against R, the difference of the images (and so of the
  // forces) of relative order (a/R)^2. E0 from 1e6 to 1e10 Pa shrinks a/R from 0.03 to 0.001:
  // the relative difference over (a/R)^2 the same number within 2 % (its next term (a/R)^4),
  // and below 1e-5 at the stiffest.
  const double k = 0.5, r = 1e-2, dgamma = 0.05;
  const double parabola = -(3.0 + k) * std::numbers::pi * dgamma * r / 2.0;
  double scaled[3];
  double last = 0.0;
  int j = 0;
  for (double e0 : {1e6, 1e8, 1e10}) {
    const double glued = 4.0 * r * std::pow(dgamma / (e0 * r), 1.0 / 3.0);
    const RunResult s =
        run_graded_sphere(k, e0, "fixed-load", "contact_radius = " + std::to_string(glued));
    ASSERT_TRUE(s.critical);
    EXPECT_EQ(s.status, RunStatus::instability);
    const double t = s.critical->contact_radius / r;
    last = s.critical->normal_force / parabola - 1.0;
    scaled[j++] = last / (t * t);
  }
  EXPECT_NEAR(scaled[1] / scaled[0], 1.0, 0.02);
  EXPECT_NEAR(scaled[2] / scaled[1], 1.0, 0.02);
  EXPECT_LT(std::abs(last), 1e-5);
}

TEST(GradedSphere, ContinuumRouteMeetsTheRow) {
  // A sphere glued at a/R = 0.3 (far from the parabola), both controls, k = 0.25 and 0.75: the
  // row (method = "event", rtol 1e-7) within its estimate of the continuum route (rtol 1e-10),
  // plus the route's 1e-10.
  for (double k : {0.25, 0.75}) {
    for (const std::string control : {"fixed-load", "fixed-grips"}) {
      SCOPED_TRACE(std::to_string(k) + " " + control);
      const RunResult continuum = run_graded_sphere(k, 1e5, control, "contact_radius = 3.0e-3");
      const RunResult row =
          run_graded_sphere(k, 1e5, control, "contact_radius = 3.0e-3",
                            "[solver]\nmethod = \"event\"\n[discretization]\nrtol = 1e-7\n");
      ASSERT_TRUE(row.critical && continuum.critical && row.accuracy.critical_error_estimate);
      EXPECT_EQ(continuum.accuracy.route, Accuracy::Route::continuum);
      EXPECT_TRUE(continuum.accuracy.rtol_met);
      const double f = continuum.critical->normal_force;
      EXPECT_LE(std::abs(row.critical->normal_force - f),
                *row.accuracy.critical_error_estimate + 1e-10 * std::abs(f));
    }
  }
}

}  // namespace
}  // namespace mdrsim
