// The shorthand with friction runs as its three-stage program (docs/friction.md): the same
// numbers as the program written out, and, where the glue holds, as the frictionless shorthand.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "tests/support/observed_or_not.hpp"

namespace mdrsim {
namespace {

// Fig. 3a's sphere: R = 1 cm, E* = G* = 1 MPa, dgamma = 0.05 J/m^2, glued at 2 a0 (d = 12 d0).
constexpr const char* kHead =
    "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
    "[profile]\ntype = \"parabolic\"\nradius = 0.01\n[detachment]\ncriterion = \"mode-mixed\"\n"
    "[discretization]\nsprings = 2000\n";
constexpr double kDepth = 2.7137817923339373e-05;  // 12 d0 [m]

Scene build(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return SceneDocument::from_text(text, "scene.toml").build(registries);
}

std::string shorthand(const char* normal, double u, const std::string& friction) {
  return std::string(kHead) +
         fmt::format(
             "[loading]\npreload = {{ contact_radius = 5.209397078678047e-4 }}\ntangential = {{ "
             "control = \"fixed-grips\", displacement = {:.17g} }}\nnormal = {{ control = \"{}\" "
             "}}\n{}",
             u, normal, friction);
}

std::string program(const char* normal, double u, double rate, const std::string& friction) {
  return std::string(kHead) +
         fmt::format(
             "[[loading.stage]]\nname = \"preload\"\nnormal = {{ control = \"fixed-grips\", to = "
             "{:.17g} }}\n[[loading.stage]]\nname = \"tangential\"\nnormal = {{ control = \"{}\" "
             "}}\ntangential = {{ control = \"fixed-grips\", to = {:.17g} }}\n[[loading.stage]]\n"
             "name = \"pull-off\"\nnormal = {{ by = {:.17g} }}\nuntil = \"separation\"\n{}",
             kDepth, normal, u, -rate, friction);
}

using test::expect_same_state;

// Below u_c (u = d0) and past it (u = 2 u_c: the glue breaks in the ramp and the pressed
// springs then slide at mu f_z), under both normal controls: the shorthand with friction is its
// program written out, to the bit.
TEST(FrictionShorthand, EqualsItsProgramWrittenOut) {
  const std::string friction = "[friction]\ncoefficient = 1.0\n";
  for (const char* normal : {"fixed-grips", "fixed-load"}) {
    for (const double u : {2.2614848269449475e-6, 2.56e-5}) {
      SCOPED_TRACE(fmt::format("{} u = {}", normal, u));
      const Scene a_scene = build(shorthand(normal, u, friction));
      const double rate = std::string(normal) == "fixed-load" ? a_scene.preload_force : kDepth;
      const RunResult a = run_scene(a_scene, {});
      const RunResult b = run_scene(build(program(normal, u, rate, friction)), {});
      EXPECT_EQ(a.status, b.status);
      EXPECT_EQ(a.sliding, b.sliding);
      EXPECT_EQ(a.counts.events, b.counts.events);
      ASSERT_EQ(a.critical.has_value(), b.critical.has_value());
      if (a.critical) expect_same_state(*a.critical, *b.critical, "critical");
      ASSERT_EQ(a.stages.size(), b.stages.size());
      for (std::size_t i = 0; i < a.stages.size(); ++i) {
        expect_same_state(a.stages[i].end, b.stages[i].end, a.stages[i].name.c_str());
        EXPECT_EQ(a.stages[i].work.friction, b.stages[i].work.friction);
      }
    }
  }
}

// Where the glue holds through the pull-off (u = d0 < u_c), every spring that lets go leaves in
// tension and friction never acts: the critical point is the frictionless shorthand's (its own
// engine, to rounding), with no frictional work.
TEST(FrictionShorthand, WhereTheGlueHoldsFrictionChangesNothing) {
  for (const char* normal : {"fixed-grips", "fixed-load"}) {
    SCOPED_TRACE(normal);
    const RunResult with = run_scene(
        build(shorthand(normal, 2.2614848269449475e-6, "[friction]\ncoefficient = 0.7\n")), {});
    const RunResult without = run_scene(build(shorthand(normal, 2.2614848269449475e-6, "")), {});
    ASSERT_TRUE(with.critical && without.critical);
    EXPECT_EQ(with.status, without.status);
    EXPECT_NEAR(with.critical->normal_force, without.critical->normal_force,
                1e-12 * std::abs(without.critical->normal_force));
    EXPECT_EQ(with.critical->springs_in_contact, without.critical->springs_in_contact);
    ASSERT_TRUE(with.work);
    EXPECT_EQ(with.work->friction, 0.0);
  }
}

}  // namespace
}  // namespace mdrsim
