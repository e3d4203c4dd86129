// Loading programs in scene files: [[loading.stage]] read into Scene::program, every mistake
// refused with its exact message, and --set / --vary into loading.stage.N.
#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

// The program every case mutates; the line numbers in the messages below refer to it.
constexpr std::string_view kProgram =
    R"(title = "program"
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
approach_work_of_adhesion = 0.01
[profile]
type = "parabolic"
radius = 0.01
[loading]
rebinding = true
[[loading.stage]]
name = "approach"
normal = { control = "fixed-grips", to = 2.0e-5 }
[[loading.stage]]
name = "shear"
normal = { control = "compliant", stiffness = 1000.0 }
tangential = { by = 4.0e-6 }
[[loading.stage]]
normal = { by = -0.866e-6 }
tangential = { control = "fixed-load", by = 0.5e-6 }
until = "separation"
[discretization]
springs = 100
)";

// The stages of kProgram, as one block of its text.
constexpr std::string_view kStages =
    R"([[loading.stage]]
name = "approach"
normal = { control = "fixed-grips", to = 2.0e-5 }
[[loading.stage]]
name = "shear"
normal = { control = "compliant", stiffness = 1000.0 }
tangential = { by = 4.0e-6 }
[[loading.stage]]
normal = { by = -0.866e-6 }
tangential = { control = "fixed-load", by = 0.5e-6 }
until = "separation"
)";

// The paper's path as the shorthand, which must build as it always did.
constexpr std::string_view kShorthand =
    R"(title = "shorthand"
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
approach_work_of_adhesion = 0.0
[profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { contact_radius = 5.0e-4 }
tangential = { control = "fixed-grips", displacement = 0.0 }
normal = { control = "fixed-load" }
[discretization]
springs = 100
)";

/// `text` with the one occurrence of `from` replaced by `to`.
std::string replaced(std::string_view text, std::string_view from, std::string_view to) {
  std::string out(text);
  const auto at = out.find(from);
  if (at == std::string::npos || out.find(from, at + 1) != std::string::npos) {
    throw std::logic_error(fmt::format("'{}' is not in the test scene exactly once", from));
  }
  return out.replace(at, from.size(), to);
}

const Registries& registries() {
  static const Registries r = Registries::builtin();
  return r;
}

Scene build(std::string_view text) {
  return SceneDocument::from_text(text, "scene.toml").build(registries());
}

SceneDocument program_document() { return SceneDocument::from_text(kProgram, "scene.toml"); }

std::string controllers() {
  std::string out;
  for (const auto& n : registries().controllers.names()) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// ---- a valid program ----

TEST(ProgramScene, ReadsEveryStage) {
  const Scene scene = build(kProgram);
  ASSERT_TRUE(scene.program.has_value());
  const Program& program = *scene.program;
  EXPECT_TRUE(program.rebinding);
  EXPECT_EQ(scene.material.approach_work_of_adhesion, 0.01);
  EXPECT_EQ(scene.material.work_of_adhesion, 0.05);
  EXPECT_EQ(scene.springs, 100);
  ASSERT_EQ(program.stages.size(), 3u);
  using Motion = StageAxis::Motion;

  const Stage& approach = program.stages[0];
  EXPECT_EQ(approach.name, "approach");
  EXPECT_FALSE(approach.until_separation);
  ASSERT_TRUE(approach.normal.has_value());
  EXPECT_EQ(approach.normal->control, "fixed-grips");
  ASSERT_NE(approach.normal->controller, nullptr);
  EXPECT_EQ(approach.normal->motion, Motion::to);
  EXPECT_EQ(approach.normal->value, 2.0e-5);
  EXPECT_FALSE(approach.tangential.has_value());

  const Stage& shear = program.stages[1];
  EXPECT_EQ(shear.name, "shear");
  EXPECT_FALSE(shear.until_separation);
  ASSERT_TRUE(shear.normal.has_value());
  EXPECT_EQ(shear.normal->control, "compliant");
  EXPECT_EQ(shear.normal->motion, Motion::hold);
  EXPECT_EQ(shear.normal->controller->constraint().force_coefficient, 1.0 / 1000.0);
  ASSERT_TRUE(shear.tangential.has_value());
  // No stage named the tangential control before: the program's fixed-grips.
  EXPECT_EQ(shear.tangential->control, "fixed-grips");
  ASSERT_NE(shear.tangential->controller, nullptr);
  EXPECT_EQ(shear.tangential->controller->held_value_key(), "displacement");
  EXPECT_EQ(shear.tangential->motion, Motion::by);
  EXPECT_EQ(shear.tangential->value, 4.0e-6);

  const Stage& pull = program.stages[2];
  EXPECT_EQ(pull.name, "stage 3");
  EXPECT_TRUE(pull.until_separation);
  ASSERT_TRUE(pull.normal.has_value());
  EXPECT_EQ(pull.normal->control, "compliant");
  // The inherited controller is the stage-2 object itself, stiffness and all.
  EXPECT_EQ(pull.normal->controller, shear.normal->controller);
  EXPECT_EQ(pull.normal->motion, Motion::by);
  EXPECT_EQ(pull.normal->value, -0.866e-6);
  ASSERT_TRUE(pull.tangential.has_value());
  EXPECT_EQ(pull.tangential->control, "fixed-load");
  EXPECT_EQ(pull.tangential->controller->held_value_key(), "force");
  EXPECT_EQ(pull.tangential->value, 0.5e-6);

  // The shorthand's fields stay unset: no preload is solved for a program.
  EXPECT_EQ(scene.glued_radius, 0.0);
  EXPECT_EQ(scene.preload_depth, 0.0);
  EXPECT_EQ(scene.normal.controller, nullptr);
  EXPECT_FALSE(scene.tangential.has_value());
}

TEST(ProgramScene, DefaultsOfAMinimalProgram) {
  // No [loading] header, no rebinding, no approach work, a stage that names nothing.
  const std::string text = replaced(
      replaced(replaced(kProgram, "approach_work_of_adhesion = 0.01\n", ""),
               "[loading]\nrebinding = true\n", ""),
      "[[loading.stage]]\nname = \"approach\"\nnormal = { control = \"fixed-grips\", to = 2.0e-5 "
      "}\n",
      "[[loading.stage]]\n");
  const Scene scene = build(text);
  ASSERT_TRUE(scene.program.has_value());
  EXPECT_FALSE(scene.program->rebinding);
  EXPECT_EQ(scene.material.approach_work_of_adhesion, 0.0);
  const Stage& first = scene.program->stages.at(0);
  EXPECT_EQ(first.name, "stage 1");
  EXPECT_FALSE(first.normal.has_value());
  EXPECT_FALSE(first.tangential.has_value());
  EXPECT_FALSE(first.until_separation);
}

TEST(ProgramScene, AxisWithoutMotionHoldsAndEqualWorkIsAllowed) {
  std::string text = replaced(kProgram, ", to = 2.0e-5 }", " }");
  text = replaced(text, "approach_work_of_adhesion = 0.01", "approach_work_of_adhesion = 0.05");
  const Scene scene = build(text);
  EXPECT_EQ(scene.program->stages[0].normal->motion, StageAxis::Motion::hold);
  EXPECT_EQ(scene.material.approach_work_of_adhesion, 0.05);
}

TEST(ProgramScene, InlineArrayOfStages) {
  const Scene scene = build(replaced(
      kProgram, kStages,
      "stage = [{ name = \"in\", normal = { to = 1e-5 } }, { normal = { by = -1e-6 }, until = "
      "\"separation\" }]\n"));
  ASSERT_EQ(scene.program->stages.size(), 2u);
  EXPECT_EQ(scene.program->stages[0].name, "in");
  EXPECT_EQ(scene.program->stages[1].normal->control, "fixed-grips");
  EXPECT_TRUE(scene.program->stages[1].until_separation);
}

TEST(ProgramScene, ShorthandBuildsAsBefore) {
  const Scene scene = build(kShorthand);
  EXPECT_FALSE(scene.program.has_value());
  EXPECT_EQ(scene.normal.control, "fixed-load");
  ASSERT_NE(scene.normal.controller, nullptr);
  ASSERT_TRUE(scene.tangential.has_value());
  EXPECT_EQ(scene.glued_radius, 5.0e-4);
  EXPECT_GT(scene.preload_depth, 0.0);
  EXPECT_EQ(scene.material.approach_work_of_adhesion, 0.0);
}

// ---- every mistake, with its message ----

struct BadProgram {
  std::string name;        ///< test name
  std::string from;        ///< text of the base scene
  std::string to;          ///< its replacement
  std::string message;     ///< the exact SceneError text
  bool shorthand = false;  ///< mutate kShorthand instead of kProgram
};

void PrintTo(const BadProgram& c, std::ostream* os) { *os << c.name; }

class BadProgramTest : public ::testing::TestWithParam<BadProgram> {};

TEST_P(BadProgramTest, FailsWithTheExactMessage) {
  const BadProgram& c = GetParam();
  const std::string text = replaced(c.shorthand ? kShorthand : kProgram, c.from, c.to);
  EXPECT_THROW_MSG(build(text), SceneError, c.message) << text;
}

std::string case_name(const ::testing::TestParamInfo<BadProgram>& info) { return info.param.name; }

constexpr const char* kNotBoth =
    "a scene has either the shorthand keys (preload, tangential, normal) or [[loading.stage]], "
    "not both";

std::vector<BadProgram> material_and_loading_cases() {
  return {
      {"ApproachWorkAboveWork", "approach_work_of_adhesion = 0.01",
       "approach_work_of_adhesion = 0.2",
       "scene.toml:6:29: material.approach_work_of_adhesion = 0.2 is above work_of_adhesion = "
       "0.05 (0 <= dgamma_a <= dgamma)"},
      {"ApproachWorkNegative", "approach_work_of_adhesion = 0.01",
       "approach_work_of_adhesion = -0.01",
       "scene.toml:6:29: material.approach_work_of_adhesion = -0.01 is outside [0, inf)"},
      {"ApproachWorkString", "approach_work_of_adhesion = 0.01",
       "approach_work_of_adhesion = \"high\"",
       "scene.toml:6:29: material.approach_work_of_adhesion: expected a number, got string "
       "\"high\""},
      {"ApproachWorkInShorthand", "approach_work_of_adhesion = 0.0",
       "approach_work_of_adhesion = 0.01",
       "scene.toml:6:29: material.approach_work_of_adhesion: applies to loading programs "
       "([[loading.stage]]) only; the shorthand's preload glues on touch",
       true},
      {"RebindingInShorthand", "[loading]\n", "[loading]\nrebinding = false\n",
       "scene.toml:11:13: loading.rebinding: applies to loading programs ([[loading.stage]]) only",
       true},
      {"PreloadWithStages", "rebinding = true\n",
       "rebinding = true\npreload = { depth = 1.0e-5 }\n",
       fmt::format("scene.toml:12:11: loading.preload: {}", kNotBoth)},
      {"NormalBeforeStages", "rebinding = true\n", "normal = { control = \"fixed-load\" }\n",
       fmt::format("scene.toml:11:10: loading.normal: {}", kNotBoth)},
      {"LoadingTypo", "rebinding = true", "rebind = true",
       "scene.toml:11:1: loading.rebind: unknown key; did you mean 'rebinding'? (known: rebinding, "
       "stage)"},
      {"RebindingNotABoolean", "rebinding = true", "rebinding = 1",
       "scene.toml:11:13: loading.rebinding: expected true or false, got 1"},
      {"RebindingString", "rebinding = true", "rebinding = \"yes\"",
       "scene.toml:11:13: loading.rebinding: expected true or false, got string \"yes\""},
      {"StagesEmpty", std::string(kStages), "stage = []\n",
       "scene.toml:12:9: loading.stage: expected at least one [[loading.stage]] table, got an "
       "empty array"},
      {"StagesNotAnArray", std::string(kStages), "stage = 3\n",
       "scene.toml:12:9: loading.stage: expected an array of tables ([[loading.stage]]), got 3"},
      {"StageElementNotATable", std::string(kStages), "stage = [{}, 3]\n",
       "scene.toml:12:14: loading.stage.2: expected a table, got 3"},
      {"StageTableNotArray", std::string(kStages), "[loading.stage]\nname = \"x\"\n",
       "scene.toml:12:1: loading.stage: expected an array of tables ([[loading.stage]]), got a "
       "table"},
      {"StageInShorthandIsAProgram", "[loading]\n", "[loading]\nstage = [{}]\n",
       fmt::format("scene.toml:12:11: loading.preload: {}", kNotBoth), true},
  };
}
INSTANTIATE_TEST_SUITE_P(MaterialAndLoading, BadProgramTest,
                         ::testing::ValuesIn(material_and_loading_cases()), case_name);

std::vector<BadProgram> stage_cases() {
  return {
      {"StageKeyTypo", "name = \"approach\"", "nmae = \"approach\"",
       "scene.toml:13:1: loading.stage.1.nmae: unknown key; did you mean 'name'? (known: "
       "duration, name, normal, speed, tangential, until)"},
      {"NameWithSpace", "name = \"shear\"", "name = \"pure shear\"",
       "scene.toml:16:8: loading.stage.2.name: \"pure shear\" is not a stage name: give letters, "
       "digits, '-' and '_' only, at least one"},
      {"NameEmpty", "name = \"shear\"", "name = \"\"",
       "scene.toml:16:8: loading.stage.2.name: \"\" is not a stage name: give letters, digits, "
       "'-' and '_' only, at least one"},
      {"NameNotAString", "name = \"shear\"", "name = 2",
       "scene.toml:16:8: loading.stage.2.name: expected a string, got 2"},
      {"NameTwice", "name = \"shear\"", "name = \"approach\"",
       "scene.toml:16:8: loading.stage.2.name: \"approach\" is the name of loading.stage.1 "
       "already; stage names must differ"},
      {"UntilUnknown", "until = \"separation\"", "until = \"separate\"",
       "scene.toml:22:9: loading.stage.3.until: unknown 'separate' (known: end, separation)"},
      {"UntilNotAString", "until = \"separation\"", "until = true",
       "scene.toml:22:9: loading.stage.3.until: expected a string, got true"},
      {"AxisNotATable", "tangential = { by = 4.0e-6 }", "tangential = 4.0e-6",
       "scene.toml:18:14: loading.stage.2.tangential: expected a table, got 4e-06"},
      {"AxisKeyTypo", "tangential = { by = 4.0e-6 }", "tangential = { bye = 4.0e-6 }",
       "scene.toml:18:16: loading.stage.2.tangential.bye: unknown key; did you mean 'by'? (known: "
       "by, control, to)"},
      {"ShorthandKeyInAStage", "tangential = { by = 4.0e-6 }",
       "tangential = { displacement = 4.0e-6 }",
       "scene.toml:18:16: loading.stage.2.tangential.displacement: unknown key (known: by, "
       "control, to)"},
      {"ControlUnknown", "control = \"fixed-grips\", to", "control = \"fixed-grip\", to",
       fmt::format("scene.toml:14:22: loading.stage.1.normal.control: unknown 'fixed-grip'; did "
                   "you mean 'fixed-grips'? "
                   "(known: {})",
                   controllers())},
      {"StiffnessOfAnotherControl", "control = \"fixed-grips\", to = 2.0e-5",
       "control = \"fixed-grips\", stiffness = 1.0, to = 2.0e-5",
       "scene.toml:14:49: loading.stage.1.normal.stiffness: applies to control = \"compliant\" "
       "only"},
      {"StiffnessWithoutControlUnderFixedGrips", "tangential = { by = 4.0e-6 }",
       "tangential = { by = 4.0e-6, stiffness = 10.0 }",
       "scene.toml:18:41: loading.stage.2.tangential.stiffness: applies to control = "
       "\"compliant\" only"},
      {"StiffnessWithoutControlUnderCompliant", "normal = { by = -0.866e-6 }",
       "normal = { by = -0.866e-6, stiffness = 10.0 }",
       "scene.toml:20:40: loading.stage.3.normal.stiffness: give control = \"compliant\" with it: "
       "an axis without control keeps its controller as it was"},
      {"CompliantWithoutStiffness", "control = \"compliant\", stiffness = 1000.0",
       "control = \"compliant\"",
       "scene.toml:17:10: loading.stage.2.normal.stiffness: missing, expected a number (machine "
       "stiffness k [N/m])"},
      {"CompliantStiffnessNegative", "stiffness = 1000.0", "stiffness = -1.0",
       "scene.toml:17:47: loading.stage.2.normal.stiffness = -1 is outside (0, inf)"},
      {"CompliantDegenerate", "stiffness = 1000.0", "stiffness = 5e-324",
       "scene.toml:17:10: loading.stage.2.normal: control = \"compliant\" is degenerate with these "
       "values (constraint a_u = 1, a_F = inf m/N)"},
      {"ToAndBy", "to = 2.0e-5 }", "to = 2.0e-5, by = 1.0e-6 }",
       "scene.toml:14:55: loading.stage.1.normal.by: give to or by, not both"},
      {"ToNotFinite", "to = 2.0e-5 }", "to = nan }",
       "scene.toml:14:42: loading.stage.1.normal.to = nan is not a finite number"},
      {"ByNotANumber", "tangential = { by = 4.0e-6 }", "tangential = { by = \"4 um\" }",
       "scene.toml:18:21: loading.stage.2.tangential.by: expected a number, got string \"4 um\""},
      {"ToUntilSeparation", "normal = { by = -0.866e-6 }", "normal = { to = -0.866e-6 }",
       "scene.toml:20:17: loading.stage.3.normal.to is refused with until = \"separation\": by is "
       "the change per unit of the stage parameter"},
      {"UntilSeparationWithoutMotion",
       "normal = { by = -0.866e-6 }\ntangential = { control = "
       "\"fixed-load\", by = 0.5e-6 }",
       "normal = { by = 0.0 }\ntangential = { control = \"fixed-load\" }",
       "scene.toml:22:9: loading.stage.3.until: \"separation\" needs a non-zero by on normal or "
       "tangential, or the stage never ends"},
  };
}
INSTANTIATE_TEST_SUITE_P(Stages, BadProgramTest, ::testing::ValuesIn(stage_cases()), case_name);

// The clock's keys (docs/programs.md "Time"). kProgram's stage 2 moves the tangential axis
// only, stage 3 both.
std::vector<BadProgram> clock_cases() {
  const std::string approach = "name = \"approach\"";
  return {
      {"DurationZero", approach, approach + "\nduration = 0.0",
       "scene.toml:14:12: loading.stage.1.duration = 0 is outside (0, inf)"},
      {"DurationNegative", approach, approach + "\nduration = -2.0",
       "scene.toml:14:12: loading.stage.1.duration = -2 is outside (0, inf)"},
      {"DurationNotFinite", approach, approach + "\nduration = nan",
       "scene.toml:14:12: loading.stage.1.duration = nan is not a finite number"},
      {"DurationNotANumber", approach, approach + "\nduration = \"2 s\"",
       "scene.toml:14:12: loading.stage.1.duration: expected a number, got string \"2 s\""},
      {"SpeedNegative", approach, approach + "\nspeed = -1e-6",
       "scene.toml:14:9: loading.stage.1.speed = -1e-06 is outside (0, inf)"},
      {"SpeedInfinite", approach, approach + "\nspeed = inf",
       "scene.toml:14:9: loading.stage.1.speed = inf is not a finite number"},
      {"DurationAndSpeed", approach, approach + "\nduration = 1.0\nspeed = 1e-6",
       "scene.toml:15:9: loading.stage.1.speed: give duration or speed, not both"},
      {"SpeedOnAHold", "tangential = { by = 4.0e-6 }", "tangential = { by = 0.0 }\nspeed = 1e-6",
       "scene.toml:19:9: loading.stage.2.speed: needs a moving axis (to, or a non-zero by); give "
       "duration for a hold"},
      {"SpeedOnTwoMovingAxes", "until = \"separation\"", "until = \"separation\"\nspeed = 1e-6",
       "scene.toml:23:9: loading.stage.3.speed: needs one moving axis; give duration for a stage "
       "that moves both"},
      {"SomeStagesTimed", approach, approach + "\nduration = 1.0",
       "scene.toml:16:1: loading.stage.2: has neither duration nor speed, which loading.stage.1 "
       "gives: a timed program gives every stage one"},
      {"ALaterStageTimed", "until = \"separation\"", "until = \"separation\"\nduration = 1.0",
       "scene.toml:12:1: loading.stage.1: has neither duration nor speed, which loading.stage.3 "
       "gives: a timed program gives every stage one"},
      {"DurationBesideTheStages", "rebinding = true\n", "rebinding = true\nduration = 1.0\n",
       "scene.toml:12:12: loading.duration: is a key of each [[loading.stage]]: every stage of a "
       "timed program gives its own"},
      {"DurationInShorthand", "[loading]\n", "[loading]\nduration = 1.0\n",
       "scene.toml:11:12: loading.duration: applies to a stage of a loading program "
       "([[loading.stage]]); the shorthand has no stage to time",
       true},
      {"SpeedInShorthand", "[loading]\n", "[loading]\nspeed = 1.0\n",
       "scene.toml:11:9: loading.speed: applies to a stage of a loading program "
       "([[loading.stage]]); the shorthand has no stage to time",
       true},
  };
}
INSTANTIATE_TEST_SUITE_P(Clock, BadProgramTest, ::testing::ValuesIn(clock_cases()), case_name);

TEST(ProgramScene, ReadsTheClock) {
  std::string text = replaced(kProgram, "name = \"approach\"", "name = \"approach\"\nspeed = 4e-6");
  text =
      replaced(text, "tangential = { by = 4.0e-6 }", "tangential = { by = 4.0e-6 }\nspeed = 1e-6");
  text = replaced(text, "until = \"separation\"", "until = \"separation\"\nduration = 7.0");
  const Scene scene = build(text);
  const auto& stages = scene.program->stages;
  EXPECT_TRUE(scene.program->timed());
  EXPECT_EQ(stages[0].speed, 4e-6);
  EXPECT_FALSE(stages[0].duration.has_value());
  EXPECT_EQ(stages[1].speed, 1e-6);
  EXPECT_EQ(stages[2].duration, 7.0);
  EXPECT_FALSE(build(kProgram).program->timed());
  // Seconds per unit of the stage parameter: the duration, or |rate| / speed.
  EXPECT_EQ(seconds_per_parameter(stages[2], -3.0), 7.0);
  EXPECT_DOUBLE_EQ(seconds_per_parameter(stages[0], -2e-5), 5.0);
}

TEST(ProgramScene, TooManyStages) {
  std::string stages = "stage = [{}";
  for (int i = 1; i < 100'001; ++i) stages += ", {}";
  stages += "]";
  EXPECT_THROW_MSG(build(replaced(kProgram, kStages, stages + "\n")), SceneError,
                   "scene.toml:12:9: loading.stage: has 100001 tables, at most 100000");
}

TEST(ProgramScene, OptionsOfTheShorthandStayAvailable) {
  const Scene scene = build(replaced(kShorthand, "springs = 100", "rtol = 1e-3"));
  EXPECT_EQ(scene.discretization.rtol, 1e-3);
}

// ---- --set and --vary at loading.stage.N ----

TEST(ProgramSet, SetsAValueInAStage) {
  SceneDocument d = program_document();
  d.set_value("loading.stage.2.normal.by", "1e-6");
  d.set_number("loading.stage.3.tangential.by", 2e-6, "--vary");
  d.set_value("loading.stage.2.until", "separation");
  d.set_value("loading.rebinding", "false");
  const Scene scene = d.build(registries());
  const Stage& shear = scene.program->stages[1];
  EXPECT_EQ(shear.normal->motion, StageAxis::Motion::by);
  EXPECT_EQ(shear.normal->value, 1e-6);
  EXPECT_EQ(shear.normal->control, "compliant");
  EXPECT_TRUE(shear.until_separation);
  EXPECT_EQ(scene.program->stages[2].tangential->value, 2e-6);
  EXPECT_FALSE(scene.program->rebinding);
}

TEST(ProgramSet, SetsTheClockOfEveryStage) {
  SceneDocument d = program_document();
  d.set_value("loading.stage.1.duration", "2.0");
  d.set_value("loading.stage.2.speed", "1e-6");
  d.set_number("loading.stage.3.duration", 3.0, "--vary");
  const Scene scene = d.build(registries());
  EXPECT_TRUE(scene.program->timed());
  EXPECT_EQ(scene.program->stages[0].duration, 2.0);
  EXPECT_EQ(scene.program->stages[1].speed, 1e-6);
  EXPECT_EQ(scene.program->stages[2].duration, 3.0);
  SceneDocument bad = program_document();
  bad.set_value("loading.stage.2.speed", "-1e-6");
  EXPECT_THROW_MSG(bad.build(registries()), SceneError,
                   "--set: loading.stage.2.speed = -1e-06 is outside (0, inf)");
}

TEST(ProgramSet, CreatesATableInsideAStage) {
  SceneDocument d = program_document();
  d.set_value("loading.stage.1.tangential.by", "3e-6");
  const SceneDocument copy = d;  // a sweep's copies replay the override
  for (const SceneDocument* doc : {static_cast<const SceneDocument*>(&d), &copy}) {
    const Scene scene = doc->build(registries());
    const Stage& approach = scene.program->stages[0];
    ASSERT_TRUE(approach.tangential.has_value());
    EXPECT_EQ(approach.tangential->control, "fixed-grips");
    EXPECT_EQ(approach.tangential->motion, StageAxis::Motion::by);
    EXPECT_EQ(approach.tangential->value, 3e-6);
  }
}

TEST(ProgramSet, ReplacesAWholeStage) {
  SceneDocument d = program_document();
  d.set_value("loading.stage.2", R"({ name = "slide", tangential = { by = 1e-6 } })");
  const Scene scene = d.build(registries());
  EXPECT_EQ(scene.program->stages[1].name, "slide");
  EXPECT_FALSE(scene.program->stages[1].normal.has_value());
}

TEST(ProgramSet, BadValuesNameTheFlagAndTheStage) {
  SceneDocument d = program_document();
  d.set_value("loading.stage.1.tangential.stiffness", "5");
  EXPECT_THROW_MSG(d.build(registries()), SceneError,
                   "--set: loading.stage.1.tangential.stiffness: applies to control = "
                   "\"compliant\" only");
  // `to` replaces the stage's `by` (docs/scene.md "Changing values from the command line"), and a
  // stage run until separation refuses it.
  SceneDocument to = program_document();
  to.set_value("loading.stage.3.normal.to", "1e-6");
  EXPECT_THROW_MSG(to.build(registries()), SceneError,
                   "--set: loading.stage.3.normal.to is refused with until = \"separation\": by "
                   "is the change per unit of the stage parameter");
  SceneDocument until = program_document();
  until.set_value("loading.stage.1.until", "separation");
  EXPECT_THROW_MSG(until.build(registries()), SceneError,
                   "scene.toml:14:42: loading.stage.1.normal.to is refused with until = "
                   "\"separation\": by is the change per unit of the stage parameter");
  SceneDocument vary = program_document();
  vary.set_number("loading.stage.3.normal.by", 0.0, "--vary");
  vary.set_number("loading.stage.3.tangential.by", 0.0, "--vary");
  EXPECT_THROW_MSG(vary.build(registries()), SceneError,
                   "scene.toml:22:9: loading.stage.3.until: \"separation\" needs a non-zero by on "
                   "normal or tangential, or the stage never ends");
}

TEST(ProgramSet, StageNumberOutOfRange) {
  SceneDocument d = program_document();
  const std::string three = "the scene has 3 stages (loading.stage.1 to loading.stage.3)";
  EXPECT_THROW_MSG(d.set_value("loading.stage.4.normal.to", "1e-6"), SceneError,
                   "--set: loading.stage.4.normal.to: " + three);
  EXPECT_THROW_MSG(d.set_value("loading.stage.0.normal.to", "1e-6"), SceneError,
                   "--set: loading.stage.0.normal.to: " + three);
  EXPECT_THROW_MSG(d.set_value("loading.stage.99999999999999999999999.name", "x"), SceneError,
                   "--set: loading.stage.99999999999999999999999.name: " + three);
  EXPECT_THROW_MSG(d.set_number("loading.stage.5", 1.0, "--vary"), SceneError,
                   "--vary: loading.stage.5: " + three);
  EXPECT_THROW_MSG(d.set_value("loading.stage.normal.to", "1e-6"), SceneError,
                   "--set: loading.stage.normal.to: 'normal' is not a stage number; " + three);
  EXPECT_THROW_MSG(d.set_value("loading.stage.-1.normal.to", "1e-6"), SceneError,
                   "--set: loading.stage.-1.normal.to: '-1' is not a stage number; " + three);
  // None of the refused keys changed the document.
  EXPECT_EQ(d.build(registries()).program->stages.size(), 3u);
}

TEST(ProgramSet, OneStageSaysSo) {
  SceneDocument d = program_document();
  d.set_value("loading.stage", R"([{ normal = { to = 1e-5 } }])");
  EXPECT_THROW_MSG(d.set_value("loading.stage.2.name", "x"), SceneError,
                   "--set: loading.stage.2.name: the scene has 1 stage (loading.stage.1)");
}

TEST(ProgramSet, NoStagesInTheScene) {
  SceneDocument d = SceneDocument::from_text(kShorthand, "scene.toml");
  EXPECT_THROW_MSG(d.set_value("loading.stage.2.normal.by", "1e-6"), SceneError,
                   "--set: loading.stage.2.normal.by: the scene has no [[loading.stage]]");
  EXPECT_THROW_MSG(d.set_number("loading.stage.1", 1.0, "--vary"), SceneError,
                   "--vary: loading.stage.1: the scene has no [[loading.stage]]");
  SceneDocument no_loading = SceneDocument::from_text(
      replaced(kShorthand,
               "[loading]\npreload = { contact_radius = 5.0e-4 }\ntangential = { control = "
               "\"fixed-grips\", displacement = 0.0 }\nnormal = { control = \"fixed-load\" }\n",
               ""),
      "scene.toml");
  EXPECT_THROW_MSG(no_loading.set_value("loading.stage.1.normal.to", "1e-6"), SceneError,
                   "--set: loading.stage.1.normal.to: the scene has no [[loading.stage]]");
  // The refused key left no empty [loading] behind.
  EXPECT_THROW_MSG(no_loading.build(registries()), SceneError,
                   "scene.toml: loading: missing, expected a table");
  // The shorthand is untouched by the refused keys.
  EXPECT_FALSE(d.build(registries()).program.has_value());
}

// ---- through the binary: bad input exits 2 with one line ----

TEST(ProgramCommand, BadProgramExitsTwoWithOneLine) {
  const std::string dir = make_temp_dir();
  const std::string path = dir + "/program.toml";
  std::ofstream(path) << replaced(kProgram, "name = \"shear\"", "name = \"approach\"");
  const CommandResult r = run_mdrsim("run '" + path + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, path +
                       ":16:8: loading.stage.2.name: \"approach\" is the name of loading.stage.1 "
                       "already; stage names must differ\n");
  const CommandResult set = run_mdrsim("run '" + path + "' --set loading.stage.7.normal.by=1");
  EXPECT_EQ(set.exit_code, 2);
  EXPECT_EQ(set.err,
            "--set: loading.stage.7.normal.by: the scene has 3 stages (loading.stage.1 to "
            "loading.stage.3)\n");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mdrsim::test
