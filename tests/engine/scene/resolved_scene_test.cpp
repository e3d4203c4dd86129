// Scene::resolved: every key read with its value after defaults, valid input that builds the
// same scene; and the warning for effective moduli no isotropic half-space has.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim::test {
namespace {

constexpr std::string_view kShorthand = R"(title = "defaults"
[material]
effective_modulus = 1.0e6
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[loading]
preload = { force = 1.0e-3 }
normal = { control = "fixed-load" }
)";

constexpr std::string_view kProgram = R"([material]
youngs_modulus = 1.0e6
poisson_ratio = 0.3
work_of_adhesion = 0.05
approach_work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
normal = { control = "fixed-grips", to = 2.0e-5 }
[[loading.stage]]
name = "retract"
normal = { by = -2.0e-5 }
until = "separation"
[discretization]
springs = 200
[solver]
method = "stepping"
)";

Scene build(std::string_view text) {
  return SceneDocument::from_scene_text(text, "scene.toml").build(Registries::builtin());
}

/// run_scene, which adds the scene's warnings to the run's, with no observers.
RunResult run(const Scene& scene) { return run_scene(scene, ObserverList{}); }

TEST(ResolvedScene, HoldsEveryDefault) {
  const nlohmann::json expected = nlohmann::json::parse(R"({
    "title": "defaults",
    "material": {"effective_modulus": 1000000.0, "effective_shear_modulus": 1000000.0,
                 "work_of_adhesion": 0.05, "approach_work_of_adhesion": 0.0},
    "profile": {"type": "parabolic", "radius": 0.01},
    "loading": {"preload": {"force": 0.001}, "normal": {"control": "fixed-load"}},
    "detachment": {"criterion": "mode-mixed"},
    "discretization": {"springs": 2000},
    "solver": {"method": "event", "max_events": 1000000000000000,
               "max_events_per_spring": 64}})");
  EXPECT_EQ(*build(kShorthand).resolved, expected) << build(kShorthand).resolved->dump(2);
}

TEST(ResolvedScene, OfAProgramKeepsWhatItsAbsenceMeans) {
  const Scene scene = build(kProgram);
  const nlohmann::json& r = *scene.resolved;
  // A stage without a name is "stage N", which a scene cannot spell; an axis without control
  // keeps its controller; stepping's step defaults to 1e-3 of the stage parameter. All stay
  // absent: written out, they would mean something else.
  const nlohmann::json stages = nlohmann::json::parse(R"([
    {"normal": {"control": "fixed-grips", "to": 2e-05}, "until": "end"},
    {"name": "retract", "normal": {"by": -2e-05}, "until": "separation"}])");
  EXPECT_EQ(r["loading"]["stage"], stages);
  EXPECT_EQ(r["loading"]["rebinding"], false);
  EXPECT_EQ(r["solver"], nlohmann::json::parse(
                             R"({"method": "stepping", "max_halvings": 30,
                                 "max_steps": 100000000, "max_events": 1000000000000000,
                                 "max_events_per_spring": 64})"));
  EXPECT_EQ(r["material"]["poisson_ratio"], 0.3);
  EXPECT_FALSE(r["material"].contains("effective_modulus"));
}

TEST(ResolvedScene, BuildsTheSameScene) {
  for (const std::string_view text : {kShorthand, kProgram}) {
    const Scene first = build(text);
    const Scene again = build(first.resolved->dump());
    EXPECT_EQ(*again.resolved, *first.resolved);
    EXPECT_EQ(again.glued_radius, first.glued_radius);
    EXPECT_EQ(again.preload_depth, first.preload_depth);
    EXPECT_EQ(again.preload_force, first.preload_force);
    EXPECT_EQ(again.material.effective_shear_modulus, first.material.effective_shear_modulus);
    const RunResult a = run(first);
    const RunResult b = run(again);
    ASSERT_EQ(a.critical.has_value(), b.critical.has_value());
    if (a.critical) {
      EXPECT_EQ(a.critical->normal_force, b.critical->normal_force);
      EXPECT_EQ(a.critical->indentation, b.critical->indentation);
    }
  }
}

TEST(ModuliWarning, OutsideTheIsotropicRange) {
  std::string text(kShorthand);
  text.insert(text.find("work_of_adhesion"), "effective_shear_modulus = 1.0e7\n");
  const Scene scene = build(text);
  const std::string warning =
      "scene.toml:4:27: material.effective_shear_modulus: G*/E* = 10 is outside [2/3, 4/3], the "
      "range of an isotropic half-space (G*/E* = 2(1-nu)/(2-nu), -1 < nu <= 0.5)";
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0], warning);
  const RunResult result = run(scene);
  ASSERT_FALSE(result.warnings.empty());
  EXPECT_EQ(result.warnings[0], warning);  // a warning, not an error: the run goes on
  EXPECT_TRUE(result.critical.has_value());
}

TEST(ModuliWarning, NoneInsideIt) {
  // The ends: nu = 0.5 gives G*/E* = 2/3, nu -> -1 gives 4/3.
  for (const char* shear : {"6.666666666666666e5", "1.0e6", "1.3333333333333e6"}) {
    std::string text(kShorthand);
    text.insert(text.find("work_of_adhesion"),
                std::string("effective_shear_modulus = ") + shear + "\n");
    EXPECT_TRUE(build(text).warnings.empty()) << shear;
  }
  EXPECT_TRUE(build(kProgram).warnings.empty());  // from E and nu: always inside
}

}  // namespace
}  // namespace mdrsim::test
