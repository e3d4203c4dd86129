// The route plan: each engine and driver chosen once as the scene is built, with its reason,
// and the refusals of an engine paired with what it cannot take, each at the key that chose it.
#include "engine/scene/route_plan.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/expect_throw_msg.hpp"

namespace mdrsim {
namespace {

/// The paper's parabola (E* = 1 MPa, R = 1 cm, dgamma = 0.05) under fixed load, with `extra`
/// tables appended.
std::string shorthand(const std::string& extra) {
  return "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
         "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
         "[loading]\npreload = { contact_radius = 5.2e-4 }\nnormal = { control = \"fixed-load\" "
         "}\n" +
         extra;
}

/// A normal approach-retract program on the same parabola, with `extra` appended.
std::string program(const std::string& extra) {
  return "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
         "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
         "[[loading.stage]]\nname = \"approach\"\n"
         "normal = { control = \"fixed-grips\", to = 2.7e-5 }\n"
         "[[loading.stage]]\nname = \"retract\"\n"
         "normal = { control = \"fixed-grips\", by = -2.7e-5 }\nuntil = \"separation\"\n" +
         extra;
}

TEST(RoutePlan, TheShorthandTakesThePullOffRowWithItsDriver) {
  const Scene one = test::build_scene_text(shorthand("[discretization]\nsprings = 1000\n"));
  EXPECT_TRUE(one.plan.made);
  EXPECT_EQ(one.plan.engine, RouteEngine::pull_off_row);
  EXPECT_EQ(one.plan.driver, RouteDriver::one_row);
  EXPECT_EQ(one.plan.describe(one),
            "pull-off row (event method), one row of 1000 springs: the shorthand (preload, "
            "tangential load, pull-off); where a first row finds the glue let go with the "
            "indenter pressed in, the shorthand runs as its three stages on the program row");
  const Scene richardson = test::build_scene_text(
      shorthand("[discretization]\nsprings = 1000\nextrapolation = \"richardson\"\n"));
  EXPECT_EQ(richardson.plan.driver, RouteDriver::richardson);
  const Scene rtol_on_row = test::build_scene_text(
      shorthand("[discretization]\nrtol = 1e-6\n[solver]\nmethod = \"event\"\n"));
  EXPECT_EQ(rtol_on_row.plan.engine, RouteEngine::pull_off_row);
  EXPECT_EQ(rtol_on_row.plan.driver, RouteDriver::rtol);
}

TEST(RoutePlan, RtolAloneTakesTheContinuumRouteWhereItAnswers) {
  const Scene scene = test::build_scene_text(shorthand("[discretization]\nrtol = 1e-6\n"));
  EXPECT_EQ(scene.plan.engine, RouteEngine::continuum);
  EXPECT_EQ(scene.plan.driver, RouteDriver::rtol);
  EXPECT_TRUE(scene.plan.continuum_by_rtol);
  EXPECT_EQ(scene.solver.method, SolverMethod::continuum);
  EXPECT_EQ(scene.plan.continuum_chosen_at.rfind("test.toml:"), 0u);
  EXPECT_NE(scene.plan.continuum_chosen_at.find("discretization.rtol: "), std::string::npos);
  // A work of adhesion that varies with the radius folds several times: rtol stays on the row.
  const std::string varying =
      "[material]\neffective_modulus = 1.0e6\n"
      "work_of_adhesion = { r = [0.0, 1e-4], value = [0.05, 0.08] }\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[loading]\npreload = { contact_radius = 5.2e-4 }\nnormal = { control = \"fixed-load\" "
      "}\n[discretization]\nrtol = 1e-4\n";
  const Scene row = test::build_scene_text(varying);
  EXPECT_EQ(row.plan.engine, RouteEngine::pull_off_row);
  EXPECT_EQ(row.plan.driver, RouteDriver::rtol);
  EXPECT_FALSE(row.plan.continuum_by_rtol);
  EXPECT_NE(row.plan.reason.find("rtol stays on the row"), std::string::npos);
}

TEST(RoutePlan, AProgramTakesTheProgramRowAndNamedContinuumTheRoute) {
  const Scene row = test::build_scene_text(program(""));
  EXPECT_EQ(row.plan.engine, RouteEngine::program_row);
  EXPECT_EQ(row.plan.reason, "a loading program ([[loading.stage]])");
  const Scene continuum = test::build_scene_text(program("[solver]\nmethod = \"continuum\"\n"));
  EXPECT_EQ(continuum.plan.engine, RouteEngine::continuum);
  EXPECT_FALSE(continuum.plan.continuum_by_rtol);
  EXPECT_EQ(continuum.plan.describe(continuum),
            "continuum route, rtol 1e-10: solver.method = \"continuum\"");
}

TEST(RoutePlan, FrictionOnTheShorthandRunsItsStagesOnTheProgramRow) {
  const Scene scene = test::build_scene_text(shorthand("[friction]\ncoefficient = 0.5\n"));
  EXPECT_EQ(scene.plan.engine, RouteEngine::program_row);
  EXPECT_EQ(scene.plan.reason, "[friction] on the shorthand: its three stages run as a program");
  EXPECT_FALSE(scene.plan.shorthand_stages);
}

// Each refusal names the engine and the part it cannot take, at the key that chose the engine.
TEST(RoutePlan, RefusalsNameBothSidesAtTheKeyThatChoseTheEngine) {
  EXPECT_THROW_MSG(test::build_scene_text(shorthand(
                       "[solver]\nmethod = \"stepping\"\n[friction]\ncoefficient = 0.5\n")),
                   SceneError,
                   "test.toml:13:15: friction.coefficient: friction runs with solver.method = "
                   "\"event\" only");
  EXPECT_THROW_MSG(
      test::build_scene_text(shorthand(
          "[solver]\nmethod = \"stepping\"\n[discretization]\nsprings = 100\nextrapolation = "
          "\"richardson\"\n")),
      SceneError,
      "test.toml:14:17: discretization.extrapolation: richardson needs solver.method = "
      "\"event\"");
  EXPECT_THROW_MSG(
      test::build_scene_text(program("[solver]\nmethod = \"continuum\"\n[friction]\ncoefficient "
                                     "= 0.5\n")),
      SceneError,
      "test.toml:17:15: friction.coefficient: friction runs with solver.method = \"event\" "
      "only");
}

// A scene built in code is planned by run_scene from its fields, keeping the method it names.
TEST(RoutePlan, ASceneBuiltInCodeIsPlannedByItsRun) {
  Scene scene = test::build_scene_text(shorthand("[discretization]\nsprings = 400\n"));
  const RunResult read = run_scene(scene, ObserverList{});
  scene.plan = RoutePlan{};
  scene.discretization.extrapolation = DiscretizationOptions::Extrapolation::automatic;
  const RunResult built = run_scene(scene, ObserverList{});
  ASSERT_TRUE(read.critical && built.critical);
  EXPECT_EQ(read.critical->normal_force, built.critical->normal_force);
  // rtol on a scene built in code stays on its named method's row.
  scene.discretization.rtol = 1e-3;
  scene.plan = RoutePlan{};
  const RunResult rtol = run_scene(scene, ObserverList{});
  EXPECT_EQ(rtol.accuracy.route == Accuracy::Route::continuum, false);
}

}  // namespace
}  // namespace mdrsim
