// A Maugis-Dugdale contact whose zone would reach past the body (a sphere's radius, a table's end):
// the shorthand refused at its preload in one line, on both routes; a program ends with step-limit
// and a warning at the last equilibrium inside the body, or is refused at its profile where
// no path exists.
#include <gtest/gtest.h>

#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/expect_throw_msg.hpp"

namespace mdrsim {
namespace {

/// R = 20 nm, E* = 1 GPa, dgamma = 0.05 J/m^2 at Maugis' lambda; the preload's line is 9.
std::string sphere(double lambda, const std::string& loading) {
  return "[material]\neffective_modulus = 1.0e9\nwork_of_adhesion = 0.05\nmaugis_parameter = " +
         std::to_string(lambda) + "\n[profile]\ntype = \"sphere\"\nradius = 2.0e-8\n" + loading;
}

RunResult run_text(const std::string& text) {
  static const Registries registries = Registries::builtin();
  return run_scene(SceneDocument::from_text(text, "md.toml").build(registries), ObserverList{});
}

constexpr const char* kRefusal =
    "md.toml:9:11: loading.preload: with material.adhesive_stress the contact and its cohesive "
    "zone reach beyond the profile's outer radius (2e-08 m) from this preload on; give a smaller "
    "preload, a wider body or a shorter range (a larger adhesive_stress)";

// At lambda = 0.1 the zone is wide (h0 = 4.2 nm): glued at 0.995 R, the branch at the preload
// depth would need a zone past R.
TEST(DugdaleEdge, ShorthandPastTheRadiusIsRefusedAtThePreload) {
  for (const char* method : {"continuum", "event"}) {
    SCOPED_TRACE(method);
    const std::string text =
        sphere(0.1,
               "[loading]\npreload = { contact_radius = 1.99e-8 }\n"
               "normal = { control = \"fixed-grips\" }\n[solver]\nmethod = \"") +
        method + "\"\n";
    EXPECT_THROW_MSG(run_text(text), SceneError, kRefusal);
  }
}

// Glued at 0.8 R the preload depth's branch lies inside the body, though half again the glued
// radius does not: the widening search stays inside the body (it once read the sphere's image
// past R and did not end).
TEST(DugdaleEdge, ShorthandGluedNearTheRadiusRuns) {
  const RunResult r = run_text(sphere(1.0,
                                      "[loading]\npreload = { contact_radius = 1.6e-8 }\n"
                                      "normal = { control = \"fixed-grips\" }\n[solver]\n"
                                      "method = \"continuum\"\n"));
  ASSERT_TRUE(r.critical.has_value());
  EXPECT_LT(r.critical->normal_force, 0.0);
  EXPECT_LT(r.accuracy.outer_radius, 2.0e-8);
}

// A fixed load of 1 N is more than the whole sphere carries: the approach ends at the last
// equilibrium the march finds inside the body, with step-limit and a warning naming the stage,
// and the retract is not run.
TEST(DugdaleEdge, ProgramPressedPastTheRadiusStopsWithAWarning) {
  const RunResult r = run_text(sphere(1.0,
                                      "[[loading.stage]]\nname = \"approach\"\n"
                                      "normal = { control = \"fixed-load\", to = 1.0 }\n"
                                      "[[loading.stage]]\nname = \"retract\"\n"
                                      "normal = { control = \"fixed-load\", to = 0.0 }\n"));
  EXPECT_EQ(r.status, RunStatus::step_limit);
  ASSERT_TRUE(r.stop_reason.has_value());
  EXPECT_EQ(*r.stop_reason, StopReason::outgrew_row);
  ASSERT_EQ(r.stages.size(), 1u);
  const ContactSnapshot& end = r.stages[0].end;
  EXPECT_GT(end.contact_radius, 0.9 * 2.0e-8);
  EXPECT_LT(end.cohesive_radius, 2.0e-8);
  EXPECT_GT(end.normal_force, 0.0);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("stage 'approach': the contact grows to a = "),
            std::string::npos);
  EXPECT_NE(r.warnings.back().find("the program stops here; stages not run: 'retract'"),
            std::string::npos)
      << r.warnings.back();
}

// A table of the parabola R = 20 nm that ends at 12 nm, under sigma_0 = 10 MPa (h0 = 5 nm):
// the zone's closing radius alone lies past the table's end, so that no program's path exists;
// refused at the profile in one line.
TEST(DugdaleEdge, ProgramOnATableEndingInsideTheZoneIsRefusedAtTheProfile) {
  const std::string text =
      "[material]\neffective_modulus = 1.0e9\nwork_of_adhesion = 0.05\nadhesive_stress = 1.0e7\n"
      "[profile]\ntype = \"tabulated\"\nr = [0.0, 0.5e-8, 1.0e-8, 1.1e-8, 1.2e-8]\n"
      "f = [0.0, 6.25e-10, 2.5e-9, 3.025e-9, 3.6e-9]\n"
      "[[loading.stage]]\nname = \"approach\"\nnormal = { control = \"fixed-grips\", to = 3.0e-9 "
      "}\n";
  EXPECT_THROW_MSG(run_text(text), SceneError,
                   "md.toml:6:8: profile.type: with material.adhesive_stress the contact and its "
                   "cohesive zone reach beyond the profile's outer radius (1.2e-08 m) on the "
                   "program's path");
}

}  // namespace
}  // namespace mdrsim
