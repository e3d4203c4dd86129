// Which route discretization.rtol takes with no method: the continuum route for the shorthand
// (checked against independent values for the exact sphere), the row for what it cannot answer.
#include "engine/scene/continuum_scope.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "engine/output/result_json.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

/// The exact sphere R = 1 cm, dgamma/(E* R) = 1e-2, glued at 0.5 R, G* = E*, with rtol and
/// the given [solver] (none when empty).
std::string sphere(const std::string& normal, const std::string& solver) {
  return fmt::format(
      "[material]\neffective_modulus = 1.0e6\neffective_shear_modulus = 1.0e6\n"
      "work_of_adhesion = 100.0\n[profile]\ntype = \"sphere\"\nradius = 0.01\n"
      "[loading]\npreload = {{ contact_radius = 0.005 }}\nnormal = {{ control = \"{}\" }}\n"
      "[discretization]\nrtol = 1e-10\n{}",
      normal, solver);
}

RunResult run(const Scene& scene) { return run_scene(scene, ObserverList{}); }

/// F/F0 of the critical point, F0 = 1.5 pi dgamma R.
double in_f0(const RunResult& r) { return r.critical.value().normal_force / (1.5 * kPi); }

// The independent values (an implementation apart from this one) carry 9 digits: 6e-10 covers
// their rounding; the route's own estimate is below 1e-12. The row at rtol 1e-10 would need
// millions of springs: only the continuum route gets there in a test's time.
TEST(ContinuumScope, RtolWithoutMethodTakesTheContinuumRoute) {
  for (const auto& [normal, want] :
       {std::pair{"fixed-load", -0.958995362}, std::pair{"fixed-grips", -0.547205656}}) {
    SCOPED_TRACE(normal);
    const Scene scene = test::build_scene_text(sphere(normal, ""));
    EXPECT_TRUE(continuum_answers(scene));
    EXPECT_EQ(scene.solver.method, SolverMethod::continuum);
    const RunResult r = run(scene);
    ASSERT_EQ(r.status, RunStatus::instability);
    EXPECT_NEAR(in_f0(r), want, 6e-10);
    const auto j = result_to_json(scene, r);
    EXPECT_EQ(j["resolution"]["route"], "continuum");
    EXPECT_EQ(j["accuracy"]["route"], "continuum");
    EXPECT_TRUE(j["accuracy"]["rtol_met"].get<bool>());
    // The resolved scene leaves method out, as the input did, and reruns on the same route.
    EXPECT_FALSE(j["scene"].contains("solver") && j["scene"]["solver"].contains("method"));
    const Scene again =
        SceneDocument::from_scene_text(j.dump(), "result.json").build(Registries::builtin());
    EXPECT_EQ(again.solver.method, SolverMethod::continuum);
  }
}

// An empty [solver] table names no method either.
TEST(ContinuumScope, EmptySolverTableNamesNoMethod) {
  const Scene scene = test::build_scene_text(sphere("fixed-load", "[solver]\n"));
  EXPECT_EQ(scene.solver.method, SolverMethod::continuum);
  const auto j = result_to_json(scene, run(scene));
  EXPECT_FALSE(j["scene"].contains("solver"));
}

// method = "event" keeps the row at rtol: a coarse rtol, so that the row is quick; its value
// is the continuum's to within the rtol it guarantees (plus the 9 digits' rounding).
TEST(ContinuumScope, MethodEventStaysOnTheRow) {
  std::string text = sphere("fixed-load", "[solver]\nmethod = \"event\"\n");
  text.replace(text.find("1e-10"), 5, "1e-4");
  const Scene scene = test::build_scene_text(text);
  EXPECT_EQ(scene.solver.method, SolverMethod::event);
  const RunResult r = run(scene);
  EXPECT_NE(r.accuracy.route, Accuracy::Route::continuum);
  EXPECT_NEAR(in_f0(r) / -0.958995362, 1.0, 1e-4);
  const auto j = result_to_json(scene, r);
  EXPECT_GT(j["springs"].get<std::int64_t>(), 0);
  EXPECT_EQ(j["scene"]["solver"]["method"], "event");
}

// Without rtol, and with an extrapolation named (a request for the row's own machinery), the
// row stays the route.
TEST(ContinuumScope, SpringsOrExtrapolationStayOnTheRow) {
  std::string springs = sphere("fixed-load", "");
  springs.replace(springs.find("rtol = 1e-10"), 12, "springs = 200");
  EXPECT_EQ(test::build_scene_text(springs).solver.method, SolverMethod::event);
  std::string extrapolated = sphere("fixed-load", "");
  extrapolated.replace(extrapolated.find("rtol = 1e-10"), 12,
                       "rtol = 1e-4\nextrapolation = \"richardson\"");
  EXPECT_EQ(test::build_scene_text(extrapolated).solver.method, SolverMethod::event);
}

// A normal loading program takes the route with rtol alone; one that shears until
// separation, or has friction, stays on the row.
TEST(ContinuumScope, NormalProgramsTakeTheRouteAndShearingOnesStayOnTheRow) {
  const std::string text =
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 100.0\n"
      "[profile]\ntype = \"sphere\"\nradius = 0.01\n"
      "[[loading.stage]]\nname = \"approach\"\nnormal = { control = \"fixed-grips\", to = "
      "1e-4 }\n"
      "[discretization]\nrtol = 1e-3\n";
  const Scene normal = test::build_scene_text(text);
  EXPECT_TRUE(continuum_answers(normal));
  EXPECT_EQ(normal.solver.method, SolverMethod::continuum);
  const Scene sheared = test::build_scene_text(
      text +
      "[[loading.stage]]\nname = \"shear\"\ntangential = { control = \"fixed-grips\", "
      "by = 1e-6 }\nuntil = \"separation\"\n");
  EXPECT_FALSE(continuum_answers(sheared));
  EXPECT_EQ(sheared.solver.method, SolverMethod::event);
  const Scene rubbing = test::build_scene_text(text + "[friction]\ncoefficient = 0.5\n");
  EXPECT_EQ(rubbing.solver.method, SolverMethod::event);
}

// A branch that may fold more than once stays on the row with rtol alone: a wavy sphere (at
// A = 1e-7 m its branch folds at several crests; the route's first fold gave -1.80e-3 N where
// the row's last jump is at -0.99e-3 N) and a tabulated table. A wavy profile named on the
// route is refused at solver.method; with amplitude 0 it is the parabola and is answered.
TEST(ContinuumScope, BranchesThatMayFoldAgainStayOnTheRow) {
  const std::string wavy =
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"wavy\"\nradius = 0.01\namplitude = 1e-7\nwavelength = 1e-4\n"
      "[loading]\npreload = { contact_radius = 5.2e-4 }\nnormal = { control = \"fixed-grips\" }\n"
      "[discretization]\nrtol = 1e-6\n";
  EXPECT_EQ(test::build_scene_text(wavy).solver.method, SolverMethod::event);
  EXPECT_THROW(test::build_scene_text(wavy + "[solver]\nmethod = \"continuum\"\n"), SceneError);
  std::string flat = wavy;
  flat.replace(flat.find("amplitude = 1e-7"), 16, "amplitude = 0.0");
  EXPECT_EQ(test::build_scene_text(flat).solver.method, SolverMethod::continuum);
  const std::string table =
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"tabulated\"\nr = [0, 1e-4, 2e-4, 3e-4, 4e-4, 6e-4, 8e-4]\n"
      "f = [0, 5e-7, 2e-6, 4.5e-6, 8e-6, 1.8e-5, 3.2e-5]\n"
      "[loading]\npreload = { contact_radius = 4e-4 }\nnormal = { control = \"fixed-grips\" }\n"
      "[discretization]\nrtol = 1e-6\n";
  EXPECT_EQ(test::build_scene_text(table).solver.method, SolverMethod::event);
}

/// A power law c r^n glued at `glued` [m] under `normal` (with its extra keys), rtol 1e-8 and
/// the given [solver] (none when empty).
std::string power_law(double coefficient, double exponent, double glued, const std::string& normal,
                      const std::string& solver) {
  return fmt::format(
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n[profile]\n"
      "type = \"power_law\"\ncoefficient = {:.17g}\nexponent = {:.17g}\n[loading]\n"
      "preload = {{ contact_radius = {:.17g} }}\nnormal = {{ control = {} }}\n"
      "[discretization]\nrtol = 1e-8\n{}",
      coefficient, exponent, glued, normal, solver);
}

// A power law's JKR branch folds at most once under fixed grips and a fixed load for every n
// (sqrt(a) g'(a) = n k a^(n - 1/2) crosses Hess's level once: continuum_scope.cpp derives it):
// rtol alone takes the continuum route for n = 0.5 and 0.8, and answers with the numbers of
// method = "continuum" to the bit. They stayed on the row, which at rtol 1e-8 ran rows of
// 131072 springs and warned that it had not met rtol.
TEST(ContinuumScope, PowerLawsBelowOneTakeTheRouteWhereTheirBranchFoldsOnce) {
  for (const double n : {0.5, 0.8}) {
    for (const std::string normal : {"\"fixed-grips\"", "\"fixed-load\""}) {
      SCOPED_TRACE(fmt::format("n = {}, {}", n, normal));
      const double coefficient = n == 0.5 ? 1e-3 : 1e-2;
      const Scene alone = test::build_scene_text(power_law(coefficient, n, 1e-3, normal, ""));
      EXPECT_TRUE(continuum_answers(alone));
      ASSERT_EQ(alone.solver.method, SolverMethod::continuum);
      const Scene named = test::build_scene_text(
          power_law(coefficient, n, 1e-3, normal, "[solver]\nmethod = \"continuum\"\n"));
      const auto a = result_to_json(alone, run(alone));
      const auto b = result_to_json(named, run(named));
      EXPECT_EQ(a["accuracy"]["route"], "continuum");
      for (const char* key : {"status", "critical", "peak_adhesion", "stages", "jumps", "work",
                              "accuracy", "warnings"}) {
        EXPECT_EQ(a.contains(key), b.contains(key)) << key;
        if (a.contains(key)) {
          EXPECT_EQ(a[key], b[key]) << key;
        }
      }
    }
  }
}

// Under a compliant machine of stiffness k the fold condition weighs sqrt(a) g'(a) by
// (1 + 2 beta a) / (1 + 6 beta a), beta = E*/k, whose log-slope reaches -(2 - sqrt 3): one
// fold for every k where n - 1/2 >= 2 - sqrt 3 (n = 0.8), possibly two below it. At n = 0.7,
// c = 4.12118e-3, k = 100 N/m the control has minima at a = 2.3e-6 and 1.35e-4 m and a
// maximum between: the route (named) jumps at the outer fold onto the branch below and off at
// the inner one. rtol alone keeps that scene on the row, and a tangential load (another
// let-go) keeps n = 0.8 there too.
TEST(ContinuumScope, APowerLawBranchThatMayFoldTwiceStaysOnTheRow) {
  const std::string compliant = "\"compliant\", stiffness = 100.0";
  EXPECT_EQ(test::build_scene_text(power_law(1e-2, 0.8, 3e-4, compliant, "")).solver.method,
            SolverMethod::continuum);
  const Scene twice = test::build_scene_text(power_law(4.12118e-3, 0.7, 3e-4, compliant, ""));
  EXPECT_FALSE(continuum_answers(twice));
  EXPECT_EQ(twice.solver.method, SolverMethod::event);
  const RunResult r = run(test::build_scene_text(
      power_law(4.12118e-3, 0.7, 3e-4, compliant, "[solver]\nmethod = \"continuum\"\n")));
  ASSERT_EQ(r.jumps.size(), 2u);
  EXPECT_NEAR(r.jumps[0].critical.contact_radius, 1.347e-4, 1e-7);
  EXPECT_GT(r.jumps[0].after.contact_radius, 0.0);  // a partial jump: the contact stays
  EXPECT_NEAR(r.jumps[1].critical.contact_radius, 2.277e-6, 1e-9);
  std::string sheared = power_law(1e-2, 0.8, 1e-3, "\"fixed-grips\"", "");
  sheared.insert(sheared.find("normal = {"),
                 "tangential = { control = \"fixed-grips\", displacement = 1e-7 }\n");
  EXPECT_EQ(test::build_scene_text(sheared).solver.method, SolverMethod::event);
}

}  // namespace
}  // namespace mdrsim

namespace mdrsim {
namespace {

// A program with a tangential stage may stop on the route (a glue let go by the moving shear):
// rtol alone keeps it on the row, which follows it; named, the route runs it.
TEST(ContinuumScope, AProgramThatShearsTakesTheRouteOnlyWhenNamed) {
  const std::string text =
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to = 2e-5 }\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = { control = \"fixed-grips\", to = 1e-6 "
      "}\n[discretization]\nrtol = 1e-4\n";
  EXPECT_EQ(test::build_scene_text(text).solver.method, SolverMethod::event);
  EXPECT_EQ(test::build_scene_text(text + "[solver]\nmethod = \"continuum\"\n").solver.method,
            SolverMethod::continuum);
}

}  // namespace
}  // namespace mdrsim
