// The shorthand's works and stage ends estimated as a program's, against the closed JKR path.
#include "engine/accuracy/shorthand_accuracy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

using mdrsim::test::JkrScenario;

namespace {

/// Fig. 2 under fixed load, derived from the closed forms alone: the machine's work from the
/// undeformed start to the critical point (a = a0 under fixed load) and the preload force.
/// Hertz (no adhesion on approach) pressed to d_H(a_g) = a_g^2 / R at fixed grips:
/// (8/15) E* R^1/2 d^5/2. The glued contact is unloaded at its flat-punch stiffness 2 E* a_g
/// (force linear in d) down to the JKR branch at a_g: a trapezoid. Then along the JKR branch
/// F(a) = A a^3 - B a^3/2, d(a) = a^2 / R - C a^1/2 (A = 4 E* / (3 R), B = (8 pi dgamma E*)^1/2,
/// C = (2 pi dgamma / E*)^1/2) from a_g to a0: the integral of F d'(a) da in closed form.
struct ClosedPath {
  double work;           ///< [J]
  double preload_force;  ///< [N]
};

ClosedPath closed_path(const JkrScenario& s) {
  const double e = s.youngs_modulus / (1.0 - s.poisson_ratio * s.poisson_ratio);
  const double r = s.radius;
  const double w = s.work_of_adhesion;
  const double pi = std::numbers::pi;
  const double a0 = std::cbrt(9.0 * pi * r * r * w / (8.0 * e));
  const double ag = s.glued_radius * a0;
  const double a_coef = 4.0 * e / (3.0 * r);
  const double b_coef = std::sqrt(8.0 * pi * w * e);
  const double c_coef = std::sqrt(2.0 * pi * w / e);
  const auto hertz_force = [&](double a) { return a_coef * a * a * a; };
  const auto jkr_force = [&](double a) { return hertz_force(a) - b_coef * std::pow(a, 1.5); };
  const auto jkr_depth = [&](double a) { return a * a / r - c_coef * std::sqrt(a); };
  const double preload_depth = ag * ag / r;
  const double pressed = 8.0 / 15.0 * e * std::sqrt(r) * std::pow(preload_depth, 2.5);
  const double unloaded = 0.5 * (hertz_force(ag) + jkr_force(ag)) * (jkr_depth(ag) - preload_depth);
  // F d'(a) = (A a^3 - B a^3/2)(2 a / R - C a^-1/2 / 2)
  //         = 2A/R a^4 - (A C / 2) a^5/2 - (2B/R) a^5/2 + (B C / 2) a
  const auto primitive = [&](double a) {
    return 2.0 * a_coef / (5.0 * r) * std::pow(a, 5) -
           (a_coef * c_coef / 2.0 + 2.0 * b_coef / r) * std::pow(a, 3.5) / 3.5 +
           b_coef * c_coef / 4.0 * a * a;
  };
  return {pressed + unloaded + primitive(a0) - primitive(ag), hertz_force(ag)};
}

bool covers(const mdrsim::RunResult& r, const std::string& path) {
  const auto& c = r.accuracy.covers;
  return std::find(c.begin(), c.end(), path) != c.end();
}

}  // namespace

// Each row's work is a right-endpoint sum, O(1/N): 3.845e-8 J at 1000 springs, 2.2e-3 off.
// Richardson across the rows N/2, N, 2N removes that term: within 1e-4 of the closed value
// (found 1.1e-6 at 1000 springs), and its estimate covers the true error.
TEST(ShorthandAccuracy, RichardsonWorkMeetsTheClosedJkrPath) {
  for (const std::int64_t n : {1000, 2000, 10000, 100000}) {
    JkrScenario s;
    s.springs = n;
    s.richardson = true;
    const ClosedPath exact = closed_path(s);
    const mdrsim::RunResult r = mdrsim::run_scene(s.build(), mdrsim::ObserverList{});
    ASSERT_TRUE(r.work.has_value()) << n;
    ASSERT_TRUE(r.accuracy.work_error_estimate.has_value()) << n;
    const double error = std::abs(r.work->normal - exact.work);
    EXPECT_LE(error, 1e-4 * exact.work) << n;
    EXPECT_LE(error, r.accuracy.work_error_estimate->normal) << n;
    EXPECT_TRUE(covers(r, "work")) << n;
    EXPECT_TRUE(covers(r, "stages.end.normal_force")) << n;
    // The preload's end, all springs pressed in: the Hertz force at a_g, within its estimate.
    ASSERT_EQ(r.stages.size(), 3U) << n;
    ASSERT_TRUE(r.stages[0].normal_force_error_estimate.has_value()) << n;
    EXPECT_LE(std::abs(r.stages[0].end.normal_force - exact.preload_force),
              *r.stages[0].normal_force_error_estimate)
        << n;
  }
}

// Under rtol the rows across the glued radius double from 512 until the works and stage ends
// meet it: the work within 1e-6 of the closed value.
TEST(ShorthandAccuracy, RtolWorkMeetsTheClosedJkrPath) {
  JkrScenario s;
  s.rtol = 1e-6;
  const ClosedPath exact = closed_path(s);
  const mdrsim::RunResult r = mdrsim::run_scene(s.build(), mdrsim::ObserverList{});
  ASSERT_TRUE(r.work.has_value());
  ASSERT_EQ(r.stages.size(), 3U);
  EXPECT_TRUE(r.accuracy.rtol_met);
  EXPECT_TRUE(covers(r, "work"));
  EXPECT_LE(std::abs(r.work->normal - exact.work), 1e-6 * exact.work);
  ASSERT_TRUE(r.accuracy.work_error_estimate.has_value());
  EXPECT_LE(std::abs(r.work->normal - exact.work), r.accuracy.work_error_estimate->normal);
}

// A plain row is the paper's row at N springs: its own work, without an estimate (0.2% off the
// closed value at 1000 springs, as a right-endpoint sum is).
TEST(ShorthandAccuracy, PlainRowKeepsItsOwnWork) {
  JkrScenario s;
  s.springs = 1000;
  const mdrsim::Scene scene = s.build();
  const mdrsim::RunResult r = mdrsim::run_scene(scene, mdrsim::ObserverList{});
  const mdrsim::RunResult row = mdrsim::test::run_quietly(scene);
  ASSERT_TRUE(r.work.has_value());
  ASSERT_TRUE(row.work.has_value());
  EXPECT_EQ(r.work->normal, row.work->normal);
  EXPECT_FALSE(r.accuracy.work_error_estimate.has_value());
  EXPECT_GT(std::abs(r.work->normal - closed_path(s).work), 1e-3 * closed_path(s).work);
}
