// The continuum route on a graded half-space E(z) = E0 (z / z0)^k against the closed forms of
// docs/graded.md (the parabola's pull-off at both controls, the flat punch) and the work
// against int F dd along the path, integrated apart from the engine's energy balance.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "engine/model/dimensionless_scales.hpp"
#include "engine/model/graded_constants.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "graded.toml").build(registries);
}

RunResult run(const std::string& text) { return run_scene(build(text), ObserverList{}); }

std::string graded_scene(double k, double nu, double e0, const std::string& profile,
                         const std::string& preload, const std::string& control,
                         double dgamma = 0.05) {
  return "[material]\nyoungs_modulus = " + std::to_string(e0) +
         "\npoisson_ratio = " + std::to_string(nu) +
         "\nwork_of_adhesion = " + std::to_string(dgamma) +
         "\ngrading = { exponent = " + std::to_string(k) + ", depth = 1.0e-3 }\n[profile]\n" +
         profile + "\n[loading]\npreload = { " + preload + " }\nnormal = { control = \"" + control +
         "\" }\n";
}

const char* kParabola = "type = \"parabolic\"\nradius = 1.0e-2";

TEST(GradedContinuum, ParabolaPullOffAtBothControls) {
  // -(3 + k) pi dgamma R / 2 (fixed load) and -(1 - k)(5 + 3k) pi dgamma R / (2 (3 + k))
  // (fixed grips), neither depending on nu nor on E0, where the fold lies inside the glued
  // radius (2 mm; at 0.5 mm and k = 0.75 the fixed load lets go at a_g). rtol 1e-10: 1e-8.
  const double r = 1e-2, dgamma = 0.05;
  for (double k : {0.25, 0.5, 0.75}) {
    for (const auto& [nu, e0] : {std::pair{0.2, 1.0e6}, std::pair{0.45, 3.0e7}}) {
      const RunResult load =
          run(graded_scene(k, nu, e0, kParabola, "contact_radius = 2.0e-3", "fixed-load"));
      ASSERT_TRUE(load.critical);
      EXPECT_EQ(load.status, RunStatus::instability);
      const double f_load = -(3.0 + k) * kPi * dgamma * r / 2.0;
      EXPECT_NEAR(load.critical->normal_force / f_load, 1.0, 1e-8) << k << " " << nu;
      const RunResult grips =
          run(graded_scene(k, nu, e0, kParabola, "contact_radius = 2.0e-3", "fixed-grips"));
      ASSERT_TRUE(grips.critical);
      const double f_grips = -(1.0 - k) * (5.0 + 3.0 * k) * kPi * dgamma * r / (2.0 * (3.0 + k));
      EXPECT_NEAR(grips.critical->normal_force / f_grips, 1.0, 1e-8) << k << " " << nu;
      // The estimates bound the distance from the closed form.
      EXPECT_LE(std::abs(load.critical->normal_force - f_load),
                *load.accuracy.critical_error_estimate + 1e-15 * std::abs(f_load));
      EXPECT_TRUE(load.accuracy.rtol_met);
    }
  }
}

TEST(GradedContinuum, FlatPunchPreloadAndPullOff) {
  // F = C_k d A^(1+k) at the preload; the fixed-load pull-off where the face's stretch reaches
  // Hess's e(A): F = -sqrt(4 pi C_k A^(3+k) dgamma / (1 + k)). Rounding only: 1e-12.
  const double k = 0.5, nu = 0.3, e0 = 2.0e6, a = 5e-4, d = 2e-6, dgamma = 0.05;
  const double ck = graded_punch_constant({k, 1e-3}, e0, nu);
  const std::string punch = "type = \"flat_punch\"\nradius = 5.0e-4";
  const Scene scene = build(graded_scene(k, nu, e0, punch, "depth = 2.0e-6", "fixed-load"));
  EXPECT_NEAR(scene.preload_force / (ck * d * std::pow(a, 1.0 + k)), 1.0, 1e-14);
  // The homogeneous JKR scales do not apply: none.
  EXPECT_FALSE(dimensionless_scales(*scene.profile, scene.material));
  const RunResult r = run_scene(scene, ObserverList{});
  ASSERT_TRUE(r.critical);
  const double pull_off = -std::sqrt(4.0 * kPi * ck * std::pow(a, 3.0 + k) * dgamma / (1.0 + k));
  EXPECT_NEAR(r.critical->normal_force / pull_off, 1.0, 1e-12);
}

TEST(GradedContinuum, WorkIsTheIntegralOfFdd) {
  // The preload's work int_0^d F dd along the graded Hertz curve and the pull-off's along the
  // pinned front and the branch to the fold, by Gauss-Kronrod on the closed forms of
  // docs/graded.md (d(a) = g_k(a) - e(a), F(a) = C_k (nf_k(a) - a^(1+k) e)): 1e-9.
  const double k = 0.5, nu = 0.3, e0 = 1.0e6, r = 1e-2, dgamma = 0.05, ag = 5e-4;
  const double ck = graded_punch_constant({k, 1e-3}, e0, nu);
  const RunResult run_result =
      run(graded_scene(k, nu, e0, kParabola, "contact_radius = 5.0e-4", "fixed-load"));
  ASSERT_TRUE(run_result.critical);
  const auto dg = [&](double x) { return 2.0 * x / ((1.0 + k) * r); };
  // nf_k = (1 + k) int_0^a x^k (g(a) - g(x)) dx = 2 a^(3+k) / ((1 + k)(3 + k) R).
  const auto nf = [&](double a) {
    return 2.0 * std::pow(a, 3.0 + k) / ((1.0 + k) * (3.0 + k) * r);
  };
  const auto e = [&](double a) {
    return std::sqrt(4.0 * kPi * std::pow(a, 1.0 - k) * dgamma / ((1.0 + k) * ck));
  };
  const auto de = [&](double a) { return 0.5 * (1.0 - k) * e(a) / a; };
  const auto force = [&](double a, double stretch) {
    return ck * (nf(a) - std::pow(a, 1.0 + k) * stretch);
  };
  using Rule = boost::math::quadrature::gauss_kronrod<double, 61>;
  const double preload =
      Rule::integrate([&](double a) { return force(a, 0.0) * dg(a); }, 0.0, ag, 15, 1e-14);
  // Pinned: F linear in d from the preload's to the let-go's.
  const double pinned = 0.5 * (force(ag, 0.0) + force(ag, e(ag))) * (-e(ag));
  const double ac = run_result.critical->contact_radius;
  const double branch = Rule::integrate([&](double a) { return force(a, e(a)) * (dg(a) - de(a)); },
                                        ag, ac, 15, 1e-14);
  ASSERT_EQ(run_result.stages.size(), 3u);
  EXPECT_NEAR(run_result.stages[0].work.normal / preload, 1.0, 1e-9);
  EXPECT_NEAR(run_result.stages[2].work.normal / (pinned + branch), 1.0, 1e-9);
}

TEST(GradedContinuum, TheResolvedSceneBuildsTheSceneAgain) {
  // The JSON result's scene is valid input: rerun, the same numbers.
  const Scene scene =
      build(graded_scene(0.5, 0.3, 1.0e6, kParabola, "contact_radius = 5.0e-4", "fixed-grips"));
  const RunResult first = run_scene(scene, ObserverList{});
  static const Registries registries = Registries::builtin();
  const RunResult again =
      run_scene(SceneDocument::from_scene_text(scene.resolved->dump(), "r.json").build(registries),
                ObserverList{});
  ASSERT_TRUE(first.critical && again.critical);
  EXPECT_EQ(again.critical->normal_force, first.critical->normal_force);
}

TEST(GradedContinuum, ExponentZeroIsTodaysScene) {
  // k = 0 takes the homogeneous path: the row's numbers to the bit.
  const std::string plain =
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\n";
  const std::string rest = std::string("[profile]\n") + kParabola +
                           "\n[loading]\npreload = { contact_radius = 5.0e-4 }\nnormal = { "
                           "control = \"fixed-grips\" }\n[discretization]\nsprings = 2000\n";
  const RunResult without = run(plain + rest);
  const RunResult with = run(plain + "grading = { exponent = 0.0, depth = 1.0e-3 }\n" + rest);
  ASSERT_TRUE(without.critical && with.critical);
  EXPECT_EQ(with.critical->normal_force, without.critical->normal_force);
  EXPECT_EQ(with.critical->indentation, without.critical->indentation);
  EXPECT_EQ(with.work->normal, without.work->normal);
  EXPECT_EQ(with.peak->normal_force, without.peak->normal_force);
}

}  // namespace
}  // namespace mdrsim
