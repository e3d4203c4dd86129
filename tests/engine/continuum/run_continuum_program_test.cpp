// Normal loading programs on the continuum route against the closed JKR cycles of
// engine/reference/program_reference (derived apart from the engine), and its refusals.
#include "engine/continuum/run_continuum_program.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/events/observer.hpp"
#include "engine/reference/program_reference.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/program_examples.hpp"

namespace mdrsim {
namespace {

namespace pr = program_reference;
using test::kExampleDepth;
using test::kExampleForce;

const double kExampleRadius =
    std::cbrt(9.0 * std::numbers::pi * 0.01 * 0.01 * 0.05 / (8.0 * 1e6));  ///< a0 [m]
const double kExampleWork = kExampleForce * kExampleDepth;                 ///< F0 d0 [J]

/// The root searches meet rtol 1e-10; the references are closed forms and TOMS 748 roots.
constexpr double kTolerance = 1e-9;

std::string read_text(const std::string& name) {
  std::ifstream in(std::string(MDRSIM_SOURCE_DIR) + "/scenes/programs/" + name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// scenes/programs/NAME on the continuum route at rtol 1e-10, `edit` applied to its text.
std::string on_continuum(std::string s) {
  const std::size_t at = s.find("springs = ");
  s.replace(at, s.find('\n', at) - at, "rtol = 1e-10");
  const std::size_t method = s.find("method = \"event\"");
  s.replace(method, std::string("method = \"event\"").size(), "method = \"continuum\"");
  return s;
}

RunResult run_text(const std::string& text, const ObserverList& observers = {}) {
  return run_scene(SceneDocument::from_text(text, "program.toml").build(Registries::builtin()),
                   observers);
}

void expect_near_relative(double value, double expected, double scale, const char* what) {
  EXPECT_NEAR(value, expected, kTolerance * std::abs(scale)) << what;
}

TEST(ContinuumProgram, ReversibleCycleIsTheClosedJkrCycle) {
  const RunResult r = run_text(on_continuum(read_text("jkr_cycle_reversible.toml")));
  const pr::ReversibleCycle c = pr::reversible_jkr_cycle(3.0);
  ASSERT_EQ(r.status, RunStatus::instability);
  ASSERT_EQ(r.jumps.size(), 2u);
  EXPECT_TRUE(r.jumps[0].inward);
  expect_near_relative(r.jumps[0].after.normal_force / kExampleForce, c.jump_in_after.normal_force,
                       1.0, "jump-in F");
  expect_near_relative(r.jumps[0].after.contact_radius / kExampleRadius,
                       c.jump_in_after.contact_radius, 1.0, "jump-in a");
  ASSERT_EQ(r.stages.size(), 2u);
  expect_near_relative(r.stages[0].end.normal_force / kExampleForce, c.approach_end.normal_force,
                       1.0, "approach end F");
  expect_near_relative(r.stages[0].end.contact_radius / kExampleRadius,
                       c.approach_end.contact_radius, 1.0, "approach end a");
  ASSERT_TRUE(r.critical);
  EXPECT_EQ(r.critical_stage, "retract");
  expect_near_relative(r.critical->normal_force / kExampleForce, c.retract_critical.normal_force,
                       1.0, "critical F");
  expect_near_relative(r.critical->indentation / kExampleDepth, c.retract_critical.indentation, 1.0,
                       "critical d");
  ASSERT_TRUE(r.work);
  expect_near_relative(r.work->normal / kExampleWork, c.dissipated_work, c.dissipated_work,
                       "cycle work");
  // The most tensile state passed: the fixed-load fold of the JKR branch, F = -F0.
  ASSERT_TRUE(r.peak);
  expect_near_relative(r.peak->normal_force / kExampleForce, -1.0, 1.0, "peak");
  EXPECT_TRUE(r.accuracy.rtol_met);
}

TEST(ContinuumProgram, GlueOnTouchCycleIsTheClosedCycle) {
  const RunResult r = run_text(on_continuum(read_text("jkr_cycle_glue_on_touch.toml")));
  const pr::GlueOnTouchCycle c = pr::glue_on_touch_cycle(3.0);
  ASSERT_EQ(r.status, RunStatus::instability);
  ASSERT_EQ(r.jumps.size(), 1u);  // no jump-in: the front grows from the tip on Hertz
  EXPECT_FALSE(r.jumps[0].inward);
  expect_near_relative(r.stages[0].end.normal_force / kExampleForce, c.load_end.normal_force,
                       c.load_end.normal_force, "load end F");
  expect_near_relative(r.stages[0].work.normal / kExampleWork, c.loading_work, c.loading_work,
                       "loading work");
  ASSERT_TRUE(r.critical);
  expect_near_relative(r.critical->normal_force / kExampleForce, c.retract_critical.normal_force,
                       1.0, "critical F");
  expect_near_relative(r.work->normal / kExampleWork, c.dissipated_work, c.dissipated_work,
                       "cycle work");
}

TEST(ContinuumProgram, ReloadWithRebindingIsTheClosedProgram) {
  const RunResult r = run_text(on_continuum(read_text("reload_rebinding_true.toml")));
  const pr::ReloadProgram c = pr::reload_program(12.0, 3.0, 6.0, true);
  ASSERT_EQ(r.stages.size(), 5u);
  for (std::size_t k = 0; k < 4; ++k) {
    SCOPED_TRACE(r.stages[k].name);
    expect_near_relative(r.stages[k].end.normal_force / kExampleForce, c.stage_end_force[k], 8.0,
                         "stage end F");
  }
  for (std::size_t k = 0; k < 5; ++k) {
    SCOPED_TRACE(r.stages[k].name);
    expect_near_relative(r.stages[k].work.normal / kExampleWork, c.stage_work[k], c.work,
                         "stage work");
  }
  ASSERT_TRUE(r.critical);
  expect_near_relative(r.critical->normal_force / kExampleForce, c.pull_off_critical.normal_force,
                       1.0, "critical F");
  expect_near_relative(r.work->normal / kExampleWork, c.work, c.work, "program work");
}

// The reversible approach, then a fixed-load retract: the JKR fixed-load fold F = -F0 (eq. 19),
// the indenter separates, and the machine's work is the branch integral from the jump-in
// radius to a0 (pinned phases: none, the advancing and receding limits agree).
TEST(ContinuumProgram, FixedLoadRetractSeparatesAtTheJkrFold) {
  std::string text = on_continuum(read_text("jkr_cycle_reversible.toml"));
  const std::string retract = "normal = { control = \"fixed-grips\", by = -1.0e-6 }";
  text.replace(text.find(retract), retract.size(),
               "normal = { control = \"fixed-load\", by = -1.0e-3 }");
  const RunResult r = run_text(text);
  ASSERT_EQ(r.status, RunStatus::instability);
  ASSERT_TRUE(r.critical);
  expect_near_relative(r.critical->normal_force / kExampleForce, -1.0, 1.0, "critical F");
  ASSERT_FALSE(r.jumps.empty());
  EXPECT_EQ(r.jumps.back().end, JumpEnd::separated);
  const double jump_in_radius = std::cbrt(16.0 / 9.0);
  const double expected = pr::jkr_branch_work(jump_in_radius, 1.0);
  expect_near_relative(r.work->normal / kExampleWork, expected, expected, "work");
}

// Without adhesion the cycle is Hertz's both ways: nothing jumps, the loop encloses nothing,
// and pressing to d stores (8/15) E* R^1/2 d^5/2.
TEST(ContinuumProgram, HertzCycleDissipatesNothing) {
  std::string text = on_continuum(read_text("jkr_cycle_glue_on_touch.toml"));
  const std::string adhesion = "work_of_adhesion = 0.05";
  text.replace(text.find(adhesion), adhesion.size(), "work_of_adhesion = 0.0");
  const RunResult r = run_text(text);
  EXPECT_EQ(r.status, RunStatus::no_instability);
  EXPECT_TRUE(r.jumps.empty());
  const double d = 6.7844544808348425e-6;
  const double stored = 8.0 / 15.0 * 1e6 * std::sqrt(0.01) * std::pow(d, 2.5);
  expect_near_relative(r.stages[0].work.normal, stored, stored, "approach work");
  EXPECT_NEAR(r.work->normal, 0.0, kTolerance * stored);
  EXPECT_TRUE(r.accuracy.rtol_met);
}

// Every sample of the reversible cycle in contact lies on the JKR branch, eq. 18 in the
// paper's units: d = 3 a^2 - 4 sqrt(a).
TEST(ContinuumProgram, SamplesLieOnTheBranchTheyFollow) {
  struct Samples : Observer {
    std::vector<ContactSnapshot> states;
    void on_event(const Event& e) override {
      if (e.kind == EventKind::sample) states.push_back(e.state);
    }
  } samples;
  ObserverList observers;
  observers.add(samples);
  const Scene scene =
      SceneDocument::from_text(on_continuum(read_text("jkr_cycle_reversible.toml")), "program.toml")
          .build(Registries::builtin());
  run_scene(scene, observers, 1000);
  ASSERT_GE(samples.states.size(), 500u);
  ASSERT_LE(samples.states.size(), 1000u);
  int on_branch = 0;
  for (const ContactSnapshot& s : samples.states) {
    if (s.contact_radius == 0.0) continue;
    const double a = s.contact_radius / kExampleRadius;
    EXPECT_NEAR(s.indentation / kExampleDepth, 3.0 * a * a - 4.0 * std::sqrt(a), 1e-9);
    ++on_branch;
  }
  EXPECT_GT(on_branch, 400);
}

TEST(ContinuumProgram, RefusesWhatItCannotAnswerExactly) {
  const auto refused = [](const std::string& text, const std::string& why) {
    try {
      run_text(text);
      ADD_FAILURE() << "accepted; expected: " << why;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  refused(on_continuum(read_text("shear_ramp_fixed_grips.toml")), "shears until separation");
  // Known only as it runs: the reload presses back springs that let go, unglued.
  refused(on_continuum(read_text("reload_rebinding_false.toml")),
          "without loading.rebinding = true they push back unglued");
  std::string compliant = on_continuum(read_text("jkr_cycle_reversible.toml"));
  const std::string retract = "normal = { control = \"fixed-grips\", by = -1.0e-6 }";
  compliant.replace(compliant.find(retract), retract.size(),
                    "normal = { control = \"compliant\", stiffness = 100.0, by = -1.0e-6 }");
  refused(compliant, "drives through a machine spring");
}

}  // namespace
}  // namespace mdrsim

namespace mdrsim {
namespace {

// Beyond the parabola's closed forms: the sphere, a cone and a power law, glued on touch, at
// dgamma_a = 0.3 dgamma and reversibly, retracted under fixed grips and a fixed load, against
// the spring row of the same program at rtol 1e-5 (its own estimates, apart from the route):
// the critical forces within the row's rtol, the works where the row vouches for its work.
TEST(ContinuumProgram, AgreesWithTheRowOnOtherProfiles) {
  struct Case {
    const char* profile;
    double approach_fraction;  ///< dgamma_a / dgamma
    const char* retract;       ///< the retract stage's normal table
    double depth;              ///< [m]
  };
  const Case cases[] = {
      {"type = \"sphere\"\nradius = 0.01", 0.3, "control = \"fixed-grips\", by = -1e-6", 1.2e-5},
      {"type = \"sphere\"\nradius = 0.01", 1.0, "control = \"fixed-load\", by = -1e-3", 6e-6},
      {"type = \"cone\"\nslope_angle_deg = 5.0", 1.0, "control = \"fixed-grips\", by = -1e-6",
       1e-4},
      {"type = \"cone\"\nslope_angle_deg = 5.0", 0.0, "control = \"fixed-load\", by = -1e-3", 1e-4},
      {"type = \"power_law\"\ncoefficient = 3e3\nexponent = 1.5", 0.0,
       "control = \"fixed-load\", by = -1e-3", 1.5e-5},
      {"type = \"power_law\"\ncoefficient = 3e3\nexponent = 1.5", 0.3,
       "control = \"fixed-grips\", by = -1e-6", 8e-6},
  };
  for (const Case& c : cases) {
    const std::string program = fmt::format(
        "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
        "approach_work_of_adhesion = {}\n[profile]\n{}\n"
        "[[loading.stage]]\nname = \"approach\"\nnormal = {{ control = \"fixed-grips\", to = {} "
        "}}\n[[loading.stage]]\nname = \"retract\"\nnormal = {{ {} }}\nuntil = \"separation\"\n",
        0.05 * c.approach_fraction, c.profile, c.depth, c.retract);
    SCOPED_TRACE(program);
    const RunResult continuum =
        run_text(program + "[discretization]\nrtol = 1e-10\n[solver]\nmethod = \"continuum\"\n");
    const RunResult row =
        run_text(program + "[discretization]\nrtol = 1e-5\n[solver]\nmethod = \"event\"\n");
    ASSERT_EQ(continuum.status, row.status);
    ASSERT_TRUE(continuum.critical && row.critical);
    EXPECT_NEAR(continuum.critical->normal_force, row.critical->normal_force,
                1e-5 * std::abs(row.critical->normal_force));
    EXPECT_EQ(continuum.jumps.size(), row.jumps.size());
    const auto& covers = row.accuracy.covers;
    if (std::find(covers.begin(), covers.end(), "work") != covers.end()) {
      // Relative to the path's scale, as rtol is: a cycle's net work may nearly cancel.
      double scale = 0.0;
      for (const StageRecord& stage : row.stages) scale += std::abs(stage.work.normal);
      EXPECT_NEAR(continuum.work->normal, row.work->normal, 1e-5 * scale);
    }
  }
}

}  // namespace
}  // namespace mdrsim

namespace mdrsim {
namespace {

/// The paper's path on the parabola (scenes/fig3a_*: glued at 2 a0, d_p = 12 d0) with the
/// tangential axis under `tangential` (a table's keys), pulled off under `normal`.
std::string paper_path(const std::string& normal, const std::string& tangential, bool program) {
  std::string s =
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n";
  if (program) {
    s += fmt::format(
        "[[loading.stage]]\nname = \"preload\"\nnormal = {{ control = \"fixed-grips\", to = "
        "2.713781792333937e-5 }}\n[[loading.stage]]\nname = \"tangential\"\nnormal = {{ "
        "control = \"{}\" }}\ntangential = {{ {} }}\n[[loading.stage]]\nname = "
        "\"pull-off\"\nnormal = {{ by = {} }}\nuntil = \"separation\"\n",
        normal, tangential, normal == "fixed-load" ? "-1e-3" : "-1e-6");
  } else {
    std::string shorthand = tangential;
    shorthand.replace(
        shorthand.find("to ="), 4,
        tangential.find("fixed-load") != std::string::npos ? "force =" : "displacement =");
    s += fmt::format(
        "[loading]\npreload = {{ contact_radius = 5.209397078678047e-4 }}\nnormal = {{ control "
        "= \"{}\" }}\ntangential = {{ {} }}\n",
        normal, shorthand);
  }
  return s + "[discretization]\nrtol = 1e-10\n[solver]\nmethod = \"continuum\"\n";
}

// SPEC: the shorthand is a program. On the continuum route its three stages, with the
// tangential load applied on the glued disk and held through the pull-off, give the
// shorthand's critical point and works: the same branch, to the last bit here.
TEST(ContinuumProgram, ThePaperPathAsAProgramIsTheShorthand) {
  for (const char* normal : {"fixed-grips", "fixed-load"}) {
    for (const char* tangential : {"control = \"fixed-grips\", to = 6e-6",
                                   "control = \"fixed-load\", to = 2.356194490192345e-3"}) {
      SCOPED_TRACE(std::string(normal) + " / " + tangential);
      const RunResult shorthand = run_text(paper_path(normal, tangential, false));
      const RunResult program = run_text(paper_path(normal, tangential, true));
      ASSERT_EQ(program.status, shorthand.status);
      ASSERT_TRUE(program.critical && shorthand.critical);
      EXPECT_NEAR(program.critical->normal_force, shorthand.critical->normal_force,
                  1e-12 * std::abs(shorthand.critical->normal_force));
      EXPECT_NEAR(program.critical->tangential_force, shorthand.critical->tangential_force,
                  1e-12 * std::abs(shorthand.critical->tangential_force));
      ASSERT_TRUE(program.work && shorthand.work);
      const double scale = std::abs(shorthand.stages[0].work.normal);
      EXPECT_NEAR(program.work->normal, shorthand.work->normal, 1e-10 * scale);
      EXPECT_NEAR(program.work->tangential, shorthand.work->tangential, 1e-10 * scale);
    }
  }
}

/// The refusal a run of `text` ends with: its message, or "" when it runs.
std::string refusal(const std::string& text) {
  try {
    run_text(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// SPEC "Continuum route": a scene the route cannot answer exactly is refused with one line,
// never approximated. A tangential load that lets the glue go as it is applied would make the
// front recede under a moving u_x, which the route does not follow: refused at the key that
// chose the route (the row then reports a shear-off, as the shorthand does).
TEST(ContinuumProgram, AShearThatLetsTheGlueGoAsItIsAppliedIsRefused) {
  const std::string text = paper_path("fixed-grips", "control = \"fixed-grips\", to = 3e-5", true);
  EXPECT_EQ(refusal(text),
            "program.toml:22:10: solver.method: stage 'tangential': the tangential load lets the "
            "glue go as it is applied (at a = 0.00052094 m), and the continuum route does not "
            "follow a front receding under a moving tangential load; use method = \"event\" "
            "(docs/continuum.md)");
  const RunResult shorthand =
      run_text(paper_path("fixed-grips", "control = \"fixed-grips\", to = 3e-5", false));
  EXPECT_EQ(shorthand.status, RunStatus::shear_off);
}

// Mode-dependent (lambda = 0.5): e' stays finite where the held u_x alone breaks the glue, so
// the retract reaches that radius with springs pressed in and shears off there; without glue
// they are the row's. Refused, where the smaller shear runs to its fold.
TEST(ContinuumProgram, AGlueBrokenOverPressedSpringsIsRefused) {
  const auto scene = [](double ux) {
    return paper_path("fixed-grips", fmt::format("control = \"fixed-grips\", to = {}", ux), true) +
           "[detachment]\ncriterion = \"mode-dependent\"\nlambda = 0.5\n";
  };
  const std::string why = refusal(scene(1.5e-5));
  EXPECT_NE(why.find("program.toml:22:10: solver.method: stage 'pull-off': the tangential load "
                     "breaks the glue unstretched at a = "),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("the continuum route does not follow pressed springs without glue; use "
                     "method = \"event\""),
            std::string::npos)
      << why;
  EXPECT_EQ(refusal(scene(1e-5)), "");
}

// With rtol alone a program that shears stays on the row (docs/continuum.md "Which route rtol
// takes"): the same scene then runs, to its shear-off.
TEST(ContinuumProgram, RtolAloneLeavesAShearingProgramOnTheRow) {
  std::string text = paper_path("fixed-grips", "control = \"fixed-grips\", to = 3e-5", true);
  const std::string method = "[solver]\nmethod = \"continuum\"\n";
  text.replace(text.find(method), method.size(), "");
  text.replace(text.find("rtol = 1e-10"), std::string("rtol = 1e-10").size(), "rtol = 1e-4");
  const RunResult r = run_text(text);
  EXPECT_NE(r.accuracy.route, Accuracy::Route::continuum);
  EXPECT_EQ(r.status, RunStatus::shear_off);
}

}  // namespace
}  // namespace mdrsim
