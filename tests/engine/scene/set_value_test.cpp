// --set at the document: a key of a group of exclusive keys replaces its siblings, a part
// switched on the command line leaves the old part's keys behind, a value the shell has split
// is named as such, and a path typed on the command line is relative to the working directory.
#include <gtest/gtest.h>

#include "tests/support/expect_throw_msg.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/scene/scene_error.hpp"
#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

constexpr std::string_view kScene = R"([material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { depth = 2.0e-5 }
tangential = { control = "fixed-grips", displacement = 1.0e-6 }
normal = { control = "compliant", stiffness = 1000.0 }
[discretization]
springs = 100
)";

constexpr std::string_view kProgram = R"([material]
effective_modulus = 1.0e6
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
normal = { control = "fixed-grips", to = 2.0e-5 }
[[loading.stage]]
normal = { by = -2.0e-5 }
until = "separation"
[discretization]
springs = 100
)";

SceneDocument document(std::string_view text = kScene) {
  return SceneDocument::from_text(text, "set.toml");
}

Scene build(const SceneDocument& d) { return d.build(Registries::builtin()); }

TEST(SetExclusiveKeys, RtolReplacesSpringsAndBack) {
  SceneDocument d = document();
  d.set_value("discretization.rtol", "1e-4");
  const Scene rtol = build(d);
  EXPECT_EQ(rtol.discretization.rtol, 1e-4);
  d.set_value("discretization.springs", "300");
  const Scene springs = build(d);
  EXPECT_FALSE(springs.discretization.rtol.has_value());
  EXPECT_EQ(springs.springs, 300);
}

TEST(SetExclusiveKeys, PreloadForceReplacesDepth) {
  SceneDocument d = document();
  d.set_value("loading.preload.force", "1e-3");
  const Scene scene = build(d);
  EXPECT_EQ(scene.preload_force, 1e-3);
  d.set_value("loading.preload.contact_radius", "5e-4");
  EXPECT_EQ(build(d).glued_radius, 5e-4);
}

TEST(SetExclusiveKeys, EffectiveModulusReplacesYoungsModulusAndPoissonRatio) {
  SceneDocument d = document();
  d.set_value("material.effective_modulus", "2e6");
  const Scene scene = build(d);
  EXPECT_EQ(scene.material.effective_modulus, 2e6);
  EXPECT_EQ(scene.material.effective_shear_modulus, 2e6);  // G* defaults to E*
  // Back: E alone, with nu gone, is incomplete, and says so.
  d.set_value("material.youngs_modulus", "1e6");
  EXPECT_THROW_MSG(build(d), SceneError,
                   "set.toml:1:1: material.poisson_ratio: missing, expected a number (Poisson's "
                   "ratio nu in (-1, 0.5])");
}

TEST(SetExclusiveKeys, HeldForceReplacesHeldDisplacement) {
  SceneDocument d = document();
  d.set_value("loading.tangential.control", "fixed-load");
  d.set_value("loading.tangential.force", "1e-4");
  const Scene scene = build(d);
  EXPECT_EQ(scene.tangential->control, "fixed-load");
  EXPECT_EQ(scene.tangential->held_value, 1e-4);
}

TEST(SetExclusiveKeys, StageByReplacesTo) {
  SceneDocument d = document(kProgram);
  d.set_value("loading.stage.1.normal.by", "3e-5");
  const Scene scene = build(d);
  EXPECT_EQ(scene.program->stages[0].normal->motion, StageAxis::Motion::by);
  EXPECT_EQ(scene.program->stages[0].normal->value, 3e-5);
}

TEST(SetExclusiveKeys, StageDurationAndSpeedReplaceEachOther) {
  // A rate sweep varies either key of a stage that gives the other.
  SceneDocument d = document(kProgram);
  d.set_value("loading.stage.1.speed", "1e-6");
  d.set_value("loading.stage.2.speed", "1e-6");
  d.set_value("loading.stage.1.duration", "2.0");
  const Scene scene = build(d);
  EXPECT_EQ(scene.program->stages[0].duration, 2.0);
  EXPECT_FALSE(scene.program->stages[0].speed.has_value());
  EXPECT_EQ(scene.program->stages[1].speed, 1e-6);
  EXPECT_FALSE(scene.program->stages[1].duration.has_value());
}

TEST(SetExclusiveKeys, ProfileArraysReplaceAFile) {
  SceneDocument d = document();
  d.set_value("profile", R"({ type = "tabulated", file = "nowhere.csv" })");
  d.set_value("profile.r", "[0, 1e-4, 2e-4, 3e-4]");
  d.set_value("profile.f", "[0, 1e-6, 4e-6, 9e-6]");
  d.set_value("loading.preload", "{ contact_radius = 2e-4 }");
  EXPECT_EQ(build(d).profile_name, "tabulated");
}

TEST(SetExclusiveKeys, ACopyReplaysThemInOrder) {
  SceneDocument d = document();
  d.set_value("discretization.springs", "300");
  d.set_value("discretization.rtol", "1e-3");
  const SceneDocument copy = d;  // re-parses the file and replays the overrides
  EXPECT_EQ(build(copy).discretization.rtol, 1e-3);
}

TEST(SetPartSwitch, LeavesTheOldPartsKeysBehind) {
  SceneDocument d = document();
  d.set_value("loading.normal.control", "fixed-load");  // stiffness belongs to compliant
  d.set_value("profile.type", "cone");                  // radius belongs to parabolic, ...
  d.set_value("profile.slope_angle_deg", "30");
  const Scene scene = build(d);
  EXPECT_EQ(scene.normal.control, "fixed-load");
  EXPECT_EQ(scene.profile_name, "cone");
  EXPECT_EQ(scene.resolved->at("profile").size(), 2u);  // type and slope_angle_deg only
}

TEST(SetPartSwitch, StillNamesWhatTheNewPartMisses) {
  SceneDocument d = document();
  d.set_value("profile.type", "cone");
  EXPECT_THROW_MSG(build(d), SceneError,
                   "set.toml:5:1: profile.slope_angle_deg: missing, expected a number (angle "
                   "theta between flank and surface [degrees])");
}

TEST(SetPartSwitch, OnlyFromTheCommandLine) {
  // In the file itself a key of another part is a mistake, reported as any unknown key is.
  const std::string text = std::string(kScene).replace(std::string(kScene).find("\"parabolic\""),
                                                       11, "\"cone\"\nslope_angle_deg = 30.0");
  EXPECT_THROW_MSG(build(document(text)), SceneError,
                   "set.toml:8:10: profile.radius: applies to type = \"flat_punch\" or "
                   "\"parabolic\" or \"sphere\" or \"wavy\" only");
}

TEST(SetSplitValue, NamesTheShell) {
  const std::string tail =
      ": unquoted, the shell splits a value at spaces, expands {a,b} and drops quotes; quote "
      "the whole KEY=VALUE, as in --set 'loading.normal={ ... }'";
  SceneDocument d = document();
  // --set loading.normal={ control = "fixed-load" } reaches mdrsim as 'loading.normal={'.
  EXPECT_THROW_MSG(d.set_value("loading.normal", "{"), SceneError,
                   "--set: loading.normal: '{' is not a whole TOML inline table" + tail);
  // --set loading.normal={control="fixed-load"} loses its quotes.
  EXPECT_THROW_MSG(d.set_value("loading.normal", "{control=fixed-load}"), SceneError,
                   "--set: loading.normal: '{control=fixed-load}' is not a whole TOML inline "
                   "table" +
                       tail);
  // --set loading.normal={control="compliant",stiffness=1} is brace-expanded into two words.
  EXPECT_THROW_MSG(
      d.set_value("loading.normal", "control=compliant"), SceneError,
      "--set: loading.normal: 'control=compliant' is a piece of an inline table" + tail);
  EXPECT_FALSE(split_value_message("loading.normal", R"({ control = "fixed-load" })"));
  EXPECT_FALSE(split_value_message("loading.normal.control", "fixed-load"));
}

TEST(SetPath, IsRelativeToTheWorkingDirectory) {
  // The scene's folder has no table; the working directory (the source folder) has one.
  const std::string dir = make_temp_dir();
  const auto scene = SceneDocument::from_text(kScene, dir + "/set.toml", dir);
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(MDRSIM_SOURCE_DIR);
  SceneDocument d = scene;
  d.set_value("profile", R"({ type = "tabulated", file = "scenes/tabulated_cone.csv" })");
  d.set_value("loading.preload", "{ contact_radius = 1e-5 }");
  std::string file;
  EXPECT_NO_THROW(file = build(d).resolved->at("profile").at("file").get<std::string>());
  std::filesystem::current_path(cwd);
  EXPECT_EQ(file, std::string(MDRSIM_SOURCE_DIR) + "/scenes/tabulated_cone.csv");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mdrsim::test
