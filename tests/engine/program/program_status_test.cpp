// The program's status where the glue and the contact part at different times: springs
// pressed without glue stay after a glue jump and lift off later, smoothly.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

constexpr double kDepth = 2.5e-5;  ///< d = a_g^2 / R for a_g = 5e-4 m, R = 1e-2 m

/// u = 0.85 u_s, u_s = sqrt(2 pi a_g dgamma / G*): the glue at a_g holds it at the preload,
/// and Fig. 3a's fixed-grips line puts the critical force above zero there.
double tangential() { return 0.85 * std::sqrt(2.0 * std::numbers::pi * 5e-4 * 0.05 / 1e6); }

std::string scene_text(const std::string& extra_stages) {
  return fmt::format(
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[loading]\n"
      "[[loading.stage]]\nname = \"preload\"\nnormal = {{ control = \"fixed-grips\", to = {} }}\n"
      "[[loading.stage]]\nname = \"shear\"\n"
      "tangential = {{ control = \"fixed-grips\", to = {:.17g} }}\n"
      "[[loading.stage]]\nname = \"pull\"\nnormal = {{ by = -1e-5 }}\nuntil = \"separation\"\n"
      "{}"
      "[discretization]\nsprings = 2000\n",
      kDepth, tangential(), extra_stages);
}

// The glue shears off at a compressive force with the inner springs still pressed: that jump
// is the instability (Fig. 3a's positive branch), though the pressed springs lift off one by
// one afterwards, to zero force.
TEST(ProgramStatus, AGlueJumpWhilePressedIsTheInstability) {
  const RunResult r = run_scene(test::build_scene_text(scene_text("")), {});
  EXPECT_EQ(r.status, RunStatus::instability);
  ASSERT_TRUE(r.critical.has_value());
  EXPECT_GT(r.critical->normal_force, 0.0);
  // The critical point is the state before the glue's jump, which left springs in contact.
  ASSERT_FALSE(r.jumps.empty());
  const JumpRecord& jump = r.jumps.front();
  EXPECT_EQ(jump.critical.springs_in_contact, r.critical->springs_in_contact);
  EXPECT_EQ(jump.critical.normal_force, r.critical->normal_force);
  EXPECT_GT(jump.after.springs_in_contact, 0);
  EXPECT_EQ(jump.glued_springs, -r.critical->springs_in_contact);
}

// A glue jump decides only the contact it broke: separated, pressed in again (no rebinding:
// pressed springs only, which cannot pull) and pulled off, the contact lifts off smoothly and
// the program has no critical point.
TEST(ProgramStatus, AGlueJumpDoesNotDecideALaterContact) {
  const RunResult r = run_scene(
      test::build_scene_text(scene_text(fmt::format(
          "[[loading.stage]]\nname = \"press\"\nnormal = {{ control = \"fixed-grips\", to = {} "
          "}}\n"
          "[[loading.stage]]\nname = \"pull-again\"\nnormal = {{ by = -1e-5 }}\n"
          "until = \"separation\"\n",
          kDepth))),
      {});
  ASSERT_EQ(r.stages.size(), 5u);
  EXPECT_GT(r.stages[3].end.springs_in_contact, 0);
  EXPECT_EQ(r.status, RunStatus::no_instability);
  EXPECT_FALSE(r.critical.has_value());
}

// A rebinding program that pushes on "until separation" while shearing never separates. Its
// 256-spring pilot row (which frames the run's rows) reaches t of about 8.5e8, where rounding
// keeps one parameter value's changes from settling: that row stops (step-limit, "without
// settling"), and the run reports the stick-slip stop of its own row with the stages before
// it, never an internal error.
TEST(ProgramStatus, AnUnsettlingCascadeStopsTheProgramWithAWarning) {
  const Scene scene = test::build_scene_text(
      "[material]\neffective_modulus = 2.0e6\nwork_of_adhesion = 0.05\n"
      "approach_work_of_adhesion = 0.02\n[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[loading]\nrebinding = true\n"
      "[[loading.stage]]\nname = \"approach\"\nnormal = { control = \"fixed-load\", to = 0.01 "
      "}\n"
      "[[loading.stage]]\nname = \"shear\"\ntangential = { control = \"fixed-load\", by = 1e-3 "
      "}\n"
      "[[loading.stage]]\nname = \"unload\"\nnormal = { to = -0.001 }\n"
      "[[loading.stage]]\nname = \"reload\"\n"
      "normal = { control = \"compliant\", stiffness = 100.0, by = 1e-5 }\n"
      "[[loading.stage]]\nname = \"pull\"\nnormal = { control = \"fixed-grips\", by = 30e-5 }\n"
      "tangential = { control = \"fixed-grips\", by = 1e-6 }\nuntil = \"separation\"\n"
      "[discretization]\nsprings = 500\n");
  const RunResult r = run_scene(scene, {});
  EXPECT_EQ(r.status, RunStatus::step_limit);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("stage 'pull'"), std::string::npos) << r.warnings.back();
  // The stages before the one that did not settle are reported.
  ASSERT_GE(r.stages.size(), 4U);
  EXPECT_EQ(r.stages[3].name, "reload");
}

// Without adhesion, a fixed load lowered through zero loses the contact as its last spring
// lifts at zero load: the stage ends there (F = 0 to the held line's rounding, no tension), at
// every spring count. The lifts' rounding once left the force a few 1e-18 N above zero after
// the last but one (200 and 300 springs): the last spring then held the pull, -0.05 N at
// d = -6.9 mm, and the run reported an instability.
TEST(ProgramStatus, AFallingLoadWithoutAdhesionLosesTheContactAtZeroForce) {
  for (const int springs : {100, 200, 300, 400, 800}) {
    SCOPED_TRACE(springs);
    const RunResult r =
        run_scene(test::build_scene_text(
                      fmt::format("[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.0\n"
                                  "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
                                  "[[loading.stage]]\nname = \"load\"\nnormal = {{ control = "
                                  "\"fixed-load\", to = 0.05 }}\n"
                                  "duration = 0.2\n"
                                  "[[loading.stage]]\nname = \"hold\"\nduration = 0.5\n"
                                  "[[loading.stage]]\nname = \"unload\"\nnormal = {{ control = "
                                  "\"fixed-load\", by = -0.1 }}\n"
                                  "duration = 0.2\n"
                                  "[discretization]\nsprings = {}\n[solver]\nmethod = \"event\"\n",
                                  springs)),
                  {});
    EXPECT_EQ(r.status, RunStatus::no_instability);
    EXPECT_FALSE(r.critical.has_value());
    ASSERT_EQ(r.stages.size(), 3u);
    const ContactSnapshot& end = r.stages[2].end;
    // 0.05 N held to 16 eps of its line's terms: the force where the contact is lost.
    EXPECT_LE(std::abs(end.normal_force), 16.0 * std::numeric_limits<double>::epsilon() * 0.15);
    EXPECT_GE(end.indentation, 0.0);
    EXPECT_LE(end.springs_in_contact, 1);
  }
}

}  // namespace
}  // namespace mdrsim
