// Statuses at the edges of the physics: no adhesion, shear-off, a small preload, few springs.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/parabolic_reference.hpp"
#include "engine/reference/part_examples.hpp"

namespace ref = mdrsim::parabolic_reference;
using mdrsim::RunStatus;
using mdrsim::test::JkrScenario;
using mdrsim::test::run_quietly;

namespace {

std::string without_adhesion(const std::string& normal, const std::string& method) {
  return "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.0\n"
         "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
         "[loading]\npreload = { depth = 1e-5 }\nnormal = { control = \"" +
         normal + "\" }\n[discretization]\nsprings = 500\n[solver]\nmethod = \"" + method + "\"\n";
}

}  // namespace

// Without adhesion every spring leaves as it stops being compressed: the Hertz contact
// unloads smoothly to zero force, one spring at a time, and nothing jumps.
TEST(RunStatus, NoAdhesionPeelsOffSmoothly) {
  for (const char* normal : {"fixed-grips", "fixed-load"}) {
    for (const char* method : {"event", "stepping"}) {
      const auto r = run_quietly(mdrsim::test::build_scene_text(without_adhesion(normal, method)));
      EXPECT_EQ(r.status, RunStatus::no_instability) << normal << " " << method;
      EXPECT_EQ(r.critical->springs_in_contact, 1);
      // Against the preload's Hertz force 4 E* a^3/(3R), a = sqrt(R d): zero up to rounding
      // for the event method; stepping's last equilibrium is one base step (1e-3 of the
      // preload control) before the spring leaves, so at most 1e-3 of it.
      const double preload_force = 4.0 / 3.0 * 1e6 * std::pow(1e-5 * 0.01, 1.5) / 0.01;
      const double tolerance = std::string(method) == "event" ? 1e-9 : 1e-3;
      EXPECT_LE(std::abs(r.critical->normal_force), tolerance * preload_force);
    }
  }
}

// The glued contact holds G* u^2 < 2 pi a dgamma at its edge (eq. 20 with no stretch), that
// is u/d0 < sqrt(16 a/a0 / gamma) = sqrt(32) for a glued radius of 2 a0 and gamma = 1.
TEST(RunStatus, TangentialDisplacementBeyondTheGlueShearsOffAtThePreload) {
  JkrScenario s;
  s.normal = "fixed-grips";
  s.springs = 2000;
  s.tangential_displacement = std::sqrt(32.0) * 1.01;
  const auto off = run_quietly(s.build());
  EXPECT_EQ(off.status, RunStatus::shear_off);
  // The requested load was never an equilibrium: no critical point, but the contact's
  // strength, F_x = sqrt(8 pi G* a^3 dgamma) = sqrt(4 (a/a0)^3) F0 = sqrt(32) F0 (1e-12: a
  // root search to full precision).
  EXPECT_FALSE(off.critical.has_value());
  ASSERT_TRUE(off.tangential_strength.has_value());
  EXPECT_NEAR(*off.tangential_strength / s.scales().force, std::sqrt(32.0), 1e-12);
  // With no adhesion (dgamma = 0) the glue has no strength at all: a strength of 0. Written
  // out: JkrScenario's lengths are in a0, which is 0 there.
  const auto none = run_quietly(mdrsim::test::build_scene_text(
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.0\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[loading]\npreload = { contact_radius = 5e-4 }\n"
      "tangential = { control = \"fixed-grips\", displacement = 1e-3 }\n"
      "normal = { control = \"fixed-grips\" }\n[discretization]\nsprings = 200\n"));
  EXPECT_EQ(none.status, RunStatus::shear_off);
  EXPECT_EQ(none.tangential_strength.value_or(-1.0), 0.0);
  s.tangential_displacement = std::sqrt(32.0) * 0.99;
  EXPECT_EQ(run_quietly(s.build()).status, RunStatus::instability);
}

// Under a held tangential force u = F_x/(2 G* a): the glue holds F_x^2 < 8 pi G* a^3 dgamma,
// that is F_x/F0 < sqrt(4 gamma (a/a0)^3) = sqrt(32) at a glued radius of 2 a0.
TEST(RunStatus, TangentialForceBeyondTheGlueShearsOffAtThePreload) {
  for (const char* normal : {"fixed-grips", "fixed-load"}) {
    JkrScenario s;
    s.normal = normal;
    s.springs = 2000;
    s.tangential_force = std::sqrt(32.0) * 1.01;
    EXPECT_EQ(run_quietly(s.build()).status, RunStatus::shear_off) << normal;
    s.tangential_force = std::sqrt(32.0) * 0.99;
    EXPECT_EQ(run_quietly(s.build()).status, RunStatus::instability) << normal;
  }
}

// Glued below the critical radius, the contact never reaches the fold: it comes off in one
// cascade at its first detachment, at the JKR force of its own radius (eq. 19), so the
// pull-off force depends on the preload.
TEST(RunStatus, SmallPreloadComesOffAtItsGluedRadius) {
  for (const auto& [normal, glued] :
       {std::pair{"fixed-load", 0.5}, std::pair{"fixed-load", 0.9}, std::pair{"fixed-grips", 0.3},
        std::pair{"fixed-grips", 0.45}}) {
    JkrScenario s;
    s.normal = normal;
    s.glued_radius = glued;
    const auto r = run_quietly(s.build());
    EXPECT_EQ(r.status, RunStatus::instability);
    EXPECT_EQ(r.critical->springs_in_contact, s.springs) << normal << " " << glued;
    EXPECT_NEAR(r.critical->normal_force / s.scales().force, ref::normal_force(glued), 1e-3)
        << normal << " " << glued;
  }
}

// One spring at x = a_g lets go at d = g(a_g) - dl(a_g): F = -2 E* a_g dl(a_g) under any
// control. Two and three springs still end in an instability with finite numbers.
TEST(RunStatus, OneTwoAndThreeSprings) {
  JkrScenario s;
  s.springs = 1;
  const double a = 2.0 * s.scales().radius;
  const double dl = std::sqrt(2.0 * std::numbers::pi * a * s.work_of_adhesion / s.youngs_modulus);
  for (const char* normal : {"fixed-grips", "fixed-load", "compliant"}) {
    s.normal = normal;
    s.normal_extra = mdrsim::test::example_keys("controller", normal, ", ");
    for (const std::int64_t n : {1, 2, 3}) {
      s.springs = n;
      const auto r = run_quietly(s.build());
      EXPECT_EQ(r.status, RunStatus::instability) << normal << " " << n;
      EXPECT_TRUE(std::isfinite(r.critical->normal_force));
      EXPECT_GE(r.critical->springs_in_contact, 1);
      if (n == 1) {
        EXPECT_NEAR(r.critical->normal_force, -2.0 * s.youngs_modulus * a * dl, 1e-12);
      }
    }
  }
}
