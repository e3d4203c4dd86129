// A held tangential force on a glued contact under friction (docs/friction.md "From adhesion to
// sliding friction"): the glue breaks at the adhesive peak, u_x jumps at that force onto
// Cattaneo-Mindlin's loading curve, where friction holds it (chi > 1), or the contact slides
// away (chi < 1). Closed forms derived here, apart from the engine.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim {
namespace {

// R = 1 cm, E* = G* = 1 MPa, dgamma = 0.05 J/m^2, glued on touch at d = 12 d0 (a_g = 2 a0).
constexpr double kRadius = 0.01;
constexpr double kModulus = 1e6;
constexpr double kWork = 0.05;
constexpr double kDepth = 2.713781792333937e-5;

struct Transition {
  double mu;
  double a = std::sqrt(kRadius * kDepth);
  double normal_force = 4.0 * kModulus * a * a * a / (3.0 * kRadius);  // Hertz at d
  double u_c = std::sqrt(2.0 * std::numbers::pi * a * kWork / kModulus);
  double peak = 2.0 * std::sqrt(2.0 * std::numbers::pi * kWork * kModulus) * std::pow(a, 1.5);
  double u_star = mu * kModulus * kDepth / kModulus;
  /// Cattaneo-Mindlin's loading curve inverted: the u_x at which friction carries F_x.
  double on_loading_curve(double force) const {
    return u_star * (1.0 - std::pow(1.0 - force / (mu * normal_force), 2.0 / 3.0));
  }
  /// The integral of the loading curve L(u) = mu F_z [1 - (1 - u/u*)^(3/2)] from u0 to u1.
  double loading_work(double u0, double u1) const {
    const auto primitive = [&](double u) {
      return mu * normal_force * (u + 0.4 * u_star * std::pow(1.0 - u / u_star, 2.5));
    };
    return primitive(u1) - primitive(u0);
  }
};

std::string scene(double mu, double force, int springs) {
  return fmt::format(
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[[loading.stage]]\nname = \"glue\"\n"
      "normal = {{ control = \"fixed-grips\", to = {:.17g} }}\n[[loading.stage]]\nname = "
      "\"shear\"\ntangential = {{ control = \"fixed-load\", to = {:.17g} }}\n[friction]\n"
      "coefficient = {}\n[discretization]\nsprings = {}\n",
      kDepth, force, mu, springs);
}

RunResult run_text(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return run_scene(SceneDocument::from_text(text, "held.toml").build(registries), {});
}

// chi = mu F_z / F_x,peak = 1.41: the glue breaks at F_x,peak and u_c (the row's N-th spring sits
// at a_g: to rounding), u_x jumps at that force to L^-1(F_x,peak), and the ramp goes on along L
// to L^-1(F_x) at its end. The machine's work is the glue's G* a_g u_c^2, the jump's F_x,peak
// (u_j - u_c) and the integral of L from u_j to the end. Bounds: the row's F_z and sums over
// springs are off by O(1/N): u_x within 2/N (observed 0.96/N), the work within 4/N.
TEST(FrictionHeldForce, FrictionHoldsTheBrokenGlueOnTheCattaneoMindlinCurve) {
  const Transition t{.mu = 1.0};
  const double force = 0.015;  // between the peak (0.01333 N) and mu F_z (0.01885 N)
  ASSERT_LT(t.peak, force);
  ASSERT_LT(force, t.mu * t.normal_force);
  for (const int springs : {2000, 8000}) {
    SCOPED_TRACE(springs);
    const RunResult r = run_text(scene(t.mu, force, springs));
    EXPECT_EQ(r.status, RunStatus::completed);
    EXPECT_FALSE(r.sliding);
    ASSERT_EQ(r.jumps.size(), 1u);
    const auto& jump = r.jumps.front();
    EXPECT_NEAR(jump.critical.tangential_force, t.peak, 1e-12 * t.peak);
    EXPECT_NEAR(jump.critical.tangential_displacement, t.u_c, 1e-12 * t.u_c);
    ASSERT_EQ(jump.end, JumpEnd::state);  // a state after it, not a flight
    const double u_jump = t.on_loading_curve(t.peak);
    EXPECT_NEAR(jump.after.tangential_force, t.peak, 1e-12 * t.peak);  // the held force
    EXPECT_NEAR(jump.after.tangential_displacement, u_jump, 2.0 / springs * u_jump);
    ASSERT_EQ(r.stages.size(), 2u);
    const auto& end = r.stages[1].end;
    const double u_end = t.on_loading_curve(force);
    EXPECT_NEAR(end.tangential_force, force, 1e-12 * force);
    EXPECT_NEAR(end.tangential_displacement, u_end, 2.0 / springs * u_end);
    // Cattaneo-Mindlin's stick radius a sqrt(1 - u/u*), within two spacings.
    EXPECT_NEAR(end.stick_radius, t.a * std::sqrt(1.0 - u_end / t.u_star), 2.0 * t.a / springs);
    const double work =
        kModulus * t.a * t.u_c * t.u_c + t.peak * (u_jump - t.u_c) + t.loading_work(u_jump, u_end);
    EXPECT_NEAR(r.stages[1].work.tangential, work, 4.0 / springs * work);
    EXPECT_GT(r.stages[1].work.friction, 0.0);
  }
}

// chi = 0.71: friction cannot carry F_x,peak; when the glue breaks every spring slides and the
// held force runs the contact away: shear-off with "sliding", the critical point at the peak.
TEST(FrictionHeldForce, FrictionBelowThePeakLetsTheContactSlideAway) {
  const Transition t{.mu = 0.5};
  ASSERT_GT(t.peak, t.mu * t.normal_force);
  const RunResult r = run_text(scene(t.mu, 0.015, 2000));
  EXPECT_EQ(r.status, RunStatus::shear_off);
  EXPECT_TRUE(r.sliding);
  ASSERT_TRUE(r.critical);
  EXPECT_NEAR(r.critical->tangential_force, t.peak, 1e-12 * t.peak);
  EXPECT_NEAR(r.critical->tangential_displacement, t.u_c, 1e-12 * t.u_c);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.front().find("slides away"), std::string::npos) << r.warnings.front();
}

}  // namespace
}  // namespace mdrsim
